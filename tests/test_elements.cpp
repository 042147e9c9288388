// Finite elements (model/elements.h, model/material.h, docs/physics.md "Finite elements"): the
// materials' stresses against their energies, the patch test, rotations, Poisson's contraction, a
// cantilever against beam theory, energy conservation, an inverted element restored, TetGen
// meshes and the refusals of bad ones.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "analysis/stability.h"
#include "core/threadpool.h"
#include "io/inputerror.h"
#include "io/scenereader.h"
#include "io/tetmesh.h"
#include "jellyscenes.h"
#include "model/model.h"
#include "model/springfit.h"
#include "solver/integrators.h"
#include "solver/physics.h"
#include "solver/simulation.h"
#include "solver/statics.h"

namespace jello {
namespace {

constexpr Lame kLame{3.0e3, 7.0e3};  // Pa

Mat3x3 randomMatrix(std::mt19937* random, double spread) {
  std::uniform_real_distribution<double> d(-spread, spread);
  Mat3x3 m = identity3();
  for (double& e : m.m) e += d(*random);
  return m;
}

Mat3x3 rotationAbout(Vec3 axis, double angle) {
  double len;
  const Vec3 u = direction(axis, &len);
  // Rodrigues: I + sin K + (1 - cos) K^2.
  const Mat3x3 k = skew(u);
  return identity3() + std::sin(angle) * k + (1 - std::cos(angle)) * (k * k);
}

// P against central differences of Psi, and dP against central differences of P, for both
// materials at random deformations (the Neo-Hookean's also inverted ones).
TEST(Materials, StressIsTheGradientOfTheEnergyAndItsDerivativeExact) {
  std::mt19937 random(4);
  for (MaterialKind kind : {MaterialKind::Corotated, MaterialKind::NeoHookean})
    for (int sample = 0; sample < 20; ++sample) {
      Mat3x3 f = randomMatrix(&random, 0.4);
      if (kind == MaterialKind::NeoHookean && sample % 4 == 0) f.setColumn(2, -1.0 * f.column(2));
      const Mat3x3 p = firstPiola(kind, kLame, f);
      const StressDerivative derivative(kind, kLame, f);
      const double h = 1e-6;
      for (int e = 0; e < 9; ++e) {
        Mat3x3 plus = f, minus = f;
        plus.m[e] += h, minus.m[e] -= h;
        const double numeric =
            (energyDensity(kind, kLame, plus) - energyDensity(kind, kLame, minus)) / (2 * h);
        EXPECT_NEAR(p.m[e], numeric, 1e-5 * kLame.lambda) << materialInfo(kind).name;
        const Mat3x3 dp = derivative.apply(unitMatrix(e / 3, e % 3));
        const Mat3x3 change =
            (1 / (2 * h)) * (firstPiola(kind, kLame, plus) - firstPiola(kind, kLame, minus));
        for (int k = 0; k < 9; ++k)
          EXPECT_NEAR(dp.m[k], change.m[k], 1e-4 * kLame.lambda) << materialInfo(kind).name;
      }
    }
}

// The corotated stress derivative stays finite where the rotation is undefined: a reflection
// (two singular values summing to 0), F = -I and a collapsed element (F = 0).
TEST(Materials, TheCorotatedDerivativeIsFiniteWhereTheRotationIsUndefined) {
  Mat3x3 reflection = identity3();
  reflection(2, 2) = -1;
  for (const Mat3x3& f : {reflection, -1.0 * identity3(), Mat3x3{}}) {
    const StressDerivative derivative(MaterialKind::Corotated, kLame, f);
    for (int e = 0; e < 9; ++e)
      for (double value : derivative.apply(unitMatrix(e / 3, e % 3)).m)
        ASSERT_TRUE(std::isfinite(value));
  }
}

// At rest and under any rotation both materials store nothing and pull nothing; at small strain
// both give Lame's stress, 2 mu eps + lambda tr(eps) I.
TEST(Materials, RotationsAreFreeAndSmallStrainIsLames) {
  for (MaterialKind kind : {MaterialKind::Corotated, MaterialKind::NeoHookean}) {
    const Mat3x3 r = rotationAbout({0.3, -1, 0.5}, 2.1);
    EXPECT_NEAR(energyDensity(kind, kLame, r), 0, 1e-9);
    for (double e : firstPiola(kind, kLame, r).m) EXPECT_NEAR(e, 0, 1e-8);
    Mat3x3 eps;
    eps(0, 0) = 1e-6, eps(1, 1) = -3e-7, eps(0, 1) = eps(1, 0) = 2e-7, eps(2, 2) = 5e-7;
    const Mat3x3 p = firstPiola(kind, kLame, identity3() + eps);
    const Mat3x3 lame = 2 * kLame.mu * eps + kLame.lambda * trace(eps) * identity3();
    for (int k = 0; k < 9; ++k) EXPECT_NEAR(p.m[k], lame.m[k], 1e-7) << materialInfo(kind).name;
  }
}

// A scene of one jelly of elements: `size` points along each axis of spacing h, the material's
// keys, and `extra` lines (gravity, pins).
WorldFile elementScene(const std::string& material, const std::string& size, double h,
                       const std::string& extra = "", double e = 1e4, double nu = 0.3) {
  char text[1024];
  std::snprintf(text, sizeof text,
                "dt = 0.0001\n%s\n[bounds]\npresent = false\n[jelly]\nshape = \"lattice\"\n"
                "size = %s\nspacing = %.17g\nmaterial = \"%s\"\nyoungs_modulus = %.17g\n"
                "poisson_ratio = %.17g\ndensity = 1000\n",
                extra.c_str(), size.c_str(), h, material.c_str(), e, nu);
  return parseScene(text, "elements.toml", "");
}

std::vector<double> forcesAt(const Model& model, const std::vector<double>& p) {
  std::vector<double> v(p.size(), 0.0), f(p.size(), 0.0);
  computeForces(model, p.data(), v.data(), f.data());
  return f;
}

// The patch test: positions x = A X + c, a uniform strain, give every element the deformation A
// exactly and leave every point inside the body without force.
TEST(Elements, AUniformStrainIsReproducedExactly) {
  const WorldFile file = elementScene("corotated", "[4, 4, 4]", 0.1);
  const Model model = makeModel(file.world, file.state);
  const Body& body = model.body();
  const int n = model.points();
  std::mt19937 random(2);
  const Mat3x3 a = randomMatrix(&random, 0.05);
  std::vector<double> p(3 * n);
  for (int q = 0; q < n; ++q) store(p.data(), q, n, a * body.restPosition(q) + Vec3{0.2, -1, 0.4});
  const ElementTerm& elements = *model.forces.elements;
  ASSERT_EQ(elements.elementCount(), 6 * 27);
  for (int e = 0; e < elements.elementCount(); ++e) {
    const Mat3x3 f = elements.deformation(e, p.data());
    for (int k = 0; k < 9; ++k) ASSERT_NEAR(f.m[k], a.m[k], 1e-13);
  }
  const std::vector<double> f = forcesAt(model, p);
  double inside = 0, outside = 0;
  for (int q = 0; q < n; ++q) {
    const auto i = body.index(q);
    const bool interior = i[0] > 0 && i[0] < 3 && i[1] > 0 && i[1] < 3 && i[2] > 0 && i[2] < 3;
    (interior ? inside : outside) =
        std::max(interior ? inside : outside, length(load(f.data(), q, n)));
  }
  EXPECT_GT(outside, 1.0);
  EXPECT_LT(inside, 1e-12 * outside);
}

// Any rigid rotation and translation of the rest shape: no force and no energy, both materials.
TEST(Elements, RigidMotionsExertNoForce) {
  for (const char* material : {"corotated", "neohookean"}) {
    const WorldFile file = elementScene(material, "[3, 4, 3]", 0.1);
    const Model model = makeModel(file.world, file.state);
    const int n = model.points();
    const Mat3x3 r = rotationAbout({1, 2, -0.5}, 2.7);
    std::vector<double> p(3 * n);
    for (int q = 0; q < n; ++q)
      store(p.data(), q, n, r * model.body().restPosition(q) + Vec3{1, 0.5, -0.3});
    double energy = 0;
    model.forces.elements->addEnergy(p.data(), &energy);
    EXPECT_NEAR(energy, 0, 1e-12) << material;
    for (double force : forcesAt(model, p)) EXPECT_NEAR(force, 0, 1e-10) << material;
  }
}

// Uniaxial stress: a bar stretched by eps along x contracts by nu eps across when its sides are
// free. The bar is stretched uniformly and its width chosen so that the forces on its side faces
// sum to zero; width change over length change is -nu.
TEST(Elements, UniaxialStretchContractsByPoissonsRatio) {
  const std::pair<const char*, double> cases[] = {
      {"corotated", 0.0},  {"corotated", 0.3},   {"corotated", 0.45},  {"neohookean", 0.0},
      {"neohookean", 0.3}, {"neohookean", 0.45}, {"neohookean", -0.5}, {"neohookean", -0.9}};
  for (const auto& [material, nu] : cases) {
    {
      const WorldFile file = elementScene(material, "[5, 3, 3]", 0.1, "", 1e4, nu);
      const Model model = makeModel(file.world, file.state);
      const Body& body = model.body();
      const int n = model.points();
      const double eps = 1e-5;
      // The y forces on the face y = its largest, for a lateral strain delta.
      auto sideForce = [&](double delta) {
        std::vector<double> p(3 * n);
        for (int q = 0; q < n; ++q) {
          const Vec3 x = body.restPosition(q);
          store(p.data(), q, n, Vec3{(1 + eps) * x.x, (1 + delta) * x.y, (1 + delta) * x.z});
        }
        const std::vector<double> f = forcesAt(model, p);
        double sum = 0;
        for (int q = 0; q < n; ++q)
          if (body.index(q)[1] == 2) sum += load(f.data(), q, n).y;
        return sum;
      };
      // The side force is linear in delta to rounding at this strain: one secant step.
      const double a = sideForce(0), b = sideForce(-eps);
      const double delta = eps * a / (b - a);
      EXPECT_NEAR(-delta / eps, nu, 2e-4) << material << " " << nu;
      if (nu < 0) {
        EXPECT_GT(delta, 0) << "an auxetic bar widens as it is stretched";
      }
    }
  }
}

// Beam theory's sag of a cantilever under its own weight, q L^4 / (8 E I), q = rho g A,
// I = h^4 / 12 for a square section h: the static sag of the tip (the mean of its face's
// points) at n elements through the thickness.
double cantileverSag(int n, double* beamTheory) {
  const double length = 0.5, h = 0.1, e = 1e9, rho = 1000, g = 9.81;
  char size[64];
  std::snprintf(size, sizeof size, "[%d, %d, %d]", 5 * n + 1, n + 1, n + 1);
  const WorldFile file = elementScene("corotated", size, h / n,
                                      "gravity = [0, 0, -9.81]\n[[pin]]\ni = [0, 0]", e, 0.0);
  const Model model = makeModel(file.world, file.state);
  const StaticSolution rest = solveStatic(model, file.state);
  EXPECT_TRUE(rest.converged);
  const int points = model.points();
  double sag = 0;
  int tip = 0;
  for (int q = 0; q < points; ++q)
    if (model.body().index(q)[0] == 5 * n) {
      sag += load(file.state.p(), q, points).z - load(rest.state.p(), q, points).z;
      ++tip;
    }
  *beamTheory = rho * g * h * h * std::pow(length, 4) / (8 * e * std::pow(h, 4) / 12);
  return sag / tip;
}

TEST(Elements, ACantileverSagsAsBeamTheorySaysAndConvergesAsTheMeshRefines) {
  double theory = 0;
  double previous = 0;
  for (int n : {1, 2, 4, 8}) {
    const double sag = cantileverSag(n, &theory);
    const double error = std::fabs(sag - theory) / theory;
    if (n > 1) {
      EXPECT_LT(error, previous) << n;
    }
    previous = error;
    if (n == 8) {
      EXPECT_LT(error, 0.05);
    }
    std::printf("cantilever n = %d: sag %.6g m, beam theory %.6g m, error %.2f%%\n", n, sag, theory,
                100 * error);
  }
}

// Kinetic plus elastic energy, J.
double totalEnergy(const Model& model, const State& s) {
  const int n = model.points();
  double energy = 0;
  model.forces.elements->addEnergy(s.p(), &energy);
  for (int q = 0; q < n; ++q)
    energy += 0.5 * model.pointMass[q] * dot(load(s.v(), q, n), load(s.v(), q, n));
  return energy;
}

// Without damping, a jelly of elements set spinning and stretching keeps its energy: RK4's drift
// falls as dt^4 (a sixteenth for half the step), and is under 1e-6 of it at the small step.
TEST(Elements, EnergyIsConservedWithoutDamping) {
  for (const char* material : {"corotated", "neohookean"}) {
    const WorldFile file = elementScene(material, "[4, 4, 4]", 0.1);
    State start = file.state;
    const int n = start.points();
    for (int q = 0; q < n; ++q) {
      const Vec3 x = load(start.p(), q, n);
      store(start.v(), q, n, Vec3{-2 * x.y + 0.5 * x.x, 2 * x.x, 0.3 * x.z});
    }
    const Model model = makeModel(file.world, start);
    const double before = totalEnergy(model, start);
    double drift[2];
    for (int k = 0; k < 2; ++k) {
      const double dt = 4e-3 / (1 << k);
      Simulation sim(model, start, Integrator::RK4, dt);
      ASSERT_TRUE(sim.advance(std::llround(0.2 / dt)).ran()) << material;
      drift[k] = std::fabs(totalEnergy(model, sim.state()) - before) / before;
    }
    std::printf("%s: energy drift %.3g at dt = 4 ms, %.3g at 2 ms\n", material, drift[0], drift[1]);
    EXPECT_LT(drift[1], 1e-6) << material;
    EXPECT_GT(drift[0], 1e-11) << material;  // the steps' error, not rounding
    EXPECT_LT(drift[1], drift[0] / 10) << material;
  }
}

// An element turned inside out (one corner pushed through the opposite face) is pushed back by
// the Neo-Hookean material: a damped run ends with every element the right way out, nothing NaN.
TEST(Elements, AnInvertedElementIsPushedBack) {
  for (const char* material : {"neohookean", "corotated"}) {
    WorldFile file = elementScene(material, "[2, 2, 2]", 0.1);
    const Model model = makeModel(file.world, file.state);
    State start = file.state;
    const int n = start.points();
    // Corner (1,1,1) pushed through to beyond corner (0,0,0).
    const int corner = model.body().pointAtIndex(1, 1, 1);
    store(start.p(), corner, n, load(start.p(), corner, n) - Vec3{0.15, 0.15, 0.15});
    int inverted = 0;
    const ElementTerm& elements = *model.forces.elements;
    for (int e = 0; e < elements.elementCount(); ++e)
      inverted += tetVolume(elements.element(e), start.p(), n) < 0;
    ASSERT_GT(inverted, 0);
    World w = file.world;
    std::shared_ptr<SceneSpec> spec = std::make_shared<SceneSpec>(*w.scene);
    spec->material.stiffnessDamping = 0.01;
    w.scene = spec;
    const Model damped = makeModel(w, start);
    Simulation sim(damped, start, Integrator::Implicit, 1e-3);
    ASSERT_TRUE(sim.advance(500).ran()) << material;
    for (int e = 0; e < elements.elementCount(); ++e)
      EXPECT_GT(tetVolume(elements.element(e), sim.state().p(), n), 0) << material;
    for (int c = 0; c < 3 * n; ++c) ASSERT_TRUE(std::isfinite(sim.state().p()[c]));
  }
}

// A jelly of elements weighs its density times its volume, each tetrahedron's mass shared by
// its four corners.
TEST(Elements, MassesAreLumpedFromTheDensity) {
  const WorldFile file = elementScene("corotated", "[3, 4, 5]", 0.1);
  const Model model = makeModel(file.world, file.state);
  double total = 0;
  for (double m : model.pointMass) total += m;
  EXPECT_NEAR(total, 1000 * 0.2 * 0.3 * 0.4, 1e-9);
  // A corner of the lattice belongs to 1 or 3 of the voxel's 6 tetrahedra; a middle point to 24.
  const double tet = 1000 * 0.001 / 6 / 4;
  const Body& body = model.body();
  EXPECT_NEAR(model.pointMass[body.pointAtIndex(1, 1, 1)], 24 * tet, 1e-12);
  EXPECT_NEAR(model.pointMass[body.pointAtIndex(0, 0, 0)], 6 * tet, 1e-12);
  EXPECT_NEAR(model.pointMass[body.pointAtIndex(2, 0, 0)], 2 * tet, 1e-12);
}

// The stability analysis of a jelly of elements, whose lumped masses differ from point to point:
// at rest no mode grows (the stiffness is positive semi-definite; its symmetric part, taken on
// M^-1 K without the masses' symmetrisation, had 25 negative eigenvalues), and the fastest mode is
// the same at rest and at the (resting) initial state.
TEST(Elements, TheStabilityAnalysisSeesNoGrowingModeAtRest) {
  const WorldFile file = elementScene("neohookean", "[5, 5, 5]", 0.02, "", 1e4, 0.45);
  const StabilityReport report = analyseStability(file.world, file.state);
  EXPECT_EQ(report.rest.growing, 0);
  EXPECT_EQ(report.initial.growing, 0);
  EXPECT_GT(report.rest.highestFrequency, 100);
  EXPECT_NEAR(report.initial.highestFrequency, report.rest.highestFrequency,
              1e-6 * report.rest.highestFrequency);
  // The quick bound of large bodies (Gershgorin's, from the Newton blocks, the elements' coupling
  // blocks among them) is below the analysis's limit, and not far below.
  const Model model = makeModel(file.world, file.state);
  const RowSumBound bound = rowSumBound(model, file.state, Integrator::RK4);
  const double limit = report.critical(Integrator::RK4);
  EXPECT_LE(bound.limit, limit);
  EXPECT_GT(bound.limit, 0.2 * limit);
  EXPECT_GE(bound.fastest, report.rest.highestFrequency);
}

// The springs fitted to a material: the lattice's cubic stiffnesses, summed spring by spring over
// the 16 offsets, are those latticeStiffness states, and the fit's solid is isotropic with the
// material's E (C11 = 3 mu', C12 = C44 = mu', E = 2.5 mu').
TEST(Elements, FittedSpringsGiveTheMaterialsYoungsModulus) {
  Material m;
  m.kind = MaterialKind::Corotated;
  m.youngsModulus = 1e4, m.poissonRatio = 0.45, m.density = 1000, m.stiffnessDamping = 0.01;
  const double h = 0.02;
  const SpringFit fit = springsFor(m, h);
  // Per unit volume, a spring of length l along n under a uniform strain e stretches by l n.e.n:
  // uniaxial e_xx gives C11 e^2 / 2, pure shear e_xy = e_yx gives 2 C44 e^2.
  double c11 = 0, c44 = 0;
  for (const SpringOffset& o : kSpringOffsets) {
    const double k = fit.constants.k[int(o.kind)], l = restLength(o, h);
    const Vec3 n = (1.0 / (l / h)) * Vec3{double(o.di), double(o.dj), double(o.dk)};
    c11 += k * l * l * n.x * n.x * n.x * n.x / (h * h * h);
    c44 += k * l * l * n.x * n.x * n.y * n.y / (h * h * h);
  }
  const CubicStiffness c = latticeStiffness(fit.constants, h);
  EXPECT_NEAR(c.c11, c11, 1e-9 * c11);
  EXPECT_NEAR(c.c44, c44, 1e-9 * c44);
  const double mu = m.youngsModulus / 2.5;
  EXPECT_NEAR(c.c11, 3 * mu, 1e-9 * mu);
  EXPECT_NEAR(c.c12, mu, 1e-9 * mu);
  // Young's modulus of the cubic solid along an axis: (C11 - C12)(C11 + 2 C12) / (C11 + C12).
  EXPECT_NEAR((c.c11 - c.c12) * (c.c11 + 2 * c.c12) / (c.c11 + c.c12), m.youngsModulus, 1e-6);
  EXPECT_NEAR(fit.constants.d[1], 0.01 * fit.constants.k[1], 1e-12);
  EXPECT_NEAR(fit.tensorResidual, 0.79, 0.01);  // nu = 0.45 is far from the springs' 0.25
  m.poissonRatio = 0.25;
  EXPECT_LT(springsFor(m, h).tensorResidual, 1e-12);  // at 0.25 the springs are exact
}

// A jelly of elements meets a jelly of springs head-on, through contact between bodies, without
// gravity or walls: the total momentum stays what it was (to rounding) while each jelly's changes.
TEST(Elements, AJellyOfElementsCollidesWithOneOfSpringsKeepingMomentum) {
  // The head-on scene of the contact tests, its first jelly made of elements.
  std::string text = test::kHeadOn;
  const std::string springs = "stiffness = 500\ndamping = 0.3\n";
  text.replace(text.find(springs), springs.size(),
               "material = \"corotated\"\nyoungs_modulus = 2e4\npoisson_ratio = 0.3\n"
               "density = 100\nstiffness_damping = 0.001\n");
  const WorldFile file = test::scene(text);
  const Model model = makeModel(file.world, file.state);
  ASSERT_NE(model.forces.elements, nullptr);
  const int n = model.points();
  auto momentum = [&](const State& s, int part) {
    Vec3 sum;
    for (int q = 0; q < n; ++q)
      if (part < 0 || model.body().partOf(q) == part) sum += model.pointMass[q] * load(s.v(), q, n);
    return sum;
  };
  Simulation sim(model, file.state, Integrator::RK4, 2e-4);
  ASSERT_TRUE(sim.advance(1500).ran());
  const Vec3 before = momentum(file.state, -1), after = momentum(sim.state(), -1);
  const double scale = length(momentum(file.state, 0));
  EXPECT_GT(length(momentum(sim.state(), 0) - momentum(file.state, 0)), 0.1 * scale);
  EXPECT_LT(length(after - before), 1e-12 * scale);
}

// The element term on ranges of points adds what the whole call adds there, bit for bit, at
// every split; and a run on two threads (core/threadpool.h) is the run on one, bit for bit.
TEST(Elements, RangesAndTwoThreadsGiveTheSameBits) {
  WorldFile file =
      elementScene("corotated", "[5, 4, 6]", 0.05, "gravity = [0, 0, -9.81]", 1e4, 0.4);
  std::shared_ptr<SceneSpec> spec = std::make_shared<SceneSpec>(*file.world.scene);
  spec->material.stiffnessDamping = 0.002, spec->material.massDamping = 0.3;
  file.world.scene = spec;
  const int n = file.state.points();
  std::mt19937 random(8);
  std::uniform_real_distribution<double> jitter(-0.005, 0.005);
  for (int c = 0; c < 3 * n; ++c)
    file.state.p()[c] += jitter(random), file.state.v()[c] = 50 * jitter(random);
  const Model model = makeModel(file.world, file.state);
  const ElementTerm& term = *model.forces.elements;
  std::vector<double> whole(3 * n, 0.0);
  term.addForces(file.state.p(), file.state.v(), nullptr, whole.data());
  for (int split = 0; split <= n; split += kRangeAlignment) {
    std::vector<double> parts(3 * n, 0.0);
    term.addForcesOn({0, split}, file.state.p(), file.state.v(), nullptr, parts.data());
    term.addForcesOn({split, n}, file.state.p(), file.state.v(), nullptr, parts.data());
    ASSERT_EQ(std::memcmp(whole.data(), parts.data(), sizeof(double) * 3 * n), 0) << split;
  }
  ThreadPool pool(2);
  Simulation one(model, file.state, Integrator::RK4, 1e-4),
      two(model, file.state, Integrator::RK4, 1e-4);
  two.setPool(&pool, false);
  ASSERT_TRUE(one.advance(100).ran() && two.advance(100).ran());
  EXPECT_EQ(std::memcmp(one.state().y.data(), two.state().y.data(), sizeof(double) * 6 * n), 0);
}

// A unit cube in five tetrahedra, numbered from 1, with comments, and its .ele.
const char* const kCubeNodes = R"(# a unit cube
8 3 0 0
1 0 0 0
2 1 0 0
3 0 1 0
4 1 1 0
5 0 0 1
6 1 0 1
7 0 1 1
8 1 1 1   # the far corner
)";
const char* const kCubeElements = R"(5 4 0
1 1 2 3 5
2 4 2 3 8
3 6 2 5 8
4 7 3 5 8
5 2 3 5 8
)";

TEST(TetMeshes, ATetGenCubeIsReadAsABody) {
  const Body body = parseTetMesh(kCubeNodes, "cube.1.node", kCubeElements, "cube.1.ele");
  EXPECT_EQ(body.count(), 8);
  ASSERT_EQ(body.meshTets.size(), 5u);
  EXPECT_TRUE(body.gridless());
  std::vector<double> rest(24);
  for (int q = 0; q < 8; ++q) store(rest.data(), q, 8, body.restPosition(q));
  double volume = 0;
  for (const Tet& t : body.meshTets) {
    EXPECT_GT(tetVolume(t, rest.data(), 8), 0);
    volume += tetVolume(t, rest.data(), 8);
  }
  EXPECT_NEAR(volume, 1, 1e-15);
  EXPECT_EQ(body.surface.size(), 12u);  // two triangles a face
  EXPECT_EQ(body.springs.size(), 18u);  // 12 edges and 6 face diagonals
  EXPECT_EQ(body.surfacePoints.size(), 8u);
  EXPECT_EQ(body.label(7), "#7");
  // Every surface triangle faces out: its normal points away from the cube's middle.
  for (const Triangle& t : body.surface) {
    const Vec3 a = body.rest[t[0]], b = body.rest[t[1]], c = body.rest[t[2]];
    EXPECT_GT(dot(cross(b - a, c - a), (1.0 / 3) * (a + b + c) - Vec3{0.5, 0.5, 0.5}), 0);
  }
}

std::string refusal(const std::string& nodes, const std::string& elements) {
  try {
    parseTetMesh(nodes, "cube.1.node", elements, "cube.1.ele");
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(TetMeshes, MalformedFilesAreRefusedWithTheirLineAndField) {
  const std::string nodes = kCubeNodes, elements = kCubeElements;
  auto replace = [](std::string text, const std::string& from, const std::string& to) {
    return text.replace(text.find(from), from.size(), to);
  };
  EXPECT_EQ(refusal(replace(nodes, "8 3 0 0", "8 2 0 0"), elements),
            "cube.1.node:2: expected a whole number from 3 to 3, got '2' (dimension)");
  EXPECT_EQ(refusal(replace(nodes, "6 1 0 1", "6 1 nan 1"), elements),
            "cube.1.node:8: expected a coordinate (m) of at most 1000000 in magnitude, got 'nan' "
            "(point 6 y)");
  EXPECT_EQ(refusal(replace(nodes, "8 1 1 1   # the far corner\n", ""), elements),
            "cube.1.node:9: the file ends after 7 of its 8 points (point 8)");
  EXPECT_EQ(refusal(replace(nodes, "5 0 0 1", "6 0 0 1"), elements),
            "cube.1.node:7: expected a whole number from 5 to 5, got '6' (point 5 number)");
  EXPECT_EQ(
      refusal(nodes, replace(elements, "5 4 0", "5 10 0")),
      "cube.1.ele:1: only linear tetrahedra (4 nodes) are read, not 10 (nodes per tetrahedron)");
  EXPECT_EQ(refusal(nodes, replace(elements, "3 6 2 5 8", "3 6 2 5 9")),
            "cube.1.ele:4: expected a whole number from 1 to 8, got '9' (tetrahedron 3 node 4)");
  EXPECT_EQ(refusal(nodes, replace(elements, "3 6 2 5 8", "3 6 2 6 8")),
            "cube.1.ele:4: node 6 twice (tetrahedron 3)");
  EXPECT_EQ(refusal(nodes, replace(elements, "3 6 2 5 8", "3 1 2 3 4")),
            "cube.1.ele:4: a tetrahedron of no volume (its four points lie in a plane) "
            "(tetrahedron 3)");
  EXPECT_EQ(refusal(nodes, replace(elements, "5 2 3 5 8\n", "5 2 3 5 8\n6 1 2 3 5\n")),
            "cube.1.ele:7: more tetrahedra than the header's 5 (header)");
  EXPECT_EQ(refusal(replace(replace(nodes, "8 3 0 0", "9 3 0 0"), "8 1 1 1", "8 1 1 1\n9 2 2 2"),
                    elements),
            "cube.1.node: point 9 belongs to no tetrahedron of cube.1.ele (point 9)");
  EXPECT_EQ(refusal("", elements),
            "cube.1.node:0: no header: expected <points> 3 <attributes> <markers> (header)");
}

// What would make a body of wrong stiffness and mass or holes in its surface, refused at its
// line: two points at one place, a tetrahedron given twice (in any order of its nodes), two
// tetrahedra on the same side of the face they share, a face of three tetrahedra.
TEST(TetMeshes, CoincidentPointsRepeatedAndOverlappingTetrahedraAreRefused) {
  const std::string nodes = kCubeNodes, elements = kCubeElements;
  auto replace = [](std::string text, const std::string& from, const std::string& to) {
    return text.replace(text.find(from), from.size(), to);
  };
  EXPECT_EQ(refusal(replace(nodes, "8 1 1 1", "8 0 1 1"), elements),
            "cube.1.node:10: at the same place as point 7 (two points at one place: their "
            "tetrahedra would not be joined) (point 8)");
  EXPECT_EQ(refusal(nodes, replace(replace(elements, "5 4 0", "6 4 0"), "5 2 3 5 8\n",
                                   "5 2 3 5 8\n6 8 5 3 2\n")),
            "cube.1.ele:7: the same four nodes as tetrahedron 5 (a tetrahedron given twice) "
            "(tetrahedron 6)");
  // A corner tetrahedron and one beside it, below the face z = 0 they share or above it.
  const std::string corner = "1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n";
  const std::string below = "5 3 0 0\n" + corner + "5 0.2 0.2 -1\n",
                    above = "5 3 0 0\n" + corner + "5 0.2 0.2 1\n",
                    both = "6 3 0 0\n" + corner + "5 0.2 0.2 -1\n6 0.2 0.2 1\n";
  EXPECT_EQ(refusal(below, "2 4 0\n1 1 2 3 4\n2 3 2 1 5\n"), "accepted");
  EXPECT_EQ(refusal(above, "2 4 0\n1 1 2 3 4\n2 3 2 1 5\n"),
            "cube.1.ele:3: overlaps tetrahedron 1 (both on the same side of the face they share) "
            "(tetrahedron 2)");
  EXPECT_EQ(refusal(both, "3 4 0\n1 1 2 3 4\n2 3 2 1 5\n3 1 2 3 6\n"),
            "cube.1.ele:4: a face that two other tetrahedra share already (tetrahedron 3)");
}

// The reader on 3,000 random corruptions of the cube's files (bytes replaced, inserted or cut,
// in either file): each is read or refused with one line naming its file, never a crash (the
// sanitizer build runs this too).
TEST(TetMeshes, CorruptedFilesAreReadOrRefusedInOneLine) {
  std::mt19937 random(17);
  const std::string alphabet = "0123456789 .-+eE#\n\tx";
  int refused = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    std::string files[2] = {kCubeNodes, kCubeElements};
    std::string& text = files[trial % 2];
    const int edits = 1 + trial % 4;
    for (int e = 0; e < edits && !text.empty(); ++e) {
      const std::size_t at = random() % text.size();
      const char c = alphabet[random() % alphabet.size()];
      switch (random() % 3) {
        case 0:
          text[at] = c;
          break;
        case 1:
          text.insert(text.begin() + at, c);
          break;
        default:
          text.erase(at, 1 + random() % 4);
          break;
      }
    }
    try {
      const Body body = parseTetMesh(files[0], "cube.1.node", files[1], "cube.1.ele");
      EXPECT_GE(body.count(), 4);
    } catch (const InputError& error) {
      const std::string why = error.what();
      ++refused;
      EXPECT_TRUE(why.rfind("cube.1.node", 0) == 0 || why.rfind("cube.1.ele", 0) == 0) << why;
      EXPECT_EQ(why.find('\n'), std::string::npos) << why;
    }
  }
  EXPECT_GT(refused, 1000);
}

// A TetGen jelly (the mould of scenes/) pinned by grid indices, which it has not; a tetrahedron
// under a micrometre.
TEST(TetMeshes, AMeshHasNoGridToPinAndNoTetrahedronUnderAMicrometre) {
  const std::string scene =
      std::string("[jelly]\nshape = \"mesh\"\nmesh = \"") + JELLO_SOURCE_DIR +
      "/scenes/models/jelly-mould-coarse.1.node\"\nmaterial = \"neohookean\"\n"
      "youngs_modulus = 5e4\npoisson_ratio = 0.4\ndensity = 1000\n";
  const WorldFile file = parseScene(scene, "s.toml", "");
  EXPECT_EQ(file.state.points(), 674);
  try {  // a .node file that is not there: refused at the scene's key
    parseScene("[jelly]\nshape = \"mesh\"\nmesh = \"/no/such.1.node\"\n", "s.toml", "");
    ADD_FAILURE() << "a missing mesh read";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "s.toml:3: /no/such.1.node: cannot open: No such file or directory (jelly.mesh)");
  }
  try {
    parseScene(scene + "[[pin]]\ni = [0, 0]\n", "s.toml", "");
    ADD_FAILURE() << "pinned by index";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "s.toml:8: a TetGen mesh has no grid to give i, j, k of: pin a region (lower, upper) "
              "(pin[1])");
  }
  const std::string nodes =
      "8 3 0 0\n1 0 0 0\n2 1e-7 0 0\n3 0 1e-7 0\n4 1e-7 1e-7 0\n5 0 0 1e-7\n6 1e-7 0 1e-7\n"
      "7 0 1e-7 1e-7\n8 1e-7 1e-7 1e-7\n";
  EXPECT_NE(refusal(nodes, kCubeElements).find("a tetrahedron under 1e-06 m across"),
            std::string::npos)
      << refusal(nodes, kCubeElements);
}

std::string sceneRefusal(const std::string& jellyKeys) {
  try {
    parseScene("[jelly]\nshape = \"lattice\"\nsize = [3, 3, 3]\n" + jellyKeys, "s.toml", "");
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

// Impossible materials, and keys that belong to the other kind of jelly.
TEST(TetMeshes, ImpossibleMaterialsAreRefused) {
  const std::string fem = "material = \"corotated\"\nyoungs_modulus = 1e4\ndensity = 1000\n";
  EXPECT_EQ(sceneRefusal(fem + "poisson_ratio = 0.5\n"),
            "s.toml:7: must be from 0 to 0.49 for corotated elasticity (below 0, material = "
            "\"neohookean\") (jelly.poisson_ratio)");
  EXPECT_EQ(sceneRefusal(fem + "poisson_ratio = -0.1\n"),
            "s.toml:7: must be from 0 to 0.49 for corotated elasticity (below 0, material = "
            "\"neohookean\") (jelly.poisson_ratio)");
  const std::string neo = "material = \"neohookean\"\nyoungs_modulus = 1e4\ndensity = 1000\n";
  EXPECT_EQ(sceneRefusal(neo + "poisson_ratio = -0.995\n"),
            "s.toml:7: must be from -0.99 to 0.49 (at -1 a solid could not keep its volume, at 0.5 "
            "it could not change it) (jelly.poisson_ratio)");
  EXPECT_EQ(sceneRefusal(neo + "poisson_ratio = -0.99\n"), "accepted");
  EXPECT_EQ(sceneRefusal("material = \"corotated\"\nyoungs_modulus = 0\npoisson_ratio = 0.3\n"
                         "density = 1000\n"),
            "s.toml:5: must be above 0 (jelly.youngs_modulus)");
  EXPECT_EQ(sceneRefusal("material = \"corotated\"\nyoungs_modulus = 1e4\npoisson_ratio = 0.3\n"),
            "s.toml:4: a jelly of finite elements needs its density (jelly.density)");
  EXPECT_EQ(sceneRefusal(fem + "poisson_ratio = 0.3\nmass = 2\n"),
            "s.toml:8: a jelly of finite elements takes its mass from its density (jelly.mass)");
  EXPECT_EQ(sceneRefusal("material = \"NeoHookean\"\n"),
            "s.toml:4: a jelly of finite elements needs its youngs_modulus (jelly.youngs_modulus)");
  EXPECT_EQ(sceneRefusal("material = \"rubber\"\n"),
            "s.toml:4: expected \"springs\", \"corotated\" or \"neohookean\" (jelly.material)");
  EXPECT_EQ(sceneRefusal(fem + "poisson_ratio = 0.3\n" + "stiffness_damping = -1\n"),
            "s.toml:8: must be at least 0 (jelly.stiffness_damping)");
  EXPECT_EQ(sceneRefusal("material = \"neohookean\"\nyoungs_modulus = 1e14\npoisson_ratio = 0.3\n"
                         "density = 1000\n"),
            "s.toml:5: is beyond 1e+12 in magnitude (jelly.youngs_modulus)");
  EXPECT_EQ(sceneRefusal("material = \"neohookean\"\nyoungs_modulus = 1e4\npoisson_ratio = 0.3\n"
                         "density = 1e-300\n"),
            "s.toml:7: must be from 0.001 to 100000 kg/m^3 (jelly.density)");
  EXPECT_EQ(sceneRefusal("youngs_modulus = 1e4\n"),
            "s.toml:4: belongs to a jelly of finite elements (material = \"corotated\" or "
            "\"neohookean\") (jelly.youngs_modulus)");
}

}  // namespace
}  // namespace jello
