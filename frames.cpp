// frames.cpp: numbered JPEG frames.

#include "frames.h"

#include <dirent.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <vector>

namespace jello {

namespace {

bool isFrameName(const char* name) {
  for (int i = 0; i < kFrameDigits; ++i)
    if (!std::isdigit(static_cast<unsigned char>(name[i]))) return false;
  return std::strcmp(name + kFrameDigits, ".jpg") == 0;
}

std::vector<std::string> frameNames(const std::string& dir) {
  std::vector<std::string> names;
  DIR* d = ::opendir(dir.c_str());
  if (!d) return names;
  while (dirent* entry = ::readdir(d))
    if (isFrameName(entry->d_name)) names.push_back(entry->d_name);
  ::closedir(d);
  return names;
}

bool isDirectory(const std::string& path) {
  struct stat info {};
  return ::stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode);
}

// mkdir -p
void makeDirectories(const std::string& dir) {
  for (std::size_t slash = 1; slash != std::string::npos;) {
    slash = dir.find('/', slash + 1);
    std::string prefix = dir.substr(0, slash);
    if (prefix.empty() || isDirectory(prefix)) continue;
    if (::mkdir(prefix.c_str(), 0777) != 0 && errno != EEXIST) {
      throw FrameError(dir + ": cannot make the folder: " + std::strerror(errno));
    }
  }
  if (!isDirectory(dir)) throw FrameError(dir + ": not a folder");
}

}  // namespace

FrameSequence::FrameSequence(std::string dir, int maxFrames, bool overwrite)
    : dir_(std::move(dir)), maxFrames_(maxFrames), overwrite_(overwrite) {
  while (dir_.size() > 1 && dir_.back() == '/') dir_.pop_back();
}

std::string FrameSequence::pathOf(int frame) const {
  char name[32];
  std::snprintf(name, sizeof name, "/%0*d.jpg", kFrameDigits, frame);
  return dir_ + name;
}

void FrameSequence::open() {
  if (opened_) return;
  makeDirectories(dir_);
  std::vector<std::string> old = frameNames(dir_);
  if (!old.empty() && !overwrite_) {
    throw FrameError(dir_ + " already holds " + std::to_string(old.size()) +
                     " frames; choose another folder, or add --overwrite to replace them");
  }
  for (const std::string& name : old) {
    if (::unlink((dir_ + "/" + name).c_str()) != 0) {
      throw FrameError(dir_ + "/" + name + ": cannot remove: " + std::strerror(errno));
    }
  }
  if (::access(dir_.c_str(), W_OK) != 0) {
    throw FrameError(dir_ + ": cannot write: " + std::strerror(errno));
  }
  opened_ = true;
}

bool FrameSequence::save(const Image& image) {
  if (full()) return false;
  open();
  try {
    writeJpeg(pathOf(written_), image);
  } catch (const std::runtime_error& e) {
    throw FrameError(e.what());
  }
  ++written_;
  return true;
}

int countFrames(const std::string& dir) { return static_cast<int>(frameNames(dir).size()); }

}  // namespace jello
