// createWorld: presets, round trips, each option, field expressions, safety, --describe, and
// the showcase worlds of world/README.md.
#include <gtest/gtest.h>
#include <muParser.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>

#include "app/describe.h"
#include "app/worldbuilder.h"
#include "test_support.h"

namespace jello {
namespace {

using test::dataPath;

struct Result {
  int status;
  std::string out, err;
};

Result createWorld(const std::string& args, const std::string& cwd = "") {
  std::string dir = test::makeTempDir();
  std::string command = (cwd.empty() ? "" : "cd '" + cwd + "' && ") + "'" + JELLO_CREATE_WORLD +
                        "' " + args + " >" + dir + "/out 2>" + dir + "/err </dev/null";
  int raw = std::system(command.c_str());
  Result r{WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, test::readText(dir + "/out"),
           test::readText(dir + "/err")};
  test::removeTree(dir);
  return r;
}

// The named parts of a world that differ between a and b.
std::set<std::string> differences(const WorldFile& a, const WorldFile& b) {
  std::set<std::string> d;
  const World &x = a.world, &y = b.world;
  if (a.run.integrator != b.run.integrator) d.insert("integrator");
  if (a.run.dt != b.run.dt) d.insert("dt");
  if (a.run.n != b.run.n) d.insert("n");
  if (x.kElastic != y.kElastic) d.insert("kElastic");
  if (x.dElastic != y.dElastic) d.insert("dElastic");
  if (x.kCollision != y.kCollision) d.insert("kCollision");
  if (x.dCollision != y.dCollision) d.insert("dCollision");
  if (x.mass != y.mass) d.insert("mass");
  if (x.hasPlane != y.hasPlane ||
      (x.hasPlane && (x.plane.a != y.plane.a || x.plane.b != y.plane.b || x.plane.c != y.plane.c ||
                      x.plane.d != y.plane.d)))
    d.insert("plane");
  if (x.field.resolution != y.field.resolution || x.field.forces != y.field.forces)
    d.insert("field");
  if (!std::equal(a.state.p(), a.state.p() + kNumCoords, b.state.p())) d.insert("positions");
  if (!std::equal(a.state.v(), a.state.v() + kNumCoords, b.state.v())) d.insert("velocities");
  return d;
}

double maxDifference(const double* a, const double* b, std::size_t n) {
  double m = 0;
  for (std::size_t i = 0; i < n; ++i) m = std::max(m, std::fabs(a[i] - b[i]));
  return m;
}

class Preset : public ::testing::TestWithParam<const char*> {};

TEST_P(Preset, RebuildsTheCourseWorldWithinItsRounding) {
  std::string name = GetParam();
  std::string dir = test::makeTempDir();
  Result r = createWorld("--preset " + name + " -o '" + dir + "/made.w'");
  ASSERT_EQ(r.status, 0) << r.err;
  WorldFile made = readWorldFile(dir + "/made.w"), course = readWorldFile(dataPath(name + ".w"));
  test::removeTree(dir);
  const World &m = made.world, &c = course.world;
  EXPECT_EQ(made.run.integrator, course.run.integrator);
  EXPECT_EQ(made.run.n, course.run.n);
  EXPECT_EQ(m.hasPlane, c.hasPlane);
  for (auto [x, y] : {std::pair{made.run.dt, course.run.dt},
                      {m.kElastic, c.kElastic},
                      {m.dElastic, c.dElastic},
                      {m.kCollision, c.kCollision},
                      {m.dCollision, c.dCollision},
                      {m.mass, c.mass},
                      {m.plane.a, c.plane.a},
                      {m.plane.b, c.plane.b},
                      {m.plane.c, c.plane.c},
                      {m.plane.d, c.plane.d}})
    EXPECT_NEAR(x, y, 1e-6);
  ASSERT_EQ(m.field.resolution, c.field.resolution);
  EXPECT_LE(maxDifference(m.field.forces.data(), c.field.forces.data(), c.field.forces.size()),
            1e-6);
  EXPECT_LE(maxDifference(made.state.y.data(), course.state.y.data(), made.state.y.size()), 1e-6);
}

INSTANTIATE_TEST_SUITE_P(Course, Preset,
                         ::testing::Values("jello", "rotate", "moveLeft", "skewedCorner",
                                           "gravity"));

TEST(CreateWorld, FromAWorldRoundTripsBitIdentically) {
  std::string dir = test::makeTempDir();
  // A world as `jello --dump` writes it: full-precision numbers, signed zeros.
  WorldFile source = readWorldFile(dataPath("jello.w"));
  source.state.v()[4] = -0.0;
  source.state.p()[7] = 0.1 + 0.2;
  writeWorldFile(dir + "/source.w", source.world, source.run, source.state);
  Result r = createWorld("--from '" + dir + "/source.w' -o '" + dir + "/copy.w'");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(test::readText(dir + "/copy.w"), test::readText(dir + "/source.w"));
  test::removeTree(dir);
}

struct OptionCase {
  const char* name;
  std::string options;
  std::set<std::string> changes;
  std::function<void(const WorldFile&)> check;
};

void PrintTo(const OptionCase& c, std::ostream* os) { *os << c.options; }

Vec3 centroidOf(const State& s) { return extentOf(s).centroid; }

std::vector<OptionCase> optionCases() {
  const std::string rotate = "'" + dataPath("rotate.w") + "'";
  // Field node (i,j,k) of a world.
  auto nodeAt = [](const World& w, int i, int j, int k) {
    int r = w.field.resolution;
    return w.field.node((i * r + j) * r + k);
  };
  return {
      {"integrator",
       "--integrator euler",
       {"integrator"},
       [](const WorldFile& f) { EXPECT_EQ(f.run.integrator, Integrator::Euler); }},
      {"dt", "--dt 0.0025", {"dt"}, [](const WorldFile& f) { EXPECT_EQ(f.run.dt, 0.0025); }},
      {"n", "--n 4", {"n"}, [](const WorldFile& f) { EXPECT_EQ(f.run.n, 4); }},
      {"k_elastic",
       "--k-elastic 123",
       {"kElastic"},
       [](const WorldFile& f) { EXPECT_EQ(f.world.kElastic, 123); }},
      {"d_elastic",
       "--d-elastic 1.5",
       {"dElastic"},
       [](const WorldFile& f) { EXPECT_EQ(f.world.dElastic, 1.5); }},
      {"k_collision",
       "--k-collision 0",
       {"kCollision"},
       [](const WorldFile& f) { EXPECT_EQ(f.world.kCollision, 0); }},
      {"d_collision",
       "--d-collision 2",
       {"dCollision"},
       [](const WorldFile& f) { EXPECT_EQ(f.world.dCollision, 2); }},
      {"mass", "--mass 0.01", {"mass"}, [](const WorldFile& f) { EXPECT_EQ(f.world.mass, 0.01); }},
      {"plane",
       "--plane 1 2 3 4",
       {"plane"},
       [](const WorldFile& f) {
         EXPECT_TRUE(f.world.hasPlane);
         EXPECT_EQ(f.world.plane.c, 3);
       }},
      {"field_uniform",
       "--field-uniform 1 -2 0.5",
       {"field"},
       [=](const WorldFile& f) {
         ASSERT_EQ(f.world.field.resolution, 30);
         EXPECT_EQ(nodeAt(f.world, 29, 3, 17).y, -2);
       }},
      {"field_swirl",
       "--field-swirl 0.5 --field-resolution 5",
       {"field"},
       [=](const WorldFile& f) {
         Vec3 node = nodeAt(f.world, 4, 1, 2);  // at (2, -1, 0): 0.5 (1, 2, 0)
         EXPECT_EQ(node.x, 0.5);
         EXPECT_EQ(node.y, 1);
         EXPECT_EQ(node.z, 0);
       }},
      {"field_radial",
       "--field-radial -0.25 --field-resolution 3",
       {"field"},
       [=](const WorldFile& f) {
         Vec3 node = nodeAt(f.world, 0, 1, 2);  // at (-2, 0, 2)
         EXPECT_EQ(node.x, 0.5);
         EXPECT_EQ(node.y, 0);
         EXPECT_EQ(node.z, -0.5);
       }},
      {"field_resolution",
       "--field-resolution 4",
       {"field"},
       [](const WorldFile& f) {
         EXPECT_EQ(f.world.field.resolution, 4);
         EXPECT_EQ(classifyField(f.world.field).kind, FieldKind::Zero);
       }},
      {"field_from",
       "--field-from " + rotate,
       {"field"},
       [](const WorldFile& f) {
         EXPECT_EQ(f.world.field.forces, readWorldFile(dataPath("rotate.w")).world.field.forces);
       }},
      {"cube_size",
       "--cube-size 0.5",
       {"positions"},
       [](const WorldFile& f) {
         Extent e = extentOf(f.state);
         EXPECT_NEAR(e.upper.x - e.lower.x, 0.5, 1e-15);
         EXPECT_EQ(e.lower.z, 0);
       }},
      {"center",
       "--center 1 -1 0.25",
       {"positions"},
       [](const WorldFile& f) {
         Vec3 c = centroidOf(f.state);
         EXPECT_NEAR(c.x, 1, 1e-14);
         EXPECT_NEAR(c.y, -1, 1e-14);
         EXPECT_NEAR(c.z, 0.25, 1e-14);
       }},
      {"rotate",
       "--rotate 0 0 90",
       {"positions"},
       [](const WorldFile& f) {
         // About the centre (0.5, 0.5, 0.5): p[7][0][0] = (1, 0, 0) goes to (1, 1, 0).
         Vec3 p = load(f.state.p(), pointIndex(7, 0, 0));
         EXPECT_NEAR(p.x, 1, 1e-14);
         EXPECT_NEAR(p.y, 1, 1e-14);
         EXPECT_NEAR(p.z, 0, 1e-14);
       }},
      {"velocity",
       "--velocity 1 2 3",
       {"velocities"},
       [](const WorldFile& f) { EXPECT_EQ(load(f.state.v(), 300).z, 3); }},
      {"spin",
       "--spin 0 0 2",
       {"velocities"},
       [](const WorldFile& f) {
         // v = w x (p - c): at p[7][0][0] = (1, 0, 0), r = (0.5, -0.5, -0.5), v = (1, 1, 0).
         Vec3 v = load(f.state.v(), pointIndex(7, 0, 0));
         EXPECT_NEAR(v.x, 1, 1e-15);
         EXPECT_NEAR(v.y, 1, 1e-15);
         EXPECT_EQ(v.z, 0);
       }},
      {"inside_out",
       "--inside-out",
       {"positions"},
       [](const WorldFile& f) {
         // p[0][0][0] and p[7][7][7] trade places.
         EXPECT_NEAR(load(f.state.p(), 0).x, 1, 1e-15);
         EXPECT_NEAR(load(f.state.p(), pointIndex(7, 7, 7)).z, 0, 1e-15);
       }},
      {"skew_corner",
       "--skew-corner 0.1 0 -0.05",
       {"positions"},
       [](const WorldFile& f) {
         Vec3 p = load(f.state.p(), pointIndex(7, 7, 7));
         EXPECT_NEAR(p.x, 1.1, 1e-15);
         EXPECT_NEAR(p.z, 0.95, 1e-15);
         for (int q = 0; q < kNumPoints - 1; ++q)
           ASSERT_EQ(load(f.state.p(), q).x, load(test::restLattice().p(), q).x);
       }},
  };
}

class EachOption : public ::testing::TestWithParam<OptionCase> {};

TEST_P(EachOption, ChangesWhatItShouldAndNothingElse) {
  const OptionCase& c = GetParam();
  std::string dir = test::makeTempDir();
  Result base = createWorld("-o '" + dir + "/base.w'");
  Result changed = createWorld(c.options + " -o '" + dir + "/changed.w'");
  ASSERT_EQ(base.status, 0) << base.err;
  ASSERT_EQ(changed.status, 0) << changed.err;
  WorldFile a = readWorldFile(dir + "/base.w"), b = readWorldFile(dir + "/changed.w");
  test::removeTree(dir);
  EXPECT_EQ(differences(a, b), c.changes);
  c.check(b);
}

INSTANTIATE_TEST_SUITE_P(Options, EachOption, ::testing::ValuesIn(optionCases()),
                         [](const auto& testInfo) { return std::string(testInfo.param.name); });

TEST(CreateWorld, NoPlaneRemovesAPresetsPlane) {
  std::string dir = test::makeTempDir();
  ASSERT_EQ(createWorld("--preset gravity -o '" + dir + "/a.w'").status, 0);
  ASSERT_EQ(createWorld("--preset gravity --no-plane -o '" + dir + "/b.w'").status, 0);
  EXPECT_EQ(differences(readWorldFile(dir + "/a.w"), readWorldFile(dir + "/b.w")),
            std::set<std::string>{"plane"});
  test::removeTree(dir);
}

TEST(CreateWorld, LinearFieldExpressionIsExactAtEveryNode) {
  auto linear = [](Vec3 p) { return Vec3{0.5 * p.x - 2 * p.y + 0.25, p.z, p.x + p.y + p.z}; };
  for (int r : {5, 30}) {
    FieldRecipe recipe;
    recipe.source = FieldRecipe::Source::Expression;
    recipe.expression = "0.5*x - 2*y + 0.25; z; x + y + z";
    recipe.resolution = r;
    ForceField field = buildField(recipe);
    ASSERT_EQ(field.resolution, r);
    // R = 5: every node coordinate, and so every value, is exact in binary: equality. R = 30:
    // to the rounding of one evaluation.
    const double tolerance = r == 5 ? 0 : 1e-14;
    for (int i = 0; i < r; ++i)
      for (int j = 0; j < r; ++j)
        for (int k = 0; k < r; ++k) {
          Vec3 p{fieldNodeCoordinate(i, r), fieldNodeCoordinate(j, r), fieldNodeCoordinate(k, r)};
          Vec3 got = field.node((i * r + j) * r + k), want = linear(p);
          ASSERT_NEAR(got.x, want.x, tolerance) << i << " " << j << " " << k;
          ASSERT_NEAR(got.y, want.y, tolerance);
          ASSERT_NEAR(got.z, want.z, tolerance);
        }
  }
}

std::string muparserMessage(const std::string& expression) {
  double x = 0, y = 0, z = 0;
  mu::Parser parser;
  parser.DefineVar("x", &x);
  parser.DefineVar("y", &y);
  parser.DefineVar("z", &z);
  try {
    parser.SetExpr(expression);
    parser.Eval();
  } catch (const mu::Parser::exception_type& e) {
    return e.GetMsg();
  }
  return "";
}

TEST(CreateWorld, BadExpressionExitsTwoWithTheLibrarysMessage) {
  std::string dir = test::makeTempDir();
  for (const char* bad : {"x +* y", "sin(x", "q", "2 x"}) {
    std::string message = muparserMessage(bad);
    ASSERT_FALSE(message.empty()) << bad;
    Result r = createWorld(std::string("--field-expr '0; ") + bad + "; 0' -o '" + dir + "/bad.w'");
    EXPECT_EQ(r.status, 2) << bad;
    EXPECT_NE(r.err.find("fy: " + message), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  Result two = createWorld("--field-expr 'x; y' -o '" + dir + "/bad.w'");
  EXPECT_EQ(two.status, 2);
  EXPECT_NE(two.err.find("three expressions"), std::string::npos) << two.err;
  Result infinite =
      createWorld("--field-resolution 3 --field-expr '1/x; 0; 0' -o '" + dir + "/bad.w'");
  EXPECT_EQ(infinite.status, 2);
  EXPECT_NE(infinite.err.find("not finite"), std::string::npos) << infinite.err;
  EXPECT_EQ(test::readText(dir + "/bad.w"), "") << "a refused world was written";
  test::removeTree(dir);
}

TEST(CreateWorld, NeverOverwritesWithoutForce) {
  std::string dir = test::makeTempDir();
  std::string path = dir + "/mine.w";
  test::writeText(path, "my own work\n");
  Result r = createWorld("--preset rotate -o '" + path + "'");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--force"), std::string::npos) << r.err;
  EXPECT_EQ(test::readText(path), "my own work\n");
  Result forced = createWorld("--preset rotate --force -o '" + path + "'");
  EXPECT_EQ(forced.status, 0) << forced.err;
  EXPECT_EQ(readWorldFile(path).world.kElastic, 500);
  test::removeTree(dir);
}

TEST(CreateWorld, RefusesWorldsTheReaderWouldReject) {
  std::string dir = test::makeTempDir();
  for (const char* bad : {"--dt 0", "--dt -1", "--mass 0", "--k-elastic -5", "--n 0",
                          "--plane 0 0 0 1", "--integrator RK5", "--field-resolution 100000",
                          "--field-resolution 1 --field-swirl 1", "--cube-size 0", "--velocity 1 2",
                          "--dt nan", "--center inf 0 0", "--preset cube", "--from /no/such.w"}) {
    Result r = createWorld(std::string(bad) + " -o '" + dir + "/bad.w'");
    EXPECT_EQ(r.status, 2) << bad;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << bad << ": " << r.err;
  }
  EXPECT_EQ(test::readText(dir + "/bad.w"), "");
  EXPECT_EQ(createWorld("--preset rotate").status, 2) << "no -o";
  test::removeTree(dir);
}

// Checked before any work: here a field expression that would be refused too, but later.
TEST(CreateWorld, AnOutputThatCannotBeWrittenIsRefusedFirst) {
  std::string dir = test::makeTempDir();
  test::writeText(dir + "/mine.w", "my own work\n");
  const std::string longName =
      dir + "/" + std::string(252, 'n') + ".w";  // 254 with its ".w": allowed
  const std::pair<std::string, std::string> cases[] = {
      {dir + "/" + std::string(254, 'n') + ".w",
       "the name is 256 bytes long, more than the 255 its folder's file system allows"},
      {dir + "/no/such/folder/w.w",
       "cannot write into " + dir + "/no/such/folder: No such file or directory"},
      {dir + "/mine.w/w.w", "cannot write into " + dir + "/mine.w: it is not a folder"},
      {dir, "is a directory"},
      {dir + "/mine.w", "already exists; add --force to replace it"},
  };
  for (const auto& [path, why] : cases) {
    Result r = createWorld("--field-expr 'x +* y; 0; 0' -o '" + path + "'");
    EXPECT_EQ(r.status, 2) << path;
    EXPECT_EQ(r.err, "createWorld: " + path + ": " + why + "\n");
  }
  Result r = createWorld("--field-expr 'x +* y; 0; 0' -o '" + longName + "'");
  EXPECT_NE(r.err.find("--field-expr: fx:"), std::string::npos)
      << "a 254-byte name was refused: " << r.err;
  EXPECT_EQ(test::readText(dir + "/mine.w"), "my own work\n");
  test::removeTree(dir);
}

// No line number of a text never written, no name of the file not written: the option to blame.
TEST(CreateWorld, AnInvalidWorldIsExplainedByTheOptionsThatMadeIt) {
  std::string dir = test::makeTempDir();
  const std::string out = " -o '" + dir + "/out.w'";
  const std::pair<std::string, std::string> cases[] = {
      {"--field-resolution 3 --field-swirl 1e308",
       "createWorld: --field-swirl: the force at field node (0,0,0) is (inf, -inf, 0) N, not "
       "finite\n"},
      {"--cube-size 1e10 --spin 0 0 1e308",
       "createWorld: --spin: the velocity of point [0][0][0] is (inf, -inf, 0) m/s, not finite\n"},
      {"--cube-size 1e308 --skew-corner 1e308 0 0",
       "createWorld: the world would be invalid: the position of point [7][7][7] is (inf, 1e+308, "
       "1e+308) m, not "
       "finite (from --cube-size, --skew-corner)\n"},
  };
  for (const auto& [options, message] : cases) {
    Result r = createWorld(options + out);
    EXPECT_EQ(r.status, 2) << options;
    EXPECT_EQ(r.err, message) << options;
  }
  EXPECT_NE(::access((dir + "/out.w").c_str(), F_OK), 0) << "an invalid world was written";
}

TEST(CreateWorld, RefusesAPlaneBeyondTheRangeOfDoublesAndWritesOneWithATinyNormal) {
  std::string dir = test::makeTempDir();
  Result far = createWorld("--plane 1e-300 0 0 1e10 -o '" + dir + "/far.w'");
  EXPECT_EQ(far.status, 2);
  EXPECT_EQ(far.err,
            "createWorld: --plane: the plane is too far from the origin to simulate: d is more "
            "than 1e308 times the "
            "largest of |a|, |b|, |c|, beyond the range of doubles\n");
  EXPECT_EQ(test::readText(dir + "/far.w"), "");
  Result tiny = createWorld("--plane 1e-300 0 0 -0.5e-300 -o '" + dir + "/tiny.w'");
  EXPECT_EQ(tiny.status, 0) << tiny.err;
  EXPECT_EQ(readWorldFile(dir + "/tiny.w").world.plane.a, 1e-300);
  test::removeTree(dir);
}

// createWorld judges dt as jello --check does, at rest and at the initial state: the course's
// jello.w starts squeezed, where EULER's limit is 0.000927 s (0.00125 s at rest), so EULER at
// 0.001 is unstable for both, and at 0.0002 stable for both.
TEST(CreateWorld, JudgesTheStepAsCheckDoesAtTheInitialStateToo) {
  std::string dir = test::makeTempDir();
  Result fast = createWorld("--preset jello --integrator EULER --dt 0.001 -o '" + dir + "/a.w'");
  EXPECT_EQ(fast.status, 0);
  EXPECT_NE(fast.err.find("dt=0.001 exceeds EULER's stable limit 0.000927 s"), std::string::npos)
      << fast.err;
  test::CommandResult check = test::runProgram({JELLO_BINARY, "--check", dir + "/a.w"});
  EXPECT_NE(
      check.out.find("with EULER: unstable (108% of the limit 0.000927 at the initial state)"),
      std::string::npos)
      << check.out;
  Result slow = createWorld("--preset jello --integrator EULER --dt 0.0002 -o '" + dir + "/b.w'");
  EXPECT_EQ(slow.err, "");
  test::removeTree(dir);
}

TEST(CreateWorld, WarnsWhenTheCubeStartsOutsideTheBoxOrAcrossThePlane) {
  std::string dir = test::makeTempDir();
  Result outside = createWorld("--center 1.8 0 0 -o '" + dir + "/a.w'");
  EXPECT_EQ(outside.status, 0);
  EXPECT_NE(outside.err.find("outside the box"), std::string::npos) << outside.err;
  Result across = createWorld("--plane 1 0 0 -0.3 -o '" + dir + "/b.w'");
  EXPECT_EQ(across.status, 0);
  EXPECT_NE(across.err.find("across the inclined plane"), std::string::npos) << across.err;
  Result fine = createWorld("--preset rotate -o '" + dir + "/c.w'");
  EXPECT_EQ(fine.err, "");
  test::removeTree(dir);
}

TEST(CreateWorld, GravityIsWrittenAsTheForceMassTimesGAndDescribedAsBoth) {
  std::string dir = test::makeTempDir();
  Result r = createWorld("--mass 0.002 --gravity 0 0 -9.8 -o '" + dir + "/g.w'");
  ASSERT_EQ(r.status, 0) << r.err;
  const World world = readWorldFile(dir + "/g.w").world;
  ASSERT_EQ(world.field.resolution, 30);
  for (std::size_t n = 0; n < world.field.forces.size() / 3; n += 997) {
    EXPECT_EQ(world.field.forces[3 * n], 0.0);
    EXPECT_EQ(world.field.forces[3 * n + 2], 0.002 * -9.8) << "node " << n;
  }
  Result described = createWorld("--describe '" + dir + "/g.w'");
  EXPECT_NE(described.out.find("F = (0, 0, -0.0196) N, a = F/m = (0, 0, -9.8) m/s^2"),
            std::string::npos)
      << described.out;
  // A student's g written as a force is shown for what it does: 5017.6 m/s^2 at 1/512 kg.
  Result force = createWorld("--describe '" + dataPath("gravity.w") + "'");
  EXPECT_NE(force.out.find("a = F/m = (0, 0, -30.722) m/s^2"), std::string::npos) << force.out;
  EXPECT_EQ(r.err, "") << "no warning for --gravity";
  Result mistaken = createWorld("--field-uniform 0 0 -9.8 -o '" + dir + "/m.w'");
  EXPECT_EQ(mistaken.status, 0);
  EXPECT_NE(mistaken.err.find("warning: --field-uniform is a force on each point, in N: it gives "
                              "each 5018 m/s^2 (512 g) at 0.001953125 kg; for an acceleration "
                              "such as gravity, use --gravity"),
            std::string::npos)
      << mistaken.err;
  EXPECT_EQ(createWorld("--field-uniform 0 0 -0.06 -o '" + dir + "/c.w'").err, "")
      << "the course's gravity.w force, 31 m/s^2, is not taken for a mistake";
  Result both = createWorld("--gravity 0 0 -9.8 --field-uniform 0 0 1 -o '" + dir + "/b.w'");
  EXPECT_EQ(both.status, 2);
  EXPECT_NE(both.err.find("--gravity"), std::string::npos) << both.err;
  test::removeTree(dir);
}

// A scene file given where createWorld reads a course world is refused by name, in one line.
TEST(Describe, ASceneFileIsRefusedByName) {
  const std::string scene = std::string(JELLO_SOURCE_DIR) + "/scenes/hanging.toml";
  const std::string dir = test::makeTempDir();
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{JELLO_CREATE_WORLD, "--describe", scene},
        std::vector<std::string>{JELLO_CREATE_WORLD, "--from", scene, "-o", dir + "/x.w"}}) {
    const test::CommandResult r = test::runProgram(args);
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "createWorld: " + scene +
                         ": a scene file; createWorld reads and writes course worlds (.w), and "
                         "jello runs scenes (docs/scenes.md)\n");
  }
  EXPECT_NE(::access((dir + "/x.w").c_str(), F_OK), 0) << "nothing written";
  test::removeTree(dir);
}

TEST(Describe, RecognisesTheCourseFields) {
  const std::pair<const char*, const char*> expected[] = {
      {"rotate.w", "swirl about z, F = 0.0097"},
      {"gravity.w", "uniform F = (0, 0, -0.06) N"},
      {"jello.w", "R = 30, zero"},
      {"moveLeft.w", "left out    plane (none in the file)"},
      {"jello.w", "-x + y + z + 2 = 0; the cube starts on its positive side"}};
  for (auto [world, phrase] : expected) {
    Result r = createWorld(std::string("--describe '") + dataPath(world) + "'");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find(phrase), std::string::npos) << world << ":\n" << r.out;
  }
  EXPECT_NEAR(classifyField(readWorldFile(dataPath("rotate.w")).world.field).strength, 5.0 / 512,
              1e-6);
  FieldRecipe radial;
  radial.source = FieldRecipe::Source::Radial;
  radial.strength = -0.3;
  radial.resolution = 7;
  EXPECT_EQ(classifyField(buildField(radial)).kind, FieldKind::Radial);
  radial.source = FieldRecipe::Source::Expression;
  radial.expression = "x*y; 0; 0";
  EXPECT_EQ(classifyField(buildField(radial)).kind, FieldKind::General);
}

// The commands in world/README.md and world/stress/README.md make their worlds exactly.
TEST(ShowcaseWorlds, AreMadeByTheCommandsInTheirReadmes) {
  std::string dir = test::makeTempDir();
  int made = 0;
  for (const char* folder : {"world/", "world/stress/"}) {
    std::ifstream readme(std::string(JELLO_SOURCE_DIR) + "/" + folder + "README.md");
    ASSERT_TRUE(readme) << folder << "README.md";
    for (std::string line; std::getline(readme, line);) {
      const std::string prefix = "    ./createWorld ";
      if (line.rfind(prefix, 0) != 0) continue;
      std::size_t out = line.rfind(" -o " + std::string(folder));
      ASSERT_NE(out, std::string::npos) << line;
      std::string name = line.substr(out + 4 + std::string(folder).size());
      Result r = createWorld(line.substr(prefix.size(), out - prefix.size()) + " -o '" + dir + "/" +
                             name + "'");
      ASSERT_EQ(r.status, 0) << line << "\n" << r.err;
      EXPECT_EQ(test::readText(dir + "/" + name),
                test::readText(std::string(JELLO_SOURCE_DIR) + "/" + folder + name))
          << folder << name << " is not what its command makes";
      ++made;
    }
  }
  EXPECT_GE(made, 13);
  test::removeTree(dir);
}

// Each showcase world runs; each stress world runs to the end with finite results or stops
// with status 1 and the message, within seconds.
TEST(ShowcaseWorlds, RunOrStopCleanly) {
  std::string dir = test::makeTempDir();
  for (const char* folder : {"world/", "world/stress/"}) {
    // The folder's worlds, in name order, read without a shell.
    std::vector<std::string> worlds;
    for (const auto& entry :
         std::filesystem::directory_iterator(std::string(JELLO_SOURCE_DIR) + "/" + folder))
      if (entry.path().extension() == ".w") worlds.push_back(entry.path().filename().string());
    std::sort(worlds.begin(), worlds.end());
    ASSERT_GE(worlds.size(), 5u) << folder;
    for (const std::string& name : worlds) {
      std::string path = std::string(JELLO_SOURCE_DIR) + "/" + folder + name,
                  dump = dir + "/" + name;
      test::CommandResult run =
          test::runJelloArgs({"--headless", "--time", "0.05", "--dump", dump, path});
      EXPECT_TRUE(run.status == 0 || run.status == 1)
          << name << ": " << run.status << " " << run.err;
      EXPECT_EQ(run.out.find("nan"), std::string::npos) << name;
      if (run.status == 0) {
        EXPECT_NO_THROW(readWorldFile(dump)) << name << ": the dump must be a finite world";
      } else {
        EXPECT_EQ(std::string(folder), "world/stress/") << name << " is a showcase: it must run";
        EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
        EXPECT_NE(run.err.find("diverged at step"), std::string::npos) << run.err;
        EXPECT_NE(run.err.find("try --dt"), std::string::npos) << run.err;
      }
    }
  }
  test::removeTree(dir);
}

}  // namespace
}  // namespace jello
