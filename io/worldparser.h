// io/worldparser.h: the world-file reader's parser, over any source of lines (linesource.h).
#pragma once

#include <string>

#include "io/input.h"
#include "io/linesource.h"

namespace jello {

// The world of the lines of `source`; `name` begins every error message. Throws InputError,
// "NAME:LINE: what is wrong (field)".
WorldFile parseLines(LineSource& source, const std::string& name);

}  // namespace jello
