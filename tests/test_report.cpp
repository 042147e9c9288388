// jello --report: the CSV, the plot, the summary and its recommendations.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <regex>
#include <sstream>

#include "app/report.h"
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
  double dt, tolerance, wall, rms, max;
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

  // A well-formed CSV.
  const std::string csv = test::readText(out + "/report.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "integrator,dt,tolerance,steps,evaluations,wall_s,rms_error,max_error,status");
  std::vector<CsvRow> all = parseRows(csv);
  ASSERT_EQ(all.size(), 3u * 6 + 1) << "six runs an integrator and the world's own";
  for (const CsvRow& r : all) {
    EXPECT_TRUE(r.integrator == "EULER" || r.integrator == "RK4" || r.integrator == "RK45")
        << r.integrator;
    EXPECT_TRUE(r.status == "ok" || r.status == "diverged") << r.status;
    EXPECT_GT(r.dt, 0);
    EXPECT_GT(r.steps, 0);
    EXPECT_GE(r.evaluations, r.steps);
    EXPECT_GE(r.wall, 0);
    EXPECT_EQ(std::isnan(r.tolerance), r.integrator != "RK45");
    if (r.status == "ok") {
      EXPECT_GE(r.max, r.rms);
      EXPECT_GE(r.rms, 0);
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
    if (r.status == "ok" && r.rms <= 1e-4 && (!best || r.wall < best->wall)) best = &r;
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

// jello.w made stiff (kElastic 30000 N/m): RK4's search for its largest stable step halves T/8
// five times, each halving a line of progress.
std::string writeStiffJello(const std::string& dir) {
  WorldFile file = readWorldFile(test::dataPath("jello.w"));
  file.world.kElastic = 30000;
  const std::string path = dir + "/stiff.w";
  writeWorldFile(path, file.world, file.state);
  return path;
}

// On a terminal the progress line counts the report's items: however many halvings a search
// takes, the count never passes its total and ends on it, and its last line ends with a newline
// before the summary.
TEST(ReportProgress, CountsToItsTotalNeverPastItAndEndsItsLineBeforeTheSummary) {
  const std::string dir = test::makeTempDir(), world = writeStiffJello(dir);
  int status = -1;
  const std::string seen = test::runJelloOnTerminal(
      {"--report", dir + "/out", "--time", "0.02", "--integrators", "RK4", world}, 200, &status);
  ASSERT_EQ(status, 0) << seen;

  const std::regex counter(R"(\((\d+)/(\d+)\))");
  std::vector<std::pair<int, int>> counts;
  for (auto it = std::sregex_iterator(seen.begin(), seen.end(), counter);
       it != std::sregex_iterator(); ++it)
    counts.emplace_back(std::stoi((*it)[1]), std::stoi((*it)[2]));
  ASSERT_GT(counts.size(), 9u) << "the search's halvings show too";
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
