// analysis/stabilitymap.cpp: jello --check --map (stabilitymap.h): kElastic swept against dt, the
// predicted and observed limits written as CSV, a gnuplot script and a picture.

#include "analysis/stabilitymap.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <sstream>

#include "analysis/stability.h"
#include "core/output.h"
#include "core/plot.h"
#include "core/progress.h"
#include "model/scenespec.h"
#include "solver/guard.h"
#include "solver/integrators.h"
#include "solver/simulation.h"

namespace jello {

namespace {

// The map's numbers: the CSV, and per integrator the gnuplot data lines "kElastic dt".
struct StiffnessSweep {
  std::string csv;
  std::map<std::string, std::string> predictedRows, observedRows;
};

// kElastic from 1/8 to 8 times the world's (500 N/m when it has none): the predicted limit of
// every explicit integrator, and the observed one of three of them (real runs are slow).
StiffnessSweep sweepStiffness(const World& world, const State& initial, double time) {
  const double base = world.kElastic > 0 ? world.kElastic : 500;
  const std::vector<Integrator> observed = {Integrator::Euler, Integrator::Midpoint,
                                            Integrator::RK4};
  StiffnessSweep sweep;
  sweep.csv = "kElastic,integrator,predicted_dt,observed_dt\n";
  Progress progress;
  for (int e = -3; e <= 3; ++e) {
    World w = world;
    w.kElastic = base * std::pow(2.0, e);
    // A scene's springs by kind, and each of its jellies' springs, scale alike.
    if (world.scene && (world.scene->springs || !world.scene->jellies.empty())) {
      auto scaled = std::make_shared<SceneSpec>(*world.scene);
      if (scaled->springs)
        for (double& k : scaled->springs->k) k *= std::pow(2.0, e);
      for (JellySpec& jelly : scaled->jellies)
        for (double& k : jelly.springs.k) k *= std::pow(2.0, e);
      w.scene = scaled;
    }
    Linearisation rest = lineariseAtRest(w);
    Model model = makeModel(w, initial);
    for (Integrator integrator : kExplicitIntegrators) {
      double predicted = criticalStep(integrator, rest.modes);
      bool measured = std::find(observed.begin(), observed.end(), integrator) != observed.end();
      double seen = measured ? observedLimit(model, initial, integrator, time, predicted) : NAN;
      char line[160];
      std::snprintf(line, sizeof line, "%.6g,%s,%.6g,%s\n", w.kElastic, integratorName(integrator),
                    predicted, std::isnan(seen) ? "" : figureText(seen).c_str());
      sweep.csv += line;
      std::snprintf(line, sizeof line, "%.6g %.6g\n", w.kElastic, predicted);
      sweep.predictedRows[integratorName(integrator)] += line;
      if (!std::isnan(seen)) {
        std::snprintf(line, sizeof line, "%.6g %.6g\n", w.kElastic, seen);
        sweep.observedRows[integratorName(integrator)] += line;
      }
    }
    char done[64];
    std::snprintf(done, sizeof done, "map: kElastic %g done", w.kElastic);
    progress.show(done);
  }
  return sweep;
}

// stability-map.gp: the data inline, so that the script alone draws the picture again.
std::string mapScript(const StiffnessSweep& sweep, const std::string& worldPath, const World& world,
                      double dt) {
  std::ostringstream gp;
  gp << "# Made by jello --check --map; `gnuplot stability-map.gp` here draws stability-map.png "
        "again.\n";
  std::string plots;
  int style = 0;
  for (const auto& [name, rows] : sweep.predictedRows) {
    std::string lt = " lt " + std::to_string(++style);  // one colour an integrator
    gp << "$P_" << name << " << EOD\n" << rows << "EOD\n";
    plots += (plots.empty() ? "" : ", ") + std::string("$P_") + name + " with lines lw 2" + lt +
             " title '" + name + " predicted'";
    if (auto observed = sweep.observedRows.find(name); observed != sweep.observedRows.end()) {
      gp << "$O_" << name << " << EOD\n" << observed->second << "EOD\n";
      plots += ", $O_" + name + " with points pt 7 ps 1.3" + lt + " title '" + name + " observed'";
    }
  }
  gp << "set terminal pngcairo size 960,640 font ',11'\n"
     << "if (!exists(\"png\")) png = 'stability-map.png'\nset output png\n"
     << "set title "
     << gnuplotString(worldPath +
                      ": largest stable step against spring stiffness (stable below each line)")
     << "\n"
     << "set logscale xy\nset xlabel 'kElastic (N/m)'\nset ylabel 'dt (s)'\nset grid\nset key "
        "outside right top\n"
     << "plot " << plots << ", '-' with points pt 6 ps 3 lc 'black' title \"the world's own\"\n"
     << world.kElastic << " " << dt << "\ne\n";
  return gp.str();
}

}  // namespace

Outcome writeStabilityMap(const std::string& dir, const std::string& worldPath,
                          const WorldFile& file, double time, bool overwrite) {
  const World& world = file.world;
  FolderClaim claim;
  const Existing existing = overwrite ? Existing::Replace : Existing::Refuse;
  try {
    claim =
        claimOutputs(dir, {"stability-map.csv", "stability-map.gp", "stability-map.png"}, existing);
  } catch (const OutputError& e) {
    return failed(std::string("--map: ") + e.what());
  }
  const StiffnessSweep sweep = sweepStiffness(world, file.state, time);
  try {
    writeFileWhole(dir + "/stability-map.csv", sweep.csv, existing);
    writeFileWhole(dir + "/stability-map.gp", mapScript(sweep, worldPath, world, file.run.dt),
                   existing);
  } catch (const OutputError& e) {
    return failed(e.what());
  }
  const std::string whyNotDrawn =
      drawWithGnuplot(dir, "stability-map.gp", "stability-map.png", existing);
  const bool drawn = whyNotDrawn.empty();
  std::printf("%s: stability map in %s/ (stability-map.csv%s)\n", worldPath.c_str(), dir.c_str(),
              drawn ? ", stability-map.png" : "");
  if (drawn) return succeeded();
  // Without gnuplot the CSV is the map; a gnuplot that failed is a failure.
  const std::string notDrawn = "stability-map.png was not drawn: " + whyNotDrawn;
  return whyNotDrawn == kGnuplotMissing ? succeeded(notDrawn) : failed(notDrawn);
}

}  // namespace jello
