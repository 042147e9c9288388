// progress.h: the one progress line of a long piece of work (a headless run, a report, a
// stability map) on stderr. It is rewritten in place (a carriage return, no newline) and shown
// only when stderr is a terminal: a log or a pipe never holds one. It ends with a newline when
// the Progress object goes (or at finish()), so what the work prints next starts a line of its
// own, and the last state of the work stays readable above it.
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
  // Ends the line shown (if any) with a newline, before the work prints its results; the
  // destructor does it otherwise. Show the work's final state first.
  void finish();
  // True when a line is shown and not yet ended.
  bool shown() const { return width_ > 0; }

 private:
  bool enabled_;
  std::size_t width_ = 0;  // characters of the longest line shown: what a shorter one blanks out
};

}  // namespace jello
