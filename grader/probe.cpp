// probe.cpp: scripts for the probe and their answers (probe.h).
#include "grader/probe.h"

#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include "core/output.h"
#include "grader/submission.h"
#include "io/input.h"
#include "model/term.h"

namespace jello::grader {
namespace {

void appendPoints(std::string& text, const double* values) {
  char line[96];
  for (int q = 0; q < kNumPoints; ++q) {
    Vec3 x = load(values, q);
    std::snprintf(line, sizeof line, "%.17g %.17g %.17g\n", x.x, x.y, x.z);
    text += line;
  }
}

// Reads `count` numbers from `text` at `at`; false when the text ends or holds a non-number.
bool readNumbers(const std::string& text, std::size_t& at, std::size_t count,
                 std::vector<double>& out) {
  const char* start = text.c_str();
  for (std::size_t n = 0; n < count; ++n) {
    char* end = nullptr;
    double value = std::strtod(start + at, &end);
    if (end == start + at) return false;
    at = static_cast<std::size_t>(end - start);
    out.push_back(value);
  }
  return true;
}

bool readWord(const std::string& text, std::size_t& at, const char* word) {
  std::size_t begin = text.find_first_not_of(" \n\t", at);
  if (begin == std::string::npos || text.compare(begin, std::strlen(word), word) != 0) return false;
  at = begin + std::strlen(word);
  return true;
}

// Lattice order "x y z" lines into per-point arrays.
std::vector<double> toArrays(const std::vector<double>& lines, std::size_t points) {
  std::vector<double> arrays(3 * points, 0.0);
  for (std::size_t q = 0; q < points; ++q) {
    for (int axis = 0; axis < 3; ++axis) {
      arrays[axis * points + q] = lines[3 * q + axis];
    }
  }
  return arrays;
}

constexpr double kFirstStretch = 1.05;

// The rest lattice centred on the origin, stretched by kFirstStretch; at rest.
State stretchedLattice() {
  State state;
  for (int q = 0; q < kNumPoints; ++q) {
    Vec3 p = {q / 64 / 7.0 - 0.5, q / 8 % 8 / 7.0 - 0.5, q % 8 / 7.0 - 0.5};
    store(state.p(), q, kFirstStretch * p);
  }
  return state;
}

thread_local double probeBudget = kProbeSeconds;
thread_local bool hung = false;

}  // namespace

void resetProbeBudget() {
  probeBudget = kProbeSeconds;
  hung = false;
}

bool probeHung() { return hung; }

void Script::world(const World& world, const RunSettings& run, const State& state) {
  std::string text = formatWorld(world, run, state);
  // The world file the student's main() reads: this world's parameters with the same cube in
  // every run (the rest lattice about the origin, stretched 5%), so that a setup that takes rest
  // lengths from the initial positions (wrong on a course world that starts deformed,
  // skewedCorner.w) shows in the spring checks, and is the same in every run of a check. The W
  // request then sets the state itself.
  if (firstWorld_.empty()) firstWorld_ = formatWorld(world, run, stretchedLattice());
  pending_ += "W\n" + text;
}

void Script::state(const State& state) {
  pending_ += "S\n";
  appendPoints(pending_, state.p());
  appendPoints(pending_, state.v());
}

void Script::answer(char kind, std::string command, std::string doing) {
  requests_.push_back(pending_ + command);
  pending_.clear();
  answering_.push_back(kind);
  doing_.push_back(std::move(doing));
}

void Script::accelerations() { answer('A', "A\n", "computeAcceleration"); }

void Script::steps(Integrator integrator, long n) {
  bool euler = integrator == Integrator::Euler;
  answer('E', (euler ? "E " : "R ") + std::to_string(n) + "\n", euler ? "Euler" : "RK4");
}

void Script::read() { answer('P', "P\n", "reading the state"); }

void Script::timing(long n) { answer('T', "T " + std::to_string(n) + "\n", "RK4"); }

State ProbeRun::state(std::size_t answer) const {
  State state;
  const std::vector<double>& values = answers.at(answer);
  std::copy(values.begin(), values.end(), state.y.begin());
  return state;
}

std::string programFilesOf(const std::string& probePath) { return probePath + ".files"; }

namespace {

// The answers of a finished run, checked for count and form, into run.answers; run.failure
// says what went wrong (`how` the run ended) when not every request was answered.
void readAnswers(const Script& script, const std::string& how, ProbeRun& run) {
  const std::string& replies = run.sandbox.replies;
  std::size_t at = 0;
  if (!readWord(replies, at, "jello-probe") || !readWord(replies, at, ".")) {
    run.failure = "the program never reached the grader: it " +
                  (run.sandbox.exitedWith(0) ? std::string("ended") : how) +
                  " before its main() called glutMainLoop()";
    return;
  }
  const auto& kinds = script.answering();
  for (std::size_t n = 0; n < kinds.size(); ++n) {
    std::vector<double> numbers;
    bool read =
        kinds[n] == 'E' ? readWord(replies, at, "ok")
        : kinds[n] == 'T'
            ? readNumbers(replies, at, 1, numbers)
            : readNumbers(replies, at, kinds[n] == 'A' ? kNumCoords : 2 * kNumCoords, numbers);
    if (!read || !readWord(replies, at, ".")) {
      run.failure = script.doing()[n] + " " + how;
      break;
    }
    if (kinds[n] == 'A') numbers = toArrays(numbers, kNumPoints);
    if (kinds[n] == 'P') {
      std::vector<double> p(numbers.begin(), numbers.begin() + kNumCoords);
      std::vector<double> v(numbers.begin() + kNumCoords, numbers.end());
      numbers = toArrays(p, kNumPoints);
      std::vector<double> va = toArrays(v, kNumPoints);
      numbers.insert(numbers.end(), va.begin(), va.end());
    }
    run.answers.push_back(std::move(numbers));
  }
}

// The program's own files (programFilesOf) where a run's sandbox finds them, scratch/files: a link
// to each where the file system allows (the run's own scratch folder is what the sandbox's user
// can reach), else a copy. The probe copies them from /work/files (read-only) into /tmp, its
// working directory, before the program starts: a program that writes over one of them can.
void layOutProgramFiles(const std::string& probePath, const Scratch& scratch) {
  namespace fs = std::filesystem;
  if (!fs::is_directory(programFilesOf(probePath))) return;
  std::error_code linked;
  fs::copy(programFilesOf(probePath), scratch.path() + "/files",
           fs::copy_options::recursive | fs::copy_options::create_hard_links, linked);
  if (!linked) return;
  fs::remove_all(scratch.path() + "/files");
  fs::copy(programFilesOf(probePath), scratch.path() + "/files", fs::copy_options::recursive);
}

// How a run that did not answer everything ended, in words.
std::string howItEnded(const SandboxResult& sandbox, const SandboxLimits& limits) {
  if (sandbox.timedOut)
    return textf(
        "did not return within %g s, waiting without computing: a read of the keyboard "
        "or a sleep?",
        limits.wallSeconds);
  if (sandbox.signal == SIGXCPU)
    return textf("did not return within %g s: an endless loop?", limits.cpuSeconds);
  if (sandbox.signal == SIGKILL && !sandbox.outputCut) return "was killed (out of memory?)";
  return sandbox.exitedWith(0) ? "gave no answer" : sandbox.describe();
}

}  // namespace

ProbeRun runProbe(const std::string& probePath, const Script& script, ProbeLimits limits) {
  ProbeRun run;
  Scratch scratch;
  std::filesystem::copy_file(probePath, scratch.path() + "/probe");
  std::filesystem::permissions(scratch.path() + "/probe", std::filesystem::perms(0755));
  // The world file the student's own main() reads: the script's first world.
  writeFileWhole(scratch.path() + "/world.w", script.firstWorld(), Existing::Refuse);
  layOutProgramFiles(probePath, scratch);
  SandboxJob job;
  job.argv = {"/work/probe", "/work/world.w"};
  job.hostDir = scratch.path();
  job.workingDir = "/tmp";
  job.requests = script.requests();
  // Time is judged in CPU seconds, which a busy machine does not take from the program; the
  // wall clock is a backstop for a program that waits (sleeps, reads) instead of computing.
  job.limits.cpuSeconds = limits.scale * probeBudget;
  job.limits.wallSeconds = kWallBackstop * job.limits.cpuSeconds;
  job.limits.memoryBytes = 1LL << 30;
  job.limits.processes = 8;
  job.limits.fileBytes = 16LL << 20;
  run.sandbox = runSandboxed(job);
  if (run.sandbox.timedOut || run.sandbox.signal == SIGXCPU) {
    probeBudget = kProbeSecondsAfterHang;
    hung = true;
  }
  readAnswers(script, howItEnded(run.sandbox, job.limits), run);
  return run;
}

bool allUsable(const std::vector<double>& values) {
  for (double value : values) {
    if (!(std::fabs(value) <= kLargestAnswer)) return false;  // NaN fails too
  }
  return true;
}

}  // namespace jello::grader
