// sandbox.cpp: bubblewrap with kernel limits. See sandbox.h for what the program sees.
#include "grader/sandbox.h"

#include <dirent.h>
#include <fcntl.h>
#include <grp.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>

namespace jello::grader {
namespace {

constexpr std::size_t kErrorsKept = 64 << 10;
const char* const kBubblewrap = "/usr/bin/bwrap";

// Sandboxes started by root run under user ids of their own, from this base: RLIMIT_NPROC counts
// processes per user and does not bind root at all. Unique per process (pid) and, among the
// sandboxes of one process (at most one a thread, 256 threads), per call (a counter), below 2^31.
constexpr unsigned kSandboxUidBase = 100000000u;
// The group of every sandbox started by root, which alone may enter the scratch folders.
constexpr gid_t kSandboxGroup = kSandboxUidBase - 1;
constexpr unsigned kSlots = 1024;
std::atomic<unsigned> sandboxCounter{0};

unsigned sandboxUid() {
  unsigned slot = sandboxCounter.fetch_add(1) % kSlots;
  return kSandboxUidBase + (static_cast<unsigned>(getpid()) % 1000000u) * kSlots + slot;
}

// Threads this user runs now (RLIMIT_NPROC counts threads): a user other than root shares the
// limit with them.
int threadsOfUser(uid_t uid) {
  int count = 0;
  DIR* proc = opendir("/proc");
  if (!proc) return 0;
  while (dirent* entry = readdir(proc)) {
    if (entry->d_name[0] < '0' || entry->d_name[0] > '9') continue;
    struct stat info;
    std::string path = std::string("/proc/") + entry->d_name;
    if (stat(path.c_str(), &info) != 0 || info.st_uid != uid) continue;
    DIR* tasks = opendir((path + "/task").c_str());
    if (!tasks) continue;
    while (dirent* task = readdir(tasks)) count += task->d_name[0] != '.';
    closedir(tasks);
  }
  closedir(proc);
  return count;
}

std::vector<std::string> bubblewrapArguments(const SandboxJob& job) {
  // Namespaces of its own (no network), gone with the grader; a new session (no terminal).
  std::vector<std::string> args = {kBubblewrap, "--unshare-all", "--die-with-parent",
                                   "--new-session"};
  // The system's programs and libraries, read-only; nothing else of the host's /etc.
  args.insert(args.end(), {"--ro-bind", "/usr", "/usr", "--symlink", "usr/bin", "/bin", "--symlink",
                           "usr/lib", "/lib", "--symlink", "usr/lib64", "/lib64", "--ro-bind-try",
                           "/etc/ld.so.cache", "/etc/ld.so.cache"});
  // Every writable file system is bounded: /tmp and /dev/shm are tmpfs of a fixed size; the root
  // and /dev are remounted read-only once made (below).
  args.insert(args.end(), {"--proc", "/proc", "--dev", "/dev", "--size",
                           std::to_string(kSandboxShmBytes), "--tmpfs", "/dev/shm", "--size",
                           std::to_string(kSandboxTmpBytes), "--tmpfs", "/tmp"});
  args.insert(args.end(), {"--ro-bind", job.hostDir, "/work"});
  if (!job.outputDir.empty()) args.insert(args.end(), {"--bind", job.outputDir, "/out"});
  for (const auto& [host, inside] : job.readOnlyFiles) {
    args.insert(args.end(), {"--ro-bind", host, inside});
  }
  args.insert(args.end(), {"--remount-ro", "/dev", "--remount-ro", "/"});
  args.insert(args.end(),
              {"--chdir", job.workingDir, "--clearenv", "--setenv", "PATH", "/usr/bin:/bin",
               "--setenv", "HOME", "/tmp", "--setenv", "LC_ALL", "C", "--"});
  args.insert(args.end(), job.argv.begin(), job.argv.end());
  return args;
}

void setLimit(int resource, rlim_t value, rlim_t hardSlack = 0) {
  struct rlimit limit = {value, value + hardSlack};
  setrlimit(resource, &limit);
}

// In the child, between fork and exec: only async-signal-safe calls.
[[noreturn]] void startChild(char* const* argv, const SandboxLimits& limits, int in, int out,
                             int err, int requests, int replies, bool switchUser, unsigned uid,
                             rlim_t processLimit) {
  setsid();
  // SIGXCPU at the soft limit says what happened; SIGKILL a second later if it is ignored.
  setLimit(RLIMIT_CPU, static_cast<rlim_t>(limits.cpuSeconds + 0.5), 1);
  setLimit(RLIMIT_AS, static_cast<rlim_t>(limits.memoryBytes));
  setLimit(RLIMIT_FSIZE, static_cast<rlim_t>(limits.fileBytes));
  setLimit(RLIMIT_CORE, 0);
  if (switchUser) {
    gid_t group = kSandboxGroup;
    if (setgroups(1, &group) != 0 || setgid(uid) != 0 || setuid(uid) != 0) _exit(126);
  }
  setLimit(RLIMIT_NPROC, processLimit);
  // The grader's signal thread blocks these in every other thread; the sandbox gets them back.
  sigset_t none;
  sigemptyset(&none);
  sigprocmask(SIG_SETMASK, &none, nullptr);
  dup2(in, 0);
  dup2(out, 1);
  dup2(err, 2);
  if (requests >= 0) {
    dup2(requests, 3);
    dup2(replies, 4);
  }
  closefrom(requests >= 0 ? 5 : 3);
  // No environment: bubblewrap's own pid 1 keeps the one it is started with.
  char* noEnvironment[] = {nullptr};
  execve(argv[0], argv, noEnvironment);
  _exit(127);
}

void setNonBlocking(int fd) { fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) | O_NONBLOCK); }

struct Pipes {
  int in[2] = {-1, -1}, out[2] = {-1, -1}, err[2] = {-1, -1};
  int requests[2] = {-1, -1}, replies[2] = {-1, -1};
  bool open(bool conversation) {
    bool ok = pipe2(in, O_CLOEXEC) == 0 && pipe2(out, O_CLOEXEC) == 0 && pipe2(err, O_CLOEXEC) == 0;
    if (ok && conversation) ok = pipe2(requests, O_CLOEXEC) == 0 && pipe2(replies, O_CLOEXEC) == 0;
    return ok;
  }
};

void closeFd(int& fd) {
  if (fd >= 0) close(fd);
  fd = -1;
}

// A pipe the grader writes: `data` from `written` on, as the pipe takes it.
struct Feed {
  int fd = -1;
  const std::string* data = nullptr;
  std::size_t written = 0;
  // Writes what the pipe takes now; true when all of `data` is written.
  bool write() {
    ssize_t n = ::write(fd, data->data() + written, data->size() - written);
    if (n > 0) written += static_cast<std::size_t>(n);
    if (n < 0 && errno != EAGAIN) written = data->size();
    return written == data->size();
  }
};

// How many lines "." `text` ends, reading from `from` on; `atLineStart` carries across calls.
std::size_t countEnds(const std::string& text, std::size_t from, bool& atLineStart) {
  std::size_t ends = 0;
  for (std::size_t n = from; n < text.size(); ++n) {
    if (atLineStart && text[n] == '.' && n + 1 < text.size() && text[n + 1] == '\n') ++ends;
    atLineStart = text[n] == '\n';
  }
  return ends;
}

// Feeds the input and the requests (one at a time: the next once the last reply has ended) and
// collects the output, the errors and the replies until they all close, or a limit is hit.
// Reads what the program wrote on stdout (which 0), stderr (1) or the replies' pipe (2) into
// `result`, up to each one's cap: a descriptor at its end is closed; standard output and error
// beyond their caps are read and counted (result.outputDiscarded); replies beyond theirs close
// all three (result.outputCut).
void readOutput(int which, const SandboxJob& job, int& out, int& err, int& replies,
                bool& atLineStart, SandboxResult& result) {
  int& fd = which == 0 ? out : which == 1 ? err : replies;
  if (fd < 0) return;
  char buffer[1 << 16];
  ssize_t n = read(fd, buffer, sizeof buffer);
  if (n <= 0) {
    if (n == 0 || errno != EAGAIN) closeFd(fd);
    return;
  }
  std::string& kept = which == 0 ? result.output : which == 1 ? result.errors : result.replies;
  std::size_t cap = which == 1 ? kErrorsKept : static_cast<std::size_t>(job.limits.outputBytes);
  std::size_t before = kept.size();
  std::size_t taken = std::min(static_cast<std::size_t>(n), cap - std::min(cap, kept.size()));
  kept.append(buffer, taken);
  // What the program prints beyond the cap is read on and counted, never kept: a right program
  // that prints a line a point for 2000 steps is not killed for it. The answers are capped.
  if (which != 2) result.outputDiscarded += static_cast<std::size_t>(n) - taken;
  if (which == 2) result.repliesEnded += countEnds(kept, before, atLineStart);
  if (which == 2 && kept.size() >= cap) {
    result.outputCut = true;
    closeFd(out);
    closeFd(err);
    closeFd(replies);
  }
}

void exchange(pid_t child, const SandboxJob& job, int in, int out, int err, int requests,
              int replies, SandboxResult& result) {
  using Clock = std::chrono::steady_clock;
  auto deadline = Clock::now() + std::chrono::duration<double>(job.limits.wallSeconds);
  Feed input{in, &job.input}, request{requests, nullptr};
  std::size_t sent = 0;  // requests begun
  bool atLineStart = true;
  if (job.input.empty()) closeFd(input.fd);
  while (out >= 0 || err >= 0 || replies >= 0) {
    // The next request, once the greeting and every earlier request are answered; the pipe
    // closes after the last.
    if (request.fd >= 0 && !request.data && sent + 1 == result.repliesEnded) {
      if (sent < job.requests.size()) {
        request = {request.fd, &job.requests[sent++], 0};
      } else {
        closeFd(request.fd);
      }
    }
    pollfd fds[5] = {{out, POLLIN, 0},
                     {err, POLLIN, 0},
                     {replies, POLLIN, 0},
                     {input.fd, POLLOUT, 0},
                     {request.data ? request.fd : -1, POLLOUT, 0}};
    auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
    if (left.count() <= 0) {
      result.timedOut = true;
      break;
    }
    if (poll(fds, 5, static_cast<int>(left.count())) < 0 && errno != EINTR) break;
    if (input.fd >= 0 && (fds[3].revents & (POLLOUT | POLLERR | POLLHUP)) && input.write())
      closeFd(input.fd);
    if (request.data && (fds[4].revents & (POLLOUT | POLLERR | POLLHUP)) && request.write())
      request.data = nullptr;
    for (int which = 0; which < 3; ++which)
      if (fds[which].revents & (POLLIN | POLLHUP | POLLERR))
        readOutput(which, job, out, err, replies, atLineStart, result);
  }
  if (result.timedOut || result.outputCut) kill(-child, SIGKILL);
  closeFd(input.fd);
  closeFd(request.fd);
  closeFd(out);
  closeFd(err);
  closeFd(replies);
}

}  // namespace

// ---- Scratch folders, and their removal when a signal stops the grader -----------------------
namespace {
std::mutex scratchMutex;
std::set<std::string> scratchFolders;  // removed whole on a signal
std::set<std::string> emptyFolders;    // removed on a signal when empty
}  // namespace

Scratch::Scratch() {
  const char* base = std::getenv("TMPDIR");
  std::string pattern = std::string(base && *base ? base : "/tmp") + "/jello-grade-XXXXXX";
  std::lock_guard<std::mutex> lock(scratchMutex);
  if (!mkdtemp(pattern.data())) {
    throw std::runtime_error(pattern + ": cannot make a scratch folder: " + std::strerror(errno));
  }
  path_ = pattern;
  scratchFolders.insert(path_);
  // Only the grader and its sandboxes: a sandbox started by root runs as a user of its own, in
  // the sandboxes' group; what the grader makes inside takes that group (the set-group-id bit).
  if (geteuid() == 0 && chown(path_.c_str(), 0, kSandboxGroup) == 0) {
    chmod(path_.c_str(), 02750);
  } else {
    chmod(path_.c_str(), 0700);
  }
}

Scratch::~Scratch() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
  std::lock_guard<std::mutex> lock(scratchMutex);
  scratchFolders.erase(path_);
}

std::string Scratch::makeFolder(const std::string& name) const {
  std::string folder = path_ + "/" + name;
  std::filesystem::remove_all(folder);
  if (mkdir(folder.c_str(), 0700) != 0) {
    throw std::runtime_error(folder + ": cannot make: " + std::strerror(errno));
  }
  return folder;
}

void removeIfEmptyOnSignal(const std::string& folder) {
  std::lock_guard<std::mutex> lock(scratchMutex);
  emptyFolders.insert(folder);
}

void installScratchCleanup() {
  sigset_t signals;
  sigemptyset(&signals);
  for (int signal : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&signals, signal);
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);
  std::thread([signals] {
    int caught = 0;
    if (sigwait(&signals, &caught) != 0) return;
    {
      std::lock_guard<std::mutex> lock(scratchMutex);
      std::error_code ignored;
      for (const auto& folder : scratchFolders) std::filesystem::remove_all(folder, ignored);
      // Deepest first: a folder sorts before the folders inside it.
      for (auto folder = emptyFolders.rbegin(); folder != emptyFolders.rend(); ++folder)
        rmdir(folder->c_str());
    }
    // The signal again, now to the handler core/output installed (its temporary files), which
    // then ends the program as the signal would have.
    sigset_t only;
    sigemptyset(&only);
    sigaddset(&only, caught);
    pthread_sigmask(SIG_UNBLOCK, &only, nullptr);
    raise(caught);
  }).detach();
}

SandboxResult runSandboxed(const SandboxJob& job) {
  SandboxResult result;
  std::vector<std::string> args = bubblewrapArguments(job);
  std::vector<char*> argv;
  for (auto& arg : args) argv.push_back(arg.data());
  argv.push_back(nullptr);
  bool switchUser = geteuid() == 0;
  unsigned uid = switchUser ? sandboxUid() : static_cast<unsigned>(getuid());
  // The sandbox's processes: bubblewrap, its pid 1, and the program's own.
  rlim_t processLimit = static_cast<rlim_t>(job.limits.processes + 2) +
                        (switchUser ? 0 : static_cast<rlim_t>(threadsOfUser(getuid())));
  if (switchUser && !job.outputDir.empty() && chown(job.outputDir.c_str(), uid, uid) != 0) {
    result.error = job.outputDir + ": cannot hand it to the sandbox: " + std::strerror(errno);
    return result;
  }
  bool conversation = !job.requests.empty();
  Pipes pipes;
  if (!pipes.open(conversation)) {
    result.error = std::string("cannot make pipes: ") + std::strerror(errno);
    return result;
  }
  auto start = std::chrono::steady_clock::now();
  pid_t child = fork();
  if (child == 0) {
    startChild(argv.data(), job.limits, pipes.in[0], pipes.out[1], pipes.err[1], pipes.requests[0],
               pipes.replies[1], switchUser, uid, processLimit);
  }
  for (int* fd :
       {&pipes.in[0], &pipes.out[1], &pipes.err[1], &pipes.requests[0], &pipes.replies[1]})
    closeFd(*fd);
  if (child < 0) {
    result.error = std::string("cannot start a process: ") + std::strerror(errno);
    for (int* fd :
         {&pipes.in[1], &pipes.out[0], &pipes.err[0], &pipes.requests[1], &pipes.replies[0]})
      closeFd(*fd);
    return result;
  }
  result.started = true;
  setNonBlocking(pipes.in[1]);
  if (conversation) setNonBlocking(pipes.requests[1]);
  signal(SIGPIPE, SIG_IGN);
  exchange(child, job, pipes.in[1], pipes.out[0], pipes.err[0], pipes.requests[1], pipes.replies[0],
           result);
  int status = 0;
  while (waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (WIFEXITED(status)) result.exitCode = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) result.signal = WTERMSIG(status);
  // bubblewrap reports its program's death by signal as exit status 128 + the signal.
  if (result.exitCode > 128 && result.exitCode < 128 + 65) {
    result.signal = result.exitCode - 128;
    result.exitCode = -1;
  }
  return result;
}

std::string SandboxResult::describe() const {
  if (!started) return "could not start: " + error;
  if (timedOut) return "did not finish in time";
  if (outputCut) return "answered more than the grader reads";
  if (signal == SIGXCPU) return "ran out of CPU time";
  if (signal == SIGXFSZ) return "wrote a file larger than allowed";
  if (signal != 0)
    return std::string("was killed by signal ") + std::to_string(signal) + " (" +
           strsignal(signal) + ")";
  return "exited with status " + std::to_string(exitCode);
}

std::string sandboxProblem() {
  if (access(kBubblewrap, X_OK) != 0) {
    return "bubblewrap (/usr/bin/bwrap) is not installed: the grader runs submissions only in "
           "its sandbox (Debian package bubblewrap)";
  }
  // A sandbox as the grader makes them: a scratch folder to read and one to write.
  Scratch scratch;
  SandboxJob job;
  job.argv = {"/bin/sh", "-c", "touch /out/written"};
  job.hostDir = scratch.path();
  job.outputDir = scratch.makeFolder("out");
  job.limits.wallSeconds = 20;
  SandboxResult result = runSandboxed(job);
  if (result.exitedWith(0)) return "";
  std::string why = result.errors.substr(0, result.errors.find('\n'));
  return "bubblewrap cannot make a sandbox here (" + (why.empty() ? result.describe() : why) +
         "); the grader runs submissions only in its sandbox";
}

}  // namespace jello::grader
