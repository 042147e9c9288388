// io/inputerror.h: the one error every reader of this folder throws on bad input (a world file, a
// scene file, an OBJ model, a field recipe): what() is one line, "FILE:LINE: what is wrong (key)"
// where the input has lines, and never a library's own words. Commands turn it into an Outcome
// (core/outcome.h); only the mains print it.
#pragma once

#include <stdexcept>

namespace jello {

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace jello
