// report.cpp: the work-precision study of jello --report.
//
// Every run starts from the world's initial state and ends at the same time T, so that all
// of them are compared at one instant with one reference: RK4 at a much smaller step, whose
// own error is estimated against a run at half its step. Steps are T/2^k, so that every run
// lands on T exactly (the world's own dt need not: its last step is shortened, see simulate).

#include "report.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <system_error>
#include <thread>

#include "integrators.h"
#include "physics.h"
#include "output.h"
#include "plot.h"
#include "progress.h"
#include "simulation.h"

namespace jello {

namespace {

using Clock = std::chrono::steady_clock;

constexpr int kSweepLength = 6;              // steps per integrator, halving
constexpr int kReferenceRefinement = 32;     // reference step: the smallest swept step / 32
constexpr long long kMaxReferenceSteps = 1 << 16;  // ... but no more steps than this
constexpr int kLargestStepDivisor = 8;       // the stability search starts at T / 8
constexpr int kSearchHalvings = 24;
constexpr double kSameEnd = 0.01;  // m RMS: two runs that end this close agree
constexpr double kRepeatBelowSeconds = 0.25;  // runs shorter than this are timed three times
constexpr double kRk45Tolerances[kSweepLength] = {1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7};

struct Run {
  State end;
  StepStats stats;
  double wall = 0;
  bool diverged = false;
};

// From the start to time T: stepsForTime(T, dt) steps, the last one shortened when dt does not
// divide T (Simulation::advanceTo). runReport has checked that T/dt is a step count for every dt
// it passes. A run that fails the checks of every run (simulation.h) has diverged.
Run simulate(const Model& model, const State& start, Integrator integrator, double dt, double time,
             Tolerances tolerances = {}) {
  Run run;
  Simulation simulation(model, start, integrator, dt, tolerances);
  Clock::time_point begin = Clock::now();
  run.diverged = !simulation.advanceTo(time).ran();
  run.wall = std::chrono::duration<double>(Clock::now() - begin).count();
  run.end = simulation.state();
  run.stats = simulation.stats();
  return run;
}

// Runs one setting into `row`: the run itself is the warm-up; runs shorter than
// kRepeatBelowSeconds are timed twice more and the least time kept. Returns the end state.
State measure(const Model& model, const State& start, double time, Tolerances tolerances, ReportRow* row) {
  Run run = simulate(model, start, row->integrator, row->dt, time, tolerances);
  double best = run.wall;
  if (!run.diverged && run.wall < kRepeatBelowSeconds) {
    for (int repeat = 0; repeat < 2; ++repeat)
      best = std::min(best, simulate(model, start, row->integrator, row->dt, time, tolerances).wall);
  }
  row->steps = run.stats.steps;
  row->evaluations = run.stats.evaluations + run.stats.jacobians;
  row->wallSeconds = best;
  row->diverged = run.diverged;
  return run.end;
}

double rms(const State& a, const State& b, double* largest) {
  double sum = 0;
  *largest = 0;
  for (int q = 0; q < kNumPoints; ++q) {
    Vec3 d = load(a.p(), q) - load(b.p(), q);
    sum += dot(d, d);
    *largest = std::max(*largest, length(d));
  }
  return std::sqrt(sum / kNumPoints);
}

// The report's progress line: what runs now, and how many of the report's runs have begun.
class ReportProgress {
 public:
  explicit ReportProgress(int total) : total_(total) {}
  void finish() { line_.finish(); }
  void show(const std::string& what) {
    ++done_;
    line_.show("report: " + what + " (" + std::to_string(done_) + "/" + std::to_string(total_) + ")");
  }

 private:
  int total_, done_ = 0;
  Progress line_;
};

std::string number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", x);
  return text;
}

// "3.2 times as fast as the world's own", or "... slower than ...".
std::string speedup(double ratio) {
  return ratio >= 1 ? number(ratio) + " times as fast as the world's own"
                    : number(1 / ratio) + " times slower than the world's own";
}

std::string describeSetting(const ReportRow& r) {
  std::string s = std::string(integratorName(r.integrator)) + " dt=" + number(r.dt);
  if (r.integrator == Integrator::RK45) s += " tolerance=" + number(r.tolerance);
  return s;
}

std::string gnuplotScript(const std::vector<ReportRow>& rows, const std::vector<Integrator>& integrators,
                          double floor, double visualTolerance, const std::string& title) {
  std::ostringstream gp;
  gp << "# Made by jello --report; run `gnuplot report.gp` in this folder to draw report.png again.\n";
  std::string plots;
  for (Integrator integrator : integrators) {
    std::string name = integratorName(integrator);
    gp << "$" << name << " << EOD\n";
    int points = 0;
    for (const ReportRow& r : rows)
      if (r.integrator == integrator && !r.diverged && r.rmsError > 0 && !r.worldsOwn) {
        gp << r.wallSeconds << " " << r.rmsError << "\n";
        ++points;
      }
    gp << "EOD\n";
    if (points == 0) continue;
    double order = fittedOrder(rows, integrator, floor);
    std::string label = name + (std::isnan(order) ? std::string() : " (order " + number(std::round(order * 100) / 100) + ")");
    plots += (plots.empty() ? "" : ", ") + std::string("$") + name + " using 1:2 with linespoints lw 2 pt 7 title '" +
             label + "'";
  }
  gp << "$OWN << EOD\n";
  for (const ReportRow& r : rows)
    if (r.worldsOwn && !r.diverged && r.rmsError > 0) gp << r.wallSeconds << " " << r.rmsError << "\n";
  gp << "EOD\n";
  gp << "set terminal pngcairo size 960,640 font ',11'\n"
     << "if (!exists(\"png\")) png = 'report.png'\n"
     << "set output png\n"
     << "set title " << gnuplotString(title) << "\n"
     << "set logscale xy\n"
     << "set format x '10^{%L}'\nset format y '10^{%L}'\n"
     << "set xlabel 'wall time of the run (s)'\n"
     << "set ylabel 'RMS position error at the end (m)'\n"
     << "set grid\nset key outside right top\n"
     << "plot " << plots << (plots.empty() ? "" : ", ")
     << "$OWN using 1:2 with points pt 6 ps 3 lc 'black' title \"the world's own\", " << visualTolerance
     << " with lines dt 2 lc 'gray40' title 'visual tolerance'\n";
  return gp.str();
}

}  // namespace

std::string reportCsv(const std::vector<ReportRow>& rows) {
  std::ostringstream csv;
  csv << "integrator,dt,tolerance,steps,evaluations,wall_s,rms_error,max_error,status\n";
  for (const ReportRow& r : rows) {
    char line[256];
    std::snprintf(line, sizeof line, "%s,%.9g,%s,%lld,%lld,%.6g,%s,%s,%s\n", integratorName(r.integrator), r.dt,
                  r.integrator == Integrator::RK45 ? number(r.tolerance).c_str() : "", r.steps, r.evaluations,
                  r.wallSeconds, r.diverged ? "" : number(r.rmsError).c_str(),
                  r.diverged ? "" : number(r.maxError).c_str(), r.diverged ? "diverged" : "ok");
    csv << line;
  }
  return csv.str();
}

double fittedOrder(const std::vector<ReportRow>& rows, Integrator integrator, double floor) {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const ReportRow& r : rows) {
    if (r.integrator != integrator || r.diverged || r.worldsOwn || !(r.rmsError > floor)) continue;
    double x = std::log(integrator == Integrator::RK45 ? r.tolerance : r.dt), y = std::log(r.rmsError);
    n += 1;
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  if (n < 2 || n * sxx - sx * sx == 0) return NAN;
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

Outcome runReport(const RunOptions& runOptions, const ReportOptions& options) {
  WorldFile file;
  if (Outcome loaded = loadRun(runOptions, &file); !loaded.ok()) return loaded;
  const World& world = file.world;
  const State& start = file.state;
  const Model model = makeModel(world, start);
  const double T = options.time;
  // The world's own setting runs to T at the world's dt (the sweeps' steps are T / 2^k).
  if (!stepsForTime(T, world.dt)) return failed("--report: " + tooManyStepsMessage(T, world.dt));
  std::vector<Integrator> integrators = options.integrators;
  if (integrators.empty())
    for (const IntegratorInfo& row : integratorTable()) integrators.push_back(row.integrator);

  // Claim the folder and check every file before the long work, not after it.
  FolderClaim claim;
  const Existing existing = options.overwrite ? Existing::Replace : Existing::Refuse;
  try {
    claim = claimOutputs(options.dir, {"report.csv", "report.md", "report.gp", "report.png"}, existing);
  } catch (const OutputError& e) {
    return failed(std::string("--report: ") + e.what());
  }

  ReportProgress progress(static_cast<int>(integrators.size()) * (kSweepLength + 2) + 3);
  std::vector<ReportRow> rows;
  std::vector<State> ends;

  // The sweeps: for each integrator, the largest step (of T/2^k) that does not diverge, then
  // halvings; RK45 sweeps its tolerance instead.
  double smallestStep = world.dt;
  for (Integrator integrator : integrators) {
    double largest = 0;
    if (integrator != Integrator::RK45) {
      // A step counts as stable when its run does not diverge and ends where the run at half
      // the step ends, to within kSameEnd: an unstable run need not reach SPEC's 100 m within T.
      Run previous = simulate(model, start, integrator, T / kLargestStepDivisor, T);
      for (int k = 0; k < kSearchHalvings && largest == 0; ++k) {
        double dt = T / (kLargestStepDivisor << k);
        progress.show(std::string("finding ") + integratorName(integrator) + "'s largest stable step, dt=" + number(dt));
        Run half = simulate(model, start, integrator, dt / 2, T);
        double ignored;
        if (!previous.diverged && !half.diverged && rms(previous.end, half.end, &ignored) < kSameEnd) largest = dt;
        previous = std::move(half);
      }
      if (largest == 0) largest = T / (static_cast<double>(kLargestStepDivisor) * (1 << kSearchHalvings));
    }
    for (int i = 0; i < kSweepLength; ++i) {
      ReportRow row;
      row.integrator = integrator;
      Tolerances tolerances;
      if (integrator == Integrator::RK45) {
        // Its largest step as large as anyone's first try, so that the tolerance alone
        // decides the steps it takes.
        row.dt = T / kLargestStepDivisor;
        row.tolerance = kRk45Tolerances[i];
        tolerances = {row.tolerance, row.tolerance};
      } else {
        row.dt = largest / (1 << i);
        smallestStep = std::min(smallestStep, row.dt);
      }
      progress.show(describeSetting(row));
      ends.push_back(measure(model, start, T, tolerances, &row));
      rows.push_back(row);
    }
  }

  // The world's own setting, unless a sweep already ran it.
  auto own = std::find_if(rows.begin(), rows.end(), [&](const ReportRow& r) {
    return r.integrator == world.integrator && r.integrator != Integrator::RK45 && r.dt == world.dt;
  });
  if (own != rows.end()) {
    own->worldsOwn = true;
  } else {
    progress.show(std::string("the world's own ") + integratorName(world.integrator));
    ReportRow row;
    row.integrator = world.integrator;
    row.dt = world.dt;
    row.tolerance = world.integrator == Integrator::RK45 ? runOptions.tolerances.rtol : 0;
    row.worldsOwn = true;
    ends.push_back(measure(model, start, T, runOptions.tolerances, &row));
    rows.push_back(row);
  }

  // The reference and its check run at once, one on each core, after the timed runs.
  long long referenceSteps = 1;
  while (referenceSteps < kMaxReferenceSteps && T / referenceSteps > smallestStep / kReferenceRefinement)
    referenceSteps *= 2;
  const double referenceStep = T / referenceSteps;
  progress.show("the reference, RK4 dt=" + number(referenceStep) + " and dt=" + number(referenceStep / 2));
  Run reference, check;
  auto runCheck = [&] { check = simulate(model, start, Integrator::RK4, referenceStep / 2, T); };
  std::thread other;
  try {
    other = std::thread(runCheck);
  } catch (const std::system_error&) {  // no thread to be had: the same work, one after the other
    runCheck();
  }
  reference = simulate(model, start, Integrator::RK4, referenceStep, T);
  if (other.joinable()) other.join();
  if (reference.diverged || check.diverged)
    return diverged("--report: the reference run (RK4 at dt=" + number(referenceStep) + ") diverged; no report");
  double referenceMax;
  const double referenceError = rms(reference.end, check.end, &referenceMax);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (!rows[i].diverged) rows[i].rmsError = rms(ends[i], reference.end, &rows[i].maxError);
  }

  // What to recommend: the cheapest setting as accurate as the world's own, and the cheapest
  // within the visual tolerance.
  const ReportRow* ownRow = nullptr;
  for (const ReportRow& r : rows)
    if (r.worldsOwn) ownRow = &r;
  auto cheapest = [&](double limit) {
    const ReportRow* best = nullptr;
    for (const ReportRow& r : rows)
      if (!r.diverged && r.rmsError <= limit && (!best || r.wallSeconds < best->wallSeconds)) best = &r;
    return best;
  };
  const ReportRow* asAccurate = ownRow && !ownRow->diverged ? cheapest(ownRow->rmsError) : nullptr;
  const ReportRow* looksSame = cheapest(options.visualTolerance);
  const double floor = 10 * referenceError;
  progress.finish();

  // The files.
  std::string title = runOptions.worldPath + ": error at T = " + number(T) + " s against run time";
  std::ostringstream md;
  md << "# Error against run time: " << runOptions.worldPath << "\n\n"
     << "Every run goes from the world's initial state to T = " << number(T)
     << " s. Error: RMS over the 512 points of the distance to the reference positions at T (max: the largest "
        "distance). Time: the least wall time of the stepping over repeated runs, after a warm-up (runs over "
     << kRepeatBelowSeconds << " s are timed once).\n\n"
     << "Reference: RK4 at dt = " << number(referenceStep) << " s (" << referenceSteps
     << " steps); its own error, estimated against RK4 at dt = " << number(referenceStep / 2) << " s, is "
     << number(referenceError) << " m RMS. Errors below " << number(floor)
     << " m are at the reference's limit and are left out of the fitted orders.\n\n"
     << "![error against run time](report.png)\n\n"
     << "| integrator | dt (s) | tolerance | steps | evaluations | wall (s) | RMS error (m) | max error (m) | status |\n"
     << "|---|---|---|---|---|---|---|---|---|\n";
  for (const ReportRow& r : rows) {
    md << "| " << integratorName(r.integrator) << (r.worldsOwn ? " (the world's own)" : "") << " | " << number(r.dt)
       << " | " << (r.integrator == Integrator::RK45 ? number(r.tolerance) : "") << " | " << r.steps << " | "
       << r.evaluations << " | " << number(r.wallSeconds) << " | " << (r.diverged ? "" : number(r.rmsError)) << " | "
       << (r.diverged ? "" : number(r.maxError)) << " | " << (r.diverged ? "diverged" : "ok") << " |\n";
  }
  md << "\n## Fitted orders\n\nThe slope of log(error) against log(dt) (RK45: against log(tolerance)).\n\n"
     << "| integrator | fitted order | theory |\n|---|---|---|\n";
  for (Integrator integrator : integrators) {
    double order = fittedOrder(rows, integrator, floor);
    md << "| " << integratorName(integrator) << " | " << (std::isnan(order) ? std::string("n/a") : number(order)) << " | "
       << (integrator == Integrator::RK45 ? std::string("(tolerance)") : std::to_string(orderOf(integrator))) << " |\n";
  }
  md << "\n## Recommendations\n\n";
  if (ownRow) {
    md << "The world's own setting, " << describeSetting(*ownRow) << ", "
       << (ownRow->diverged ? std::string("diverges before T.")
                            : "takes " + number(ownRow->wallSeconds) + " s for an error of " + number(ownRow->rmsError) +
                                  " m.")
       << "\n\n";
  }
  auto recommend = [&](const char* what, const ReportRow* r) {
    md << "- **" << what << "**: ";
    if (!r) {
      md << "none of the runs.\n";
      return;
    }
    if (r == ownRow) {
      md << "the world's own setting; nothing cheaper is as accurate.\n";
      return;
    }
    md << describeSetting(*r) << ": " << number(r->wallSeconds) << " s, error " << number(r->rmsError) << " m";
    if (ownRow && !ownRow->diverged && r->wallSeconds > 0) md << ", " << speedup(ownRow->wallSeconds / r->wallSeconds);
    md << ".\n";
  };
  recommend("The cheapest setting at least as accurate as the world's own", asAccurate);
  recommend(("The cheapest setting within the visual tolerance (" + number(options.visualTolerance) + " m RMS)").c_str(),
            looksSame);

  try {
    writeFileWhole(options.dir + "/report.csv", reportCsv(rows), existing);
    writeFileWhole(options.dir + "/report.md", md.str(), existing);
    writeFileWhole(options.dir + "/report.gp", gnuplotScript(rows, integrators, floor, options.visualTolerance, title),
                   existing);
  } catch (const OutputError& e) {
    return failed(e.what());
  }
  const std::string whyNotDrawn = drawWithGnuplot(options.dir, "report.gp", "report.png", existing);
  const bool drawn = whyNotDrawn.empty();

  std::printf("%s: report in %s/ (report.csv, report.md%s): %zu runs to T=%g s; reference RK4 dt=%g, its error %.3g m\n",
              runOptions.worldPath.c_str(), options.dir.c_str(), drawn ? ", report.png" : "", rows.size(), T,
              referenceStep, referenceError);
  if (asAccurate == ownRow && ownRow)
    std::printf("as accurate as the world's own: nothing cheaper than the world's own setting\n");
  else if (asAccurate && ownRow && asAccurate->wallSeconds > 0)
    std::printf("as accurate as the world's own: %s, %s\n", describeSetting(*asAccurate).c_str(),
                speedup(ownRow->wallSeconds / asAccurate->wallSeconds).c_str());
  if (looksSame && ownRow && !ownRow->diverged && looksSame->wallSeconds > 0)
    std::printf("within %g m: %s, %s\n", options.visualTolerance, describeSetting(*looksSame).c_str(),
                speedup(ownRow->wallSeconds / looksSame->wallSeconds).c_str());
  if (drawn) return succeeded();
  // Without gnuplot the data files are the report; a gnuplot that failed is a failure.
  const std::string notDrawn = "report.png was not drawn: " + whyNotDrawn;
  return whyNotDrawn == kGnuplotMissing ? succeeded(notDrawn) : failed(notDrawn);
}

}  // namespace jello
