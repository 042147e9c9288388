// progress.h: the one progress line of a long piece of work (a headless run, a report, a
// stability map) on stderr. It is rewritten in place (a carriage return, no newline) and shown
// only when stderr is a terminal: a log or a pipe never holds one. It is wiped when the
// Progress object goes, so the object lives exactly as long as the work it reports on.
#pragma once

#include <cstddef>
#include <string>

namespace jello {

class Progress {
 public:
  Progress();
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  // True when stderr is a terminal, so that show() prints: a caller may skip making the text.
  bool enabled() const { return enabled_; }
  // Replaces the line shown with `line` (one line, no newline).
  void show(const std::string& line);
  // Wipes the line now, before the work prints its results; the destructor does it otherwise.
  void finish();

 private:
  bool enabled_;
  std::size_t width_ = 0;  // characters of the longest line shown: what a shorter one blanks out
};

}  // namespace jello
