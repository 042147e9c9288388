// submission.cpp: finding, copying and building a submission (submission.h).
#include "grader/submission.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include "core/output.h"
#include "grader/coursefiles.h"
#include "grader/sandbox.h"

namespace fs = std::filesystem;

namespace jello::grader {
namespace {

// What is copied out of a submission: source files only, within these bounds.
constexpr int kMostEntries = 5000;
constexpr int kMostFiles = 300;
constexpr std::uintmax_t kMostBytes = 16u << 20;
constexpr std::uintmax_t kMostArchiveBytes = 64u << 20;
const std::set<std::string> kSourceExtensions = {".cpp", ".cc", ".cxx", ".c",  ".h",
                                                 ".hpp", ".hh", ".hxx", ".inl"};
const std::set<std::string> kCompiledExtensions = {".cpp", ".cc", ".cxx"};
// The course's files around physics.cpp that draw, read files or hold main(): not built.
const std::set<std::string> kViewerFiles = {"jello.cpp",       "input.cpp", "showCube.cpp",
                                            "createWorld.cpp", "pic.cpp",   "ppm.cpp"};
// Headers of the course that bring GL: given empty stand-ins when the course API serves.
const char* const kGlHeaders[] = {"openGL-headers.h", "pic.h", "input.h", "showCube.h"};

bool hasSuffix(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

bool isArchive(const std::string& path) {
  return hasSuffix(path, ".zip") || hasSuffix(path, ".tar.gz") || hasSuffix(path, ".tgz");
}

std::string readWhole(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void writeText(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out) throw std::runtime_error(path.string() + ": cannot write");
}

// Copies the source files under `from` into `to`, keeping the layout; symbolic links and other
// files are not followed or read.
void copySources(const fs::path& from, const fs::path& to, std::vector<std::string>& notes) {
  int entries = 0, files = 0;
  std::uintmax_t bytes = 0;
  std::error_code error;
  for (fs::recursive_directory_iterator it(from, error), end; !error && it != end;
       it.increment(error)) {
    if (++entries > kMostEntries) {
      notes.push_back("more than " + std::to_string(kMostEntries) + " entries: the rest ignored");
      break;
    }
    fs::file_status status = it->symlink_status();
    fs::path relative = fs::relative(it->path(), from);
    if (fs::is_symlink(status)) {
      notes.push_back(relative.string() + ": a symbolic link, not followed");
      if (it.depth() >= 0) it.disable_recursion_pending();
      continue;
    }
    if (fs::is_directory(status)) {
      if (it.depth() >= 8) it.disable_recursion_pending();
      continue;
    }
    if (!fs::is_regular_file(status) || !kSourceExtensions.count(it->path().extension().string())) {
      continue;
    }
    bytes += it->file_size(error);
    if (++files > kMostFiles || bytes > kMostBytes) {
      notes.push_back("more source than the grader takes (300 files, 16 MB): the rest ignored");
      break;
    }
    fs::create_directories(to / relative.parent_path());
    writeText(to / relative, readWhole(it->path()));
  }
}

// Unpacks an archive in the sandbox into `into` (a folder of the scratch), by a fixed script:
// nothing of the archive's names reaches a shell outside the sandbox.
std::string unpack(const Submission& submission, const Scratch& scratch, const fs::path& into) {
  // The archive is copied first: the sandbox's user may not reach where it lies.
  std::error_code error;
  if (fs::file_size(submission.path, error) > kMostArchiveBytes || error) {
    return "the archive is larger than 64 MB, or unreadable";
  }
  std::string copy = scratch.path() + "/submission-archive";
  fs::copy_file(submission.path, copy);
  fs::permissions(copy, fs::perms(0644));
  std::string out = scratch.makeFolder("unpacked");
  bool zip = hasSuffix(submission.path, ".zip");
  std::string extract = zip ? "unzip -qq /in/submission -d x >/dev/null"
                            : "tar -xzf /in/submission -C x --no-same-owner --no-same-permissions";
  SandboxJob job;
  job.argv = {"/bin/sh", "-c",
              "cd /tmp && mkdir x && " + extract +
                  " && [ \"$(du -sk x | cut -f1)\" -le 65536 ] && cp -R x/. /out/"};
  job.hostDir = scratch.path();
  job.outputDir = out;
  job.readOnlyFiles = {{copy, "/in/submission"}};
  job.limits.wallSeconds = 30;
  job.limits.cpuSeconds = 30;
  SandboxResult result = runSandboxed(job);
  if (!result.exitedWith(0)) {
    return "cannot unpack " + std::string(zip ? "the zip" : "the tar.gz") + " archive (" +
           result.describe() + ", or more than 64 MB unpacked)";
  }
  std::vector<std::string> ignored;
  copySources(out, into, ignored);
  return "";
}

// The shallowest physics.cpp under `root`, or "" when there is none.
fs::path findPhysics(const fs::path& root) {
  fs::path best;
  std::size_t bestDepth = ~std::size_t{0};
  for (auto& entry : fs::recursive_directory_iterator(root)) {
    if (!entry.is_regular_file() || entry.path().filename() != "physics.cpp") continue;
    std::size_t depth =
        static_cast<std::size_t>(std::distance(entry.path().begin(), entry.path().end()));
    if (depth < bestDepth) {
      best = entry.path();
      bestDepth = depth;
    }
  }
  return best;
}

// Whether `text` calls or defines a function main: the word, then blanks, then '('. A plain
// scan: a pattern would recurse once per blank, and a file of blanks would crash the grader.
bool hasMain(const std::string& text) {
  for (std::size_t at = text.find("main"); at != std::string::npos;
       at = text.find("main", at + 1)) {
    bool wordStart =
        at == 0 || !(std::isalnum(static_cast<unsigned char>(text[at - 1])) || text[at - 1] == '_');
    std::size_t next = at + 4;
    while (next < text.size() && std::isspace(static_cast<unsigned char>(text[next]))) ++next;
    if (wordStart && next < text.size() && text[next] == '(') return true;
  }
  return false;
}

// A name the compiler can only take for a file: letters, digits, '.', '_', '-', not first '-'.
bool plainName(const std::string& name) {
  if (name.empty() || name[0] == '-') return false;
  for (char c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '_' && c != '-')
      return false;
  }
  return true;
}

// The files of `folder` to compile, physics.cpp first, each as "./NAME" (never an option).
std::vector<std::string> compiledFiles(const fs::path& folder, std::vector<std::string>& notes) {
  std::vector<std::string> files = {"./physics.cpp"};
  for (auto& entry : fs::directory_iterator(folder)) {
    std::string name = entry.path().filename().string();
    if (!entry.is_regular_file() || name == "physics.cpp" ||
        !kCompiledExtensions.count(entry.path().extension().string())) {
      continue;
    }
    if (!plainName(name)) {
      notes.push_back(
          printable(name) +
          ": left out (a name of other characters than letters, digits, '.', '_' and '-')");
    } else if (kViewerFiles.count(name) || hasMain(readWhole(entry.path()))) {
      notes.push_back(name + ": left out (the course's viewer, or a main())");
    } else {
      files.push_back("./" + name);
    }
  }
  std::sort(files.begin() + 1, files.end());
  return files;
}

// Copies the program the sandbox built to `to`: only a regular file, never through a link the
// sandbox may have put in its place. False when there is none.
bool copyBuiltProgram(const std::string& from, const std::string& to) {
  int in = open(from.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
  struct stat info;
  if (in < 0) return false;
  bool ok = fstat(in, &info) == 0 && S_ISREG(info.st_mode) && info.st_size < (256 << 20);
  std::string bytes;
  char buffer[1 << 16];
  for (ssize_t n; ok && (n = read(in, buffer, sizeof buffer)) != 0;) {
    if (n < 0)
      ok = false;
    else
      bytes.append(buffer, static_cast<std::size_t>(n));
  }
  close(in);
  if (!ok) return false;
  writeText(to, bytes);
  fs::permissions(to, fs::perms(0755));
  return true;
}

// The first line of the compiler's output that says what is wrong, without sandbox paths.
std::string firstError(const std::string& log) {
  std::istringstream lines(log);
  std::string line;
  while (std::getline(lines, line)) {
    if (line.find("error") != std::string::npos ||
        line.find("undefined reference") != std::string::npos) {
      for (const char* prefix : {"/work/build/", "/work/probe/", "/usr/bin/ld: "}) {
        for (std::size_t at; (at = line.find(prefix)) != std::string::npos;) {
          line.erase(at, std::strlen(prefix));
        }
      }
      if (line.rfind("./", 0) == 0) line.erase(0, 2);  // the files are given as ./NAME
      return line.size() > 300 ? line.substr(0, 300) + "..." : line;
    }
  }
  return log.empty() ? "the compiler gave no reason" : log.substr(0, log.find('\n'));
}

struct Attempt {
  const char* headers;
  bool courseJello, coursePhysics;
};

// Prepares scratch/build for an attempt: the source folder, with the course API's headers in
// place of the submission's where the attempt says so.
void prepareAttempt(const fs::path& source, const fs::path& build, const Attempt& attempt) {
  fs::remove_all(build);
  fs::create_directories(build);
  for (auto& entry : fs::directory_iterator(source)) {
    if (entry.is_regular_file()) fs::copy_file(entry.path(), build / entry.path().filename());
  }
  if (attempt.courseJello) {
    writeText(build / "jello.h", kCourseJelloH);
    for (const char* header : kGlHeaders) writeText(build / header, "/* no GL when grading */\n");
  }
  if (attempt.coursePhysics) writeText(build / "physics.h", kCoursePhysicsH);
}

// The submission's header an attempt needs and the folder lacks, or nullptr: the probe includes
// jello.h and physics.h, so without them the attempt fails at its first line, after a second of
// compiling (a submission with neither header saves two such attempts).
const char* missingHeader(const fs::path& source, const Attempt& attempt) {
  if (!attempt.courseJello && !fs::exists(source / "jello.h")) return "jello.h";
  if (!attempt.coursePhysics && !fs::exists(source / "physics.h")) return "physics.h";
  return nullptr;
}

}  // namespace

std::string whyNotSubmission(const std::string& path) {
  struct stat info;
  if (path.empty()) return "an empty name is no submission";
  if (stat(path.c_str(), &info) != 0) return path + ": " + std::strerror(errno);
  if (S_ISDIR(info.st_mode)) return "";
  if (S_ISREG(info.st_mode) && isArchive(path)) return "";
  return path + ": not a folder, .zip, .tar.gz or .tgz";
}

std::vector<Submission> nameSubmissions(const std::vector<std::string>& paths) {
  std::vector<Submission> submissions;
  std::set<std::string> taken;
  for (const auto& path : paths) {
    std::string name = fs::path(path).lexically_normal().filename().string();
    if (name.empty()) name = fs::path(path).lexically_normal().parent_path().filename().string();
    for (const char* extension : {".zip", ".tar.gz", ".tgz"}) {
      if (hasSuffix(name, extension)) name.erase(name.size() - std::strlen(extension));
    }
    for (char& c : name) {
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '_' && c != '-') c = '_';
    }
    if (name.empty() || name[0] == '.') name = "submission" + name;
    // The names of the report's own files are not a submission's folder.
    for (const char* reserved :
         {"summary.md", "summary.csv", "junit.xml", "grading.txt", "CTestTestfile.cmake"}) {
      if (name == reserved) name += "-submission";
    }
    std::string unique = name;
    for (int n = 2; taken.count(unique); ++n) unique = name + "-" + std::to_string(n);
    taken.insert(unique);
    submissions.push_back({path, unique});
  }
  return submissions;
}

BuildResult buildSubmission(const Submission& submission, const std::string& probePath) {
  auto start = std::chrono::steady_clock::now();
  BuildResult result;
  Scratch scratch;
  fs::path sources = fs::path(scratch.path()) / "sources";
  fs::create_directories(sources);
  if (isArchive(submission.path)) {
    result.diagnosis = unpack(submission, scratch, sources);
    if (!result.diagnosis.empty()) return result;
  } else {
    copySources(submission.path, sources, result.notes);
  }
  fs::path physics = findPhysics(sources);
  if (physics.empty()) {
    result.diagnosis = "no physics.cpp in the submission";
    return result;
  }
  std::vector<std::string> files = compiledFiles(physics.parent_path(), result.notes);
  fs::create_directories(fs::path(scratch.path()) / "probe");
  writeText(fs::path(scratch.path()) / "probe" / "probe.cpp", kProbeSource);
  const Attempt attempts[] = {{"its own headers", false, false},
                              {"its physics.h with the course API's jello.h", true, false},
                              {"the course API's jello.h and physics.h", true, true}};
  for (const Attempt& attempt : attempts) {
    if (const char* missing = missingHeader(physics.parent_path(), attempt)) {
      result.log += "--- with " + std::string(attempt.headers) + ": not tried, no " + missing +
                    " beside physics.cpp\n";
      continue;
    }
    prepareAttempt(physics.parent_path(), fs::path(scratch.path()) / "build", attempt);
    std::string out = scratch.makeFolder("out");
    SandboxJob job;
    job.argv = {"/usr/bin/g++", "-std=c++17", "-O2", "-fpermissive", "-w", "-I/work/build"};
    job.argv.insert(job.argv.end(), files.begin(), files.end());
    job.argv.insert(job.argv.end(), {"/work/probe/probe.cpp", "-o", "/out/probe", "-lm"});
    job.hostDir = scratch.path();
    job.outputDir = out;
    job.workingDir = "/work/build";
    job.limits = {60, 60, 4LL << 30, 16, 256LL << 20, 1LL << 20};
    SandboxResult compiled = runSandboxed(job);
    result.log += "--- with " + std::string(attempt.headers) + ": " + compiled.describe() + "\n" +
                  compiled.errors + compiled.output;
    if (compiled.exitedWith(0) && copyBuiltProgram(out + "/probe", probePath)) {
      result.built = true;
      result.headers = attempt.headers;
      break;
    }
    if (result.diagnosis.empty() || attempt.coursePhysics) {
      result.diagnosis = compiled.started && !compiled.timedOut && compiled.signal == 0
                             ? firstError(compiled.errors)
                             : "the compiler " + compiled.describe();
    }
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace jello::grader
