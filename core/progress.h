// progress.h: the one progress line of a long piece of work (a headless run, a report, a
// stability map) on stderr. On a terminal it is rewritten in place (a carriage return, no
// newline), cut to the terminal's width, since a carriage return goes back to the start of the
// last screen row only and a wrapped line would leave its first rows behind; it is wiped when the
// Progress object goes (or ended with a newline by finish(lastLine)), so the object lives exactly
// as long as the work it reports on. To a log or a pipe it goes as whole lines, one every
// kLogSeconds of the work at most and none before (work that ends sooner says nothing), so that
// a long run in CI or under nohup shows it is alive without filling the log.
#pragma once

#include <cstddef>
#include <string>

namespace jello {

// Seconds between two progress lines written to a log (not a terminal).
constexpr double kLogSeconds = 5;

class Progress {
 public:
  Progress();
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  // True when show() would print now (on a terminal always; to a log once kLogSeconds have
  // passed since the last line): a caller may skip making the text.
  bool enabled() const;
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
  bool terminal_;
  double lastLogged_;      // steady-clock seconds of the last line to a log (the start at first)
  std::size_t width_ = 0;  // characters of the longest line shown: what a shorter one blanks out
};

}  // namespace jello
