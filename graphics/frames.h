// frames.h: a numbered sequence of JPEG frames in a folder: DIR/0000.jpg, DIR/0001.jpg, ...
// Never overwrites frames a user already has unless asked to.
#pragma once

#include <stdexcept>
#include <string>

#include "app/pictures.h"
#include "core/output.h"
#include "graphics/image.h"

namespace jello {

class FrameError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class FrameSequence {
 public:
  FrameSequence(std::string dir, int maxFrames, bool overwrite);

  // Makes the folder (and its parents) when missing and claims it for this sequence (output.h:
  // a second run naming it is refused while this one holds it). When it already holds frames
  // (NNNN.jpg), refuses with a FrameError naming it, or, with overwrite, removes them so the
  // new sequence has no stale tail. Throws FrameError with a one-line message.
  void open();

  // Writes the next frame; false once maxFrames have been written (nothing is written then).
  bool save(const Image& image);

  bool full() const { return written_ >= maxFrames_; }
  int written() const { return written_; }
  int maxFrames() const { return maxFrames_; }
  const std::string& dir() const { return dir_; }
  std::string pathOf(int frame) const;

 private:
  std::string dir_;
  int maxFrames_;
  bool overwrite_;
  bool opened_ = false;
  FolderClaim claim_;
  int written_ = 0;
};

// The number of files named like frames (NNNN.jpg) in dir; 0 when dir does not exist.
int countFrames(const std::string& dir);

}  // namespace jello
