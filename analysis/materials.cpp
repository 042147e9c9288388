// analysis/materials.cpp: springs against elements on one body (materials.h).

#include "analysis/materials.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iterator>
#include <memory>

#include "model/model.h"
#include "model/springfit.h"
#include "solver/simulation.h"

namespace jello {

namespace {

// The voxels of `mask`, each split into 8 of half the edge.
VoxelMask refined(const VoxelMask& mask) {
  VoxelMask fine{2 * mask.nx, 2 * mask.ny, 2 * mask.nz, {}};
  fine.filled.assign(std::size_t(fine.nx) * fine.ny * fine.nz, 0);
  for (int i = 0; i < fine.nx; ++i)
    for (int j = 0; j < fine.ny; ++j)
      for (int k = 0; k < fine.nz; ++k)
        fine.filled[fine.cell(i, j, k)] = mask.at(i / 2, j / 2, k / 2);
  return fine;
}

// The coarse points about fine node (I, J, K): those at (I/2, J/2, K/2) rounded down and up on each
// axis (one where it is even), whose mean places the fine point (exact for any affine state).
std::vector<int> coarseAround(const Body& coarse, int i, int j, int k) {
  std::vector<int> out;
  for (int a : {i / 2, (i + 1) / 2})
    for (int b : {j / 2, (j + 1) / 2})
      for (int c : {k / 2, (k + 1) / 2}) {
        const int q = coarse.pointAtIndex(a, b, c);
        if (q >= 0) out.push_back(q);
      }
  return out;
}

struct Variant {
  World world;
  State start;
  std::vector<int> probes;  // the coarse points' numbers in this body, in coarse order
  double dt = 0;
  int stepsPerSample = 1;
};

// The file's world with `body` (springs or elements by `material`) and masses of `material`.
World withBody(const World& base, std::shared_ptr<const Body> body, const Material& material,
               const SpringFit& fit, std::vector<int> pinned) {
  World w = base;
  auto spec = std::make_shared<SceneSpec>(*base.scene);
  spec->body = body;
  spec->material = material;
  spec->pinned = std::move(pinned);
  if (!material.elements()) {
    spec->springs = fit.constants;
    w.mass = meanElementMass(*body, material);
    w.kElastic = fit.constants.k[0];
    w.dElastic = fit.constants.d[0];
  }
  w.scene = spec;
  return w;
}

// The body at spacing h / factor (factor 1 or 2), its state and pins from the coarse ones.
Variant variantOf(const WorldFile& file, const Body& coarse, int factor, const Material& material,
                  const SpringFit& fineFit, const SpringFit& coarseFit) {
  Variant v;
  const double h = coarse.spacing / factor;
  const VoxelMask mask = factor == 1 ? coarse.voxels : refined(coarse.voxels);
  Body body = voxelBody(mask, h, coarse.what);
  if (material.elements()) body.springs.clear();
  auto shared = std::make_shared<const Body>(std::move(body));
  const Body& b = *shared;
  const int n = b.count(), nc = coarse.count();
  v.start = State(n);
  std::vector<char> coarsePinned(nc, 0);
  for (int q : file.world.scene->pinned) coarsePinned[q] = 1;
  std::vector<int> pinned;
  for (int q = 0; q < n; ++q) {
    const auto idx = b.index(q);
    const std::vector<int> around =
        factor == 1 ? std::vector<int>{q} : coarseAround(coarse, idx[0], idx[1], idx[2]);
    Vec3 p, vel;
    bool allPinned = true;
    for (int c : around) {
      p += load(file.state.p(), c, nc);
      vel += load(file.state.v(), c, nc);
      allPinned = allPinned && coarsePinned[c];
    }
    store(v.start.p(), q, n, (1.0 / around.size()) * p);
    store(v.start.v(), q, n, (1.0 / around.size()) * vel);
    if (allPinned) pinned.push_back(q);
  }
  for (int q = 0; q < nc; ++q) {
    const auto idx = coarse.index(q);
    v.probes.push_back(b.pointAtIndex(factor * idx[0], factor * idx[1], factor * idx[2]));
  }
  v.world = withBody(file.world, shared, material, factor == 1 ? coarseFit : fineFit, pinned);
  v.dt = file.run.dt / factor;
  v.stepsPerSample = file.run.n * factor;
  return v;
}

// Runs the variant for `samples` samples, recording its probes' positions after each.
MaterialRun runVariant(const Variant& v, Integrator integrator, int samples,
                       std::vector<Vec3>* track) {
  const Model model = makeModel(v.world, v.start);
  MaterialRun out;
  out.points = model.points();
  out.spacing = model.body().spacing;
  out.dt = v.dt;
  Simulation sim(model, v.start, integrator, v.dt);
  const int n = model.points();
  track->clear();
  double seconds = 0;
  for (int s = 0; s < samples; ++s) {
    const auto begin = std::chrono::steady_clock::now();
    const RunOutcome step = sim.advance(v.stepsPerSample);
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    if (!step.ran()) {
      out.ran = false;
      break;
    }
    for (int q : v.probes) track->push_back(load(sim.state().p(), q, n));
  }
  out.wallSeconds = seconds;
  out.usPerStep = 1e6 * seconds / std::max<long long>(1, sim.step());
  return out;
}

// Why the world cannot be compared (empty when it can).
std::string whyNotComparable(const WorldFile& file, const std::string& name) {
  const SceneSpec* spec = file.world.scene.get();
  if (!spec || !spec->jellies.empty() || !spec->material.elements())
    return name +
           ": --compare-materials needs a scene of one jelly of finite elements ([jelly] "
           "material = \"corotated\" or \"neohookean\")";
  const Body& coarse = bodyOf(file.world);
  if (coarse.gridless())
    return name +
           ": --compare-materials needs a jelly on a grid (a lattice, a sphere or a mesh's "
           "voxels), not a TetGen mesh";
  const VoxelMask& mask = coarse.voxels;
  if (2 * std::max({mask.nx, mask.ny, mask.nz}) >= kMostBodyPoints)
    return name + ": --compare-materials halves the spacing: at most " +
           std::to_string((kMostBodyPoints - 1) / 2) + " voxels along each axis";
  return {};
}

// The reference's motion and each run's error against it (tracks: the runs' probe positions,
// sample after sample; the reference's last).
void measureErrors(const WorldFile& file, const std::vector<std::vector<Vec3>>& tracks,
                   MaterialComparison* out) {
  const std::vector<Vec3>& reference = tracks.back();
  const int probes = out->probes;
  double motion = 0;
  for (int s = 0; s < out->samples; ++s)
    for (int q = 0; q < probes; ++q) {
      const Vec3 d = reference[std::size_t(s) * probes + q] - load(file.state.p(), q, probes);
      motion += dot(d, d);
    }
  out->motion = std::sqrt(motion / (double(out->samples) * probes));
  for (std::size_t i = 0; i < out->runs.size(); ++i) {
    if (!out->runs[i].ran) continue;
    double sum = 0;
    for (std::size_t e = 0; e < reference.size(); ++e) {
      const Vec3 d = tracks[i][e] - reference[e];
      sum += dot(d, d);
    }
    out->runs[i].error = std::sqrt(sum / reference.size());
  }
}

std::string fitText(const Material& material, double spacing, const SpringFit& fit) {
  char text[640];
  std::snprintf(text, sizeof text,
                "springs for E = %g Pa, nu = %g at spacing %g m: structural = bend = %.6g N/m, "
                "shear = %.6g N/m, dampers %g s times each; their nu is 0.25, their elasticity "
                "tensor %.1f%% from the material's",
                material.youngsModulus, material.poissonRatio, spacing, fit.constants.k[0],
                fit.constants.k[1], material.stiffnessDamping, 100 * fit.tensorResidual);
  std::string out = text;
  if (material.massDamping != 0)
    out += textf("; springs have no mass damping: the elements' alpha = %g 1/s has no match",
                 material.massDamping);
  return out;
}

}  // namespace

Outcome compareMaterials(const RunOptions& options, MaterialComparison* out) {
  WorldFile file;
  if (Outcome loaded = loadRun(options, &file); !loaded.ok()) return loaded;
  if (const std::string why = whyNotComparable(file, options.worldPath); !why.empty())
    return failed(why);
  const Body& coarse = bodyOf(file.world);
  const Material material = file.world.scene->material;
  Material springs = material;
  springs.kind = MaterialKind::Springs;
  const SpringFit coarseFit = springsFor(material, coarse.spacing);
  const SpringFit fineFit = springsFor(material, coarse.spacing / 2);
  const double sampleTime = file.run.dt * file.run.n;
  out->samples =
      std::max(1, static_cast<int>(std::llround(options.time.value_or(1.0) / sampleTime)));
  out->probes = coarse.count();
  // Springs and elements at the scene's spacing, then at half of it: the last is the reference.
  const std::pair<const Material*, int> plans[] = {
      {&springs, 1}, {&material, 1}, {&springs, 2}, {&material, 2}};
  std::vector<std::vector<Vec3>> tracks(std::size(plans));
  out->runs.clear();
  for (std::size_t i = 0; i < std::size(plans); ++i) {
    const auto [model, factor] = plans[i];
    const Variant v = variantOf(file, coarse, factor, *model, fineFit, coarseFit);
    MaterialRun run = runVariant(v, file.run.integrator, out->samples, &tracks[i]);
    run.model = model->elements()
                    ? std::string("elements (") + materialInfo(material.kind).name + ")"
                    : "springs (fitted)";
    run.reference = i + 1 == std::size(plans);
    out->runs.push_back(run);
  }
  if (!out->runs.back().ran)
    return diverged(options.worldPath + ": the reference (elements at half the spacing, dt " +
                    textf("%g", out->runs.back().dt) + " s) diverged; try a smaller dt");
  measureErrors(file, tracks, out);
  out->fitText = fitText(material, coarse.spacing, coarseFit);
  return succeeded();
}

std::string materialComparisonText(const std::string& worldPath, const MaterialComparison& c) {
  std::string out =
      worldPath + ": springs against finite elements on the same body\n  " + c.fitText + "\n";
  char line[256];
  std::snprintf(line, sizeof line,
                "  error: RMS over %d probe points (the body's points) and %d samples against the "
                "reference; its motion %.4g m RMS\n\n",
                c.probes, c.samples, c.motion);
  out += line;
  out +=
      "  model                    spacing (m)   points   dt (s)      error (m)    error/motion   "
      "run (s)   us/step\n";
  for (const MaterialRun& r : c.runs) {
    if (!r.ran) {
      std::snprintf(line, sizeof line, "  %-24s %-13.6g %-8d %-11.4g diverged\n", r.model.c_str(),
                    r.spacing, r.points, r.dt);
    } else if (r.reference) {
      std::snprintf(line, sizeof line,
                    "  %-24s %-13.6g %-8d %-11.4g (reference)                 %-9.3f %.1f\n",
                    r.model.c_str(), r.spacing, r.points, r.dt, r.wallSeconds, r.usPerStep);
    } else {
      std::snprintf(line, sizeof line, "  %-24s %-13.6g %-8d %-11.4g %-12.4g %-14.3f %-9.3f %.1f\n",
                    r.model.c_str(), r.spacing, r.points, r.dt, r.error,
                    c.motion > 0 ? r.error / c.motion : 0.0, r.wallSeconds, r.usPerStep);
    }
    out += line;
  }
  return out;
}

}  // namespace jello
