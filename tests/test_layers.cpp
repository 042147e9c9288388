// The code's layers (docs/design.md): every #include points down them, and Eigen, Spectra and GL
// appear only where they are needed.
//
//   core/ < world.h, vec3.h, input.cpp, physics.*, forces/, scene/ < solver/ < app/, grader/
//         < graphics/, showCube.* < jello.cpp, createWorld.cpp
// (grader/course/ is the course API a student's code is built with, not the project's.)
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <regex>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

std::optional<int> layerOf(const std::string& path) {
  static const std::map<std::string, int> folders = {{"core", 0},    {"forces", 1}, {"scene", 1},
                                                     {"solver", 2},  {"app", 3},    {"grader", 3},
                                                     {"graphics", 4}};
  static const std::map<std::string, int> rootFiles = {
      {"world.h", 1},      {"vec3.h", 1},      {"input.cpp", 1},
      {"physics.h", 1},    {"physics.cpp", 1}, {"showCube.h", 4},
      {"showCube.cpp", 4}, {"jello.cpp", 5},   {"createWorld.cpp", 5}};
  const std::size_t slash = path.find('/');
  if (slash != std::string::npos) {
    auto folder = folders.find(path.substr(0, slash));
    return folder == folders.end() ? std::nullopt : std::optional<int>(folder->second);
  }
  auto file = rootFiles.find(path);
  return file == rootFiles.end() ? std::nullopt : std::optional<int>(file->second);
}

// The project's own sources, as paths relative to the source folder.
std::vector<std::string> projectSources() {
  const fs::path root = JELLO_SOURCE_DIR;
  std::vector<std::string> out;
  for (const char* folder : {"core", "forces", "scene", "solver", "app", "grader", "graphics"})
    for (const auto& entry : fs::directory_iterator(root / folder))
      if (entry.is_regular_file())
        out.push_back(std::string(folder) + "/" + entry.path().filename().string());
  for (const auto& entry : fs::directory_iterator(root))
    if (entry.is_regular_file() && layerOf(entry.path().filename().string()))
      out.push_back(entry.path().filename().string());
  return out;
}

// "file:line: what" for every include that breaks a rule.
std::vector<std::string> breaches(const std::string& path) {
  std::vector<std::string> out;
  std::ifstream in(std::string(JELLO_SOURCE_DIR) + "/" + path);
  const std::regex include(R"(\s*#include\s+[<"]([^>"]+)[>"].*)");
  const int own = *layerOf(path);
  const bool eigenAllowed = (path.rfind("solver/", 0) == 0 || path.rfind("app/", 0) == 0) &&
                            ((path.size() > 4 && path.compare(path.size() - 4, 4, ".cpp") == 0) ||
                             path == "solver/jacobian.h");
  const bool glAllowed = path.rfind("graphics/", 0) == 0 || path == "showCube.cpp";
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    std::smatch match;
    if (!std::regex_match(line, match, include)) continue;
    const std::string target = match[1];
    const std::string where = path + ":" + std::to_string(number) + ": ";
    if (std::optional<int> theirs = layerOf(target); theirs && *theirs > own)
      out.push_back(where + "includes " + target + ", a layer above");
    if (target.rfind("Eigen/", 0) == 0 && !eigenAllowed) out.push_back(where + "includes Eigen");
    // Spectra (the Lanczos eigensolvers) is linked to app/ alone.
    if (target.rfind("Spectra/", 0) == 0 && !(eigenAllowed && path.rfind("app/", 0) == 0))
      out.push_back(where + "includes Spectra");
    if ((target.rfind("GL/", 0) == 0 || target.rfind("GLUT/", 0) == 0) && !glAllowed)
      out.push_back(where + "includes GL");
  }
  return out;
}

TEST(Layers, EveryIncludePointsDownAndEigenSpectraAndGlStayWhereNeeded) {
  const std::vector<std::string> sources = projectSources();
  EXPECT_GT(sources.size(), 60u);
  std::vector<std::string> found;
  for (const std::string& path : sources)
    for (const std::string& breach : breaches(path)) found.push_back(breach);
  std::string all;
  for (const std::string& breach : found) all += breach + "\n";
  EXPECT_TRUE(found.empty()) << all;
}

}  // namespace
