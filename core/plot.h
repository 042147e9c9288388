// plot.h: drawing a PNG with gnuplot (Debian's gnuplot-nox), for the reports.
//
// No shell is involved and no name reaches a script unescaped: gnuplot is started directly
// (fork and exec) in the output folder, and every text a script shows (a world's name in a
// title) goes through gnuplotString.
#pragma once

#include <string>
#include <string_view>

#include "core/output.h"

namespace jello {

// drawWithGnuplot's answer when gnuplot is not on the PATH: the one reason not to fail a run
// (gnuplot is an optional package; the data files are written all the same).
inline constexpr const char* kGnuplotMissing = "gnuplot is not installed";

// Draws `png` in `dir` by running gnuplot on `script`, a file in `dir` that sets its output
// with `set output png` after `if (!exists("png")) png = 'NAME.png'` (so that the user can run
// `gnuplot SCRIPT` there to draw the picture again). The picture is written under the rules of
// output.h: gnuplot draws into a temporary file, which takes the name `png` only when gnuplot
// succeeded and the file is not empty (gnuplot exits 0 on some write errors). Returns "" when
// the picture was drawn, otherwise why not, in a few words.
std::string drawWithGnuplot(const std::string& dir, const std::string& script,
                            const std::string& png, Existing existing);

// `text` as a gnuplot single-quoted string literal: inside single quotes gnuplot expands
// nothing (no backquotes, no macros) and '' is a quote; control characters and bytes that are
// not UTF-8 are shown as \xNN (printable), so a newline cannot end the string.
std::string gnuplotString(std::string_view text);

}  // namespace jello
