// Several jellies in one scene ([[jelly]], io/jellyreader.h) and state files (io/statefile.h):
// each jelly's own mass, springs and modes, the starts refused, saved states continued bit for bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "analysis/modes.h"
#include "io/inputerror.h"
#include "io/scenereader.h"
#include "io/statefile.h"
#include "jellyscenes.h"
#include "solver/physics.h"
#include "solver/simulation.h"
#include "test_support.h"

namespace jello {
namespace {

using test::kHeadOn;

std::string refusal(const std::string& text) {
  try {
    test::scene(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

// --check's modes at rest: two jellies apart are each jelly's modes; the fastest is the lighter's.
TEST(SceneJellies, TheModesAtRestAreEachJellysOwn) {
  const std::string one =
      "[jelly]\nshape = \"lattice\"\nsize = [4, 4, 4]\nspacing = 0.1\nstiffness = 500\n";
  const double alone = lineariseAtRest(test::scene(one).world).highestFrequency;
  std::string two = kHeadOn;
  const double both = lineariseAtRest(test::scene(two).world).highestFrequency;
  EXPECT_GT(alone, 100);
  EXPECT_NEAR(both, alone, 1e-9 * alone);
  two.replace(two.rfind("stiffness = 500"), 15, "stiffness = 500\nmass = 0.00048828125");
  // Four times lighter points: twice as fast (omega^2 = k / m).
  EXPECT_NEAR(lineariseAtRest(test::scene(two).world).highestFrequency, 2 * alone, 1e-6 * alone);
}

TEST(StateFiles, ARunSavedAndContinuedIsTheRunThatWentOnBitForBit) {
  const WorldFile file = test::scene(kHeadOn);
  const Model model = makeModel(file.world, file.state);
  Simulation whole(model, file.state, Integrator::RK4, 0.0002);
  ASSERT_TRUE(whole.advance(600).ran());
  Simulation first(model, file.state, Integrator::RK4, 0.0002);
  ASSERT_TRUE(first.advance(300).ran());
  const std::string text = formatState(model.body(), first.state());
  EXPECT_EQ(text.substr(0, text.find('\n')), "body,index,x,y,z,vx,vy,vz");
  const State saved = parseState(text, "saved.csv", model.body());
  EXPECT_EQ(saved.y, first.state().y);
  Simulation second(model, saved, Integrator::RK4, 0.0002);
  ASSERT_TRUE(second.advance(300).ran());
  EXPECT_EQ(second.state().y, whole.state().y);
}

// From the command line: --save-state, then a scene that starts from the file, runs on as the
// one run did, byte for byte in the saved file.
TEST(StateFiles, SavedByTheCommandLineAndContinuedByAScene) {
  const std::string dir = test::makeTempDir();
  test::writeText(dir + "/two.toml", kHeadOn);
  test::writeText(dir + "/more.toml", std::string("state = \"half.csv\"\n") + kHeadOn);
  const auto run = [&](const std::string& scene, const char* steps, const std::string& out) {
    return test::runJelloArgs(
        {"--headless", "--steps", steps, "--save-state", dir + "/" + out, dir + "/" + scene});
  };
  ASSERT_EQ(run("two.toml", "400", "whole.csv").status, 0);
  ASSERT_EQ(run("two.toml", "200", "half.csv").status, 0);
  ASSERT_EQ(run("more.toml", "200", "end.csv").status, 0);
  const std::string whole = test::readText(dir + "/whole.csv");
  EXPECT_EQ(test::readText(dir + "/end.csv"), whole);
  EXPECT_EQ(std::count(whole.begin(), whole.end(), '\n'), 129);  // the header and 128 points
  // Empty lines after the last point (an editor's) are read as the file without them.
  test::writeText(dir + "/half.csv", test::readText(dir + "/half.csv") + "\n\r\n");
  ASSERT_EQ(run("more.toml", "200", "again.csv").status, 0);
  EXPECT_EQ(test::readText(dir + "/again.csv"), whole);
  // The state a scene starts from is one of the files it reads: --save-state never replaces it.
  const std::string started = test::readText(dir + "/half.csv");
  const test::CommandResult onInput = run("more.toml", "10", "half.csv");
  EXPECT_EQ(onInput.status, 2);
  EXPECT_NE(onInput.err.find("--save-state " + dir + "/half.csv: is read by the scene being run (" +
                             dir + "/half.csv); it is never replaced, name another file"),
            std::string::npos)
      << onInput.err;
  EXPECT_EQ(test::readText(dir + "/half.csv"), started);
  // A state of another body is refused with its line and field, exit status 2.
  test::writeText(dir + "/other.toml",
                  "state = \"half.csv\"\n[jelly]\nshape = \"lattice\"\n"
                  "size = [3, 3, 3]\n");
  const test::CommandResult other = test::runJelloArgs({"--headless", dir + "/other.toml"});
  EXPECT_EQ(other.status, 2);
  EXPECT_NE(other.err.find("other.toml:1: " + dir +
                           "/half.csv:29: more points than the scene's "
                           "body has (27) (body) (state)"),
            std::string::npos)
      << other.err;
  // A point beyond 100 m, where a run would stop at once as diverged, is refused as it is read.
  std::string far = whole;
  const std::size_t row = far.find('\n') + 1, x = far.find(',', far.find(',', row) + 1) + 1;
  far.replace(x, far.find(',', x) - x, "-150");
  test::writeText(dir + "/half.csv", far);
  const test::CommandResult beyond = test::runJelloArgs({"--headless", dir + "/more.toml"});
  EXPECT_EQ(beyond.status, 2);
  EXPECT_NE(beyond.err.find("/half.csv:2: is more than 100 m from the origin, where a run stops as "
                            "diverged (x) (state)"),
            std::string::npos)
      << beyond.err;
  test::removeTree(dir);
}

// --dump writes a course world, which holds one cube: several jellies are refused, pointing to
// --save-state.
TEST(StateFiles, DumpRefusesSeveralJelliesAndNamesSaveState) {
  const std::string dir = test::makeTempDir();
  test::writeText(dir + "/two.toml", kHeadOn);
  const test::CommandResult r = test::runJelloArgs(
      {"--headless", "--steps", "1", "--dump", dir + "/out.w", dir + "/two.toml"});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("this scene has 2 jellies; use --save-state for every point"),
            std::string::npos)
      << r.err;
  test::removeTree(dir);
}

// Overlapping jellies from the command line: one line, exit status 2, nothing run.
TEST(SceneJellies, OverlappingJelliesAreRefusedByJelloWithExitStatusTwo) {
  const std::string dir = test::makeTempDir();
  std::string text = kHeadOn;
  text.replace(text.find("offset = [0.2"), 13, "offset = [0.1");
  test::writeText(dir + "/overlap.toml", text);
  const test::CommandResult r = test::runJelloArgs({"--headless", dir + "/overlap.toml"});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("overlap.toml:16: jelly 2 starts overlapping jelly 1"), std::string::npos);
  EXPECT_EQ(r.out, "");
  test::removeTree(dir);
}

TEST(StateFiles, AMalformedStateIsRefusedWithItsLineAndField) {
  const WorldFile file = test::scene(kHeadOn);
  const Body& body = *file.world.scene->body;
  std::string text = formatState(body, file.state);
  auto refused = [&](const std::string& bad) {
    try {
      parseState(bad, "s.csv", body);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(refused("x,y\n"), "s.csv:1: expected the header body,index,x,y,z,vx,vy,vz (header)");
  std::string swapped = text;
  swapped.replace(swapped.find("\n1,1,") + 1, 3, "2,1");
  EXPECT_EQ(refused(swapped), "s.csv:3: expected jelly 1 here (body)");
  std::string word = text;
  word.replace(word.find("\n1,0,") + 5, 1, "z");
  EXPECT_NE(refused(word).find("s.csv:2: 'z"), std::string::npos) << refused(word);
  std::size_t tenth = 0;
  for (int line = 0; line < 11; ++line) tenth = text.find('\n', tenth) + 1;
  EXPECT_EQ(refused(text.substr(0, tenth)),
            "s.csv:11: ends after 10 points; the scene's body has 128 (body)");
  EXPECT_NE(refused(text + "1,0,0,0,0,0,0,0\n").find("more points than"), std::string::npos);
}

TEST(SceneJellies, BadStartsAreRefusedWithTheirLineAndKey) {
  std::string overlapping = kHeadOn;
  overlapping.replace(overlapping.find("offset = [0.2"), 13, "offset = [0.05");
  EXPECT_EQ(refusal(overlapping).substr(0, 58),
            "test.toml:16: jelly 2 starts overlapping jelly 1: points [");
  EXPECT_NE(refusal(overlapping).find("(jelly[2].offset)"), std::string::npos);
  std::string outside = kHeadOn;
  outside.replace(outside.find("[bounds]\npresent = false\n"), 25, "");
  outside.replace(outside.find("offset = [0.2"), 13, "offset = [2.2");
  EXPECT_EQ(refusal(outside).substr(0, 68),
            "test.toml:14: jelly 2 starts outside the bounding box (its point [0]");
  std::string inside = R"(
[bounds]
present = false
[[jelly]]
shape = "lattice"
size = [10, 10, 10]
spacing = 0.1
[[jelly]]
shape = "lattice"
size = [2, 2, 2]
spacing = 0.1
)";
  EXPECT_EQ(refusal(inside), "test.toml:8: jelly 2 starts inside jelly 1 (jelly[2].offset)");
  std::string many = "[bounds]\npresent = false\n";
  for (int i = 0; i < 10; ++i)
    many += "[[jelly]]\nshape = \"lattice\"\nsize = [48, 48, 48]\nspacing = 0.01\noffset = [" +
            std::to_string(i) + ", 0, 0]\n";
  EXPECT_NE(refusal(many).find("more than 1048576 points in all (jelly)"), std::string::npos)
      << refusal(many);
  EXPECT_NE(
      refusal("[jelly]\nshape = \"lattice\"\nsize = [1, 1, 5]\n").find("at most one side may be 1"),
      std::string::npos);
  EXPECT_NE(refusal("[contact]\ndistance = 0.1\n").find("belongs to contact between bodies"),
            std::string::npos);
}

TEST(SceneJellies, EachJellyKeepsItsOwnMassAndSprings) {
  std::string text = kHeadOn;
  text.replace(text.rfind("stiffness = 500"), 15, "stiffness = 900\nmass = 0.01");
  const WorldFile file = test::scene(text);
  const Model model = makeModel(file.world, file.state);
  EXPECT_EQ(model.pointMass.front(), 1.0 / kNumPoints);
  EXPECT_EQ(model.pointMass.back(), 0.01);
  EXPECT_EQ(model.forces.springs->constants(0).k[0], 500);
  EXPECT_EQ(model.forces.springs->constants(1).k[2], 900);
  EXPECT_EQ(model.body().label(64), "[0][0][0] of jelly 2");
}

}  // namespace
}  // namespace jello
