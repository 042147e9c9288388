// core/readfile.h: reading a whole input file (a scene, an OBJ model) under the rules the readers
// promise: only a regular file (a FIFO is not waited on, a folder is refused), at most a given
// size, never more than read into memory.
#pragma once

#include <cstddef>
#include <string>

namespace jello {

// Reads the whole of the regular file `path`, at most `maxBytes` long, into *text. False with
// *why one line naming the file otherwise: "PATH: cannot open: ...", "PATH: not a regular file
// (WHAT is read whole)", "PATH: larger than LIMIT" or "PATH: cannot read: ...", where `what`
// names the kind of file ("a scene file") and `limit` the size in words ("1048576 bytes").
bool readRegularFile(const std::string& path, std::size_t maxBytes, const std::string& what,
                     const std::string& limit, std::string* text, std::string* why);

}  // namespace jello
