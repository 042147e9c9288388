// Reader and writer of world files (docs/world-format.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <functional>
#include <iterator>
#include <random>

#include "io/input.h"
#include "model/vec3.h"
#include "model/world.h"
#include "test_support.h"

namespace jello {
namespace {

using test::dataPath;

bool bitIdentical(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

void expectSameWorld(const WorldFile& a, const WorldFile& b) {
  const World &x = a.world, &y = b.world;
  EXPECT_EQ(a.run.integrator, b.run.integrator);
  EXPECT_TRUE(bitIdentical({a.run.dt, x.kElastic, x.dElastic, x.kCollision, x.dCollision, x.mass,
                            x.plane.a, x.plane.b, x.plane.c, x.plane.d},
                           {b.run.dt, y.kElastic, y.dElastic, y.kCollision, y.dCollision, y.mass,
                            y.plane.a, y.plane.b, y.plane.c, y.plane.d}));
  EXPECT_EQ(a.run.n, b.run.n);
  EXPECT_EQ(x.hasPlane, y.hasPlane);
  EXPECT_EQ(x.field.resolution, y.field.resolution);
  EXPECT_TRUE(bitIdentical(x.field.forces, y.field.forces));
  EXPECT_TRUE(bitIdentical(a.state.y, b.state.y));
}

struct CourseWorld {
  const char* file;
  double dt, kElastic, dElastic, kCollision, dCollision;
  bool hasPlane;
  Plane plane;
  Vec3 fieldAtNode0, p777, velocity0;
};

// The values of ../shared/reference-worlds/README.md, as written (six decimals).
const CourseWorld kCourseWorlds[] = {
    {"jello.w",
     0.0005,
     200,
     0.25,
     400,
     0.25,
     true,
     {-1, 1, 1, 2},
     {0, 0, 0},
     {1.142857, 1.142857, 1.142857},
     {10, -10, 20}},
    {"rotate.w",
     0.001,
     500,
     0.25,
     1000,
     0.25,
     true,
     {1, -1, -1, 4},
     {0.019531, -0.019531, 0},
     {1, 1, 1},
     {0, 0, 0}},
    {"moveLeft.w", 0.0005, 500, 0.25, 1000, 0.25, false, {}, {0, 0, 0}, {1, 1, 1}, {-50, 0, 0}},
    {"skewedCorner.w",
     0.00001,
     500,
     0.25,
     1000,
     0.25,
     false,
     {},
     {0, 0, 0},
     {1.142857, 1.142857, 1.142857},
     {0, 0, 0}},
    {"gravity.w",
     0.0001,
     500,
     0.25,
     1000,
     0.25,
     true,
     {-1, 1, 2, 6},
     {0, 0, -0.06},
     {1, 1, 1},
     {10, -10, 0}},
};

TEST(WorldReader, CourseWorldsLoadWithTheirExactValues) {
  for (const CourseWorld& c : kCourseWorlds) {
    SCOPED_TRACE(c.file);
    WorldFile f = readWorldFile(dataPath(c.file));
    const World& w = f.world;
    EXPECT_EQ(f.run.integrator, Integrator::RK4);
    EXPECT_EQ(f.run.dt, c.dt);
    EXPECT_EQ(f.run.n, 1);
    EXPECT_EQ(w.kElastic, c.kElastic);
    EXPECT_EQ(w.dElastic, c.dElastic);
    EXPECT_EQ(w.kCollision, c.kCollision);
    EXPECT_EQ(w.dCollision, c.dCollision);
    EXPECT_EQ(w.mass, 0.001953);
    EXPECT_EQ(w.hasPlane, c.hasPlane);
    if (c.hasPlane) {
      EXPECT_EQ(w.plane.a, c.plane.a);
      EXPECT_EQ(w.plane.b, c.plane.b);
      EXPECT_EQ(w.plane.c, c.plane.c);
      EXPECT_EQ(w.plane.d, c.plane.d);
    }
    ASSERT_EQ(w.field.resolution, 30);
    ASSERT_EQ(w.field.forces.size(), 3u * 30 * 30 * 30);
    EXPECT_EQ(w.field.forces[0], c.fieldAtNode0.x);
    EXPECT_EQ(w.field.forces[1], c.fieldAtNode0.y);
    EXPECT_EQ(w.field.forces[2], c.fieldAtNode0.z);
    Vec3 p0 = load(f.state.p(), pointIndex(0, 0, 0));
    EXPECT_EQ(p0.x, 0);
    EXPECT_EQ(p0.y, 0);
    EXPECT_EQ(p0.z, 0);
    EXPECT_EQ(load(f.state.p(), pointIndex(0, 0, 1)).z, 0.142857);
    Vec3 p777 = load(f.state.p(), pointIndex(7, 7, 7));
    EXPECT_EQ(p777.x, c.p777.x);
    EXPECT_EQ(p777.y, c.p777.y);
    EXPECT_EQ(p777.z, c.p777.z);
    for (int q = 0; q < kNumPoints; ++q) {
      Vec3 v = load(f.state.v(), q);
      ASSERT_EQ(v.x, c.velocity0.x);
      ASSERT_EQ(v.y, c.velocity0.y);
      ASSERT_EQ(v.z, c.velocity0.z);
    }
  }
}

TEST(WorldReader, SwirlFieldOfRotateIsStoredAtIRRPlusJRPlusK) {
  // rotate.w: F = (5/512)(-y, x, 0), rounded to six decimals, at node (i,j,k).
  WorldFile f = readWorldFile(dataPath("rotate.w"));
  const int r = 30;
  for (int i : {0, 7, 29})
    for (int j : {0, 13, 29})
      for (int k : {0, 5, 29}) {
        double x = -2 + 4.0 * i / (r - 1), y = -2 + 4.0 * j / (r - 1);
        const double* node = &f.world.field.forces[3 * (i * r * r + j * r + k)];
        EXPECT_NEAR(node[0], -5.0 / 512 * y, 1e-6);
        EXPECT_NEAR(node[1], 5.0 / 512 * x, 1e-6);
        EXPECT_EQ(node[2], 0);
      }
}

TEST(WorldReader, CrlfFilesReadTheSame) {
  std::string text = test::readText(dataPath("gravity.w"));
  std::string crlf;
  for (char c : text) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  expectSameWorld(parseWorld(text, "lf"), parseWorld(crlf, "crlf"));
}

// The message a reader of `text` (as a string and as a file) gives, or "" when it is accepted.
std::string readerMessage(const std::string& text, const std::string& path) {
  test::writeText(path, text);
  std::string fromMemory, fromFile;
  try {
    parseWorld(text, path);
  } catch (const InputError& e) {
    fromMemory = e.what();
  }
  try {
    readWorldFile(path);
  } catch (const InputError& e) {
    fromFile = e.what();
  }
  EXPECT_EQ(fromMemory, fromFile);
  return fromFile;
}

TEST(WorldReader, AUtf8ByteOrderMarkIsSkippedAsWindowsEditorsWriteIt) {
  std::string dir = test::makeTempDir();
  std::string text = test::readText(dataPath("gravity.w"));
  EXPECT_EQ(readerMessage("\xEF\xBB\xBF" + text, dir + "/bom.w"), "");
  expectSameWorld(parseWorld(text, "plain"), readWorldFile(dir + "/bom.w"));
  // Only at the start of the file: elsewhere its bytes are not text.
  std::string inside = text.substr(0, 4) + "\xEF\xBB\xBF" + text.substr(4);
  EXPECT_EQ(readerMessage(inside, dir + "/inside.w"),
            dir + "/inside.w:2: byte 0xef in column 1: not a text file, not a world file (dt n)");
  test::removeTree(dir);
}

TEST(WorldReader, ACrOnlyFileIsToldToConvertItsLineEnds) {
  std::string dir = test::makeTempDir();
  const std::string expected =
      ":1: lines end with CR only (classic Mac OS line ends): convert the file to LF or CRLF "
      "line ends (integrator)";
  for (const char* world : {"gravity.w", "still.w"}) {
    std::string cr = test::readText(dataPath(world));
    std::replace(cr.begin(), cr.end(), '\n', '\r');
    EXPECT_EQ(readerMessage(cr, dir + "/cr.w"), dir + "/cr.w" + expected) << world;
  }
  // A short CR-only file is not one long line, but the same mistake.
  EXPECT_EQ(readerMessage("RK4\r0.001 1\r", dir + "/short.w"), dir + "/short.w" + expected);
  // CRLF, and a CR before the LF of a line with trailing blanks, are fine.
  EXPECT_EQ(readerMessage("RK4 \r \r\n", dir + "/crlf.w"),
            dir + "/crlf.w:2: file ends early, expected 2 numbers (dt n)");
  test::removeTree(dir);
}

TEST(WorldReader, IntegratorNamesAreCaseInsensitive) {
  std::string text = test::readText(dataPath("moveLeft.w"));
  const std::pair<const char*, Integrator> names[] = {
      {"euler", Integrator::Euler},       {"Rk4", Integrator::RK4},
      {"midpoint", Integrator::Midpoint}, {"Symplectic", Integrator::Symplectic},
      {"VERLET", Integrator::Verlet},     {"rk45", Integrator::RK45},
      {"implicit", Integrator::Implicit}};
  for (auto [name, integrator] : names) {
    std::string renamed = name + text.substr(text.find('\n'));
    EXPECT_EQ(parseWorld(renamed, "w").run.integrator, integrator) << name;
  }
}

TEST(WorldWriter, CourseWorldsRoundTripBitIdentically) {
  for (const CourseWorld& c : kCourseWorlds) {
    SCOPED_TRACE(c.file);
    WorldFile original = readWorldFile(dataPath(c.file));
    std::string written = formatWorld(original);
    WorldFile back = parseWorld(written, "written");
    expectSameWorld(original, back);
    EXPECT_EQ(formatWorld(back), written);
  }
}

TEST(WorldWriter, ArbitraryDoublesRoundTripBitIdentically) {
  std::mt19937_64 random(42);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::uniform_int_distribution<int> exponent(-300, 300);
  auto any = [&] { return std::ldexp(unit(random), exponent(random)); };
  auto positive = [&] { return std::fabs(any()) + 1e-300; };
  World w;
  const RunSettings run{Integrator::Verlet, positive(), 7};
  w.kElastic = positive();
  w.dElastic = 0;
  w.kCollision = positive();
  w.dCollision = positive();
  w.mass = positive();
  w.hasPlane = true;
  w.plane = {any(), any(), 1.0 / 3, -0.0};
  w.field.resolution = 3;
  for (int i = 0; i < 3 * 27; ++i) w.field.forces.push_back(any());
  State s;
  for (double& value : s.y) value = unit(random) * 3;
  s.y[5] = 5e-324;  // the smallest subnormal
  std::string text = formatWorld(w, run, s);
  WorldFile back = parseWorld(text, "random");
  expectSameWorld({w, run, s, {}}, back);
  EXPECT_TRUE(std::signbit(back.world.plane.d));
}

TEST(WorldWriter, WriteWorldFileWritesWholeFilesAndNothingElse) {
  std::string dir = test::makeTempDir();
  WorldFile f = readWorldFile(dataPath("jello.w"));
  std::string path = dir + "/out.w";
  writeWorldFile(path, f.world, f.run, f.state);
  expectSameWorld(f, readWorldFile(path));
  const auto entries = std::distance(std::filesystem::directory_iterator(dir),
                                     std::filesystem::directory_iterator());
  EXPECT_EQ(entries, 1) << "temporary file left behind";
  EXPECT_THROW(writeWorldFile(dir + "/no/such/dir/out.w", f.world, f.run, f.state),
               std::runtime_error);
  test::removeTree(dir);
}

// findWorldProblem (createWorld's judge) and the reader agree: each value the reader refuses in
// a file is the problem named, with its part and point or node.
TEST(WorldProblems, AreWhatTheReaderRefusesNamedByPartAndPlace) {
  using Part = WorldProblem::Part;
  const WorldFile good = readWorldFile(dataPath("rotate.w"));
  EXPECT_FALSE(findWorldProblem(good));
  struct Case {
    std::function<void(WorldFile&)> spoil;
    Part part;
    std::size_t index;
    std::string what;
  };
  const Case cases[] = {
      {[](WorldFile& f) { f.world.mass = 0; }, Part::Parameters, 0,
       "mass must be > 0 and finite, got 0"},
      {[](WorldFile& f) { f.run.dt = -1e-9; }, Part::Parameters, 0,
       "dt must be > 0 and finite, got -1e-09"},
      {[](WorldFile& f) { f.world.kCollision = INFINITY; }, Part::Parameters, 0,
       "kCollision must be >= 0 and finite, got inf"},
      {[](WorldFile& f) {
         f.world.plane = {0, 0, 0, 1};
       },
       Part::Plane, 0, "the plane's normal (a,b,c) is zero"},
      {[](WorldFile& f) { f.world.field.forces[3 * 931 + 2] = NAN; }, Part::Field, 931,
       "the force at field node (1,1,1) is (0.018184, -0.018184, nan) N, not finite"},
      {[](WorldFile& f) { f.state.p()[coordIndex(pointIndex(7, 7, 7), 0)] = INFINITY; },
       Part::Position, 511, "the position of point [7][7][7] is (inf, 1, 1) m, not finite"},
      {[](WorldFile& f) { f.state.v()[coordIndex(pointIndex(0, 1, 2), 1)] = -INFINITY; },
       Part::Velocity, 10, "the velocity of point [0][1][2] is (0, -inf, 0) m/s, not finite"},
  };
  for (const Case& c : cases) {
    WorldFile f = good;
    c.spoil(f);
    std::optional<WorldProblem> problem = findWorldProblem(f);
    ASSERT_TRUE(problem) << c.what;
    EXPECT_EQ(problem->part, c.part) << c.what;
    EXPECT_EQ(problem->index, c.index) << c.what;
    EXPECT_EQ(problem->what, c.what);
    EXPECT_THROW(parseWorld(formatWorld(f), "spoilt.w"), InputError) << c.what;
  }
}

TEST(WorldWriter, WritesInBlocksOfAtMost64KilobytesTheSameBytesAsOneString) {
  const WorldFile f = readWorldFile(dataPath("gravity.w"));
  std::string joined;
  std::size_t blocks = 0, largest = 0;
  formatWorldInBlocks(f.world, f.run, f.state, [&](std::string_view block) {
    ++blocks;
    largest = std::max(largest, block.size());
    joined += block;
  });
  const std::string text = formatWorld(f);
  EXPECT_EQ(joined, text);
  EXPECT_GE(blocks, text.size() / (65536 + 100));  // 5 for its 310 KB
  EXPECT_LE(largest, 65536u + 100) << "a block is the whole text, not a part of it";
  std::string dir = test::makeTempDir();
  writeWorldFile(dir + "/out.w", f.world, f.run, f.state);
  EXPECT_EQ(test::readText(dir + "/out.w"), text);
  test::removeTree(dir);
}

class MalformedWorld : public ::testing::TestWithParam<test::MalformedCase> {};

TEST_P(MalformedWorld, IsRejectedNamingFileLineAndField) {
  const test::MalformedCase& c = GetParam();
  try {
    parseWorld(c.text, "bad.w");
    FAIL() << "accepted";
  } catch (const InputError& e) {
    std::string message = e.what();
    std::string prefix = "bad.w:" + std::to_string(c.line) + ": ";
    EXPECT_EQ(message.rfind(prefix, 0), 0u) << message;
    EXPECT_NE(message.find("(" + c.field), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_LT(message.size(), 300u) << message;
  }
}

INSTANTIATE_TEST_SUITE_P(Cases, MalformedWorld, ::testing::ValuesIn(test::malformedCases()),
                         [](const auto& testInfo) { return testInfo.param.name; });

TEST(WorldReader, UnreadablePathsGiveOneLineErrors) {
  EXPECT_THROW(readWorldFile("/no/such/file.w"), InputError);
  try {
    readWorldFile(JELLO_TEST_DATA);
    FAIL() << "a directory was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("directory"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace jello
