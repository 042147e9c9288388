// The code's floor plan (README: "The code's map"; docs/design.md): each folder is a layer and a
// library, every #include points down the layers, Eigen, Spectra and GL appear only where they
// are needed, and no file or function outgrows what a reader takes in at once. The links are
// checked on the built libraries by check-links.sh (Layers.EveryLinkPointsDown).
//
//   core < model < io < solver < analysis < app < grader, graphics < jello.cpp, createWorld.cpp
//
// A file's layer is read from its path alone: a folder's files are its layer; a course file at
// the root (physics.cpp, input.cpp, showCube.cpp) is in the layer of the folder that holds its
// header (solver/physics.h, io/input.h, graphics/showCube.h); a root file without one (the mains)
// is above every layer. Folders of one rank are siblings and include nothing of each other.
// (grader/course/ and grader/standins/ are what a student's code is built with, not the project.)
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

const std::map<std::string, int>& folderRanks() {
  static const std::map<std::string, int> ranks = {{"core", 0},   {"model", 1},    {"io", 2},
                                                   {"solver", 3}, {"analysis", 4}, {"app", 5},
                                                   {"grader", 6}, {"graphics", 6}};
  return ranks;
}
constexpr int kMains = 7;  // jello.cpp, createWorld.cpp

struct Layer {
  std::string folder;  // "" for the mains
  int rank = 0;
};

// The folder of a root file's header ("physics.cpp" -> "solver"), or "" when no folder has one.
std::string headerFolder(const std::string& rootFile) {
  const std::string header = fs::path(rootFile).stem().string() + ".h";
  for (const auto& [folder, rank] : folderRanks())
    if (fs::exists(fs::path(JELLO_SOURCE_DIR) / folder / header)) return folder;
  return "";
}

// The layer of a project path ("model/term.h", "physics.cpp"); none for a path outside the
// project's layers (a system header, grader/course/).
std::optional<Layer> layerOf(const std::string& path) {
  const std::size_t slash = path.find('/');
  if (slash == std::string::npos) {
    if (!fs::exists(fs::path(JELLO_SOURCE_DIR) / path)) return std::nullopt;
    const std::string folder = headerFolder(path);
    if (folder.empty()) return Layer{"", kMains};
    return Layer{folder, folderRanks().at(folder)};
  }
  const std::string folder = path.substr(0, slash);
  auto found = folderRanks().find(folder);
  if (found == folderRanks().end() || path.rfind("grader/course/", 0) == 0 ||
      path.rfind("grader/standins/", 0) == 0)
    return std::nullopt;
  return Layer{folder, found->second};
}

bool endsWith(const std::string& text, const std::string& end) {
  return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}

// The project's own production sources (the layers and the root's), relative to the source folder.
std::vector<std::string> projectSources() {
  const fs::path root = JELLO_SOURCE_DIR;
  std::vector<std::string> out;
  for (const auto& [folder, rank] : folderRanks())
    for (const auto& entry : fs::directory_iterator(root / folder))
      if (entry.is_regular_file() &&
          (endsWith(entry.path().string(), ".cpp") || endsWith(entry.path().string(), ".h")))
        out.push_back(folder + "/" + entry.path().filename().string());
  for (const auto& entry : fs::directory_iterator(root))
    if (entry.is_regular_file() &&
        (endsWith(entry.path().string(), ".cpp") || endsWith(entry.path().string(), ".h")))
      out.push_back(entry.path().filename().string());
  return out;
}

// "file:line: what" for every include that breaks a rule.
std::vector<std::string> breaches(const std::string& path) {
  std::vector<std::string> out;
  std::ifstream in(std::string(JELLO_SOURCE_DIR) + "/" + path);
  const std::regex include(R"(\s*#include\s+[<"]([^>"]+)[>"].*)");
  const Layer own = *layerOf(path);
  const bool source = endsWith(path, ".cpp");
  const bool eigenAllowed = ((own.folder == "solver" || own.folder == "analysis") && source) ||
                            path == "solver/jacobian.h";
  const bool spectraAllowed = own.folder == "analysis" && source;
  const bool glAllowed = own.folder == "graphics";
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    std::smatch match;
    if (!std::regex_match(line, match, include)) continue;
    const std::string target = match[1];
    const std::string where = path + ":" + std::to_string(number) + ": ";
    if (std::optional<Layer> theirs = layerOf(target)) {
      if (target.find('/') == std::string::npos)
        out.push_back(where + "includes " + target + ", a root file (nothing includes those)");
      else if (theirs->folder != own.folder && theirs->rank >= own.rank)
        out.push_back(where + "includes " + target + ", from a layer " +
                      (theirs->rank == own.rank ? "beside it" : "above"));
    }
    if (target.rfind("Eigen/", 0) == 0 && !eigenAllowed) out.push_back(where + "includes Eigen");
    if (target.rfind("Spectra/", 0) == 0 && !spectraAllowed)
      out.push_back(where + "includes Spectra");
    if ((target.rfind("GL/", 0) == 0 || target.rfind("GLUT/", 0) == 0) && !glAllowed)
      out.push_back(where + "includes GL");
  }
  return out;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string all;
  for (const std::string& line : lines) all += line + "\n";
  return all;
}

TEST(Layers, EveryIncludePointsDownAndEigenSpectraAndGlStayWhereNeeded) {
  const std::vector<std::string> sources = projectSources();
  EXPECT_GT(sources.size(), 100u);
  std::vector<std::string> found;
  for (const std::string& path : sources)
    for (const std::string& breach : breaches(path)) found.push_back(breach);
  EXPECT_TRUE(found.empty()) << joined(found);
}

TEST(Layers, TheLayerOfAFileIsReadFromItsPath) {
  EXPECT_EQ(layerOf("model/term.h")->rank, 1);
  EXPECT_EQ(layerOf("physics.cpp")->folder, "solver");
  EXPECT_EQ(layerOf("input.cpp")->folder, "io");
  EXPECT_EQ(layerOf("showCube.cpp")->folder, "graphics");
  EXPECT_EQ(layerOf("jello.cpp")->rank, kMains);
  EXPECT_EQ(layerOf("createWorld.cpp")->rank, kMains);
  EXPECT_FALSE(layerOf("grader/course/physics.h"));
  EXPECT_FALSE(layerOf("vector"));
  // Every folder of the project that holds code is a layer (a new one must be placed).
  for (const auto& entry : fs::directory_iterator(JELLO_SOURCE_DIR)) {
    if (!entry.is_directory()) continue;
    const std::string name = entry.path().filename().string();
    if (name == "tests" || name == "fuzz" || name == "benchmarks" || name[0] == '.' ||
        name.rfind("build", 0) == 0)
      continue;
    bool code = false;
    for (const auto& file : fs::directory_iterator(entry.path()))
      code = code || endsWith(file.path().string(), ".cpp");
    EXPECT_TRUE(!code || folderRanks().count(name)) << name << "/ holds code but is no layer";
  }
}

// Production files (not the tests, fuzzers and benchmarks) are read in one sitting.
constexpr int kMostFileLines = 600;
constexpr int kMostFunctionLines = 60;

int lineCount(const std::string& path) {
  std::ifstream in(std::string(JELLO_SOURCE_DIR) + "/" + path);
  int lines = 0;
  for (std::string line; std::getline(in, line);) ++lines;
  return lines;
}

TEST(Layers, NoSourceFileIsOver600Lines) {
  std::vector<std::string> found;
  for (const std::string& path : projectSources())
    if (endsWith(path, ".cpp") && lineCount(path) > kMostFileLines)
      found.push_back(path + ": " + std::to_string(lineCount(path)) + " lines");
  EXPECT_TRUE(found.empty()) << joined(found);
}

// Every function's extent, from universal-ctags (scripts/debian-packages.txt): "NAME FILE:LINE N".
std::vector<std::string> longFunctions(const std::vector<std::string>& paths) {
  std::string command =
      "cd '" + std::string(JELLO_SOURCE_DIR) + "' && ctags --fields=+ne --c++-kinds=f -o -";
  for (const std::string& path : paths) command += " '" + path + "'";
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen((command + " 2>/dev/null").c_str(), "r"),
                                             pclose);
  std::vector<std::string> out;
  if (!pipe) return {"cannot run ctags"};
  char buffer[4096];
  int functions = 0;
  while (std::fgets(buffer, sizeof buffer, pipe.get())) {
    std::istringstream fields(buffer);
    std::string name, file, field;
    std::getline(fields, name, '\t');
    std::getline(fields, file, '\t');
    long first = 0, end = 0;
    while (std::getline(fields, field, '\t')) {
      if (field.rfind("line:", 0) == 0) first = std::stol(field.substr(5));
      if (field.rfind("end:", 0) == 0) end = std::stol(field.substr(4));
    }
    ++functions;
    if (end - first + 1 > kMostFunctionLines)
      out.push_back(file + ":" + std::to_string(first) + ": " + name + ", " +
                    std::to_string(end - first + 1) + " lines");
  }
  if (functions < 500)
    out.push_back("ctags found only " + std::to_string(functions) + " functions");
  return out;
}

TEST(Layers, NoFunctionIsOver60Lines) {
  if (std::system("command -v ctags >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "no ctags (make deps installs universal-ctags)";
  std::vector<std::string> paths;
  for (const std::string& path : projectSources()) paths.push_back(path);
  const std::vector<std::string> found = longFunctions(paths);
  EXPECT_TRUE(found.empty()) << joined(found);
}

}  // namespace
