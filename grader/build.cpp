// build.cpp: building a submission's program in the sandbox (build.h).
#include "grader/build.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include "core/output.h"
#include "grader/checkkit.h"
#include "grader/compilerlog.h"
#include "grader/graderfiles.h"
#include "grader/leniency.h"
#include "grader/probe.h"
#include "grader/sandbox.h"
#include "model/term.h"

namespace fs = std::filesystem;

namespace jello::grader {
namespace {

constexpr int kMostCompiled = 100;          // source files compiled in one attempt
constexpr int kRewriteRounds = 3;           // compilations again after Visual C++'s rewrites
constexpr std::size_t kPrintedKept = 4000;  // of what a program that stops early printed
// What is left of the submission's compile budget (build.h), on the thread building it.
thread_local double compileSecondsLeft = kCompileBudgetSeconds;
thread_local double compileBudget = kCompileBudgetSeconds;
// What a program that looks for a grader may test (docs/grading.md, "What no grader can prevent").
const char* const kTells[] = {"F_GETFD", "/proc/self/fd", "isatty", "getenv(\"DISPLAY\")"};
// GCC's warnings, all off (-w would hide the one rewriteMissingReturns reads) but -Wreturn-type;
// then those of C++ and of C alone.
const char* const kQuietWarnings =
    "-Wno-all -Wno-extra -Wno-write-strings -Wno-deprecated -Wno-deprecated-declarations "
    "-Wno-unused-result -Wno-format -Wno-int-to-pointer-cast -Wno-return-local-addr "
    "-Wno-narrowing -Wno-attributes -Wno-pragmas -Wno-unknown-pragmas -Wno-multichar "
    "-Wno-overflow -Wno-address -Wno-div-by-zero -Wno-stringop-overflow -Wno-array-bounds "
    "-Wno-aggressive-loop-optimizations -Wno-free-nonheap-object -Wno-builtin-declaration-mismatch "
    "-Wno-cpp -Wreturn-type";
const char* const kQuietCxx = "-Wno-conversion-null";
const char* const kQuietC =
    "-Wno-pointer-to-int-cast -Wno-implicit-function-declaration -Wno-int-conversion "
    "-Wno-incompatible-pointer-types";
// The course's headers that bring GL into jello.h: empty when the course API's jello.h serves.
const char* const kCourseGlHeaders[] = {"openGL-headers.h", "input.h", "showCube.h"};
// Copies of the libraries the grader stands in for, which a submission may ship: each is
// replaced by the stand-in, whatever its case ("Glut.h" too).
const std::map<std::string, std::string> kStoodInHeaders = {
    {"pic.h", "standins/always/pic.h"},
    {"gl.h", "standins/always/GL/gl.h"},
    {"glu.h", "standins/always/GL/glu.h"},
    {"glut.h", "standins/always/GL/glut.h"},
    {"freeglut.h", "standins/always/GL/freeglut.h"},
    {"freeglut_std.h", "standins/always/GL/freeglut_std.h"},
    {"freeglut_ext.h", "standins/always/GL/freeglut_ext.h"},
    {"glew.h", "standins/always/GL/glew.h"}};

// The build script, fixed text: file names reach it only through /work/list, one "ROLE PATH" a
// line, each PATH a plain relative name (plainPath), and only ever as one quoted argument.
// The compiler's messages all go to standard output, in order (warnings may be many: what is
// beyond the sandbox's cap is discarded, never the reason a build fails). Everything the
// compiler writes stays in the sandbox's /tmp, a tmpfs of kSandboxTmpBytes: only the program
// reaches the host's disk (/out). Each file is compiled apart; the roots (the probe, physics.cpp,
// the program's main) are linked with the rest as an archive, from which the linker takes only what
// the program needs: a stray file that does not compile, or defines something twice, or needs GL,
// is left out unless used.
const char* const kBuildScript = R"(set -u -f
exec 2>&1
cd /work/build || exit 1
mkdir /tmp/o || exit 1
cxx=$(cat /work/cxxflags); cc=$(cat /work/cflags); probe=$(cat /work/probeflags)
n=0; roots=; libs=; broken=
while read -r role source; do
  n=$((n + 1))
  echo "jello-grader: compiling $role"
  case $source in
    *.c) gcc $cc -c "./$source" -o "/tmp/o/$n.o" ;;
    *) if [ "$role" = probe ]; then g++ $cxx $probe -c "./$source" -o "/tmp/o/$n.o"
       else g++ $cxx -c "./$source" -o "/tmp/o/$n.o"; fi ;;
  esac
  if [ $? -ne 0 ]; then
    [ "$role" = lib ] || { broken=1; break; }
  elif [ "$role" = lib ]; then libs="$libs /tmp/o/$n.o"
  else roots="$roots /tmp/o/$n.o"
  fi
done < /work/list
[ -z "$broken" ] || exit 1
if [ -n "$libs" ]; then ar rcs /tmp/o/lib.a $libs || exit 1; libs=/tmp/o/lib.a; fi
echo "jello-grader: linking"
g++ -o /tmp/o/probe $roots $libs -lm || exit 1
exec cp /tmp/o/probe /out/probe
)";

// Whether `text` calls or defines a function `word`: the word, then blanks, then '('. A plain
// scan: a pattern would recurse once per blank, and a file of blanks would crash the grader.
bool callsWord(const std::string& text, const std::string& word) {
  for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) {
    bool wordStart =
        at == 0 || !(std::isalnum(static_cast<unsigned char>(text[at - 1])) || text[at - 1] == '_');
    std::size_t next = at + word.size();
    while (next < text.size() && std::isspace(static_cast<unsigned char>(text[next]))) ++next;
    if (wordStart && next < text.size() && text[next] == '(') return true;
  }
  return false;
}

// The submission as copied, from physics.cpp's folder down.
struct Tree {
  fs::path root;                        // physics.cpp's folder
  std::vector<std::string> sources;     // files to compile, relative to root, plain; sorted
  std::set<std::string> definesMain;    // of those, the ones with a main()
  std::string mainFile;                 // the program's main(): the one calling glutMainLoop
  std::vector<std::string> headerDirs;  // folders below root (relative, plain) with headers
  bool picSource = false;               // it carries the course's picture library (pic.cpp)
  std::string cxxStandard = "gnu++17";  // its Makefile's -std=, as GNU's dialect
  std::vector<std::string> notes;
};

// The shallowest physics.cpp under `root`, or "" when there is none.
fs::path findPhysics(const fs::path& root) {
  fs::path best;
  std::size_t bestDepth = ~std::size_t{0};
  for (auto& entry : fs::recursive_directory_iterator(root)) {
    if (!entry.is_regular_file() || entry.path().filename() != "physics.cpp") continue;
    auto depth = static_cast<std::size_t>(std::distance(entry.path().begin(), entry.path().end()));
    if (depth < bestDepth) {
      best = entry.path();
      bestDepth = depth;
    }
  }
  return best;
}

// The C++ standard the hand-in's own Makefile asks for (-std=c++11, gnu++14, ...), as GNU's
// dialect of it: code written for C++11 may not compile as C++17 (dynamic exception
// specifications). gnu++17 when no Makefile says.
std::string makefileStandard(const fs::path& root) {
  for (const char* name : {"Makefile", "makefile", "GNUmakefile"}) {
    std::string text = readWhole(root / name);
    for (const char* flag : {"-std=c++", "-std=gnu++"}) {
      std::size_t at = text.find(flag);
      if (at == std::string::npos) continue;
      at += std::strlen(flag);
      std::string version;
      while (at < text.size() && std::isalnum(static_cast<unsigned char>(text[at])) &&
             version.size() < 2)
        version += text[at++];
      for (const char* known : {"98", "03", "0x", "11", "1y", "14", "1z", "17", "2a", "20"})
        if (version == known) return "gnu++" + version;
    }
  }
  return "gnu++17";
}

Tree readTree(const fs::path& physics) {
  Tree tree;
  tree.root = physics.parent_path();
  std::set<std::string> headerDirs;
  for (auto& entry : fs::recursive_directory_iterator(tree.root)) {
    if (!entry.is_regular_file()) continue;
    std::string relative = fs::relative(entry.path(), tree.root).generic_string();
    std::string extension = entry.path().extension().string();
    if (isHeader(entry.path()) && entry.path().parent_path() != tree.root &&
        plainPath(fs::relative(entry.path().parent_path(), tree.root).generic_string())) {
      headerDirs.insert(fs::relative(entry.path().parent_path(), tree.root).generic_string());
    }
    if (!isCompiled(entry.path()) || relative == kProbeName) continue;
    if (!plainPath(relative)) {
      tree.notes.push_back(printable(relative) +
                           ": left out (a name the compiler could read as an option: one that "
                           "starts with '-', or holds other characters than letters, digits, "
                           "'.', '_' and '-')");
      continue;
    }
    tree.sources.push_back(relative);
    std::string stem = lower(entry.path().stem().string());
    if (stem == "pic") tree.picSource = true;
    std::string text = readWhole(entry.path());
    for (const char* tell : kTells) {
      if (text.find(tell) != std::string::npos)
        tree.notes.push_back("the source looks for " + std::string(tell) + " (" + relative +
                             "): a program can behave differently when graded; read it");
    }
    if (callsWord(text, "main")) {
      tree.definesMain.insert(relative);
      // The program's main: the one that starts GLUT, else jello.cpp's.
      if (callsWord(text, "glutMainLoop") ||
          (tree.mainFile.empty() && entry.path().filename() == "jello.cpp"))
        tree.mainFile = relative;
    }
  }
  std::sort(tree.sources.begin(), tree.sources.end());
  if (static_cast<int>(tree.sources.size()) > kMostCompiled) {
    tree.notes.push_back("more than " + std::to_string(kMostCompiled) +
                         " files to compile: the rest left out");
    tree.sources.resize(kMostCompiled);
  }
  tree.headerDirs.assign(headerDirs.begin(), headerDirs.end());
  tree.cxxStandard = makefileStandard(tree.root);
  if (tree.cxxStandard != "gnu++17")
    tree.notes.push_back("compiled as " + tree.cxxStandard +
                         ", the standard its Makefile asks for");
  return tree;
}

enum class Mode { Program, PhysicsAlone };
struct Attempt {
  Mode mode;
  bool courseJello, coursePhysics;
  const char* words;
  bool lenient = false;  // each is tried as written, then leniently where that did not compile
};
const Attempt kAttempts[] = {
    {Mode::Program, false, false, "its whole program (its own main()), its own headers"},
    {Mode::PhysicsAlone, false, false, "physics.cpp alone, its own headers"},
    {Mode::PhysicsAlone, true, false,
     "physics.cpp alone, its physics.h with the course API's jello.h"},
    {Mode::PhysicsAlone, true, true, "physics.cpp alone, the course API's jello.h and physics.h"},
};

// Why an attempt cannot be made with this tree, or "" when it can.
std::string whyNot(const Tree& tree, const Attempt& attempt) {
  if (attempt.mode == Mode::Program) {
    if (tree.mainFile.empty()) return "no main() that calls glutMainLoop()";
    if (!fs::exists(tree.root / "jello.h")) return "no jello.h beside physics.cpp";
    return "";
  }
  if (!attempt.courseJello && !fs::exists(tree.root / "jello.h"))
    return "no jello.h beside physics.cpp";
  if (!attempt.coursePhysics && !fs::exists(tree.root / "physics.h"))
    return "no physics.h beside physics.cpp";
  return "";
}

// scratch/build: the tree from physics.cpp's folder, the stand-ins' copies replaced, the course
// API's headers where the attempt says so, the probe. scratch/standins: the stand-ins.
void layOut(const Tree& tree, const Attempt& attempt, const fs::path& work) {
  fs::path build = work / "build";
  fs::remove_all(build);
  fs::copy(tree.root, build, fs::copy_options::recursive);
  for (auto& entry : fs::recursive_directory_iterator(build)) {
    std::string name = lower(entry.path().filename().string());
    auto stood = kStoodInHeaders.find(name);
    // The course's picture library is portable C: a hand-in that carries its source (pic.cpp)
    // builds it with its own pic.h; the stand-in serves one that linked the library built.
    if (name == "pic.h" && tree.picSource) continue;
    if (entry.is_regular_file() && stood != kStoodInHeaders.end())
      writeText(entry.path(), graderFile(stood->second));
  }
  if (attempt.courseJello) {
    writeText(build / "jello.h", graderFile("course/jello.h"));
    for (const char* header : kCourseGlHeaders) writeText(build / header, "/* no GL */\n");
  }
  if (attempt.coursePhysics || !fs::exists(build / "physics.h"))
    writeText(build / "physics.h", graderFile("course/physics.h"));
  writeText(build / kProbeName, graderFile("course/probe.cpp"));
  fs::remove_all(work / "standins");
  fs::remove_all(work / "case");
  fs::create_directories(work / "case");
  for (const GraderFile& file : graderFiles()) {
    std::string path = file.path;
    if (path.rfind("standins/", 0) == 0) writeText(work / path, file.text);
  }
}

// The flag files and the list of the attempt; returns the leniencies it used, in words.
std::vector<std::string> writeFlags(const Tree& tree, const Attempt& attempt,
                                    const fs::path& work) {
  std::vector<std::string> leniencies;
  std::string include = "-I/work/standins/always -I.";
  for (const auto& dir : tree.headerDirs) include += " -I./" + dir;
  // Warnings are off but for the one a missing return gives (rewriteMissingReturns).
  std::string common =
      "-O2 -fdiagnostics-column-unit=byte -fno-diagnostics-color " + std::string(kQuietWarnings);
  std::string cxx = "-std=" + tree.cxxStandard + " " + common + " " + kQuietCxx,
              cc = "-std=gnu11 " + common + " " + kQuietC;
  if (attempt.lenient) {
    include += " -I/work/case -I/work/standins/lenient";
    cxx += " -fpermissive -include jello-grader-lenient.h";
    cc += " -include jello-grader-lenient.h";
    for (const auto& note : serveLibraryCopies(work / "build")) leniencies.push_back(note);
    for (const auto& note : matchIncludeCase(work / "build", work / "standins", work / "case"))
      leniencies.push_back(note);
  }
  writeFileWhole((work / "cxxflags").string(), cxx + " " + include + "\n", Existing::Replace);
  writeFileWhole((work / "cflags").string(), cc + " " + include + "\n", Existing::Replace);
  writeFileWhole((work / "probeflags").string(),
                 attempt.mode == Mode::Program ? "-DJELLO_GRADER_PROGRAM\n" : "\n",
                 Existing::Replace);
  // The files the program needs first, the student's own before the probe: the first that does
  // not compile ends the attempt (its error is the one reported; the rest would cost time only).
  std::string list = "root physics.cpp\n";
  if (attempt.mode == Mode::Program && tree.mainFile != "physics.cpp")
    list += "root " + tree.mainFile + "\n";
  list += "probe " + std::string(kProbeName) + "\n";
  for (const auto& source : tree.sources) {
    if (source == "physics.cpp" || source == tree.mainFile) continue;
    // Alone, physics.cpp is linked with the probe's main(): no other main() may come in.
    if (attempt.mode == Mode::PhysicsAlone && tree.definesMain.count(source)) continue;
    list += "lib " + source + "\n";
  }
  writeFileWhole((work / "list").string(), list, Existing::Replace);
  writeFileWhole((work / "build.sh").string(), kBuildScript, Existing::Replace);
  return leniencies;
}

struct Compiled {
  bool built = false;
  std::string log;
  std::string firstError;
};

// Runs the build script in the sandbox; on success the program is at `out`/probe.
Compiled compile(const Scratch& scratch, const std::string& out) {
  if (compileSecondsLeft < 1) {
    Compiled none;
    none.firstError = textf(
        "the compiler used the submission's whole budget (%.0f s for all its "
        "attempts): a compile-time loop?",
        compileBudget);
    none.log = none.firstError + "\n";
    return none;
  }
  SandboxJob job;
  job.argv = {"/bin/sh", "/work/build.sh"};
  job.hostDir = scratch.path();
  job.outputDir = out;
  job.workingDir = "/work/build";
  double seconds = std::min(kCompileSeconds, compileSecondsLeft);
  job.limits = {seconds, seconds, 4LL << 30, 16, 256LL << 20, 1LL << 20};
  SandboxResult result = runSandboxed(job);
  compileSecondsLeft -= result.seconds;
  Compiled compiled;
  compiled.built = result.exitedWith(0);
  compiled.log = result.describe() + "\n" + result.errors + result.output;
  compiled.firstError = result.started && !result.timedOut && result.signal == 0
                            ? firstError(result.errors + result.output)
                            : "the compiler " + result.describe();
  return compiled;
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

// Whether a program built whole reaches the grader: its main() runs its setup and calls
// glutMainLoop(). "" when it does; otherwise what happened.
std::string whyNotReaching(const std::string& probePath, std::string* printed) {
  Script script;
  script.world(probeWorld(), probeRun(), restLattice(kCentred));  // the term checks' world, at rest
  script.accelerations();
  ProbeRun run = runProbe(probePath, script);
  std::string failure = run.failure;
  if (failure.rfind("the program never reached", 0) != 0) return "";
  // What it printed says why (a file it could not open): the log keeps the start of it.
  *printed = (run.sandbox.output + run.sandbox.errors).substr(0, kPrintedKept);
  return failure;
}

// A build whose functions end without returning their value, built again with the returns
// added (rewriteMissingReturns); the first build is kept when the second does not build.
void mendMissingReturns(const Scratch& scratch, Compiled& compiled,
                        std::vector<std::string>& leniencies) {
  fs::path work = scratch.path();
  std::map<std::string, std::string> before;  // the files as they were
  for (auto& entry : fs::recursive_directory_iterator(work / "build"))
    if (entry.is_regular_file() && isSource(entry.path()))
      before[entry.path().string()] = readWhole(entry.path());
  std::vector<std::string> notes = rewriteMissingReturns(work / "build", compiled.log);
  if (notes.empty()) return;
  fs::rename(work / "out", work / "out-first");
  Compiled again = compile(scratch, scratch.makeFolder("out"));
  if (again.built) {
    fs::remove_all(work / "out-first");
    again.log = compiled.log + "--- again, with the missing returns added:\n" + again.log;
    compiled = again;
    leniencies.insert(leniencies.end(), notes.begin(), notes.end());
    return;
  }
  for (const auto& [path, text] : before) writeText(path, text);
  fs::remove_all(work / "out");
  fs::rename(work / "out-first", work / "out");
  compiled.log += "--- with the missing returns added, it did not build: kept as it was\n";
}

// One attempt: laid out, flags written, compiled (leniently, once more after the rewrites).
Compiled buildAttempt(const Tree& tree, const Attempt& attempt, const Scratch& scratch,
                      std::vector<std::string>& leniencies) {
  fs::path work = scratch.path();
  layOut(tree, attempt, work);
  leniencies = writeFlags(tree, attempt, work);
  Compiled compiled = compile(scratch, scratch.makeFolder("out"));
  if (compiled.built) mendMissingReturns(scratch, compiled, leniencies);
  if (!attempt.lenient) return compiled;
  // Each rewrite round can let the compiler reach code it did not before: a few rounds.
  for (int round = 0; round < kRewriteRounds && !compiled.built; ++round) {
    std::vector<std::string> rewrites = rewriteForVisualCpp(work / "build", compiled.log);
    if (rewrites.empty()) break;
    leniencies.insert(leniencies.end(), rewrites.begin(), rewrites.end());
    Compiled again = compile(scratch, scratch.makeFolder("out"));
    again.log = compiled.log + "--- again, after the rewrites:\n" + again.log;
    compiled = again;
  }
  for (const auto& header : standInsUsed(compiled.log))
    leniencies.push_back(header + " stood in for (a Windows header)");
  leniencies.push_back(
      "the standard headers another compiler brings in on its own (<string>, <vector>, <cmath>, "
      "...) included before each file, and -fpermissive");
  return compiled;
}

// One attempt, as written, then leniently where that did not compile. True when it built a
// program that reaches the grader (`result` then says how); `programError` keeps why the whole
// program was not graded, for the notes of a later attempt or the diagnosis.
bool tryAttempt(const Tree& tree, Attempt attempt, const Scratch& scratch,
                const std::string& probePath, BuildResult& result, std::string& programError) {
  std::string asWritten;  // the first error of the attempt as written
  for (bool lenient : {false, true}) {
    attempt.lenient = lenient;
    std::vector<std::string> leniencies;
    Compiled compiled = buildAttempt(tree, attempt, scratch, leniencies);
    if (!lenient && !compiled.built) asWritten = compiled.firstError;
    result.log +=
        "--- " + std::string(attempt.words) + (lenient ? ", leniently" : "") + ": " + compiled.log;
    if (result.diagnosis.empty() && !compiled.built) result.diagnosis = compiled.firstError;
    if (!compiled.built) {
      if (lenient && compiled.firstError == asWritten && unmendable(asWritten)) {
        result.log += "--- the other attempts: not tried, " + kUnmendable + "\n";
        result.notes.push_back(kUnmendable);
        return false;
      }
      // Leniency cannot mend a changed API: the grader's own call does not compile.
      bool apiChanged = compiled.firstError.rfind(kApiChanged, 0) == 0;
      if (attempt.mode == Mode::Program && (lenient || apiChanged))
        programError = "its whole program did not build (" + result.diagnosis + ")";
      if (apiChanged) return false;
      continue;
    }
    if (!copyBuiltProgram(scratch.path() + "/out/probe", probePath)) return false;
    if (attempt.mode == Mode::Program) {
      std::string printed;
      std::string notReaching = whyNotReaching(probePath, &printed);
      if (!notReaching.empty()) {
        std::string said = printed.substr(0, printed.find('\n'));
        programError = "its whole program built, but " + notReaching +
                       (said.empty() ? "" : " (it printed \"" + said.substr(0, 120) + "\")");
        result.log +=
            "--- its whole program, run: " + notReaching + "; it printed:\n" + printed + "\n";
        return false;
      }
    }
    if (!programError.empty()) result.notes.push_back(programError + ": physics.cpp graded alone");
    if (lenient) result.notes.push_back("built leniently: as written, " + asWritten);
    for (const auto& leniency : leniencies) result.notes.push_back("leniency: " + leniency);
    result.built = true;
    result.how = std::string(attempt.words) + (lenient ? ", leniently" : "");
    result.diagnosis.clear();
    return true;
  }
  return false;
}

// The files beside the program's source that it may read as it starts (textures, worlds), for
// its runs: the folder its working directory is (programFilesOf).
void copyProgramFiles(const fs::path& root, const std::string& to) {
  fs::remove_all(to);
  fs::create_directories(to);
  for (auto& entry : fs::recursive_directory_iterator(root)) {
    std::string relative = fs::relative(entry.path(), root).generic_string();
    if (!entry.is_regular_file() || isSource(entry.path()) || !plainPath(relative)) continue;
    fs::path target = fs::path(to) / relative;
    fs::create_directories(target.parent_path());
    fs::copy_file(entry.path(), target);
  }
}

}  // namespace

BuildResult buildSubmission(const Submission& submission, const std::string& probePath,
                            double budgetSeconds) {
  auto start = std::chrono::steady_clock::now();
  compileSecondsLeft = compileBudget = budgetSeconds;
  BuildResult result;
  Scratch scratch;
  fs::path sources = fs::path(scratch.path()) / "sources";
  result.diagnosis = copySubmission(submission, scratch, sources.string(), result.notes);
  if (!result.diagnosis.empty()) return result;
  fs::path physics = fs::exists(sources) ? findPhysics(sources) : fs::path();
  if (physics.empty()) {
    result.diagnosis = "no physics.cpp in the submission";
    return result;
  }
  Tree tree = readTree(physics);
  result.notes.insert(result.notes.end(), tree.notes.begin(), tree.notes.end());
  copyProgramFiles(tree.root, programFilesOf(probePath));
  std::string programError;  // why its whole program was not graded
  for (const Attempt& attempt : kAttempts) {
    std::string why = whyNot(tree, attempt);
    if (!why.empty()) {
      result.log += "--- " + std::string(attempt.words) + ": not tried, " + why + "\n";
      continue;
    }
    if (tryAttempt(tree, attempt, scratch, probePath, result, programError)) break;
    if (!result.notes.empty() && result.notes.back() == kUnmendable) break;
  }
  // Nothing built: a whole program that built but never reached the grader says why first
  // (physics.cpp alone then failed for want of what that program's setup defines).
  if (!result.built && programError.rfind("its whole program built", 0) == 0)
    result.diagnosis = programError + "; physics.cpp alone: " + result.diagnosis;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace jello::grader
