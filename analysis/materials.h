// analysis/materials.h: springs against finite elements on the same body (jello
// --compare-materials, docs/physics.md "Springs for a material"): the scene's jelly of elements
// run as it is, as the springs fitted to its material (model/springfit.h), and both again at half
// the spacing; every run's error against the elements at half the spacing, the reference, with
// its cost.
//
// Units: metres, seconds.
#pragma once

#include <string>
#include <vector>

#include "core/outcome.h"
#include "solver/run.h"

namespace jello {

struct MaterialRun {
  std::string model;   // "springs" or "elements (corotated)"
  double spacing = 0;  // m
  int points = 0;
  double dt = 0;           // s
  double error = 0;        // m: RMS over the probe points and the samples of |x - x_reference|
  double wallSeconds = 0;  // the run's, one thread
  double usPerStep = 0;
  bool reference = false;
  bool ran = true;  // false: it diverged (its error is then not measured)
};
struct MaterialComparison {
  std::vector<MaterialRun> runs;
  double motion = 0;  // m: RMS over the probes and samples of the reference's |x(t) - x(0)|
  int probes = 0, samples = 0;
  std::string fitText;  // the fitted springs, their Poisson's ratio and residual
};

// Refuses (failed, one line) a world that is not a scene of one jelly of finite elements on a grid
// of at most 23 voxels along each axis (so that half the spacing fits kMostBodyPoints).
Outcome compareMaterials(const RunOptions& options, MaterialComparison* out);
// The comparison as the command prints it: the fit, then a table of the runs.
std::string materialComparisonText(const std::string& worldPath, const MaterialComparison& c);

}  // namespace jello
