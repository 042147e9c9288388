// jello --report: the CSV, the plot, the summary and its recommendations.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <regex>
#include <sstream>

#include "analysis/report.h"
#include "analysis/reportstudy.h"
#include "test_support.h"

namespace jello {
namespace {

std::vector<std::string> split(const std::string& line, char separator) {
  std::vector<std::string> fields;
  std::stringstream in(line);
  for (std::string field; std::getline(in, field, separator);) fields.push_back(field);
  if (!line.empty() && line.back() == separator) fields.push_back("");
  return fields;
}

struct CsvRow {
  std::string integrator, status;
  double dt, tolerance, cpu, rms, max;
  long long steps, evaluations;
};

std::vector<CsvRow> parseRows(const std::string& text) {
  std::stringstream csv(text);
  std::string line;
  std::getline(csv, line);
  std::vector<CsvRow> rows;
  while (std::getline(csv, line)) {
    std::vector<std::string> f = split(line, ',');
    EXPECT_EQ(f.size(), 9u) << line;
    if (f.size() != 9) continue;
    auto value = [](const std::string& s) { return s.empty() ? NAN : std::stod(s); };
    rows.push_back({f[0], f[8], value(f[1]), value(f[2]), value(f[5]), value(f[6]), value(f[7]),
                    std::stoll(f[3]), std::stoll(f[4])});
  }
  return rows;
}

// One report (it takes seconds), checked for everything: jello.w from its start (stretched,
// moving, about to hit the plane), with its own setting overridden by one that is useless at
// this step: EULER at 2 ms.
TEST(Report, CsvPlotSummaryAndRecommendations) {
  const std::string dir = test::makeTempDir(), out = dir + "/out";
  test::CommandResult result = test::runJello("--report '" + out +
                                              "' --time 0.02 --integrator euler --dt 0.002 "
                                              "--integrators EULER,RK4,RK45 '" +
                                              test::dataPath("jello.w") + "'");
  ASSERT_EQ(result.status, 0) << result.err;

  // The three files, and where they are.
  EXPECT_NE(result.out.find("report in " + out + "/"), std::string::npos) << result.out;
  const std::string md = test::readText(out + "/report.md");
  EXPECT_GT(md.size(), 500u);
  const bool drawn = test::haveGnuplot();  // without gnuplot: all but the picture, then skipped
  if (drawn) {
    std::string png = test::readText(out + "/report.png");
    ASSERT_GT(png.size(), 1000u) << "no plot";
    EXPECT_EQ(png.substr(1, 3), "PNG");
  }

  // The legend and the fitted orders name what each fit is against: RK45's tolerance, the
  // others' dt; nothing reads as an "order" of RK45.
  const std::string gp = test::readText(out + "/report.gp");
  EXPECT_NE(gp.find("title 'RK45: error \u221d tolerance^{0."), std::string::npos) << gp;
  EXPECT_NE(gp.find("title 'RK4: error \u221d dt^{4."), std::string::npos) << gp;
  EXPECT_EQ(gp.find("order"), std::string::npos) << gp;
  EXPECT_NE(md.find("| RK45 | error \u221d tolerance^0."), std::string::npos) << md;
  // The y axis holds the visual tolerance's line and every error drawn with room around them:
  // none on the plot's edge.
  const std::size_t range = gp.find("set yrange ["),
                    toleranceLine = gp.find(" with lines dt 2 lc 'gray40'");
  ASSERT_NE(range, std::string::npos) << gp;
  ASSERT_NE(toleranceLine, std::string::npos) << gp;
  const double low = std::stod(gp.substr(range + 12)),
               high = std::stod(gp.substr(gp.find(':', range) + 1)),
               tolerance = std::stod(gp.substr(gp.rfind(", ", toleranceLine) + 2));
  EXPECT_LT(low, tolerance / 2);
  EXPECT_GT(high, tolerance * 2);

  // A well-formed CSV.
  const std::string csv = test::readText(out + "/report.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "integrator,dt,tolerance,steps,evaluations,cpu_s,rms_error,max_error,status");
  std::vector<CsvRow> all = parseRows(csv);
  ASSERT_EQ(all.size(), 3u * 6 + 1) << "six runs an integrator and the world's own";
  for (const CsvRow& r : all) {
    EXPECT_TRUE(r.integrator == "EULER" || r.integrator == "RK4" || r.integrator == "RK45")
        << r.integrator;
    EXPECT_TRUE(r.status == "ok" || r.status == "diverged") << r.status;
    EXPECT_GT(r.dt, 0);
    EXPECT_GT(r.steps, 0);
    EXPECT_GE(r.evaluations, r.steps);
    EXPECT_GE(r.cpu, 0);
    EXPECT_EQ(std::isnan(r.tolerance), r.integrator != "RK45");
    if (r.status == "ok") {
      EXPECT_GE(r.max, r.rms);
      EXPECT_GE(r.rms, 0);
      if (r.rms > 0) {
        EXPECT_LT(low, r.rms / 2) << r.integrator << " " << r.dt;
        EXPECT_GT(high, r.rms * 2) << r.integrator << " " << r.dt;
      }
    } else {
      EXPECT_TRUE(std::isnan(r.rms)) << "a diverged run has no error";
    }
  }

  // Errors shrink with the step (and with RK45's tolerance), EULER's in proportion.
  std::map<std::string, std::vector<CsvRow>> sweep;
  for (std::size_t i = 0; i + 1 < all.size(); ++i)
    sweep[all[i].integrator].push_back(all[i]);  // the last is the world's own
  for (auto& [name, list] : sweep) {
    ASSERT_EQ(list.size(), 6u) << name;
    for (std::size_t i = 1; i < list.size(); ++i) {
      const CsvRow &bigger = list[i - 1], &smaller = list[i];
      if (name == "RK45") {
        EXPECT_LT(smaller.tolerance, bigger.tolerance);
        EXPECT_LE(smaller.rms, bigger.rms * 1.5) << name << " tolerance " << smaller.tolerance;
      } else {
        EXPECT_DOUBLE_EQ(smaller.dt, bigger.dt / 2);
        EXPECT_LT(smaller.rms, bigger.rms) << name << " dt " << smaller.dt;
      }
    }
  }
  // The three smallest steps are in the asymptotic range.
  EXPECT_NEAR(std::log2(sweep["EULER"][3].rms / sweep["EULER"][5].rms) / 2, 1, 0.3)
      << "EULER is first order";

  // The world's own row, and a recommendation that agrees with the table.
  EXPECT_EQ(all.back().integrator, "EULER");
  EXPECT_EQ(all.back().dt, 0.002);
  const CsvRow* best = nullptr;
  for (const CsvRow& r : all)
    if (r.status == "ok" && r.rms <= 1e-4 && (!best || r.cpu < best->cpu)) best = &r;
  ASSERT_NE(best, nullptr);
  std::ostringstream setting;
  setting << best->integrator << " dt=" << best->dt;
  std::string line = md.substr(md.find("within the visual tolerance"));
  line = line.substr(0, line.find('\n'));
  EXPECT_NE(line.find(setting.str()), std::string::npos) << line << "\nexpected " << setting.str();

  // A second report into the same folder is refused.
  test::CommandResult again = test::runJello(
      "--report '" + out + "' --time 0.001 --integrators RK4 '" + test::dataPath("jello.w") + "'");
  EXPECT_EQ(again.status, 2);
  EXPECT_NE(again.err.find("--overwrite"), std::string::npos) << again.err;
  EXPECT_EQ(test::readText(out + "/report.csv"), csv);
  test::removeTree(dir);
  if (!drawn) GTEST_SKIP() << "gnuplot is not installed: report.png not checked";
}

// The reference's step as report.md gives it: T / its steps.
double referenceStep(const std::string& md, double T) {
  const std::size_t at = md.find(" steps); its own error");
  if (at == std::string::npos) return NAN;
  return T / static_cast<double>(std::stoll(md.substr(md.rfind('(', at) + 1)));
}

// The world's own setting can be a run of a sweep: it is then that row, marked, not a row of its
// own; and the reference stays 32 times below the smallest step of every sweep, those of the
// integrators after it included (the runs are on every core, their rows gathered afterwards).
TEST(Report, AWorldsOwnSettingInASweepIsThatRowAndTheReferenceIsBelowEverySweep) {
  const std::string dir = test::makeTempDir(), T = "0.01";
  ASSERT_EQ(test::runJelloArgs({"--report", dir + "/first", "--time", T, "--integrators", "RK4",
                                test::dataPath("rotate.w")})
                .status,
            0);
  double largest = 0;  // RK4's largest stable step, now the world's own dt
  for (const CsvRow& r : parseRows(test::readText(dir + "/first/report.csv")))
    if (r.integrator == "RK4") largest = std::max(largest, r.dt);
  WorldFile file = readWorldFile(test::dataPath("rotate.w"));
  file.run.integrator = Integrator::RK4;
  file.run.dt = largest;
  const std::string world = dir + "/own.w";
  writeWorldFile(world, file.world, file.run, file.state);

  test::CommandResult r = test::runJelloArgs(
      {"--report", dir + "/second", "--time", T, "--integrators", "RK4,EULER", world});
  ASSERT_EQ(r.status, 0) << r.err;
  const std::vector<CsvRow> rows = parseRows(test::readText(dir + "/second/report.csv"));
  EXPECT_EQ(rows.size(), 2u * 6) << "the world's own is RK4's first run, not a row of its own";
  double smallest = INFINITY;
  for (const CsvRow& row : rows) smallest = std::min(smallest, row.dt);
  EXPECT_LT(smallest, largest / 32) << "EULER's sweep goes below RK4's";
  const double reference = referenceStep(test::readText(dir + "/second/report.md"), 0.01);
  EXPECT_LE(reference, smallest / 32) << "the reference is below EULER's steps too";
  test::removeTree(dir);
}

// A body at rest under no force: every run is exact to the bit, every error 0. The report is
// written whole, its picture too (axes given, a line saying why it is empty): before, gnuplot
// found no point for its log scale and the run failed (exit 2).
TEST(Report, ErrorsThatAreAllZeroStillMakeTheWholeReport) {
  const std::string dir = test::makeTempDir(), scene = dir + "/rest.toml";
  test::writeText(scene,
                  "dt = 0.001\nn = 10\n\n[jelly]\nshape = \"lattice\"\nsize = [2, 2, 2]\n"
                  "spacing = 0.2\ntotal_mass = 1\nstiffness = 100\ndamping = 0.5\n");
  test::CommandResult r = test::runJelloArgs({"--report", dir + "/rep", "--time", "0.05", scene});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(test::readText(dir + "/rep/report.md").find("error 0 m"), std::string::npos);
  EXPECT_NE(test::readText(dir + "/rep/report.gp").find("nothing to draw on a log scale"),
            std::string::npos);
  if (test::haveGnuplot()) {
    struct stat info {};
    EXPECT_EQ(::stat((dir + "/rep/report.png").c_str(), &info), 0);
    EXPECT_GT(info.st_size, 1000);
  }
  test::removeTree(dir);
}

TEST(ReportFunctions, FittedOrderOfAnExactPowerLaw) {
  std::vector<ReportRow> rows;
  for (double dt : {1e-3, 5e-4, 2.5e-4}) {
    ReportRow r;
    r.integrator = Integrator::Midpoint;
    r.dt = dt;
    r.rmsError = 7 * dt * dt;
    rows.push_back(r);
  }
  EXPECT_NEAR(fittedOrder(rows, Integrator::Midpoint, 0), 2, 1e-12);
  EXPECT_TRUE(std::isnan(fittedOrder(rows, Integrator::RK4, 0)));
  rows[0].diverged = true;
  rows[1].rmsError = 1e-20;  // below the reference's floor: left out
  EXPECT_TRUE(std::isnan(fittedOrder(rows, Integrator::Midpoint, 1e-15)));
}

// The words of a POSIX shell command line made of plain words and single-quoted ones, as
// shellLine writes them ('\'' inside quotes is a quote).
std::vector<std::string> shellWords(const std::string& line) {
  std::vector<std::string> words;
  std::string word;
  bool inWord = false, quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '\'')
        quoted = false;
      else
        word += c;
    } else if (c == '\'') {
      quoted = inWord = true;
    } else if (c == '\\' && i + 1 < line.size()) {
      word += line[++i];
      inWord = true;
    } else if (c == ' ') {
      if (inWord) words.push_back(word);
      word.clear();
      inWord = false;
    } else {
      word += c;
      inWord = true;
    }
  }
  if (inWord) words.push_back(word);
  return words;
}

// The lines of `text` that start with `prefix`, less the prefix.
std::vector<std::string> linesAfter(const std::string& text, const std::string& prefix) {
  std::vector<std::string> found;
  std::stringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (line.rfind(prefix, 0) == 0) found.push_back(line.substr(prefix.size()));
  return found;
}

TEST(ReportWords, SpeedsWithinTenPercentAreTheSameSpeedOthersARatio) {
  EXPECT_EQ(kSameSpeedWithin, 0.10);
  EXPECT_EQ(speedAgainstOwn(1.05, 1), "the same speed as the world's own");
  EXPECT_EQ(speedAgainstOwn(1, 1.05), "the same speed as the world's own");
  EXPECT_EQ(speedAgainstOwn(1.0, 1.0), "the same speed as the world's own");
  EXPECT_EQ(speedAgainstOwn(1.12796, 1), "1.1 times as fast as the world's own");
  EXPECT_EQ(speedAgainstOwn(2.30019, 1), "2.3 times as fast as the world's own");
  EXPECT_EQ(speedAgainstOwn(0.0233606, 0.280915), "takes 12 times as long as the world's own");
  EXPECT_EQ(speedAgainstOwn(1, 1.5), "takes 1.5 times as long as the world's own");
}

TEST(ReportWords, RK45IsLabelledByItsToleranceTheOthersByTheirStep) {
  EXPECT_EQ(legendLabel(Integrator::RK45, 0.899009), "RK45: error \u221d tolerance^{0.90}");
  EXPECT_EQ(legendLabel(Integrator::RK4, 4.07143), "RK4: error \u221d dt^{4.07}");
  EXPECT_EQ(legendLabel(Integrator::Euler, NAN), "EULER");
  EXPECT_EQ(fittedLaw(Integrator::RK45, 0.899009), "error \u221d tolerance^0.90");
  EXPECT_EQ(fittedLaw(Integrator::Midpoint, 2.00201), "error \u221d dt^2.00");
  EXPECT_EQ(fittedLaw(Integrator::Midpoint, NAN), "n/a");
}

TEST(ReportWords, CommandsQuoteOnlyTheWordsThatNeedIt) {
  EXPECT_EQ(shellWord("world/rotate.w"), "world/rotate.w");
  EXPECT_EQ(shellWord("my world.w"), "'my world.w'");
  EXPECT_EQ(shellWord("it's.w"), "'it'\\''s.w'");
  // A newline, a terminal's escape or a byte outside UTF-8: one line, nothing raw.
  EXPECT_EQ(shellWord("a\nb's\\.w"), "$'a\\x0ab\\'s\\\\.w'");
  EXPECT_EQ(shellWord("\x1b[2J\xff\xc3\xa9.w"), "$'\\x1b[2J\\xff\\xc3\\xa9.w'");
  EXPECT_EQ(shellWord("\xc3\xa9t\xc3\xa9 world.w"), "'\xc3\xa9t\xc3\xa9 world.w'")
      << "UTF-8 text as it is";
  EXPECT_EQ(shellWord("$HOME/a.w"), "'$HOME/a.w'");
  EXPECT_EQ(shellWord("~/a.w"), "'~/a.w'");
  EXPECT_EQ(shellWord(""), "''");

  ReportRow rk4;
  rk4.integrator = Integrator::RK4;
  rk4.dt = 0.001953125;
  EXPECT_EQ(settingText(rk4), "RK4 dt=0.001953125");
  EXPECT_EQ(shellLine(runCommand("world/rotate.w", rk4)),
            "./jello --integrator RK4 --dt 0.001953125 world/rotate.w");
  EXPECT_EQ(shellLine(worldFileCommand("my worlds/rotate.w", "my report", rk4)),
            "./createWorld --from 'my worlds/rotate.w' --integrator RK4 --dt 0.001953125 -o "
            "'my report/rotate-rk4-dt0.001953125.w'")
      << "kept beside the report, never in the world's folder (the project's own world/)";
  EXPECT_EQ(shellLine(runCommand("-odd.w", rk4)),
            "./jello --integrator RK4 --dt 0.001953125 ./-odd.w")
      << "a world named like an option";

  ReportRow rk45;
  rk45.integrator = Integrator::RK45;
  rk45.dt = 0.025;
  rk45.tolerances = {1e-7, 1e-7};
  EXPECT_EQ(settingText(rk45), "RK45 dt=0.025 rtol=atol=1e-07");
  EXPECT_FALSE(worldFileHolds(rk45));
  EXPECT_EQ(shellLine(runCommand("world/rotate.w", rk45)),
            "./jello --integrator RK45 --dt 0.025 --rtol 1e-07 --atol 1e-07 world/rotate.w");
  EXPECT_TRUE(worldFileCommand("world/rotate.w", "out", rk45).empty())
      << "no world file holds rtol";
  rk45.tolerances = Tolerances{};
  EXPECT_TRUE(worldFileHolds(rk45)) << "a world file's RK45 runs at the default tolerances";
  EXPECT_EQ(shellLine(runCommand("world/rotate.w", rk45)),
            "./jello --integrator RK45 --dt 0.025 world/rotate.w");
}

// A report compares runs by their work, not by single timings a loaded machine disturbs: RK4
// at dt = 1/1024 s (4096 evaluations) is never cheaper than at 1/1000 s (4000), whatever one
// timing said; IMPLICIT, whose steps are not evaluations alone, keeps its own timing.
TEST(ReportCosts, AnExplicitRunCostsItsWorkNotItsOneTiming) {
  std::vector<ReportRow> rows(3);
  rows[0].integrator = Integrator::RK4, rows[0].dt = 0.001, rows[0].evaluations = 4000;
  rows[0].cpuSeconds = 0.13, rows[0].worldsOwn = true;  // timed while the machine was busy
  rows[1].integrator = Integrator::RK4, rows[1].dt = 0.0009765625, rows[1].evaluations = 4096;
  rows[1].cpuSeconds = 0.10;
  rows[2].integrator = Integrator::Implicit, rows[2].dt = 0.01, rows[2].evaluations = 300;
  rows[2].cpuSeconds = 0.5;
  assignCosts(rows);
  EXPECT_LT(rows[0].cost, rows[1].cost);
  EXPECT_NEAR(rows[1].cost / rows[0].cost, 4096.0 / 4000, 1e-12);
  EXPECT_EQ(rows[2].cost, 0.5);
  for (ReportRow& row : rows) row.rmsError = 1e-6;
  const Advice advice = advise("world/rotate.w", "out", rows[1], &rows[0]);
  EXPECT_EQ(advice.setting.find("times as fast"), std::string::npos) << advice.setting;
}

// Every recommended command, run as printed (parsed into its words, never through a shell),
// ends where the report's run of that setting ended: its error against the reference, run the
// same way, is the reported error; and the createWorld command writes a world with that
// integrator and dt. The world sits in a folder whose name needs quoting.
class RecommendedCommands : public ::testing::TestWithParam<const char*> {};

TEST_P(RecommendedCommands, RunAsPrintedAndReproduceTheReportedError) {
  const std::string dir = test::makeTempDir(), folder = dir + "/the student's worlds";
  ASSERT_EQ(::mkdir(folder.c_str(), 0700), 0);
  const std::string world = folder + "/rotate.w", T = "0.02";
  test::writeText(world, test::readText(test::dataPath("rotate.w")));
  // The world's own overridden by a costly one, RK4 at 0.1 ms, so that a cheaper setting is
  // recommended.
  test::CommandResult report = test::runJelloArgs({"--report", dir + "/out", "--time", T, "--dt",
                                                   "0.0001", "--integrators", GetParam(), world});
  ASSERT_EQ(report.status, 0) << report.err;
  const std::vector<std::string> runs = linesAfter(report.out, "  run it:  ");
  ASSERT_FALSE(runs.empty()) << report.out;
  EXPECT_EQ(runs[0].find(std::string("--integrator ") + GetParam()), 8u) << runs[0];
  if (std::string(GetParam()) == "RK45") {
    EXPECT_NE(report.out.find("  (a world file holds RK45 and its dt but not its tolerances (RK45 "
                              "from a world file runs at rtol=1e-06 atol=1e-09): give --rtol and "
                              "--atol each time)\n"),
              std::string::npos)
        << report.out;
    EXPECT_TRUE(linesAfter(report.out, "  keep it: ").empty()) << report.out;
  } else {
    EXPECT_FALSE(linesAfter(report.out, "  keep it: ").empty()) << report.out;
  }

  // The reference, as report.md gives it: RK4 at T / steps.
  const std::string md = test::readText(dir + "/out/report.md");
  const std::size_t at = md.find(" steps); its own error");
  ASSERT_NE(at, std::string::npos) << md;
  const long long steps = std::stoll(md.substr(md.rfind('(', at) + 1));
  char referenceDt[40];
  std::snprintf(referenceDt, sizeof referenceDt, "%.17g", std::stod(T) / steps);
  ASSERT_EQ(test::runJelloArgs({"--headless", "--time", T, "--integrator", "RK4", "--dt",
                                referenceDt, "--dump", dir + "/reference.w", world})
                .status,
            0);
  const State reference = readWorldFile(dir + "/reference.w").state;
  // "reference RK4 dt=..., its error E m" on the summary's first line.
  const std::size_t errorAt = report.out.find(", its error ");
  ASSERT_NE(errorAt, std::string::npos) << report.out;
  const double referenceError = std::stod(report.out.substr(errorAt + 12));

  const std::vector<CsvRow> rows = parseRows(test::readText(dir + "/out/report.csv"));
  for (const std::string& line : runs) {
    std::vector<std::string> words = shellWords(line);
    ASSERT_GE(words.size(), 6u) << line;
    EXPECT_EQ(words.front(), "./jello");
    EXPECT_EQ(words.back(), world) << "the world's path, as given, unquoted again";
    words.erase(words.begin());
    words.insert(words.end() - 1, {"--headless", "--time", T, "--dump", dir + "/end.w"});
    test::CommandResult run = test::runJelloArgs(words);
    ASSERT_EQ(run.status, 0) << line << "\n" << run.err;
    const double error = test::rmsDistance(readWorldFile(dir + "/end.w").state.p(), reference.p());
    const double dt = std::stod(words[3]);  // --integrator NAME --dt DT [--rtol R --atol R]
    const bool rk45 = words[4] == "--rtol";
    EXPECT_EQ(rk45, words[1] == "RK45");
    const CsvRow* measured = nullptr;
    for (const CsvRow& r : rows)
      if (r.integrator == words[1] && r.dt == dt && (!rk45 || r.tolerance == std::stod(words[5])))
        measured = &r;
    ASSERT_NE(measured, nullptr) << line;
    // The report's reference is extrapolated (Richardson) where the test's is not: they differ
    // by about a fifteenth of the reference's own error, which matters only for runs whose error
    // is near it (a recommendation of RK4 at T/256, error 9e-15 m, against a reference error of
    // 1.3e-15 m).
    EXPECT_NEAR(error, measured->rms, 1e-5 * measured->rms + referenceError / 10) << line;
    EXPECT_EQ(::unlink((dir + "/end.w").c_str()), 0);
  }

  for (const std::string& line : linesAfter(report.out, "  keep it: ")) {
    std::vector<std::string> words = shellWords(line);
    ASSERT_EQ(words.size(), 9u) << line;
    EXPECT_EQ(words[0], "./createWorld");
    words[0] = JELLO_CREATE_WORLD;
    ASSERT_EQ(test::runProgram(words).status, 0) << line;
    const WorldFile made = readWorldFile(words[8]);
    EXPECT_EQ(integratorName(made.run.integrator), words[4]);
    EXPECT_EQ(made.run.dt, std::stod(words[6]));
    EXPECT_EQ(words[8], dir + "/out/rotate-rk4-dt" + words[6] + ".w") << "kept beside the report";
  }
  test::removeTree(dir);
}

// RK4: settings a world file holds; RK45: tolerances it does not.
INSTANTIATE_TEST_SUITE_P(Report, RecommendedCommands, ::testing::Values("RK4", "RK45"));

// A scene's recommended setting is kept in the scene's own keys (createWorld writes course worlds,
// which hold no gravity, obstacles or pins): the keys as printed, added to the scene, run where
// the printed command ran, bit for bit.
TEST(Report, ASceneKeepsItsRecommendedSettingInItsOwnKeys) {
  const std::string dir = test::makeTempDir();
  const std::string body = "world = \"" + test::dataPath("rotate.w") + "\"\n";
  const std::string scene = dir + "/spin.toml";
  test::writeText(scene, body + "gravity = [0, 0, -9.81]\n");
  const test::CommandResult report =
      test::runJelloArgs({"--report", dir + "/out", "--time", "0.02", "--dt", "0.0001",
                          "--integrators", "RK4", scene});
  ASSERT_EQ(report.status, 0) << report.err;
  EXPECT_EQ(report.out.find("createWorld"), std::string::npos) << report.out;
  const std::vector<std::string> keeps = linesAfter(report.out, "  keep it: ");
  const std::vector<std::string> runs = linesAfter(report.out, "  run it:  ");
  ASSERT_FALSE(keeps.empty()) << report.out;
  ASSERT_EQ(keeps.size(), runs.size());
  const std::string& keep = keeps[0];
  const std::size_t dt = keep.find("\" and dt = "), in = keep.find(" in ");
  ASSERT_EQ(keep.rfind("integrator = \"RK4\" and dt = ", 0), 0u) << keep;
  ASSERT_NE(in, std::string::npos) << keep;
  EXPECT_EQ(keep.substr(in + 4), scene);
  const std::string kept = dir + "/kept.toml";
  test::writeText(kept, body + "integrator = \"RK4\"\ndt = " + keep.substr(dt + 10, in - dt - 10) +
                            "\ngravity = [0, 0, -9.81]\n");
  std::vector<std::string> words = shellWords(runs[0]);
  words.erase(words.begin());
  words.insert(words.end() - 1, {"--headless", "--time", "0.02", "--dump", dir + "/run.w"});
  ASSERT_EQ(test::runJelloArgs(words).status, 0);
  ASSERT_EQ(
      test::runJelloArgs({"--headless", "--time", "0.02", "--dump", dir + "/kept.w", kept}).status,
      0);
  EXPECT_EQ(readWorldFile(dir + "/run.w").state.y, readWorldFile(dir + "/kept.w").state.y);
  test::removeTree(dir);
}

// A soft, spinning cube (createWorld's recipe), `where`: by a wall it hits, or in the middle of
// the box. Soft, so that RK4 is stable at T/8 and the report takes a second or two.
std::string writeSpinningCube(const std::string& dir, const std::vector<std::string>& where) {
  const std::string path = dir + "/spinning.w";
  std::vector<std::string> argv = {JELLO_CREATE_WORLD,
                                   "--k-elastic",
                                   "5",
                                   "--d-elastic",
                                   "0.02",
                                   "--k-collision",
                                   "50",
                                   "--d-collision",
                                   "0.25",
                                   "--spin",
                                   "0",
                                   "0",
                                   "6",
                                   "-o",
                                   path};
  argv.insert(argv.end(), where.begin(), where.end());
  EXPECT_EQ(test::runProgram(argv).status, 0);
  return path;
}

// The fitted p of report.md's "| NAME | error ∝ dt^p" row; NaN without one.
double fittedInTable(const std::string& md, const std::string& name) {
  const std::string row = "| " + name + " | error \u221d dt^";
  const std::size_t at = md.find(row);
  return at == std::string::npos ? NAN : std::stod(md.substr(at + row.size()));
}

// A cube that hits a wall: RK4's errors shrink about as dt^1, and the report says that the
// contacts are why, when they began, and what --time ends before them; the same cube in the
// middle of the box fits dt^4 and gets no such note.
TEST(ReportOrders, AFitFarFromItsTheoryIsPutDownToTheContactsOfTheRun) {
  const std::string dir = test::makeTempDir();
  const std::string world =
      writeSpinningCube(dir, {"--center", "1.45", "0", "0", "--velocity", "2", "0", "0"});
  test::CommandResult r = test::runJelloArgs(
      {"--report", dir + "/out", "--time", "0.05", "--integrators", "RK4", world});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("note: RK4's fitted order is "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(", not 4: the cube touched the walls during "), std::string::npos) << r.out;
  const std::string md = test::readText(dir + "/out/report.md");
  // About order 1 across contacts (0.94 over the runs above the reference's floor, 1.05 with the
  // finest too when the reference's error was estimated against half its step, not twice).
  EXPECT_NEAR(fittedInTable(md, "RK4"), 1, 0.25) << md;
  EXPECT_NE(md.find("**RK4: error \u221d dt^"), std::string::npos) << md;
  EXPECT_NE(md.find("- The cube touched the walls during "), std::string::npos) << md;
  EXPECT_NE(md.find("not a fault of RK4"), std::string::npos) << md;
  EXPECT_EQ(md.find("The cube touched the plane"), std::string::npos) << "this world has none";
  test::removeTree(dir + "/out");

  const std::string smooth = writeSpinningCube(dir, {"--force", "--center", "0", "0", "0"});
  r = test::runJelloArgs(
      {"--report", dir + "/out", "--time", "0.05", "--integrators", "RK4", smooth});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.find("note:"), std::string::npos) << r.out;
  const std::string smoothMd = test::readText(dir + "/out/report.md");
  EXPECT_NEAR(fittedInTable(smoothMd, "RK4"), 4, kOrderSlack) << smoothMd;
  EXPECT_EQ(smoothMd.find("touched"), std::string::npos) << smoothMd;
  test::removeTree(dir);
}

// Rows of one integrator's sweep with errors E dt^order from dt = 0.01 down by halves.
std::vector<ReportRow> sweep(Integrator integrator, const std::vector<double>& errors) {
  std::vector<ReportRow> rows;
  double dt = 0.01;
  for (double error : errors) {
    ReportRow r;
    r.integrator = integrator;
    r.dt = dt;
    r.rmsError = error;
    rows.push_back(r);
    dt /= 2;
  }
  return rows;
}

TEST(ReportOrders, TheReasonsForAFarFitAreTheOnesTheRunsShow) {
  const ContactActivity none{100, 0, NAN, {}};
  const ContactActivity walls{100, 41, 0.0312, {"walls", "plane"}};
  // RK4 at dt^4: not far, no words.
  OrderCheck c = checkOrder(sweep(Integrator::RK4, {1e-2, 6.25e-4, 3.9e-5, 2.44e-6}),
                            Integrator::RK4, 1e-15, walls);
  EXPECT_NEAR(c.fitted, 4, 0.01);
  EXPECT_FALSE(c.far);
  EXPECT_EQ(orderWarning(c, walls), "");
  // RK4 at dt^1 with contacts: contacts, and a --time before the first.
  c = checkOrder(sweep(Integrator::RK4, {8e-3, 4e-3, 2e-3, 1e-3}), Integrator::RK4, 1e-15, walls);
  EXPECT_NEAR(c.fitted, 1, 1e-9);
  EXPECT_TRUE(c.far && c.contacts);
  EXPECT_FALSE(c.edgeOfStability || c.nearReference || c.divergedSteps);
  std::string words = orderWarning(c, walls);
  EXPECT_NE(words.find("- The cube touched the walls and the plane during 41% of the run, first "
                       "at t = 0.031 s."),
            std::string::npos)
      << words;
  EXPECT_NE(words.find("`--time 0.031`"), std::string::npos) << words;
  EXPECT_EQ(orderWarningLine(c, walls),
            "RK4's fitted order is 1.00, not 4: the cube touched the walls and the plane during "
            "41% of the run, and contacts are not smooth (report.md says more)");
  // EULER whose largest step is near its limit: 16 times the next error, then dt^1.
  c = checkOrder(sweep(Integrator::Euler, {0.16, 1e-2, 5e-3, 2.5e-3}), Integrator::Euler, 1e-15,
                 none);
  EXPECT_TRUE(c.far && c.edgeOfStability);
  EXPECT_FALSE(c.contacts || c.nearReference);
  EXPECT_EQ(c.largestStep, 0.01);
  EXPECT_NEAR(c.withoutLargest, 1, 1e-9);
  EXPECT_NE(orderWarning(c, none).find("- Its largest step, dt = 0.01 s, is close to its "
                                       "stability limit"),
            std::string::npos);
  // MIDPOINT flattened by a reference only 10 to 100 times below its errors.
  c = checkOrder(sweep(Integrator::Midpoint, {4e-6, 2e-6, 1.2e-6, 1e-6}), Integrator::Midpoint,
                 5e-8, none);
  EXPECT_TRUE(c.far && c.nearReference);
  EXPECT_EQ(c.finestError, 1e-6);
  EXPECT_NE(orderWarning(c, none).find("within 100 times the reference's own error (5e-08 m)"),
            std::string::npos)
      << orderWarning(c, none);
  // None of them: said so.
  c = checkOrder(sweep(Integrator::Verlet, {1e-2, 9e-3, 8e-3, 7e-3}), Integrator::Verlet, 1e-15,
                 none);
  EXPECT_NE(orderWarning(c, none).find("- None of the usual causes"), std::string::npos);
  // RK45's slope is against its tolerance: never held against an order.
  std::vector<ReportRow> rk45 = sweep(Integrator::RK45, {1e-3, 9e-4});
  rk45[0].tolerances = {1e-2, 1e-2};
  rk45[1].tolerances = {1e-3, 1e-3};
  EXPECT_FALSE(checkOrder(rk45, Integrator::RK45, 1e-15, walls).far);
}

// jello.w made stiff (kElastic 30000 N/m): RK4's search for its largest stable step halves T/8
// at least once, each halving a line of progress. T is short (2 ms) because the reference's cost
// grows with T over the stable step (16384 RK4 steps here): the test stays a few seconds even
// under the sanitizers, where T = 20 ms took two minutes.
std::string writeStiffJello(const std::string& dir) {
  WorldFile file = readWorldFile(test::dataPath("jello.w"));
  file.world.kElastic = 30000;
  const std::string path = dir + "/stiff.w";
  writeWorldFile(path, file.world, file.run, file.state);
  return path;
}

// On a terminal the progress line counts the report's items: however many halvings a search
// takes, the count never passes its total and ends on it, and its last line ends with a newline
// before the summary.
TEST(ReportProgress, CountsToItsTotalNeverPastItAndEndsItsLineBeforeTheSummary) {
  const std::string dir = test::makeTempDir(), world = writeStiffJello(dir);
  int status = -1;
  const std::string seen = test::runJelloOnTerminal(
      {"--report", dir + "/out", "--time", "0.002", "--integrators", "RK4", world}, 200, &status);
  ASSERT_EQ(status, 0) << seen;

  const std::regex counter(R"(\((\d+)/(\d+)\))");
  std::vector<std::pair<int, int>> counts;
  for (auto it = std::sregex_iterator(seen.begin(), seen.end(), counter);
       it != std::sregex_iterator(); ++it)
    counts.emplace_back(std::stoi((*it)[1]), std::stoi((*it)[2]));
  ASSERT_GT(counts.size(), 10u) << "the search's halvings show too";
  const int total = 1 + 6 + 1 + 1;  // RK4's search, its sweep, the world's own, the reference
  for (const auto& [begun, shown] : counts) {
    EXPECT_EQ(shown, total);
    EXPECT_LE(begun, total);
  }
  EXPECT_EQ(counts.back().first, total);

  // The last progress line stays, on a line of its own, and the summary starts on the next.
  const std::size_t summary = seen.find(world + ": report in");
  ASSERT_NE(summary, std::string::npos) << seen;
  const std::string before = seen.substr(0, summary);
  ASSERT_GE(before.size(), 2u);
  EXPECT_EQ(before.substr(before.size() - 2), "\r\n") << "a terminal turns \\n into \\r\\n";
  const std::string lastLine = before.substr(before.rfind('\r', before.size() - 3) + 1);
  EXPECT_EQ(lastLine.rfind("report: done, 9/9 in ", 0), 0u) << lastLine;
  EXPECT_EQ(seen.find("report: ", summary), std::string::npos) << "no progress after the summary";
  test::removeTree(dir);
}

// A line wider than the terminal would wrap, and a carriage return would leave its first rows
// behind: every line is cut to the terminal's width less one.
TEST(ReportProgress, LinesFitANarrowTerminal) {
  const std::string dir = test::makeTempDir();
  int status = -1;
  const std::string seen =
      test::runJelloOnTerminal({"--report", dir + "/out", "--time", "0.01", "--integrators", "RK45",
                                test::dataPath("rotate.w")},
                               40, &status);
  ASSERT_EQ(status, 0) << seen;
  const std::string progress = seen.substr(0, seen.find(test::dataPath("rotate.w") + ":"));
  std::size_t lines = 0;
  std::stringstream in(progress);
  for (std::string line; std::getline(in, line, '\r'); ++lines) {
    if (!line.empty() && line[0] == '\n') line.erase(0, 1);
    EXPECT_LE(line.size(), 39u) << line;
  }
  EXPECT_GT(lines, 6u);
  test::removeTree(dir);
}

}  // namespace
}  // namespace jello

namespace jello {
namespace {

// A report whose reference run diverges (a point thrown at 1e20 m/s) says so (exit 1) and
// leaves no empty report folder behind; a folder that was there stays.
TEST(Report, AReferenceThatDivergesLeavesNoEmptyFolder) {
  const std::string dir = test::makeTempDir(), world = dir + "/wild.w";
  WorldFile file = readWorldFile(test::dataPath("rotate.w"));
  file.state.v()[0] = 1e20;
  test::writeText(world, formatWorld(file));
  test::CommandResult r = test::runJelloArgs(
      {"--report", dir + "/rep", "--time", "0.01", "--integrators", "EULER", world});
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("the reference run (RK4 at dt="), std::string::npos) << r.err;
  struct stat info {};
  EXPECT_NE(::stat((dir + "/rep").c_str(), &info), 0) << "an empty folder left";
  ASSERT_EQ(::mkdir((dir + "/mine").c_str(), 0755), 0);
  r = test::runJelloArgs(
      {"--report", dir + "/mine", "--time", "0.01", "--integrators", "EULER", world});
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(::stat((dir + "/mine").c_str(), &info), 0) << "the user's own folder stays";
  test::removeTree(dir);
}

// --report recommends only steps --check calls stable (one definition: below the stable
// fraction of the integrator's limit). On rotate.w to T = 0.25 s, MIDPOINT at dt = T/256 =
// 0.0009765625 does not diverge and is the cheapest within 1 cm, but it is 100% of MIDPOINT's
// limit (0.00098 s), which --check calls marginal: it is named and left out, and what is
// recommended --check calls stable.
TEST(Report, RecommendsOnlyStepsThatCheckCallsStable) {
  // Its reference is 65536 RK4 steps: 10 s here, over two minutes under the sanitizers, whose
  // build runs every other report test; the release suite runs this one.
  if (test::kAddressSanitizer) GTEST_SKIP() << "too slow under AddressSanitizer";
  const std::string dir = test::makeTempDir(), world = test::dataPath("rotate.w");
  test::CommandResult r =
      test::runJelloArgs({"--report", dir + "/rep", "--time", "0.25", "--tolerance", "0.01",
                          "--integrators", "MIDPOINT", world});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("(MIDPOINT dt=0.000976562 is cheaper but left out: --check calls it "
                       "marginal (100% of its limit 0.00098034 s; stable is below 80%))"),
            std::string::npos)
      << r.out;
  EXPECT_NE(test::readText(dir + "/rep/report.md").find("is cheaper but left out"),
            std::string::npos);
  for (const std::string& line : linesAfter(r.out, "  run it: ")) {
    std::vector<std::string> words = shellWords(line);
    ASSERT_GE(words.size(), 5u) << line;
    test::CommandResult check =
        test::runJelloArgs({"--check", "--integrator", words[2], "--dt", words[4], world});
    EXPECT_NE(check.out.find(": stable ("), std::string::npos) << line << "\n" << check.out;
  }
  test::removeTree(dir);
}

}  // namespace
}  // namespace jello
