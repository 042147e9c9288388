// Every force term keeps the contract of model/term.h, checked through the interface alone, so
// that a new term is checked by these tests as soon as a scene holds it: its Jacobian blocks
// against finite differences of its own force, its stored energy against its force, its reach
// test against the force it exerts.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "io/scenereader.h"
#include "solver/physics.h"
#include "test_support.h"

namespace jello {
namespace {

// A world with every term: springs with dampers, walls, a plane, a trilinear field.
World everyTermWorld() {
  World w = test::springsOnlyWorld();
  w.dElastic = 0.3;
  w.kCollision = 700;
  w.dCollision = 0.4;
  w.hasPlane = true;
  w.plane = {0.3, -0.2, 1, 0.35};
  w.field.resolution = 4;
  w.field.forces.resize(3 * 64);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> force(-2, 2);
  for (double& f : w.field.forces) f = force(random);
  return w;
}

// The rest lattice moved so that points lie beyond the wall x = 2 and across the plane, shaken a
// little (no point exactly on a wall, a plane or a field cell's face), with random velocities.
State contactState() {
  State s = test::restLattice();
  std::mt19937 random(11);
  std::uniform_real_distribution<double> jitter(-0.02, 0.02), speed(-1, 1);
  for (int q = 0; q < kNumPoints; ++q) {
    store(s.p(), q,
          load(s.p(), q) +
              Vec3{1.45 + jitter(random), -0.4 + jitter(random), -0.75 + jitter(random)});
    store(s.v(), q, Vec3{speed(random), speed(random), speed(random)});
  }
  return s;
}

// The term's blocks as a dense matrix of dF/dp (or dF/dv), 3n square for n points.
class DenseSink final : public JacobianSink {
 public:
  DenseSink(const ForceTerm& term, const double* p, bool velocity)
      : n_(term.pointCount()),
        pairs_(term.pairsAt(p)),
        couplings_(term.couplings()),
        velocity_(velocity),
        m_(std::size_t(3 * n_) * (3 * n_), 0.0) {}
  void addPair(const Block3& dFdL, const Block3& dFdw) override {
    auto [a, b] = pairs_[next_++];
    const Block3& block = velocity_ ? dFdw : dFdL;
    for (auto [row, column, sign] :
         {std::tuple{a, a, 1.0}, {a, b, -1.0}, {b, a, -1.0}, {b, b, 1.0}})
      add(row, column, block, sign);
  }
  void addPoint(int q, const Block3& dFdp, const Block3& dFdv) override {
    add(q, q, velocity_ ? dFdv : dFdp, 1.0);
  }
  void addCoupling(std::size_t k, const Block3& dFdp, const Block3& dFdv) override {
    ASSERT_LT(k, couplings_.size());
    add(couplings_[k].first, couplings_[k].second, velocity_ ? dFdv : dFdp, 1.0);
  }
  double at(int row, int column) const {
    return m_[static_cast<std::size_t>(row) * 3 * n_ + column];
  }

 private:
  void add(int row, int column, const Block3& block, double sign) {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        m_[static_cast<std::size_t>(coordIndex(row, i, n_)) * 3 * n_ + coordIndex(column, j, n_)] +=
            sign * block.m[3 * i + j];
  }
  int n_;
  std::vector<std::pair<int, int>> pairs_, couplings_;
  bool velocity_;
  std::size_t next_ = 0;
  std::vector<double> m_;
};

std::vector<double> termForce(const ForceTerm& term, const std::vector<double>& p,
                              const std::vector<double>& v) {
  std::vector<double> f(p.size(), 0.0);
  term.addForces(p.data(), v.data(), nullptr, f.data());
  return f;
}

// The largest difference between the term's blocks and central differences of its force, for
// `samples` coordinates of the positions (or velocities) at random, and the largest block entry.
std::pair<double, double> jacobianError(const ForceTerm& term, std::vector<double> p,
                                        std::vector<double> v, bool velocity, int samples,
                                        std::mt19937* random) {
  const int coords = static_cast<int>(p.size());
  DenseSink sink(term, p.data(), velocity);
  term.addJacobian(p.data(), v.data(), &sink);
  double worst = 0, scale = 0;
  for (int sample = 0; sample < samples; ++sample) {
    const int c = std::uniform_int_distribution<int>(0, coords - 1)(*random);
    std::vector<double>& x = velocity ? v : p;
    const double saved = x[c], h = 1e-6 * std::max(1.0, std::fabs(saved));
    x[c] = saved + h;
    std::vector<double> plus = termForce(term, p, v);
    x[c] = saved - h;
    std::vector<double> minus = termForce(term, p, v);
    x[c] = saved;
    for (int r = 0; r < coords; ++r) {
      const double numeric = (plus[r] - minus[r]) / (2 * h), analytic = sink.at(r, c);
      worst = std::max(worst, std::fabs(numeric - analytic));
      scale = std::max(scale, std::fabs(analytic));
    }
  }
  return {worst, scale};
}

// Every term's blocks against central differences of its own force, for 40 coordinates of
// positions and of velocities each.
TEST(ForceTerms, EachJacobianMatchesFiniteDifferencesOfItsForce) {
  const World w = everyTermWorld();
  const State s = contactState();
  const Model model = makeModel(w, s, KernelChoice::General);
  ASSERT_EQ(model.forces.terms.size(), 4u);
  std::vector<double> p(s.p(), s.p() + kNumCoords), v(s.v(), s.v() + kNumCoords);
  std::mt19937 random(5);
  for (const auto& term : model.forces.terms)
    for (bool velocity : {false, true}) {
      const auto [worst, scale] = jacobianError(*term, p, v, velocity, 40, &random);
      EXPECT_LE(worst, 1e-5 * std::max(scale, 1.0))
          << term->describe(p.data())[0].label << (velocity ? " dF/dv" : " dF/dp");
    }
}

// A jelly of finite elements of each material, bent and moving: its term's blocks (elastic,
// viscous and mass damping) against central differences of its force.
TEST(ForceTerms, ElementJacobiansMatchFiniteDifferencesOfTheirForce) {
  for (const char* material : {"corotated", "neohookean"}) {
    const WorldFile file = parseScene(std::string(R"(
[bounds]
present = false
[jelly]
shape = "lattice"
size = [3, 3, 3]
spacing = 0.1
youngs_modulus = 1e4
poisson_ratio = 0.3
density = 1000
mass_damping = 0.5
stiffness_damping = 0.01
material = ")") + material + "\"\n",
                                      "elements.toml", "");
    State s = file.state;
    const int n = s.points();
    std::mt19937 random(9);
    std::uniform_real_distribution<double> jitter(-0.02, 0.02), speed(-1, 1);
    for (int q = 0; q < n; ++q) {
      store(s.p(), q, n, load(s.p(), q, n) + Vec3{jitter(random), jitter(random), jitter(random)});
      store(s.v(), q, n, Vec3{speed(random), speed(random), speed(random)});
    }
    const Model model = makeModel(file.world, s, KernelChoice::General);
    ASSERT_NE(model.forces.elements, nullptr);
    std::vector<double> p(s.p(), s.p() + 3 * n), v(s.v(), s.v() + 3 * n);
    for (bool velocity : {false, true}) {
      const auto [worst, scale] =
          jacobianError(*model.forces.elements, p, v, velocity, 3 * n, &random);
      EXPECT_GT(scale, 1.0);
      EXPECT_LE(worst, 1e-6 * scale) << material << (velocity ? " dF/dv" : " dF/dp");
    }
  }
}

// Without damping, each term's force is minus the gradient of the energy it stores (the field
// stores none and exerts a force: it is the one term the guard bounds by its largest force).
TEST(ForceTerms, EachStoredEnergyIsThePotentialOfItsForce) {
  World w = everyTermWorld();
  w.dElastic = w.dCollision = 0;
  const State s = contactState();
  const Model model = makeModel(w, s, KernelChoice::General);
  std::vector<double> p(s.p(), s.p() + kNumCoords), v(kNumCoords, 0.0);
  std::mt19937 random(3);
  int checked = 0;
  for (const auto& term : model.forces.terms) {
    if (term->largestExternalForce() > 0) continue;
    const std::vector<double> force = termForce(*term, p, v);
    // The 30 coordinates the term pushes hardest, and 30 at random.
    std::vector<int> coords(kNumCoords);
    for (int c = 0; c < kNumCoords; ++c) coords[c] = c;
    std::partial_sort(coords.begin(), coords.begin() + 30, coords.end(),
                      [&](int a, int b) { return std::fabs(force[a]) > std::fabs(force[b]); });
    coords.resize(30);
    for (int extra = 0; extra < 30; ++extra)
      coords.push_back(std::uniform_int_distribution<int>(0, kNumCoords - 1)(random));
    double worst = 0, scale = 0;
    for (int c : coords) {
      const double h = 1e-6, saved = p[c];
      double plus = 0, minus = 0;
      p[c] = saved + h;
      term->addEnergy(p.data(), &plus);
      p[c] = saved - h;
      term->addEnergy(p.data(), &minus);
      p[c] = saved;
      worst = std::max(worst, std::fabs(-(plus - minus) / (2 * h) - force[c]));
      scale = std::max(scale, std::fabs(force[c]));
    }
    EXPECT_GT(scale, 1.0) << "the state should load every term";
    EXPECT_LE(worst, 1e-4 * scale) << term->describe(p.data())[0].label;
    ++checked;
  }
  EXPECT_EQ(checked, 3);  // springs, walls, plane
}

// A term whose reach test says no exerts no force on a cube in that box; one that says yes does,
// for this state where every term acts.
TEST(ForceTerms, AReachTestThatSaysNoMeansNoForce) {
  const World w = everyTermWorld();
  const State touching = contactState(), rest = test::restLattice();
  const Model model = makeModel(w, touching, KernelChoice::General);
  for (const auto& term : model.forces.terms) {
    for (const State* s : {&touching, &rest}) {
      std::vector<double> p(s->p(), s->p() + kNumCoords), v(s->v(), s->v() + kNumCoords);
      const std::vector<double> f = termForce(*term, p, v);
      const bool any = std::any_of(f.begin(), f.end(), [](double x) { return x != 0; });
      if (!term->mayReach(boundsOf(p.data(), kNumPoints))) {
        EXPECT_FALSE(any) << term->describe(p.data())[0].label;
      }
      if (s == &touching) {
        EXPECT_TRUE(any && term->mayReach(boundsOf(p.data(), kNumPoints)))
            << term->describe(p.data())[0].label;
      }
    }
  }
}

// Contacts count the points they push: the walls those beyond one, the plane those across it;
// the smooth terms and a contact without spring or damper, none.
TEST(ForceTerms, ContactsCountThePointsTheyPushAndTheSmoothTermsNone) {
  World w = everyTermWorld();
  const State touching = contactState(), rest = test::restLattice();
  int beyondWall = 0;
  for (int q = 0; q < kNumPoints; ++q) {
    const Vec3 p = load(touching.p(), q);
    beyondWall += std::fabs(p.x) > 2 || std::fabs(p.y) > 2 || std::fabs(p.z) > 2;
  }
  ASSERT_GT(beyondWall, 0);
  const Model model = makeModel(w, touching, KernelChoice::General);
  const int acrossPlane = pointsAcrossPlane(model, touching);
  ASSERT_GT(acrossPlane, 0);
  for (const auto& term : model.forces.terms) {
    const std::string label = term->describe(touching.p())[0].label;
    const int expected = label == "walls" ? beyondWall : label == "plane" ? acrossPlane : 0;
    EXPECT_EQ(term->pointsInContact(touching.p()), expected) << label;
    EXPECT_EQ(term->pointsInContact(rest.p()), 0) << label;
  }
  w.kCollision = w.dCollision = 0;
  const Model without = makeModel(w, touching, KernelChoice::General);
  for (const auto& term : without.forces.terms)
    EXPECT_EQ(term->pointsInContact(touching.p()), 0) << term->describe(touching.p())[0].label;
}

}  // namespace
}  // namespace jello
