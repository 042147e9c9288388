// frames.cpp: numbered JPEG frames.

#include "graphics/frames.h"

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
  try {
    claim_ = claimFolder(dir_);
  } catch (const OutputError& e) {
    throw FrameError(e.what());
  }
  std::vector<std::string> old = frameNames(dir_);
  if (!old.empty() && !overwrite_) {
    throw FrameError(dir_ + " already holds " + std::to_string(old.size()) +
                     " frames; choose another folder, or add --overwrite to replace them");
  }
  try {
    removeOutputs(dir_, old);
  } catch (const OutputError& e) {
    throw FrameError(e.what());
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
