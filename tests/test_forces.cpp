// Force terms of the physics model (docs/physics.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include "solver/guard.h"
#include "solver/jacobian.h"
#include "solver/physics.h"
#include "test_support.h"

namespace jello {
namespace {

double maxAbs(const std::vector<double>& a) {
  double m = 0;
  for (double x : a) m = std::max(m, std::fabs(x));
  return m;
}

TEST(Springs, SixThousandTwoHundredTwentyWithIdealRestLengths) {
  std::vector<Spring> springs = buildSprings();
  ASSERT_EQ(springs.size(), 6220u);
  int structural = 0, shear = 0, bend = 0;
  std::set<std::pair<int, int>> pairs;
  State rest = test::restLattice();
  for (const Spring& s : springs) {
    structural += s.kind == SpringKind::Structural;
    shear += s.kind == SpringKind::Shear;
    bend += s.kind == SpringKind::Bend;
    pairs.insert({std::min(s.a, s.b), std::max(s.a, s.b)});
    EXPECT_NEAR(s.rest, length(load(rest.p(), s.a) - load(rest.p(), s.b)), 1e-15);
    double expected = s.kind == SpringKind::Bend         ? 2.0 / 7
                      : s.kind == SpringKind::Structural ? 1.0 / 7
                                                         : 0;
    if (expected > 0)
      EXPECT_DOUBLE_EQ(s.rest, expected);
    else
      EXPECT_TRUE(std::fabs(s.rest - std::sqrt(2.0) / 7) < 1e-15 ||
                  std::fabs(s.rest - std::sqrt(3.0) / 7) < 1e-15);
  }
  EXPECT_EQ(structural, 3 * 7 * 64);
  EXPECT_EQ(shear, 6 * 7 * 7 * 8 + 4 * 7 * 7 * 7);
  EXPECT_EQ(bend, 3 * 6 * 64);
  EXPECT_EQ(pairs.size(), 6220u) << "a pair of points is joined twice";
}

// A rigid motion of the rest lattice: rotated, moved, spinning and drifting. Its springs are
// all at rest length and no end moves along its spring, so every force must vanish.
TEST(Springs, RestLatticeUnderRigidMotionFeelsNoForce) {
  World w = test::springsOnlyWorld();
  w.dElastic = 2.0;  // damping on, so that the relative velocities are tested too
  State state = test::restLattice();
  Model model = makeModel(w, state);
  const double angle = 0.7;
  Vec3 axis{1 / std::sqrt(3.0), 1 / std::sqrt(3.0), -1 / std::sqrt(3.0)};
  Vec3 shift{-0.9, 0.4, 0.3}, drift{3, -1, 2}, spin{4, -2, 5};
  for (int q = 0; q < kNumPoints; ++q) {
    Vec3 r = load(state.p(), q) - Vec3{0.5, 0.5, 0.5};
    // Rodrigues' rotation of r about axis.
    Vec3 cross{axis.y * r.z - axis.z * r.y, axis.z * r.x - axis.x * r.z,
               axis.x * r.y - axis.y * r.x};
    Vec3 rotated = std::cos(angle) * r + std::sin(angle) * cross +
                   (dot(axis, r) * (1 - std::cos(angle))) * axis;
    Vec3 spun{spin.y * rotated.z - spin.z * rotated.y, spin.z * rotated.x - spin.x * rotated.z,
              spin.x * rotated.y - spin.y * rotated.x};
    store(state.p(), q, rotated + shift);
    store(state.v(), q, drift + spun);
  }
  std::vector<double> force(kNumCoords);
  computeForces(model, state.p(), state.v(), force.data());
  // A spring stretched by 1e-12 m would give 5e-10 N; rounding leaves far less.
  EXPECT_LT(maxAbs(force), 1e-11);
}

double springEnergy(const Model& model, const double* p) {
  double energy = 0;
  for (const Spring& s : model.springs()) {
    double stretch = length(load(p, s.a) - load(p, s.b)) - s.rest;
    energy += 0.5 * model.world.kElastic * stretch * stretch;
  }
  return energy;
}

TEST(Springs, ForceIsMinusTheGradientOfTheSpringEnergy) {
  World w = test::springsOnlyWorld();
  w.dElastic = 0;
  State state = test::restLattice();
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> jitter(-0.03, 0.03);
  for (int c = 0; c < kNumCoords; ++c) state.p()[c] += jitter(random);
  Model model = makeModel(w, state);
  std::vector<double> force(kNumCoords);
  computeForces(model, state.p(), state.v(), force.data());

  const double h = 1e-6;
  double errorSquared = 0, forceSquared = 0;
  std::vector<double> p(state.p(), state.p() + kNumCoords);
  for (int c = 0; c < kNumCoords; ++c) {
    double saved = p[c];
    p[c] = saved + h;
    double up = springEnergy(model, p.data());
    p[c] = saved - h;
    double down = springEnergy(model, p.data());
    p[c] = saved;
    double numeric = -(up - down) / (2 * h);
    errorSquared += (numeric - force[c]) * (numeric - force[c]);
    forceSquared += force[c] * force[c];
  }
  ASSERT_GT(forceSquared, 1.0);
  EXPECT_LT(std::sqrt(errorSquared / forceSquared), 1e-6);
}

TEST(Springs, HandComputedStretchedAndDampedSpring) {
  // L = (0.3, 0.4, 0) from b to a, |L| = 0.5, rest 0.2, u = (0.6, 0.8, 0).
  // relVel . u = (1*0.6 + 2*0.8) = 2.2. F = -10*(0.3) u - 0.5*2.2 u = -4.1 u.
  Vec3 f = springForce({0.3, 0.4, 0}, {1, 2, 7}, 10, 0.5, 0.2);
  EXPECT_NEAR(f.x, -4.1 * 0.6, 1e-15);
  EXPECT_NEAR(f.y, -4.1 * 0.8, 1e-15);
  EXPECT_EQ(f.z, 0);
  Vec3 zero = springForce({0, 0, 0}, {1, 2, 3}, 10, 0.5, 0.2);
  EXPECT_EQ(zero.x, 0);
  EXPECT_EQ(zero.y, 0);
  EXPECT_EQ(zero.z, 0);
}

TEST(Walls, PointBeyondOneWall) {
  // x = 2.5 is 0.5 past x = 2: F = -1000*0.5 - 0.25*(v.u)u with u = +x, v.u = 1.
  Vec3 f = wallForce({2.5, 0.3, -1}, {1, 2, 3}, {1000, 0.25});
  EXPECT_DOUBLE_EQ(f.x, -500.25);
  EXPECT_EQ(f.y, 0);
  EXPECT_EQ(f.z, 0);
  // Beyond the floor z = -2 by 0.1, moving down at 3 m/s: u = -z, v.u = 3, F = +100 + 0.75.
  Vec3 floor = wallForce({0, 0, -2.1}, {0, 0, -3}, {1000, 0.25});
  EXPECT_NEAR(floor.z, 100.0 + 0.75, 1e-12);  // -2.1 + 2 is -0.1 only to rounding
}

TEST(Walls, PointBeyondTwoWallsGetsTwoSprings) {
  // 0.5 past x = -2 and 1 past y = 2: u_x = -x, u_y = +y.
  Vec3 f = wallForce({-2.5, 3, 0.5}, {1, -2, 9}, {1000, 0.25});
  EXPECT_DOUBLE_EQ(f.x, 500 - 0.25 * 1);  // -k(-0.5) - d (v.u)(u_x) = 500 - 0.25*(-1)*(-1)
  EXPECT_DOUBLE_EQ(f.y, -1000 + 0.5);     // -k(1) - d(-2)(1)
  EXPECT_EQ(f.z, 0);
}

TEST(Walls, PointOnAWallOrInsideFeelsNothing) {
  for (Vec3 p : {Vec3{2, 0, 0}, Vec3{-2, -2, 2}, Vec3{1.999, 0, -1.999}, Vec3{0, 0, 0}}) {
    Vec3 f = wallForce(p, {5, 5, 5}, {1000, 0.25});
    EXPECT_EQ(f.x, 0);
    EXPECT_EQ(f.y, 0);
    EXPECT_EQ(f.z, 0);
  }
}

TEST(Plane, HandComputedCollisionSpring) {
  // Plane x + y + z - 1 = 0, allowed side positive. The origin is on the other side, s = -1:
  // L = (s/3)(1,1,1), u = -(1,1,1)/sqrt3. With v = (0,0,-1): v.u = 1/sqrt3,
  // F = -k L - d (v.u) u = (k/3 + d/3)(1,1,1).
  Plane plane{1, 1, 1, -1};
  Vec3 f = planeForce(plane, +1, {0, 0, 0}, {0, 0, -1}, {1000, 0.25});
  EXPECT_NEAR(f.x, 1000.25 / 3, 1e-12);
  EXPECT_NEAR(f.y, 1000.25 / 3, 1e-12);
  EXPECT_NEAR(f.z, 1000.25 / 3, 1e-12);
  // Scaling the plane's equation changes nothing.
  Vec3 g = planeForce({2, 2, 2, -2}, +1, {0, 0, 0}, {0, 0, -1}, {1000, 0.25});
  EXPECT_NEAR(g.x, f.x, 1e-12);
  // On the allowed side, or on the plane: nothing.
  for (Vec3 p : {Vec3{1, 1, 1}, Vec3{1, 0, 0}}) {
    Vec3 none = planeForce(plane, +1, p, {1, 1, 1}, {1000, 0.25});
    EXPECT_EQ(none.x, 0);
    EXPECT_EQ(none.z, 0);
  }
  // With the negative side allowed, the roles swap: (1,1,1) has s = 2, L = (2/3)(1,1,1).
  Vec3 h = planeForce(plane, -1, {1, 1, 1}, {0, 0, 0}, {1000, 0.25});
  EXPECT_NEAR(h.x, -2000.0 / 3, 1e-12);
  Vec3 none = planeForce(plane, -1, {0, 0, 0}, {0, 0, 0}, {1000, 0.25});
  EXPECT_EQ(none.x, 0);
}

TEST(Plane, AllowedSideIsTheSideOfTheInitialCentroid) {
  World w = test::springsOnlyWorld();
  w.hasPlane = true;
  State rest = test::restLattice();  // centroid (0.5, 0.5, 0.5)
  w.plane = {1, 0, 0, -0.25};        // centroid on the positive side
  EXPECT_EQ(makeModel(w, rest).planeSide(), 1);
  w.plane = {1, 0, 0, -0.75};  // negative side
  EXPECT_EQ(makeModel(w, rest).planeSide(), -1);
  w.plane = {-1, 0, 0, 0.5};  // on the plane: positive
  EXPECT_EQ(makeModel(w, rest).planeSide(), 1);
}

// The rest lattice with the plane x = 0.25 (or a multiple of it): the points of the face i = 0
// and of i = 1 (x = 1/7) are across it, the centroid is not.
Model latticeWithPlane(Plane plane) {
  World w = test::springsOnlyWorld();
  w.kCollision = 1000;
  w.dCollision = 0.25;
  w.hasPlane = true;
  w.plane = plane;
  return makeModel(w, test::restLattice());
}

std::vector<double> forcesOf(const Model& model, const State& state) {
  std::vector<double> force(kNumCoords);
  computeForces(model, state.p(), state.v(), force.data());
  return force;
}

TEST(Plane, ANormalOfAnySizePushesBackWithTheForceOfTheUnitNormal) {
  // Before, (1e-300, 0, 0, ...) gave |n|^2 = 0 and a NaN force; (1e200, ...) gave |n|^2 = inf
  // and no force at all.
  State rest = test::restLattice();
  store(rest.v(), 0, {-1, 0.5, 0});
  const std::vector<double> unit = forcesOf(latticeWithPlane({1, 0, 0, -0.25}), rest);
  const Vec3 across = load(unit.data(), 0);
  ASSERT_GT(across.x, 100) << "the unit plane pushes the point at x = 0 back to positive x";
  for (double scale : {1e-300, 5e-320, 1e200, 1e300}) {
    const Model model = latticeWithPlane({scale, 0, 0, -0.25 * scale});
    EXPECT_TRUE(std::isfinite(model.plane().a * model.plane().a)) << scale;
    EXPECT_EQ(pointsAcrossPlane(model, rest), 2 * kLatticeSize * kLatticeSize) << scale;
    const std::vector<double> force = forcesOf(model, rest);
    for (int c = 0; c < kNumCoords; ++c)
      ASSERT_NEAR(force[c], unit[c], 1e-12 * std::fabs(unit[c])) << scale << " " << c;
  }
  // The plane x + y + z = 1.5 scaled by 1e200 (the issue's): the corner at the origin is across.
  const std::vector<double> tilted = forcesOf(latticeWithPlane({1, 1, 1, -1.5}), rest);
  const std::vector<double> huge =
      forcesOf(latticeWithPlane({1e200, 1e200, 1e200, -1.5e200}), rest);
  ASSERT_GT(load(tilted.data(), 0).x, 100);
  for (int c = 0; c < kNumCoords; ++c)
    ASSERT_NEAR(huge[c], tilted[c], 1e-12 * std::fabs(tilted[c])) << c;
}

TEST(Plane, APlaneScaledByAPowerOfTwoGivesBitIdenticalForcesJacobiansAndEnergies) {
  State state = test::restLattice();
  store(state.v(), 0, {-1, 0.5, 0});
  const Model unit = latticeWithPlane({1, 0.5, 0.25, -0.6});
  for (int exponent : {-1000, -3, 5, 900, 1020}) {  // every coefficient stays a normal double
    const Model scaled = latticeWithPlane({std::ldexp(1, exponent), std::ldexp(0.5, exponent),
                                           std::ldexp(0.25, exponent), std::ldexp(-0.6, exponent)});
    EXPECT_EQ(forcesOf(scaled, state), forcesOf(unit, state)) << exponent;
    AccelerationJacobian a, b;
    accelerationJacobian(unit, state.p(), state.v(), nullptr, &a);
    accelerationJacobian(scaled, state.p(), state.v(), nullptr, &b);
    EXPECT_EQ(Eigen::MatrixXd(a.dAdp), Eigen::MatrixXd(b.dAdp)) << exponent;
    EXPECT_EQ(mechanicalEnergy(scaled, state), mechanicalEnergy(unit, state)) << exponent;
  }
}

TEST(Plane, APlaneBeyondTheRangeOfDoublesIsRefusedByTheReader) {
  // d / a = 1e310: the plane is further than any double can say; a normal of 1e-300 alone is fine.
  World w = test::springsOnlyWorld();
  w.hasPlane = true;
  w.plane = {1e-300, 0, 0, 1e10};
  EXPECT_NE(planeProblem(w.plane), "");
  EXPECT_EQ(planeProblem({1e-300, 0, 0, 1e-290}), "");
  EXPECT_EQ(planeProblem({1e300, -1e300, 0, 1e-300}), "");
  try {
    parseWorld(formatWorld(w, RunSettings{}, test::restLattice()), "far.w");
    FAIL() << "a plane 1e310 m away was read";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "far.w:6: the plane is too far from the origin to simulate: d is more than 1e308 "
              "times the largest of |a|, |b|, |c|, beyond the range of doubles (plane d)");
  }
}

ForceField gridOf(int r, const std::function<Vec3(Vec3)>& f) {
  ForceField field;
  field.resolution = r;
  for (int i = 0; i < r; ++i)
    for (int j = 0; j < r; ++j)
      for (int k = 0; k < r; ++k) {
        double h = r > 1 ? 4.0 / (r - 1) : 0;
        Vec3 value = f({-2 + h * i, -2 + h * j, -2 + h * k});
        field.forces.insert(field.forces.end(), {value.x, value.y, value.z});
      }
  return field;
}

TEST(Field, TrilinearIsExactAtTheNodes) {
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> any(-1, 1);
  for (int r : {2, 3, 5, 30}) {
    ForceField field = gridOf(r, [&](Vec3) { return Vec3{any(random), any(random), any(random)}; });
    // For R = 2, 3, 5 the node spacing (4, 2, 1 m) is exact in binary and so is every weight;
    // for R = 30 the node's own coordinates are rounded, and so is the result, by a few ulps.
    const double tolerance = r == 30 ? 1e-13 : 0;
    const double h = 4.0 / (r - 1);
    for (int i = 0; i < r; ++i)
      for (int j = 0; j < r; j += 2)
        for (int k = 0; k < r; k += 3) {
          Vec3 f = fieldForce(field, {-2 + h * i, -2 + h * j, -2 + h * k});
          const double* node = &field.forces[3 * ((i * r + j) * r + k)];
          EXPECT_NEAR(f.x, node[0], tolerance)
              << "R=" << r << " node " << i << "," << j << "," << k;
          EXPECT_NEAR(f.y, node[1], tolerance);
          EXPECT_NEAR(f.z, node[2], tolerance);
        }
  }
}

TEST(Field, TrilinearReproducesLinearFields) {
  auto linear = [](Vec3 p) {
    return Vec3{0.3 * p.x - 0.2 * p.y + 0.7 * p.z + 0.1, -p.x + 0.5 * p.z, 2 * p.y - 0.25};
  };
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> inside(-2, 2);
  for (int r : {2, 3, 7, 30}) {
    ForceField field = gridOf(r, linear);
    for (int trial = 0; trial < 200; ++trial) {
      Vec3 p{inside(random), inside(random), inside(random)};
      Vec3 f = fieldForce(field, p), exact = linear(p);
      EXPECT_NEAR(f.x, exact.x, 1e-13);
      EXPECT_NEAR(f.y, exact.y, 1e-13);
      EXPECT_NEAR(f.z, exact.z, 1e-13);
    }
  }
}

TEST(Field, HandComputedCellOfAResolutionTwoGrid) {
  // R = 2: one cell; only node (1,1,1) at (2,2,2) is non-zero. At (0,0,0) every weight is 1/8;
  // at (1,-1,0) the weight of (1,1,1) is (3/4)(1/4)(1/2).
  ForceField field;
  field.resolution = 2;
  field.forces.assign(24, 0.0);
  field.forces[21] = 8;
  field.forces[22] = -16;
  EXPECT_DOUBLE_EQ(fieldForce(field, {0, 0, 0}).x, 1);
  EXPECT_DOUBLE_EQ(fieldForce(field, {0, 0, 0}).y, -2);
  EXPECT_DOUBLE_EQ(fieldForce(field, {1, -1, 0}).x, 8 * 0.75 * 0.25 * 0.5);
}

TEST(Field, ResolutionOneIsUniformInsideTheBoxIncludingItsWalls) {
  ForceField field;
  field.resolution = 1;
  field.forces = {0.5, -1, 2};
  for (Vec3 p : {Vec3{0, 0, 0}, Vec3{2, 2, 2}, Vec3{-2, 1.5, -2}}) {
    Vec3 f = fieldForce(field, p);
    EXPECT_EQ(f.x, 0.5);
    EXPECT_EQ(f.y, -1);
    EXPECT_EQ(f.z, 2);
  }
  EXPECT_EQ(fieldForce(field, {2.0000001, 0, 0}).x, 0);
}

TEST(Field, NoFieldForceOutsideTheBox) {
  ForceField field = gridOf(30, [](Vec3) { return Vec3{1, 2, 3}; });
  EXPECT_DOUBLE_EQ(fieldForce(field, {2, -2, 2}).z, 3);  // walls are inside
  for (Vec3 p : {Vec3{2.01, 0, 0}, Vec3{0, -2.5, 0}, Vec3{0, 0, 7}, Vec3{-3, -3, -3}}) {
    Vec3 f = fieldForce(field, p);
    EXPECT_EQ(f.x, 0);
    EXPECT_EQ(f.y, 0);
    EXPECT_EQ(f.z, 0);
  }
  ForceField none;
  EXPECT_EQ(fieldForce(none, {0, 0, 0}).x, 0);
}

TEST(Field, ANotANumberCoordinateTakesAValidCellAndReadsNoOtherMemory) {
  // Before, std::max(NaN, 0.0) let the NaN through to the int conversion (undefined; INT_MIN
  // here, an index far outside the field), in the kernel and in the Jacobian alike.
  ForceField field = gridOf(5, [](Vec3 p) { return Vec3{p.y, -p.x, 1}; });
  World w = test::springsOnlyWorld();
  w.field = field;
  State state = test::restLattice();
  const int nan = pointIndex(7, 7, 7), far = pointIndex(0, 0, 0);
  store(state.p(), nan, {NAN, 0.5, 0.5});
  for (KernelChoice choice : {KernelChoice::Specialised, KernelChoice::General}) {
    Model model = makeModel(w, state, choice);
    for (Vec3 outside :
         {Vec3{0, 0, 0}, Vec3{-2.5, 0, 0}}) {  // the field's own path, then the contact path
      store(state.p(), far, outside);
      std::vector<double> force = forcesOf(model, state);
      EXPECT_TRUE(std::isnan(force[coordIndex(nan, 0)]));
      const Vec3 f = load(force.data(), pointIndex(0, 0, 1));  // no spring to the NaN point
      EXPECT_TRUE(std::isfinite(f.x) && std::isfinite(f.y) && std::isfinite(f.z));
    }
  }
  for (Vec3 p : {Vec3{NAN, 0, 0}, Vec3{0, NAN, 0}, Vec3{0, 0, NAN}}) {
    Mat3 J = toMatrix(fieldJacobian(field, p));
    EXPECT_EQ(J, Mat3::Zero()) << "no gradient where there is no field";
  }
}

TEST(Forces, TotalForceSumsEveryTermOnEveryPoint) {
  // One point pushed through the floor and the plane, a uniform field: the total on it is the
  // sum of its springs, its wall, its plane and its field, each computed on its own.
  WorldFile f = readWorldFile(test::dataPath("gravity.w"));
  State state = f.state;
  Model model = makeModel(f.world, state);
  const int q = pointIndex(3, 4, 0);
  store(state.p(), q, {1.5, -1.5, -1.9});  // inside the box, past the plane
  store(state.v(), q, {0.5, -0.25, -3});
  std::vector<double> force(kNumCoords);
  computeForces(model, state.p(), state.v(), force.data());
  const World& w = f.world;
  Vec3 expected = wallForce(load(state.p(), q), load(state.v(), q), {w.kCollision, w.dCollision}) +
                  planeForce(w.plane, model.planeSide(), load(state.p(), q), load(state.v(), q),
                             {w.kCollision, w.dCollision}) +
                  fieldForce(w.field, load(state.p(), q));
  for (const Spring& s : model.springs()) {
    if (s.a != q && s.b != q) continue;
    Vec3 fs =
        springForce(load(state.p(), s.a) - load(state.p(), s.b),
                    load(state.v(), s.a) - load(state.v(), s.b), w.kElastic, w.dElastic, s.rest);
    expected += s.a == q ? fs : -fs;
  }
  EXPECT_NE(
      planeForce(w.plane, model.planeSide(), load(state.p(), q), load(state.v(), q), {1, 0}).x, 0)
      << "plane not hit";
  Vec3 got = load(force.data(), q);
  EXPECT_NEAR(got.x, expected.x, 1e-9);
  EXPECT_NEAR(got.y, expected.y, 1e-9);
  EXPECT_NEAR(got.z, expected.z, 1e-9);
}

}  // namespace
}  // namespace jello
