// Every input a fuzzer ever found a fault with (tests/data/fuzz/: world-* for the reader, expr-*
// for field expressions, cli-* for jello's command line), and the fuzzers' seeds, replayed through
// the fuzzers' own checks, which abort on a fault. See `make fuzz`.
#include <dirent.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "../fuzz/checks.h"
#include "test_support.h"

namespace jello {
namespace {

std::vector<std::string> filesIn(const std::string& dir, const std::string& prefix) {
  std::vector<std::string> out;
  if (DIR* d = ::opendir(dir.c_str())) {
    while (dirent* e = ::readdir(d)) {
      std::string name = e->d_name;
      if (name.rfind(prefix, 0) == 0 && name != "." && name != "..")
        out.push_back(dir + "/" + name);
    }
    ::closedir(d);
  }
  return out;
}

void replay(const std::vector<std::string>& files,
            void (*check)(const std::uint8_t*, std::size_t)) {
  for (const std::string& path : files) {
    SCOPED_TRACE(path);
    std::string bytes = test::readText(path);
    check(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  }
}

TEST(FuzzRegressions, WorldReaderInputs) {
  std::vector<std::string> files = filesIn(test::dataPath("fuzz"), "world-");
  for (const char* world :
       {"jello.w", "rotate.w", "moveLeft.w", "skewedCorner.w", "gravity.w", "still.w"})
    files.push_back(test::dataPath(world));
  ASSERT_GE(files.size(), 8u);
  replay(files, fuzz::checkWorldText);
}

TEST(FuzzRegressions, FieldExpressionInputs) {
  std::vector<std::string> files = filesIn(test::dataPath("fuzz"), "expr-");
  std::vector<std::string> seeds = filesIn(std::string(JELLO_FUZZ_SEEDS) + "/expressions", "");
  files.insert(files.end(), seeds.begin(), seeds.end());
  ASSERT_GE(files.size(), 6u);
  replay(files, fuzz::checkFieldExpression);
}

TEST(FuzzRegressions, SceneReaderInputs) {
  std::vector<std::string> files = filesIn(test::dataPath("fuzz"), "scene-");
  std::vector<std::string> seeds = filesIn(std::string(JELLO_SOURCE_DIR) + "/scenes", "");
  for (const std::string& seed : seeds)  // the scenes, not their models' folder
    if (seed.size() > 5 && seed.compare(seed.size() - 5, 5, ".toml") == 0) files.push_back(seed);
  ASSERT_GE(files.size(), 7u);
  replay(files, fuzz::checkSceneText);
}

TEST(FuzzRegressions, CommandLineInputs) {
  std::vector<std::string> files = filesIn(test::dataPath("fuzz"), "cli-");
  std::vector<std::string> seeds = filesIn(std::string(JELLO_FUZZ_SEEDS) + "/commandline", "");
  files.insert(files.end(), seeds.begin(), seeds.end());
  ASSERT_GE(files.size(), 10u);
  ::testing::internal::CaptureStdout();  // --help and --version print
  ::testing::internal::CaptureStderr();
  replay(files, fuzz::checkCommandLine);
  ::testing::internal::GetCapturedStdout();
  ::testing::internal::GetCapturedStderr();
}

}  // namespace
}  // namespace jello
