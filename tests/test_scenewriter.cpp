// test_scenewriter.cpp: a setup written back as a scene (io/scenewriter.h, the window's "save as")
// reads back as the same world and state: the saved scene's run is bit for bit the run it saved,
// for every shipped scene and course world.

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "core/output.h"
#include "io/input.h"
#include "io/scenereader.h"
#include "io/scenewriter.h"
#include "model/model.h"
#include "model/scenespec.h"
#include "solver/simulation.h"
#include "test_support.h"

namespace jello {
namespace {

WorldFile readAny(const std::string& path) {
  return isSceneFile(path) ? readSceneFile(path) : readWorldFile(path);
}

// `path` run `before` steps, saved, read back; then both run `after` more steps: the same bits.
void expectSavedSceneRunsOnAlike(const std::string& path, int before, int after) {
  SCOPED_TRACE(path);
  const WorldFile file = readAny(path);
  const Model model = makeModel(file.world, file.state);
  Simulation run(model, file.state, file.run);
  ASSERT_TRUE(run.advance(before).ran());
  const std::string saved = test::makeTempDir() + "/saved.toml";
  writeScene(saved, file.world, file.run, run.state(), false);
  const WorldFile back = readSceneFile(saved);
  EXPECT_EQ(back.state.y, run.state().y);
  EXPECT_EQ(back.run.dt, file.run.dt);
  EXPECT_EQ(back.run.n, file.run.n);
  EXPECT_EQ(back.run.integrator, file.run.integrator);
  const Model again = makeModel(back.world, back.state);
  EXPECT_EQ(again.pinned, model.pinned);
  EXPECT_EQ(again.pointMass, model.pointMass);
  // The same terms (a course world read back through a scene words what it leaves out otherwise).
  EXPECT_EQ(summarise(again.forces).kept, summarise(model.forces).kept);
  Simulation rerun(again, back.state, back.run);
  ASSERT_TRUE(run.advance(after).ran());
  ASSERT_TRUE(rerun.advance(after).ran());
  EXPECT_EQ(rerun.state().y, run.state().y) << "the saved scene's run left the session's";
}

TEST(SavedScene, EveryShippedSceneAndCourseWorldRunsOnBitForBitFromItsSave) {
  const std::string source = JELLO_SOURCE_DIR;
  // (cantilever.toml aside: IMPLICIT on a stiff beam, seconds a step; its pins and elements are
  // wobble's, mould-elements' and the scene below's.)
  for (const char* scene :
       {"bar", "cloth-on-ball", "fold", "hanging", "head-on", "jelly-mould", "mould-elements",
        "rotate-on-ball", "slope-friction", "slope-slides", "sphere-drop", "stack", "wobble"})
    expectSavedSceneRunsOnAlike(source + "/scenes/" + scene + ".toml", 7, 13);
  for (const char* world : {"jello", "rotate", "skewedCorner", "gravity"})
    expectSavedSceneRunsOnAlike(source + "/world/" + world + ".w", 7, 13);
}

TEST(SavedScene, ASceneBuiltInMemoryIsWrittenWithEveryKeyItNeeds) {
  // Obstacles of each kind with their own contact and friction, a plane whose normal is not a
  // unit vector, a box of its own, gravity, pins on the grid and springs by kind: all of it must
  // come back.
  const std::string dir = test::makeTempDir();
  test::writeText(dir + "/in.toml", R"(dt = 0.0003
integrator = "MIDPOINT"
n = 3
gravity = [0.1, -0.2, -9.81]
[jelly]
shape = "lattice"
size = [5, 4, 3]
spacing = 0.2
stiffness = { structural = 300, shear = 120 }
damping = { bend = 0.5 }
offset = [0.1, 0, 0.3]
[bounds]
lower = [-1.5, -2, -1]
upper = [2, 2, 2.5]
friction_static = 0.4
[[sphere]]
centre = [0, 0, -0.9]
radius = 0.3
stiffness = 4000
friction_static = 0.7
friction_dynamic = 0.5
friction_speed = 0.02
[[box]]
lower = [0.5, -1, -1]
upper = [1, 1, -0.6]
damping = 3
[[plane]]
point = [0, 0, -0.95]
normal = [0, 0.2, 1]
[[pin]]
i = [0, 1]
j = [1, 2]
k = [2, 2]
[[pin]]
i = [4, 4]
)");
  expectSavedSceneRunsOnAlike(dir + "/in.toml", 5, 20);
  const WorldFile back = [&] {
    writeScene(dir + "/out.toml", readSceneFile(dir + "/in.toml").world,
               readSceneFile(dir + "/in.toml").run, readSceneFile(dir + "/in.toml").state, false);
    return readSceneFile(dir + "/out.toml");
  }();
  const WorldFile in = readSceneFile(dir + "/in.toml");
  const SceneSpec& a = *in.world.scene;
  const SceneSpec& b = *back.world.scene;
  ASSERT_EQ(a.obstacles.size(), b.obstacles.size());
  for (std::size_t i = 0; i < a.obstacles.size(); ++i) {
    EXPECT_EQ(a.obstacles[i].normal.y, b.obstacles[i].normal.y);
    EXPECT_EQ(a.obstacles[i].normal.z, b.obstacles[i].normal.z);
    EXPECT_EQ(a.obstacles[i].spring.k, b.obstacles[i].spring.k);
    EXPECT_EQ(a.obstacles[i].friction.speed, b.obstacles[i].friction.speed);
  }
  EXPECT_EQ(a.gravity.y, b.gravity.y);
  EXPECT_EQ(a.pinned, b.pinned);
  EXPECT_EQ(a.springs->k, b.springs->k);
  EXPECT_EQ(a.springs->d, b.springs->d);
  ASSERT_TRUE(b.bounds.has_value());
  EXPECT_EQ(a.bounds->friction.muStatic, b.bounds->friction.muStatic);
}

// Friction's rule is one (model/obstacle.h frictionFault), kept by the reader, the panel and the
// writer: every friction it allows is read, saved and read back bit for bit; every one it
// refuses, the reader refuses at the key it names.
TEST(SavedScene, EveryFrictionTheRuleAllowsIsSavedAndReadBackAndNoOther) {
  const std::string dir = test::makeTempDir();
  auto number = [](double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", value);
    return std::string(text);
  };
  int allowed = 0, refused = 0;
  for (double muStatic : {0.0, 0.3, 10.0, 10.5})
    for (double muDynamic : {0.0, 0.2, 0.3, 0.30000000000000004, 10.0})
      for (double speed : {0.01, 1e-9, 5.0}) {
        const Friction f{muStatic, muDynamic, speed};
        test::writeText(dir + "/in.toml",
                        "dt = 0.0003\n[jelly]\nshape = \"lattice\"\n"
                        "size = [3, 3, 3]\n[[sphere]]\ncentre = [0, 0, -2]\n"
                        "radius = 0.5\nfriction_static = " +
                            number(muStatic) + "\nfriction_dynamic = " + number(muDynamic) +
                            "\nfriction_speed = " + number(speed) + "\n");
        const auto fault = frictionFault(f);
        SCOPED_TRACE(number(muStatic) + " " + number(muDynamic) + " " + number(speed));
        if (fault) {
          ++refused;
          try {
            readSceneFile(dir + "/in.toml");
            ADD_FAILURE() << "accepted, against the rule: " << fault->why;
          } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("(sphere[1]." + std::string(fault->key) + ")"),
                      std::string::npos)
                << e.what();
          }
          continue;
        }
        ++allowed;
        const WorldFile in = readSceneFile(dir + "/in.toml");
        writeScene(dir + "/out.toml", in.world, in.run, in.state, true);
        const Friction back =
            readSceneFile(dir + "/out.toml").world.scene->obstacles.at(0).friction;
        EXPECT_EQ(back.muStatic, muStatic);
        EXPECT_EQ(back.muDynamic, muDynamic);
        EXPECT_EQ(back.speed, speed);
      }
  EXPECT_EQ(allowed, 27);
  EXPECT_EQ(refused, 33);
  test::removeTree(dir);
}

TEST(SavedScene, RefusesANameThatIsNotTomlAndFilesThatExistUnlessTold) {
  const std::string dir = test::makeTempDir();
  const WorldFile file = readSceneFile(std::string(JELLO_SOURCE_DIR) + "/scenes/sphere-drop.toml");
  EXPECT_THROW(writeScene(dir + "/saved.txt", file.world, file.run, file.state, false),
               OutputError);
  EXPECT_FALSE(std::filesystem::exists(dir + "/saved.w"));
  test::writeText(dir + "/saved.csv", "mine\n");
  try {
    writeScene(dir + "/saved.toml", file.world, file.run, file.state, false);
    ADD_FAILURE() << "an existing state file was replaced";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("saved.csv"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(dir + "/saved.toml")) << "a partial save was left";
  EXPECT_FALSE(std::filesystem::exists(dir + "/saved.w")) << "a partial save was left";
  EXPECT_EQ(test::readText(dir + "/saved.csv"), "mine\n");
  writeScene(dir + "/saved.toml", file.world, file.run, file.state, true);
  EXPECT_NE(test::readText(dir + "/saved.csv"), "mine\n");
  EXPECT_NO_THROW(readSceneFile(dir + "/saved.toml"));
}

}  // namespace
}  // namespace jello
