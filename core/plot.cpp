// plot.cpp: gnuplot started without a shell, its picture written whole.

#include "core/plot.h"

#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace jello {

namespace {

constexpr int kExecFailed = 127;  // the child's status when gnuplot could not be started

// Runs gnuplot in `dir` with `png` set to `output`; its exit status, or -1 when it could not
// be started at all. *startError: errno of a start that failed (ENOENT: no gnuplot), told by
// the child through a pipe that closes on exec.
int runGnuplot(const std::string& dir, const std::string& script, const std::string& output,
               int* startError) {
  const std::string setOutput = "png='" + output + "'";  // output is our own temporary name
  int told[2];
  if (::pipe2(told, O_CLOEXEC) != 0) return -1;
  // Signals wait until the child is remembered: one arriving between the fork and
  // rememberChild would end us and leave gnuplot to write its picture after us.
  sigset_t every, before;
  ::sigfillset(&every);
  ::pthread_sigmask(SIG_BLOCK, &every, &before);
  pid_t child = ::fork();
  if (child < 0) {
    *startError = errno;
    ::pthread_sigmask(SIG_SETMASK, &before, nullptr);
    ::close(told[0]);
    ::close(told[1]);
    return -1;
  }
  if (child == 0) {
    ::pthread_sigmask(SIG_SETMASK, &before, nullptr);
    ::close(told[0]);
    int quiet = ::open("/dev/null", O_RDWR);
    if (quiet >= 0) {
      ::dup2(quiet, STDIN_FILENO);
      ::dup2(quiet, STDOUT_FILENO);
      ::dup2(quiet, STDERR_FILENO);
    }
    if (::chdir(dir.c_str()) == 0) {
      const char* argv[] = {"gnuplot", "-e", setOutput.c_str(), script.c_str(), nullptr};
      ::execvp(argv[0], const_cast<char* const*>(argv));
    }
    const int error = errno;
    (void)!::write(told[1], &error, sizeof error);
    ::_exit(kExecFailed);
  }
  rememberChild(child);  // killed with us by a signal: it would write its picture after us
  ::pthread_sigmask(SIG_SETMASK, &before, nullptr);
  ::close(told[1]);
  *startError = 0;
  while (::read(told[0], startError, sizeof *startError) < 0 && errno == EINTR) {
  }
  ::close(told[0]);
  int status = 0;
  while (::waitpid(child, &status, 0) < 0)
    if (errno != EINTR) {
      forgetChild(child);
      return -1;
    }
  forgetChild(child);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// gnuplot exits 0 even when it could not write its picture whole (a full disk): a PNG is
// complete when it starts with its signature and ends with its IEND chunk.
bool isCompletePng(const std::string& path) {
  static const unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  static const unsigned char kEnd[8] = {'I',  'E',  'N',  'D',
                                        0xAE, 0x42, 0x60, 0x82};  // type and CRC
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) return false;
  unsigned char head[8] = {}, tail[8] = {};
  bool complete = std::fread(head, 1, 8, file) == 8 && std::fseek(file, -8, SEEK_END) == 0 &&
                  std::fread(tail, 1, 8, file) == 8 && std::memcmp(head, kSignature, 8) == 0 &&
                  std::memcmp(tail, kEnd, 8) == 0;
  std::fclose(file);
  return complete;
}

}  // namespace

std::string drawWithGnuplot(const std::string& dir, const std::string& script,
                            const std::string& png, Existing existing) {
  std::string temporary;
  try {
    temporary = makeTemporary(dir, ".png");
  } catch (const OutputError& e) {
    return e.what();
  }
  const std::string name = temporary.substr(temporary.find_last_of('/') + 1);
  int startError = 0;
  const int status = runGnuplot(dir, script, name, &startError);
  if (status != 0 || !isCompletePng(temporary)) {
    discardTemporary(temporary);
    // Not installed only when there is no gnuplot to start; one that could not start (memory,
    // processes) is a failure.
    if (startError == ENOENT) return kGnuplotMissing;
    if (startError != 0)
      return std::string("gnuplot could not start: ") + std::strerror(startError);
    return status != 0 ? "gnuplot failed" : "gnuplot could not write it whole";
  }
  try {
    publishTemporary(temporary, dir + "/" + png, existing);
  } catch (const OutputError& e) {
    return e.what();
  }
  return {};
}

std::string gnuplotString(std::string_view text) {
  std::string quoted = "'";
  for (char c : printable(text)) quoted += c == '\'' ? std::string("''") : std::string(1, c);
  return quoted + "'";
}

}  // namespace jello
