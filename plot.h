// plot.h: drawing a PNG with gnuplot (Debian's gnuplot-nox), for the reports.
#pragma once

#include <string>

namespace jello {

// Runs `gnuplot SCRIPT` in `dir` (the script names its own output). False when gnuplot is
// missing or fails.
bool runGnuplot(const std::string& dir, const std::string& script);

}  // namespace jello
