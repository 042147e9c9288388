// plot.cpp: gnuplot through the shell, with the folder quoted.

#include "plot.h"

#include <cstdlib>

namespace jello {

namespace {

std::string shellQuoted(const std::string& text) {
  std::string quoted = "'";
  for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

}  // namespace

bool runGnuplot(const std::string& dir, const std::string& script) {
  if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) return false;
  return std::system(("cd " + shellQuoted(dir) + " && gnuplot " + shellQuoted(script) + " 2>/dev/null").c_str()) == 0;
}

}  // namespace jello
