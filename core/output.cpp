// output.cpp: whole-file writes, folder claims, signal cleanup and one-line errors. See
// output.h for the rules; comments here say why the code keeps them the way it does.

#include "core/output.h"

#include <fcntl.h>
#include <limits.h>
#include <pthread.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <mutex>

namespace jello {

namespace {

// ---- Temporary files to remove on a signal -------------------------------------------------
// A signal handler may call only async-signal-safe functions, so the names live in fixed
// buffers it can read without locking: a slot is filled first and marked in use after.
constexpr int kTemporarySlots = 16;  // writes under way at once (one per thread at most)
struct TemporarySlot {
  std::atomic<bool> used{false};
  char path[PATH_MAX];
};
std::array<TemporarySlot, kTemporarySlots> temporaries;
std::mutex temporariesMutex;

void rememberTemporary(const std::string& path) {
  std::lock_guard<std::mutex> lock(temporariesMutex);
  for (TemporarySlot& slot : temporaries) {
    if (slot.used.load()) continue;
    if (path.size() >= sizeof slot.path) return;  // cannot happen: mkstemp took the name
    std::memcpy(slot.path, path.c_str(), path.size() + 1);
    slot.used.store(true);
    return;
  }
}

void forgetTemporary(const std::string& path) {
  std::lock_guard<std::mutex> lock(temporariesMutex);
  for (TemporarySlot& slot : temporaries)
    if (slot.used.load() && path == slot.path) slot.used.store(false);
}

// The handlers these replaced, per signal: a second copy of this file (one linked into the
// graphics library, which keeps its own copy of the list) installs its handler too, and each
// cleans its own list, then hands the signal on, the last one to the default action.
constexpr int kCleanedSignals[] = {SIGINT, SIGTERM, SIGHUP};
struct sigaction previousActions[3];
bool installed = false;

constexpr int kChildSlots = 8;
std::array<std::atomic<int>, kChildSlots> children{};

extern "C" void removeTemporariesAndDie(int signal) {
  for (std::atomic<int>& child : children) {
    const int pid = child.load();
    if (pid > 0 && ::kill(pid, SIGKILL) == 0) ::waitpid(pid, nullptr, 0);
  }
  for (TemporarySlot& slot : temporaries)
    if (slot.used.load()) ::unlink(slot.path);
  for (int n = 0; n < 3; ++n) {
    const struct sigaction& previous = previousActions[n];
    if (kCleanedSignals[n] != signal || (previous.sa_flags & SA_SIGINFO) ||
        previous.sa_handler == SIG_DFL || previous.sa_handler == SIG_IGN)
      continue;
    previous.sa_handler(signal);  // the other copy's cleanup, which ends the program
    return;
  }
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

std::string withError(const std::string& path, const std::string& what, int error) {
  return path + ": " + what + (error ? std::string(": ") + std::strerror(error) : "");
}

mode_t defaultMode() {
  mode_t mask = ::umask(0);
  ::umask(mask);
  return 0666 & ~mask;
}

// Why an existing entry at `path` may not be replaced (also when nothing is there, none).
WriteCheck whyNotReplaceable(const std::string& path, Existing existing, struct stat* found) {
  if (::lstat(path.c_str(), found) != 0) {
    found->st_mode = 0;
    return {};
  }
  if (S_ISLNK(found->st_mode)) return {"is a symbolic link; name the file itself"};
  if (S_ISDIR(found->st_mode)) return {"is a directory"};
  if (!S_ISREG(found->st_mode))
    return {"is not a regular file (a device, FIFO or socket); it is never replaced"};
  if (existing == Existing::Refuse) return {"already exists", true};
  if ((found->st_mode & 0222) == 0 || ::access(path.c_str(), W_OK) != 0)
    return {"is read-only; it is not replaced"};
  return {};
}

std::string temporaryTemplate(const std::string& dir, const std::string& suffix) {
  return dir + "/.jello-XXXXXX" + suffix;
}

// Gives the finished temporary file its name: rename replaces, link refuses an existing name
// (the check and the write are one atomic step).
void nameTemporary(const std::string& temporary, const std::string& path, Existing existing) {
  struct stat found {};
  std::string why = whyNotReplaceable(path, existing, &found).why;
  if (!why.empty()) throw OutputError(path + ": " + why);
  if (found.st_mode != 0)
    ::chmod(temporary.c_str(), found.st_mode & 07777);  // keep the user's mode
  if (existing == Existing::Replace) {
    if (::rename(temporary.c_str(), path.c_str()) != 0)
      throw OutputError(withError(path, "cannot write", errno));
    return;
  }
  if (::link(temporary.c_str(), path.c_str()) != 0) {
    int error = errno;
    throw OutputError(error == EEXIST ? path + ": already exists"
                                      : withError(path, "cannot write", error));
  }
  ::unlink(temporary.c_str());
}

}  // namespace

std::string whyNotWritable(const std::string& path, Existing existing) {
  return checkWritable(path, existing).why;
}

WriteCheck checkWritable(const std::string& path, Existing existing) {
  if (path.empty()) return {"an empty name"};
  struct stat found {};
  WriteCheck replaceable = whyNotReplaceable(path, existing, &found);
  if (!replaceable.writable()) return replaceable;
  const std::size_t slash = path.find_last_of('/');
  const std::string dir = folderOf(path),
                    name = slash == std::string::npos ? path : path.substr(slash + 1);
  if (name.empty()) return {"names a folder, not a file"};
  struct stat info {};
  if (::stat(dir.c_str(), &info) != 0)
    return {"cannot write into " + dir + ": " + std::strerror(errno)};
  if (!S_ISDIR(info.st_mode)) return {"cannot write into " + dir + ": it is not a folder"};
  if (::access(dir.c_str(), W_OK) != 0)
    return {"cannot write into " + dir + ": " + std::strerror(errno)};
  long longest = ::pathconf(dir.c_str(), _PC_NAME_MAX);
  if (longest <= 0) longest = NAME_MAX;
  if (name.size() > static_cast<std::size_t>(longest))
    return {"the name is " + std::to_string(name.size()) + " bytes long, more than the " +
            std::to_string(longest) + " its folder's file system allows"};
  if (path.size() >= PATH_MAX)
    return {"the path is longer than the system's " + std::to_string(PATH_MAX) + " bytes"};
  return {};
}

void removeOutputs(const std::string& dir, const std::vector<std::string>& names) {
  for (const std::string& name : names) {
    const WriteCheck check = checkWritable(dir + "/" + name, Existing::Replace);
    if (!check.writable())
      throw OutputError(dir + "/" + name + ": " + check.why.substr(0, check.why.find(";")) +
                        "; --overwrite replaces only "
                        "regular files it may write: move it away, or choose another folder");
  }
  for (const std::string& name : names) {
    if (::unlink((dir + "/" + name).c_str()) != 0)
      throw OutputError(withError(dir + "/" + name, "cannot remove", errno));
  }
}

namespace {

// Signals wait while it lives: a temporary file made and remembered in one step, so that a
// signal cannot end the program between the two and leave the file behind.
class SignalsHeld {
 public:
  SignalsHeld() {
    sigset_t every;
    ::sigfillset(&every);
    ::pthread_sigmask(SIG_BLOCK, &every, &before_);
  }
  ~SignalsHeld() { ::pthread_sigmask(SIG_SETMASK, &before_, nullptr); }
  SignalsHeld(const SignalsHeld&) = delete;
  SignalsHeld& operator=(const SignalsHeld&) = delete;

 private:
  sigset_t before_;
};

}  // namespace

std::string makeTemporary(const std::string& dir, const std::string& suffix) {
  std::string temporary = temporaryTemplate(dir, suffix);
  const SignalsHeld held;
  int fd = ::mkstemps(temporary.data(), static_cast<int>(suffix.size()));
  if (fd < 0) throw OutputError(withError(dir, "cannot write", errno));
  rememberTemporary(temporary);
  ::close(fd);
  return temporary;
}

void discardTemporary(const std::string& temporary) {
  ::unlink(temporary.c_str());
  forgetTemporary(temporary);
}

void publishTemporary(const std::string& temporary, const std::string& path, Existing existing) {
  struct stat info {};
  try {
    if (::stat(temporary.c_str(), &info) != 0 || info.st_size == 0)
      throw OutputError(path + ": was not written (empty)");
    ::chmod(temporary.c_str(), defaultMode());
    nameTemporary(temporary, path, existing);
  } catch (...) {
    discardTemporary(temporary);
    throw;
  }
  forgetTemporary(temporary);
}

void writeFileWhole(const std::string& path, const std::function<void(std::FILE*)>& fill,
                    Existing existing) {
  std::string why = whyNotWritable(path, existing);
  if (!why.empty()) throw OutputError(path + ": " + why);
  std::string temporary = temporaryTemplate(folderOf(path), "");
  int fd = -1;
  {
    const SignalsHeld held;
    fd = ::mkstemp(temporary.data());
    if (fd >= 0) rememberTemporary(temporary);
  }
  if (fd < 0) throw OutputError(withError(path, "cannot write", errno));
  std::FILE* file = ::fdopen(fd, "wb");
  if (!file) {
    int error = errno;
    ::close(fd);
    discardTemporary(temporary);
    throw OutputError(withError(path, "cannot write", error));
  }
  try {
    try {
      fill(file);
    } catch (const OutputError&) {
      throw;
    } catch (const std::exception& e) {
      throw OutputError(path + ": " + e.what());
    }
    // A full disk shows at the flush or at fsync, not necessarily at fwrite.
    if (std::fflush(file) != 0 || std::ferror(file) || ::fsync(fd) != 0)
      throw OutputError(withError(path, "cannot write", errno));
    ::fchmod(fd, defaultMode());
    std::FILE* closing = file;
    file = nullptr;
    if (std::fclose(closing) != 0) throw OutputError(withError(path, "cannot write", errno));
    nameTemporary(temporary, path, existing);
  } catch (...) {
    if (file) std::fclose(file);
    discardTemporary(temporary);
    throw;
  }
  forgetTemporary(temporary);
}

void writeFileWhole(const std::string& path, std::string_view bytes, Existing existing) {
  writeFileWhole(
      path,
      [bytes](std::FILE* file) {
        // Not an OutputError: the caller above puts the file's name before it.
        if (!bytes.empty() && std::fwrite(bytes.data(), 1, bytes.size(), file) != bytes.size())
          throw std::runtime_error(std::string("cannot write: ") + std::strerror(errno));
      },
      existing);
}

FolderClaim::FolderClaim(FolderClaim&& other) noexcept : fd_(other.fd_) { other.fd_ = -1; }
FolderClaim& FolderClaim::operator=(FolderClaim&& other) noexcept {
  if (this != &other) {
    if (fd_ >= 0) ::close(fd_);
    fd_ = other.fd_;
    other.fd_ = -1;
  }
  return *this;
}
FolderClaim::~FolderClaim() {
  if (fd_ >= 0) ::close(fd_);
}

FolderClaim claimFolder(const std::string& dir) {
  if (dir.empty()) throw OutputError("an empty folder name");
  // mkdir -p: each missing level made in turn; EEXIST is another run (or a user) being first.
  for (std::size_t slash = dir.find('/', 1);; slash = dir.find('/', slash + 1)) {
    const std::string prefix = dir.substr(0, slash);
    if (::mkdir(prefix.c_str(), 0777) != 0 && errno != EEXIST)
      throw OutputError(withError(prefix, "cannot make the folder", errno));
    if (slash == std::string::npos) break;
  }
  FolderClaim claim;
  // O_CLOEXEC: a child program (gnuplot) must not hold the claim past its parent.
  claim.fd_ = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (claim.fd_ < 0) throw OutputError(withError(dir, "not a folder", errno));
  // flock, not a lock file: the lock ends with the process, however it ends, so a killed run
  // leaves nothing that blocks the next one.
  if (::flock(claim.fd_, LOCK_EX | LOCK_NB) != 0)
    throw OutputError(dir + ": in use by another run; wait for it, or choose another folder");
  if (::access(dir.c_str(), W_OK) != 0) throw OutputError(withError(dir, "cannot write", errno));
  return claim;
}

std::string folderOf(const std::string& path) {
  std::size_t slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

bool heldByAnotherRun(const std::string& dir) {
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return false;
  const bool held = ::flock(fd, LOCK_EX | LOCK_NB) != 0 && errno == EWOULDBLOCK;
  ::close(fd);  // and with it the lock taken to ask
  return held;
}

std::string makeNewFolder(const std::string& parent, const std::string& stem) {
  claimFolder(parent);  // made when missing; the claim ends at once
  constexpr int kMostFolders = 9999;
  for (int i = 1; i <= kMostFolders; ++i) {
    char suffix[16];
    std::snprintf(suffix, sizeof suffix, "-%03d", i);
    const std::string candidate = parent + "/" + stem + suffix;
    if (::mkdir(candidate.c_str(), 0777) == 0) return candidate;
    if (errno != EEXIST) throw OutputError(withError(candidate, "cannot make the folder", errno));
  }
  throw OutputError(parent + ": holds " + std::to_string(kMostFolders) + " folders of " + stem +
                    " already");
}

FolderClaim claimOutputs(const std::string& dir, const std::vector<std::string>& names,
                         Existing existing) {
  FolderClaim claim = claimFolder(dir);
  for (const std::string& name : names) {
    const std::string path = dir + "/" + name;
    const WriteCheck check = checkWritable(path, existing);
    if (check.alreadyExists)
      throw OutputError(path + ": " + check.why + "; choose another folder, or add --overwrite");
    if (!check.writable()) throw OutputError(path + ": " + check.why);
  }
  return claim;
}

void rememberChild(int pid) {
  for (std::atomic<int>& child : children) {
    int none = 0;
    if (child.compare_exchange_strong(none, pid)) return;
  }
}

void forgetChild(int pid) {
  for (std::atomic<int>& child : children) {
    int ours = pid;
    child.compare_exchange_strong(ours, 0);
  }
}

void installSignalCleanup() {
  if (installed) return;
  installed = true;
  for (int n = 0; n < 3; ++n) {
    struct sigaction action {};
    action.sa_handler = removeTemporariesAndDie;
    sigemptyset(&action.sa_mask);
    ::sigaction(kCleanedSignals[n], &action, &previousActions[n]);
  }
}

bool sameFile(const std::string& a, const std::string& b) {
  struct stat first {
  }, second{};
  return ::stat(a.c_str(), &first) == 0 && ::stat(b.c_str(), &second) == 0 &&
         first.st_dev == second.st_dev && first.st_ino == second.st_ino;
}

namespace {
// Length of the valid UTF-8 sequence starting at s[i] (1 to 4), or 0 when there is none.
std::size_t utf8Length(std::string_view s, std::size_t i) {
  const auto byte = [&s](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char lead = byte(i);
  std::size_t length = lead < 0x80           ? 1
                       : (lead >> 5) == 0x6  ? 2
                       : (lead >> 4) == 0xE  ? 3
                       : (lead >> 3) == 0x1E ? 4
                                             : 0;
  if (length == 0 || i + length > s.size()) return 0;
  for (std::size_t k = 1; k < length; ++k)
    if ((byte(i + k) >> 6) != 0x2) return 0;
  if (length == 2 && lead < 0xC2) return 0;  // overlong
  if (length == 3) {
    const unsigned char second = byte(i + 1);
    if ((lead == 0xE0 && second < 0xA0) || (lead == 0xED && second >= 0xA0))
      return 0;  // overlong, surrogate
  }
  if (length == 4) {
    const unsigned char second = byte(i + 1);
    if ((lead == 0xF0 && second < 0x90) || (lead == 0xF4 && second >= 0x90) || lead > 0xF4)
      return 0;
  }
  return length;
}
}  // namespace

namespace {

// The code point of the well-formed UTF-8 sequence of `length` bytes at `i`.
unsigned codePoint(std::string_view text, std::size_t i, std::size_t length) {
  static const unsigned kFirstMask[5] = {0, 0x7F, 0x1F, 0x0F, 0x07};
  unsigned code = static_cast<unsigned char>(text[i]) & kFirstMask[length];
  for (std::size_t k = 1; k < length; ++k)
    code = (code << 6) | (static_cast<unsigned char>(text[i + k]) & 0x3F);
  return code;
}

// Whether the sequence at `i` is a control a terminal or a reader acts on though it is not below
// U+0020: a C1 control or a bidirectional formatting character.
bool isHiddenControl(std::string_view text, std::size_t i, std::size_t length) {
  if (length < 2) return false;
  unsigned code = codePoint(text, i, length);
  return (code >= 0x80 && code <= 0x9F) || (code >= 0x202A && code <= 0x202E) ||
         (code >= 0x2066 && code <= 0x2069) || code == 0x200E || code == 0x200F;
}

}  // namespace

std::string printable(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    const std::size_t length = utf8Length(text, i);
    if (c == '\\') {
      out += "\\\\";
    } else if (length == 0 || c < 0x20 || c == 0x7F) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02X", c);
      out += escaped;
    } else if (isHiddenControl(text, i, length)) {
      // A C1 control (U+0080-U+009F: U+009B is a terminal's CSI) or a bidirectional override
      // (U+202A-U+202E, U+2066-U+2069, U+200E, U+200F), which reorders what a reader sees.
      char escaped[16];
      std::snprintf(escaped, sizeof escaped, "\\u%04X", codePoint(text, i, length));
      out += escaped;
      i += length;
      continue;
    } else {
      out.append(text.substr(i, length));
      i += length;
      continue;
    }
    ++i;
  }
  return out;
}

bool isUtf8(std::string_view text) {
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t length = utf8Length(text, i);
    if (length == 0) return false;
    i += length;
  }
  return true;
}

namespace {
const char* programName = "jello";
}

void setProgramName(const char* name) { programName = name; }

std::string unwrittenStandardOutput() {
  errno = 0;
  const bool flushed = std::fflush(stdout) == 0;
  const int error = errno;  // the flush's own, never an earlier call's
  if (flushed && !std::ferror(stdout)) return "";
  return std::string("cannot write to standard output") +
         (!flushed && error != 0 ? std::string(": ") + std::strerror(error) : "");
}

void printError(std::string_view message) {
  std::fprintf(stderr, "%s: %s\n", programName, printable(message).c_str());
}

}  // namespace jello
