// core/readfile.cpp: a whole regular file read into memory (readfile.h).

#include "core/readfile.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace jello {

bool readRegularFile(const std::string& path, std::size_t maxBytes, const std::string& what,
                     const std::string& limit, std::string* text, std::string* why) {
  // O_NONBLOCK: a FIFO's open does not wait for a writer (it is then refused as not a regular
  // file).
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) return *why = path + ": cannot open: " + std::strerror(errno), false;
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat info {};
  if (::fstat(fd, &info) != 0 || !S_ISREG(info.st_mode))
    return *why = path + ": not a regular file (" + what + " is read whole)", false;
  if (static_cast<std::size_t>(info.st_size) > maxBytes)
    return *why = path + ": larger than " + limit, false;
  text->assign(static_cast<std::size_t>(info.st_size), '\0');
  std::size_t got = 0;
  while (got < text->size()) {
    const ssize_t n = ::read(fd, &(*text)[got], text->size() - got);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return *why = path + ": cannot read: " + std::strerror(n < 0 ? errno : EIO), false;
    got += static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace jello
