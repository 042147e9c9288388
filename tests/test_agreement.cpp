// 2000 steps of the course worlds against the independent reference results (docs/physics.md).
#include <gtest/gtest.h>

#include "solver/integrators.h"
#include "solver/physics.h"
#include "test_support.h"

namespace jello {
namespace {

struct AgreementCase {
  const char* world;
  Integrator integrator;
  double dt;  // 0: the world's own
  const char* expected;
};

void PrintTo(const AgreementCase& c, std::ostream* os) { *os << c.expected; }

class Agreement : public ::testing::TestWithParam<AgreementCase> {};

TEST_P(Agreement, TwoThousandStepsMatchTheReference) {
  const AgreementCase& c = GetParam();
  WorldFile f = readWorldFile(test::dataPath(c.world));
  Model model = makeModel(f.world, f.state);
  const double dt = c.dt > 0 ? c.dt : f.run.dt;
  Stepper stepper(c.integrator);
  for (int s = 0; s < 2000; ++s) stepper.step(model, f.state, dt);
  std::vector<double> expected = test::readExpectedPositions(c.expected);
  double rms = test::rmsDistance(f.state.p(), expected.data());
  std::printf("%s: RMS distance to the reference %.3e m\n", c.expected, rms);
  EXPECT_LT(rms, 1e-9);
}

INSTANTIATE_TEST_SUITE_P(
    CourseWorlds, Agreement,
    ::testing::Values(
        AgreementCase{"jello.w", Integrator::RK4, 0, "jello.RK4.2000.txt"},
        AgreementCase{"rotate.w", Integrator::RK4, 0, "rotate.RK4.2000.txt"},
        AgreementCase{"moveLeft.w", Integrator::RK4, 0, "moveLeft.RK4.2000.txt"},
        AgreementCase{"skewedCorner.w", Integrator::RK4, 0, "skewedCorner.RK4.2000.txt"},
        AgreementCase{"gravity.w", Integrator::RK4, 0, "gravity.RK4.2000.txt"},
        AgreementCase{"skewedCorner.w", Integrator::Euler, 0, "skewedCorner.EULER.2000.txt"},
        AgreementCase{"jello.w", Integrator::Euler, 1e-4, "jello.EULER.dt0.0001.2000.txt"}),
    [](const auto& testInfo) {
      std::string name = testInfo.param.expected;
      name = name.substr(0, name.find(".2000"));
      for (char& ch : name)
        if (ch == '.') ch = '_';
      return name;
    });

}  // namespace
}  // namespace jello
