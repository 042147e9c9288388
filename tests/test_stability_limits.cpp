// The stability analysis's limits against those of the dense analysis it replaced: every explicit
// integrator, at rest, at the initial state and with a face on a wall, on every course and stress
// world.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>

#include "analysis/stability.h"
#include "io/input.h"
#include "solver/integrators.h"

namespace jello {
namespace {

// Integrators in the order of the columns below (the integrator table's).
const std::array<const char*, 6> kColumns = {"EULER",  "SYMPLECTIC", "MIDPOINT",
                                             "VERLET", "RK4",        "RK45"};

struct DenseLimits {
  const char* world;  // from the source tree's top folder
  // s, by kColumns: jello --check --json's critical_dt, initial_state and face_on_wall.
  std::array<double, 6> atRest, atStart, onWall;
};

// Printed by `jello --check --json WORLD` (%.6g of each) built from commit 4a1ab37, the last
// whose analysis solved the whole 1536 x 1536 stiffness densely (SelfAdjointEigenSolver) and
// took every one of its modes: the numbers this analysis must keep.
const DenseLimits kDense[] = {
    {"world/drop.w",
     {0.000500032, 0.000592047, 0.000980362, 0.000942585, 0.00127105, 0.00164971},
     {0.000500032, 0.000592047, 0.000980362, 0.000942585, 0.00127105, 0.00164971},
     {0.000374542, 0.000592035, 0.00098034, 0.00094257, 0.00127102, 0.00164967}},
    {"world/gravity.w",
     {0.000500032, 0.000592019, 0.000980342, 0.000942525, 0.001271, 0.00164966},
     {0.000500032, 0.000592019, 0.00098034, 0.000942524, 0.001271, 0.00164965},
     {0.000374542, 0.000592008, 0.000980318, 0.000942509, 0.00127098, 0.00164962}},
    {"world/jello.w",
     {0.00125008, 0.000729591, 0.00168308, 0.000942525, 0.00215203, 0.00252441},
     {0.000926824, 0.00072959, 0.00168308, 0.000942524, 0.00215203, 0.00252441},
     {0.000936356, 0.000729578, 0.00168304, 0.000942509, 0.00215198, 0.00252435}},
    {"world/moveLeft.w",
     {0.000500032, 0.000592019, 0.000980342, 0.000942525, 0.001271, 0.00164966},
     {0.000500032, 0.000592019, 0.00098034, 0.000942524, 0.001271, 0.00164965},
     {0.000374542, 0.000592008, 0.000980318, 0.000942509, 0.00127098, 0.00164962}},
    {"world/rotate.w",
     {0.000500032, 0.000592019, 0.000980342, 0.000942525, 0.001271, 0.00164966},
     {0.000500032, 0.000592019, 0.00098034, 0.000942524, 0.001271, 0.00164965},
     {0.000374713, 0.000592008, 0.000980318, 0.000942509, 0.00127098, 0.00164962}},
    {"world/skewedCorner.w",
     {0.000500032, 0.000592019, 0.000980342, 0.000942525, 0.001271, 0.00164966},
     {0.00037073, 0.000592018, 0.00098034, 0.000942524, 0.001271, 0.00164965},
     {0.000374542, 0.000592008, 0.000980318, 0.000942509, 0.00127098, 0.00164962}},
    {"world/spin.w",
     {0.000500032, 0.000592047, 0.000980362, 0.000942585, 0.00127105, 0.00164971},
     {0.000500015, 0.000592048, 0.000980351, 0.000942596, 0.00127104, 0.0016497},
     {0.000374542, 0.000592035, 0.00098034, 0.00094257, 0.00127102, 0.00164967}},
    {"world/stiff.w",
     {0.000100003, 0.000222887, 0.00026142, 0.000266646, 0.000429776, 0.000500273},
     {0.000100003, 0.000222887, 0.00026142, 0.000266646, 0.000429776, 0.000500273},
     {6.15724e-05, 0.000222883, 0.000261412, 0.00026664, 0.000429768, 0.000500261}},
    {"world/tornado.w",
     {0.000500032, 0.000592047, 0.000980362, 0.000942585, 0.00127105, 0.00164971},
     {0.000621695, 0.000643875, 0.00117223, 0.000952524, 0.00146785, 0.00189044},
     {0.00037451, 0.000592035, 0.000980339, 0.00094257, 0.00127102, 0.00164967}},
    {"tests/data/still.w",
     {0.000500032, 0.000592019, 0.000980342, 0.000942525, 0.001271, 0.00164966},
     {0.000500032, 0.000592019, 0.000980342, 0.000942525, 0.001271, 0.00164966},
     {0.000374713, 0.000592008, 0.000980318, 0.000942509, 0.00127098, 0.00164962}},
    {"world/stress/collapsed.w",
     {0.000500032, 0.000592047, 0.000980362, 0.000942585, 0.00127105, 0.00164971},
     {9.74614e-06, 0.000502242, 0.000504226, 0.000626948, 0.000988678, 0.00116032},
     {0.000374542, 0.000592035, 0.00098034, 0.00094257, 0.00127102, 0.00164967}},
    {"world/stress/damped-5.w",
     {4.72394e-05, 4.70172e-05, 4.72394e-05, 4.71278e-05, 6.57877e-05, 7.81e-05},
     {4.72393e-05, 4.70172e-05, 4.72393e-05, 4.71277e-05, 6.57876e-05, 7.81e-05},
     {4.72398e-05, 4.70177e-05, 4.72398e-05, 4.71282e-05, 6.57883e-05, 7.81008e-05}},
    {"world/stress/field-r1.w",
     {0.000500032, 0.000592047, 0.000980362, 0.000942585, 0.00127105, 0.00164971},
     {0.000500032, 0.000592047, 0.000980362, 0.000942585, 0.00127105, 0.00164971},
     {0.000374542, 0.000592035, 0.00098034, 0.00094257, 0.00127102, 0.00164967}},
    {"world/stress/field-r2.w",
     {0.000500032, 0.000592047, 0.000980362, 0.000942585, 0.00127105, 0.00164971},
     {0.000500032, 0.000592047, 0.000980362, 0.000942585, 0.00127105, 0.00164971},
     {0.000374489, 0.000592035, 0.000980339, 0.00094257, 0.00127102, 0.00164967}},
    {"world/stress/half-outside.w",
     {0.000500032, 0.000592047, 0.000980362, 0.000942585, 0.00127105, 0.00164971},
     {0.000388644, 0.00056721, 0.000934756, 0.000906045, 0.00121466, 0.00157622},
     {0.000374542, 0.000592035, 0.00098034, 0.00094257, 0.00127102, 0.00164967}},
    {"world/stress/inside-out.w",
     {0.000500032, 0.000592047, 0.000980362, 0.000942585, 0.00127105, 0.00164971},
     {0.000500032, 0.000592047, 0.000980362, 0.000942585, 0.00127105, 0.00164971},
     {0.000374542, 0.000592035, 0.00098034, 0.00094257, 0.00127102, 0.00164967}},
    {"world/stress/stiff-1e5.w",
     {2.50016e-06, 6.61951e-05, 2.43534e-05, 6.6365e-05, 9.92735e-05, 7.8413e-05},
     {2.03335e-06, 6.61951e-05, 2.43534e-05, 6.63649e-05, 9.92734e-05, 7.84129e-05},
     {2.50019e-06, 6.61951e-05, 2.43536e-05, 6.63649e-05, 9.92735e-05, 7.84132e-05}},
    {"world/stress/stiff-2e4.w",
     {1.25008e-05, 0.000141513, 7.42382e-05, 0.000143271, 0.000225629, 0.000199237},
     {1.01668e-05, 0.000141513, 7.42382e-05, 0.000143271, 0.000225629, 0.000199237},
     {1.25009e-05, 0.000141513, 7.42387e-05, 0.000143271, 0.000225629, 0.000199237}},
    {"world/stress/wall-1e5-200.w",
     {0.000500032, 0.000592047, 0.000980362, 0.000942585, 0.00127105, 0.00164971},
     {0.000500032, 0.000592047, 0.000980362, 0.000942585, 0.00127105, 0.00164971},
     {1.07743e-05, 0.00026039, 0.000100768, 0.000262029, 0.000401315, 0.000319907}},
};

constexpr double kTolerance = 0.02;  // relative

void PrintTo(const DenseLimits& d, std::ostream* os) { *os << d.world; }

class LimitsAgainstTheDenseAnalysis : public ::testing::TestWithParam<DenseLimits> {};

TEST_P(LimitsAgainstTheDenseAnalysis, StayWithinTwoPercentForEveryIntegrator) {
  const DenseLimits& dense = GetParam();
  const WorldFile f = readWorldFile(std::string(JELLO_SOURCE_DIR) + "/" + dense.world);
  const StabilityReport report = analyseStability(f.world, f.state);
  ASSERT_TRUE(report.beyond.empty()) << report.beyond;
  for (std::size_t i = 0; i < kExplicitIntegrators.size(); ++i) {
    const std::string name = integratorName(kExplicitIntegrators[i]);
    ASSERT_EQ(name, kColumns[i]);
    EXPECT_NEAR(report.criticalRest[i] / dense.atRest[i], 1, kTolerance) << name << " at rest";
    EXPECT_NEAR(report.criticalFaceOnWall[i] / dense.onWall[i], 1, kTolerance)
        << name << " with a face on a wall";
    // Explicit Euler's limit at the initial state of jello.w, skewedCorner.w, tornado.w,
    // half-outside.w, stiff-2e4.w and stiff-1e5.w comes from a mode inside the spectrum (a
    // strained corner's, the compressed cube's, the cube's on deep contact springs), which the
    // ends alone missed by up to 33%: held to the same 2%.
    EXPECT_NEAR(report.criticalInitial[i] / dense.atStart[i], 1, kTolerance)
        << name << " at the initial state";
  }
}

INSTANTIATE_TEST_SUITE_P(Worlds, LimitsAgainstTheDenseAnalysis, ::testing::ValuesIn(kDense),
                         [](const auto& info) {
                           std::string name = info.param.world;
                           name = name.substr(name.find('/') + 1);
                           for (char& ch : name)
                             if (ch == '.' || ch == '-' || ch == '/') ch = '_';
                           return name;
                         });

}  // namespace
}  // namespace jello
