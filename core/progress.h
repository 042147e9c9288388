// progress.h: the one progress line of a long piece of work (a headless run, a report, a
// stability map) on stderr. It is rewritten in place (a carriage return, no newline) and shown
// only when stderr is a terminal: a log or a pipe never holds one. It is cut to the terminal's
// width, since a carriage return goes back to the start of the last screen row only and a
// wrapped line would leave its first rows behind. It is wiped when the Progress object goes
// (or ended with a newline by finish(lastLine)), so the object lives exactly as long as the
// work it reports on.
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
  // Wipes the line now (work that stops with an error message); the destructor does it
  // otherwise.
  void finish();
  // True when a line is shown and not yet ended.
  bool shown() const { return width_ > 0; }
  // Replaces the line with `lastLine` and ends it with a newline, so that it stays on the
  // terminal above what the work prints next (a report's summary on stdout).
  void finish(const std::string& lastLine);

 private:
  bool enabled_;
  std::size_t width_ = 0;  // characters of the longest line shown: what a shorter one blanks out
};

}  // namespace jello
