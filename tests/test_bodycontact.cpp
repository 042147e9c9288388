// Contact between jellies and of a jelly with itself, and cloth (model/bodycontact.h;
// docs/physics.md "Contact between bodies"). Each test asserts a number: momentum, gaps, winding
// numbers, Jacobian entries.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "io/scenereader.h"
#include "jellyscenes.h"
#include "model/bodycontact.h"
#include "model/winding.h"
#include "solver/physics.h"
#include "solver/simulation.h"
#include "test_support.h"

namespace jello {
namespace {

using test::contactTerm;
using test::kHeadOn;

Vec3 momentum(const Model& model, const State& s) {
  Vec3 total;
  for (int q = 0; q < model.points(); ++q)
    total += model.pointMass[q] * load(s.v(), q, model.points());
  return total;
}

// The largest winding number of a point of one jelly about another's surface: about 1 inside.
double deepestInside(const Model& model, const State& s) {
  const Body& body = model.body();
  double worst = 0;
  for (int q = 0; q < body.count(); ++q)
    for (std::size_t part = 0; part < body.parts.size(); ++part)
      if (body.partOf(q) != int(part) && !isSheet(*body.parts[part]))
        worst = std::max(
            worst, std::fabs(windingNumber(body, int(part), s.p(), load(s.p(), q, body.count()))));
  return worst;
}

// The smallest distance between two surface points of one part more than kSelfNeighbourhood apart
// in the grid: a surface that passed through itself brings such points together.
double smallestSelfGap(const Body& body, const State& s) {
  const int n = body.count();
  double smallest = INFINITY;
  for (int a : body.surfacePoints)
    for (int b : body.surfacePoints) {
      if (b <= a || body.partOf(a) != body.partOf(b)) continue;
      const auto i = body.index(a), j = body.index(b);
      if (std::max({std::abs(i[0] - j[0]), std::abs(i[1] - j[1]), std::abs(i[2] - j[2])}) <=
          kSelfNeighbourhood)
        continue;
      smallest = std::min(smallest, length(load(s.p(), a, n) - load(s.p(), b, n)));
    }
  return smallest;
}

TEST(BodyContact, HeadOnJelliesKeepTheirMomentumAndNeverEnterEachOther) {
  const WorldFile file = test::scene(kHeadOn);
  const Model model = makeModel(file.world, file.state);
  ASSERT_NE(contactTerm(model), nullptr);
  Simulation run(model, file.state, Integrator::Verlet, 0.0002);
  const Vec3 before = momentum(model, file.state);
  const double scale = 0.5 * model.points() * model.pointMass[0] * 1.0;  // one jelly's |p|
  double drift = 0, inside = 0, gap = INFINITY;
  int touching = 0;
  for (int step = 0; step < 2000; ++step) {
    ASSERT_TRUE(run.advance(1).ran());
    drift = std::max(drift, length(momentum(model, run.state()) - before) / scale);
    if (step % 5 == 0) inside = std::max(inside, deepestInside(model, run.state()));
    gap = std::min(gap, contactTerm(model)->smallestGap(run.state().p()));
    touching += contactTerm(model)->pointsInContact(run.state().p()) > 0;
  }
  RecordProperty("momentum_drift", textf("%.3g", drift));
  RecordProperty("smallest_gap_m", textf("%.6g", gap));
  EXPECT_LT(drift, 1e-9);
  EXPECT_LT(inside, 0.5);
  EXPECT_GT(touching, 50);  // they met
  EXPECT_GT(gap, 0.03);     // m: never closer than 0.3 of the contact distance
  // And they part: the first jelly now moves back.
  const Body& body = model.body();
  Vec3 first;
  for (int q = 0; q < body.partFirst[1]; ++q) first += load(run.state().v(), q, body.count());
  EXPECT_LT(first.x / body.partFirst[1], -0.2);
}

TEST(BodyContact, JacobianMatchesCentralDifferencesWithFriction) {
  std::string text = kHeadOn;
  text.replace(
      text.find("damping = 0.3\n["), 13,
      "damping = 0.3\nfriction_static = 0.6\nfriction_dynamic = 0.4\nfriction_speed = 0.05");
  WorldFile file = test::scene(text);
  // Jelly 2 moved 2 cm into jelly 1's reach, and everything shaken so that contacts are at every
  // angle and slide at every speed.
  std::mt19937 random(3);
  std::uniform_real_distribution<double> jitter(-0.01, 0.01), speed(-0.3, 0.3);
  const int n = file.state.points();
  for (int q = file.world.scene->body->partFirst[1]; q < n; ++q) file.state.p()[q] -= 0.02;
  for (int c = 0; c < 3 * n; ++c)
    file.state.p()[c] += jitter(random), file.state.v()[c] += speed(random);
  const Model model = makeModel(file.world, file.state);
  const BodyContactTerm& term = *contactTerm(model);
  std::vector<double> p(file.state.p(), file.state.p() + 3 * n),
      v(file.state.v(), file.state.v() + 3 * n);
  const std::vector<std::pair<int, int>> pairs = term.pairsAt(p.data());
  ASSERT_GT(pairs.size(), 10u);
  struct Dense final : JacobianSink {
    std::vector<std::pair<int, int>> pairs;
    int n;
    bool velocity;
    std::size_t next = 0;
    std::vector<double> m;
    void addPair(const Block3& dFdL, const Block3& dFdw) override {
      const auto [a, b] = pairs[next++];
      const Block3& block = velocity ? dFdw : dFdL;
      for (auto [row, column, sign] :
           {std::tuple{a, a, 1.0}, {a, b, -1.0}, {b, a, -1.0}, {b, b, 1.0}})
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j)
            m[std::size_t(coordIndex(row, i, n)) * 3 * n + coordIndex(column, j, n)] +=
                sign * block.m[3 * i + j];
    }
    void addPoint(int, const Block3&, const Block3&) override {}
    void addCoupling(std::size_t, const Block3&, const Block3&) override {}
  };
  double worst = 0, largest = 0;
  for (bool velocity : {false, true}) {
    Dense sink;
    sink.pairs = pairs, sink.n = n, sink.velocity = velocity;
    sink.m.assign(std::size_t(9) * n * n, 0.0);
    term.addJacobian(p.data(), v.data(), &sink);
    for (const auto& [a, b] : pairs)
      for (int q : {a, b})
        for (int axis = 0; axis < 3; ++axis) {
          const int c = coordIndex(q, axis, n);
          std::vector<double>& x = velocity ? v : p;
          const double saved = x[c], h = 1e-7;
          std::vector<double> plus(3 * n, 0.0), minus(3 * n, 0.0);
          x[c] = saved + h;
          term.addForces(p.data(), v.data(), nullptr, plus.data());
          x[c] = saved - h;
          term.addForces(p.data(), v.data(), nullptr, minus.data());
          x[c] = saved;
          if (term.pairsAt(p.data()) != pairs) continue;  // a contact began or ended within h
          for (int r = 0; r < 3 * n; ++r) {
            const double analytic = sink.m[std::size_t(r) * 3 * n + c];
            worst = std::max(worst, std::fabs((plus[r] - minus[r]) / (2 * h) - analytic));
            largest = std::max(largest, std::fabs(analytic));
          }
        }
  }
  EXPECT_GT(largest, 100);  // N/m: the contacts' stiffness is in it
  EXPECT_LT(worst, 1e-5 * largest);
}

TEST(BodyContact, ItsStoredEnergyIsThePotentialOfItsForce) {
  WorldFile file = test::scene(kHeadOn);
  const int n = file.state.points();
  for (int q = file.world.scene->body->partFirst[1]; q < n; ++q) file.state.p()[q] -= 0.025;
  const Model model = makeModel(file.world, file.state);
  const BodyContactTerm& term = *contactTerm(model);
  std::vector<double> p(file.state.p(), file.state.p() + 3 * n), zero(3 * n, 0.0),
      force(3 * n, 0.0);
  term.addForces(p.data(), zero.data(), nullptr, force.data());
  double worst = 0, largest = 0;
  for (int c = 0; c < 3 * n; ++c) {
    if (force[c] == 0) continue;
    const double saved = p[c], h = 1e-7;
    double plus = 0, minus = 0;
    p[c] = saved + h;
    term.addEnergy(p.data(), &plus);
    p[c] = saved - h;
    term.addEnergy(p.data(), &minus);
    p[c] = saved;
    worst = std::max(worst, std::fabs(-(plus - minus) / (2 * h) - force[c]));
    largest = std::max(largest, std::fabs(force[c]));
  }
  EXPECT_GT(largest, 1);
  EXPECT_LT(worst, 1e-6 * largest);
}

TEST(BodyContact, AStackOfThreeComesToRestWithoutEnteringEachOther) {
  std::string text = R"(
dt = 0.0005
gravity = [0.0, 0.0, -9.81]
[bounds]
lower = [-1.0, -1.0, -1.0]
upper = [1.0, 1.0, 1.0]
stiffness = 3000
damping = 2
[contact]
stiffness = 3000
damping = 2
)";
  for (double z : {-0.84, -0.43, -0.02})
    text +=
        "[[jelly]]\nshape = \"lattice\"\nsize = [4, 4, 4]\nspacing = 0.1\nstiffness = 800\n"
        "damping = 1.5\ntotal_mass = 0.5\noffset = [0.0, 0.0, " +
        std::to_string(z) + "]\n";
  const WorldFile file = test::scene(text);
  const Model model = makeModel(file.world, file.state);
  Simulation run(model, file.state, Integrator::RK4, 0.0005);
  double inside = 0;
  for (int frame = 0; frame < 60; ++frame) {
    ASSERT_TRUE(run.advance(100).ran());
    inside = std::max(inside, deepestInside(model, run.state()));
  }
  const int n = model.points();
  double fastest = 0;
  for (int q = 0; q < n; ++q) fastest = std::max(fastest, length(load(run.state().v(), q, n)));
  EXPECT_LT(inside, 0.5);
  EXPECT_LT(fastest, 0.05);  // m/s after 3 s (the top one landed at 2.4 m/s): at rest
  // Still stacked: each jelly's lowest point above the one below's highest minus a spacing.
  const Body& body = model.body();
  auto heights = [&](int part) {
    double low = INFINITY, high = -INFINITY;
    for (int q = body.partFirst[part]; q < body.partFirst[part + 1]; ++q)
      low = std::min(low, load(run.state().p(), q, n).z),
      high = std::max(high, load(run.state().p(), q, n).z);
    return std::pair{low, high};
  };
  EXPECT_GT(heights(1).first, heights(0).second + 0.03);
  EXPECT_GT(heights(2).first, heights(1).second + 0.03);
}

TEST(BodyContact, ABarFallingOntoABallFoldsWithoutPassingThroughItself) {
  const WorldFile file = test::scene(R"(
dt = 0.0005
gravity = [0.0, 0.0, -9.81]
[bounds]
lower = [-1.2, -1.2, -1.2]
upper = [1.2, 1.2, 1.2]
[contact]
stiffness = 3000
damping = 1
friction_static = 0.3
[jelly]
shape = "lattice"
size = [30, 3, 3]
spacing = 0.06
total_mass = 0.5
stiffness = { structural = 150, shear = 60, bend = 10 }
damping = 0.3
self_contact = true
offset = [0.0, 0.0, 0.4]
[[sphere]]
centre = [0.0, 0.0, 0.0]
radius = 0.2
stiffness = 3000
damping = 1
friction_static = 0.5
friction_dynamic = 0.4
)");
  const Model model = makeModel(file.world, file.state);
  Simulation run(model, file.state, Integrator::RK4, 0.0005);
  double gap = INFINITY, deepest = 0;
  const int n = model.points();
  for (int frame = 0; frame < 40; ++frame) {
    ASSERT_TRUE(run.advance(100).ran());
    gap = std::min(gap, smallestSelfGap(model.body(), run.state()));
    for (int q = 0; q < n; ++q)
      deepest = std::max(deepest, 0.2 - length(load(run.state().p(), q, n)));
  }
  // Folded over the ball: both ends below its centre after 2 s; its surface never closer to
  // itself than 0.4 of its contact distance (0.06 m), and never 2 cm into the ball.
  EXPECT_LT(load(run.state().p(), 0, n).z, 0.0);
  EXPECT_LT(load(run.state().p(), n - 1, n).z, 0.0);
  EXPECT_GT(gap, 0.024);
  EXPECT_LT(deepest, 0.02);
}

TEST(BodyContact, ASheetFoldedOverOntoItselfLiesOnItselfInsteadOfPassingThrough) {
  // A 20 x 5 sheet on the floor whose right half is flung up and over, turning about the line
  // between its columns 9 and 10 at 9 rad/s: it lands on its left half. Without self-contact the
  // halves pass through each other (their points come within 4 mm); with it they stay a contact
  // distance apart.
  const std::string text = R"(
dt = 0.0002
gravity = [0.0, 0.0, -9.81]
[bounds]
lower = [-1.0, -1.0, -1.0]
upper = [1.0, 1.0, 1.0]
stiffness = 2000
damping = 0.5
friction_static = 0.5
[contact]
stiffness = 2000
damping = 0.5
[jelly]
shape = "lattice"
size = [20, 5, 1]
spacing = 0.05
total_mass = 0.1
stiffness = { structural = 300, shear = 100, bend = 2 }
damping = 0.1
offset = [0.0, 0.0, -0.95]
self_contact = true
)";
  for (bool self : {true, false}) {
    std::string withOrWithout = text;
    if (!self) withOrWithout.replace(withOrWithout.find("self_contact = true"), 19, "");
    WorldFile file = test::scene(withOrWithout);
    const Body& body = *file.world.scene->body;
    const int n = body.count();
    const double hinge = 0.05 * 9.5 - 0.5 * 0.05 * 19;
    for (int q = 0; q < n; ++q) {
      const double dx = load(file.state.p(), q, n).x - hinge;
      if (dx > 0) store(file.state.v(), q, n, {0, 0, 9.0 * dx});
    }
    const Model model = makeModel(file.world, file.state);
    Simulation run(model, file.state, Integrator::RK4, 0.0002);
    double gap = INFINITY;
    for (int frame = 0; frame < 30; ++frame) {
      ASSERT_TRUE(run.advance(250).ran());
      gap = std::min(gap, smallestSelfGap(body, run.state()));
    }
    // Folded: its tip (column 19) came over to the left half's side of the hinge.
    EXPECT_LT(load(run.state().p(), body.pointAtIndex(19, 2, 0), n).x, hinge - 0.2);
    if (self)
      EXPECT_GT(gap, 0.04);  // m: 0.8 of its contact distance, 0.05 m
    else
      EXPECT_LT(gap, 0.02);  // what self-contact prevents
  }
}

TEST(BodyContact, SelfContactPushesApartFarPointsOfOneJellyAndLeavesItsNeighboursToTheSprings) {
  // A sheet folded in two by hand: its rows j and 9 - j face each other 0.05 m apart.
  const WorldFile file = test::scene(
      "[bounds]\npresent = false\n[jelly]\nshape = \"lattice\"\nsize = [4, 10, 1]\n"
      "spacing = 0.1\nself_contact = true\n");
  State folded = file.state;
  const Body& body = *file.world.scene->body;
  const int n = body.count();
  for (int q = 0; q < n; ++q) {
    const auto i = body.index(q);
    const bool upper = i[1] >= 5;
    store(folded.p(), q, n, {0.1 * i[0], 0.1 * (upper ? 9 - i[1] : i[1]), upper ? 0.05 : 0.0});
  }
  const Model model = makeModel(file.world, folded);
  const std::vector<ContactPair> pairs = contactTerm(model)->contacts(folded.p());
  // Each point faces one across the fold, 0.05 m away (closer than 0.1 m), except where rows 4
  // and 5 meet, grid neighbours: rows j <= 3 pair with 9 - j straight across (diagonally, with
  // their neighbours' partners, they are 0.112 m apart: out of reach).
  int across = 0;
  for (const ContactPair& pair : pairs) {
    const auto a = body.index(pair.a), b = body.index(pair.b);
    EXPECT_GT(std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1])}), kSelfNeighbourhood);
    across += a[0] == b[0] && a[1] + b[1] == 9;
  }
  EXPECT_EQ(across, 4 * 4);  // rows 0-9, 1-8, 2-7, 3-6 of 4 points each
  EXPECT_EQ(static_cast<int>(pairs.size()), across);
  std::vector<double> force(3 * n, 0.0), zero(3 * n, 0.0);
  contactTerm(model)->addForces(folded.p(), zero.data(), nullptr, force.data());
  const int low = body.pointAtIndex(1, 1, 0), high = body.pointAtIndex(1, 8, 0);
  EXPECT_NEAR(load(force.data(), low, n).z, -model.world.kCollision * 0.05, 1e-9);
  EXPECT_NEAR(load(force.data(), high, n).z, model.world.kCollision * 0.05, 1e-9);
}

TEST(BodyContact, ClothPinnedAtTwoCornersDrapesOverABallWithoutCrossingItself) {
  const WorldFile file = test::scene(R"(
dt = 0.0005
gravity = [0.0, 0.0, -9.81]
[bounds]
lower = [-1.0, -1.0, -1.0]
upper = [1.0, 1.0, 1.0]
[contact]
stiffness = 2000
damping = 0.5
[jelly]
shape = "lattice"
size = [14, 14, 1]
spacing = 0.08
total_mass = 0.2
stiffness = { structural = 400, shear = 100, bend = 20 }
damping = 0.6
self_contact = true
offset = [0.0, 0.0, 0.35]
[[pin]]
i = [0, 0]
j = [0, 0]
[[pin]]
i = [13, 13]
j = [0, 0]
[[sphere]]
centre = [0.0, 0.0, -0.1]
radius = 0.35
stiffness = 2000
damping = 1
friction_static = 0.5
friction_dynamic = 0.4
)");
  const Model model = makeModel(file.world, file.state);
  Simulation run(model, file.state, Integrator::RK4, 0.0005);
  const int n = model.points();
  const Vec3 centre{0, 0, -0.1};
  double gap = INFINITY, deepest = 0, fastest = 0, kinetic = 0;
  for (int frame = 0; frame < 40; ++frame) {
    ASSERT_TRUE(run.advance(100).ran());
    gap = std::min(gap, smallestSelfGap(model.body(), run.state()));
    double energy = 0;
    for (int q = 0; q < n; ++q) {
      deepest = std::max(deepest, 0.35 - length(load(run.state().p(), q, n) - centre));
      energy +=
          0.5 * model.pointMass[q] * dot(load(run.state().v(), q, n), load(run.state().v(), q, n));
    }
    fastest = std::max(fastest, energy);
    kinetic = energy;
  }
  // Its middle lies on the ball's top; it came to rest (a fortieth of the landing's kinetic
  // energy left after 2 s); never through itself or 2 cm into the ball.
  const Vec3 middle = load(run.state().p(), model.body().pointAtIndex(7, 7, 0), n);
  EXPECT_NEAR(length(middle - centre), 0.35, 0.02);
  EXPECT_LT(kinetic, fastest / 40);
  EXPECT_GT(gap, 0.032);
  EXPECT_LT(deepest, 0.02);
}

// The broad phase against every pair, on points scattered far apart (its hashed cells) and
// packed close (its dense array of cells), in two jellies and one with self-contact.
TEST(BodyContact, TheBroadPhaseFindsEveryPairThatEveryPairCheckFinds) {
  std::string text = kHeadOn;
  text.replace(text.find("stiffness = 500"), 15, "stiffness = 500\nself_contact = true");
  const WorldFile file = test::scene(text);
  const Model model = makeModel(file.world, file.state);
  const BodyContactTerm& term = *contactTerm(model);
  const Body& body = model.body();
  const int n = body.count();
  std::mt19937 random(17);
  for (double size : {40.0, 0.6}) {
    std::uniform_real_distribution<double> where(-size / 2, size / 2);
    State s = file.state;
    for (int c = 0; c < 3 * n; ++c) s.p()[c] = where(random);
    // A few points put next to others, so that the scattered case has pairs too.
    for (int q = 0; q < 64; q += 3)
      store(s.p(), q + 64, n, load(s.p(), q, n) + Vec3{0.03, -0.02, 0.05});
    std::vector<std::pair<int, int>> expected;
    for (int a : body.surfacePoints)
      for (int b : body.surfacePoints) {
        if (b <= a) continue;
        const auto i = body.index(a), j = body.index(b);
        const bool near = std::max({std::abs(i[0] - j[0]), std::abs(i[1] - j[1]),
                                    std::abs(i[2] - j[2])}) <= kSelfNeighbourhood;
        const bool self = body.partOf(a) == body.partOf(b);
        if (self && (body.partOf(a) == 1 || near)) continue;
        if (length(load(s.p(), a, n) - load(s.p(), b, n)) < 0.1) expected.emplace_back(a, b);
      }
    EXPECT_EQ(term.pairsAt(s.p()), expected) << size;
    EXPECT_GT(expected.size(), size > 1 ? 10u : 40u);
  }
}

// Every point of two jellies at one place: each point of the first may touch all 296 surface
// points of the second, and keeps 64 of them (the first in the broad phase's order), not
// 87,616 pairs; every pair is then at L = 0 (n = +z) and its force finite.
TEST(BodyContact, APointKeepsAtMostItsFirst64PartnersOfAStartCollapsedToOnePlace) {
  std::string text = kHeadOn;  // two 8^3 jellies
  for (std::size_t at; (at = text.find("size = [4, 4, 4]")) != std::string::npos;)
    text.replace(at, 16, "size = [8, 8, 8]");
  text.replace(text.find("offset = [0.2, 0.03"), 19, "offset = [1.2, 0.03");
  const WorldFile file = test::scene(text);
  const Model model = makeModel(file.world, file.state);
  const BodyContactTerm& term = *contactTerm(model);
  const Body& body = model.body();
  const int n = body.count();
  State s = file.state;
  for (int q = 0; q < n; ++q) store(s.p(), q, n, Vec3{0.1, 0.2, 0.3});
  std::vector<int> first, second;
  for (int q : body.surfacePoints) (body.partOf(q) == 0 ? first : second).push_back(q);
  ASSERT_EQ(first.size(), 296u);
  ASSERT_EQ(second.size(), 296u);
  const std::vector<std::pair<int, int>> pairs = term.pairsAt(s.p());
  EXPECT_EQ(pairs.size(), first.size() * kMostContactPartners);
  std::map<int, std::set<int>> partners;
  for (const auto& [a, b] : pairs) {
    EXPECT_EQ(body.partOf(a), 0);
    EXPECT_EQ(body.partOf(b), 1);
    partners[a].insert(b);
  }
  for (int a : first) EXPECT_EQ(partners[a].size(), std::size_t(kMostContactPartners)) << a;
  std::vector<double> force(3 * n, 0.0);
  term.addForcesOn({0, n}, s.p(), s.v(), nullptr, force.data());
  for (double f : force) EXPECT_TRUE(std::isfinite(f));
}

TEST(BodyContact, OneJellyWithoutSelfContactHasNoContactTerm) {
  const WorldFile file = test::scene("[jelly]\nshape = \"lattice\"\nsize = [3, 3, 3]\n");
  EXPECT_EQ(contactTerm(makeModel(file.world, file.state)), nullptr);
}

// IMPLICIT through the collision, its Jacobian's pattern following the pairs in contact: the
// jellies part, keeping their momentum to the Newton solve's tolerance.
TEST(BodyContact, ImplicitStepsThroughTheCollision) {
  const WorldFile file = test::scene(kHeadOn);
  const Model model = makeModel(file.world, file.state);
  Simulation run(model, file.state, Integrator::Implicit, 0.001);
  const Vec3 before = momentum(model, file.state);
  const double scale = 0.5 * model.points() * model.pointMass[0];
  double drift = 0, inside = 0;
  for (int step = 0; step < 400; ++step) {
    ASSERT_TRUE(run.advance(1).ran());
    drift = std::max(drift, length(momentum(model, run.state()) - before) / scale);
    if (step % 5 == 0) inside = std::max(inside, deepestInside(model, run.state()));
  }
  const Body& body = model.body();
  Vec3 first;
  for (int q = 0; q < body.partFirst[1]; ++q) first += load(run.state().v(), q, body.count());
  RecordProperty("momentum_drift", textf("%.3g", drift));
  EXPECT_LT(first.x / body.partFirst[1], -0.1);  // parted
  EXPECT_LT(inside, 0.5);
  EXPECT_LT(drift, 1e-6);
}

}  // namespace
}  // namespace jello
