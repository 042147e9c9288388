// sandbox.h: runs an untrusted program (a submission's build or its probe) inside bubblewrap.
//
// What the program sees: /usr read-only (and /bin, /lib, /lib64 as links into it), a fresh
// /proc and /dev, /etc/ld.so.cache, a private /tmp of kSandboxTmpBytes and /dev/shm of
// kSandboxShmBytes (the root and the rest of /dev read-only), and one folder of the host,
// `hostDir`, read-only at /work, and when given a second, `outputDir`, writable at /out (an empty
// folder the grader made for this sandbox, handed to the sandbox's user). No network, no other
// process, no other file of the host: other submissions and the grader's report are not there to
// read or write. No environment either: bubblewrap itself is started with none, so not even its
// own pid 1 (/proc/1/environ) holds the grader's.
//
// Limits, each enforced by the kernel: CPU seconds and address space per process, processes
// (RLIMIT_NPROC, counted per user: when the grader runs as root each sandbox gets a user id of its
// own, so one submission's fork bomb cannot starve another's), size of any file it writes, and
// the wall clock (the whole sandbox is killed). Standard output and error are kept up to a cap;
// what is written beyond it is read, counted and discarded (never a reason to kill a program).
//
// A conversation (SandboxJob::requests): the grader's requests go in on descriptor 3 and the
// replies come out on descriptor 4, one request at a time. The program speaks first (a greeting,
// reply 0, that says it is ready); request n is written only once reply n has ended (a line
// "."), so the program can never read a request ahead of its answer.
#pragma once

#include <string>
#include <vector>

namespace jello::grader {

constexpr long long kSandboxTmpBytes = 256LL << 20;
constexpr long long kSandboxShmBytes = 16LL << 20;

struct SandboxLimits {
  double cpuSeconds = 10;
  double wallSeconds = 15;
  long long memoryBytes = 2LL << 30;   // address space of each process
  int processes = 16;                  // at once, in the sandbox
  long long fileBytes = 64LL << 20;    // the largest file it may write
  long long outputBytes = 64LL << 20;  // standard output kept (more is discarded) and answers
};

struct SandboxJob {
  std::vector<std::string> argv;     // argv[0] an absolute path inside the sandbox
  std::string hostDir;               // bound read-only at /work
  std::string outputDir;             // when not empty: bound writable at /out
  std::string workingDir = "/work";  // inside the sandbox
  std::vector<std::pair<std::string, std::string>> readOnlyFiles;  // host path, sandbox path
  std::string input;                                               // standard input
  std::vector<std::string> requests;  // when not empty: a conversation on descriptors 3 and 4
  SandboxLimits limits;
};

struct SandboxResult {
  bool started = false;             // false: bubblewrap itself could not run (see `error`)
  int exitCode = -1;                // when it exited
  int signal = 0;                   // when a signal ended it (SIGKILL also for limits below)
  bool timedOut = false;            // killed at the wall-clock limit
  bool outputCut = false;           // killed for answering more than outputBytes
  std::size_t outputDiscarded = 0;  // bytes of standard output and error beyond their caps
  std::string output;               // standard output
  std::string replies;              // a conversation's replies, each ending in a line "."
  std::size_t repliesEnded = 0;     // how many replies ended
  std::string errors;               // standard error, at most 64 KB
  std::string error;                // why it did not start
  double seconds = 0;               // wall clock
  bool exitedWith(int code) const { return signal == 0 && !timedOut && exitCode == code; }
  // "killed by SIGSEGV (segmentation fault)", "did not finish within 15 s", "exited with 3".
  std::string describe() const;
};

// A folder of its own under $TMPDIR (or /tmp), removed with everything in it with the object, or
// when the grader is stopped by a signal (installScratchCleanup). Only the grader and its
// sandboxes can enter it: mode 0700, or when the grader runs as root (whose sandboxes run under
// user ids of their own) 2750 with the sandboxes' group, kSandboxGroup, which every sandbox
// joins and no user of the system has.
class Scratch {
 public:
  Scratch();
  ~Scratch();
  Scratch(const Scratch&) = delete;
  Scratch& operator=(const Scratch&) = delete;
  const std::string& path() const { return path_; }
  // A new empty folder `name` inside, for a sandbox to write (mode 0700).
  std::string makeFolder(const std::string& name) const;

 private:
  std::string path_;
};

SandboxResult runSandboxed(const SandboxJob& job);

// Called once by main before any thread starts: SIGINT, SIGTERM and SIGHUP are then taken by a
// thread of their own, which removes every Scratch folder and every folder given to
// removeIfEmptyOnSignal (a report folder the run made) before the signal ends the program as it
// would have (core/output's cleanup of temporary files included).
void installScratchCleanup();
void removeIfEmptyOnSignal(const std::string& folder);

// "" when bubblewrap can make a sandbox here; otherwise why not, in one line.
std::string sandboxProblem();

}  // namespace jello::grader
