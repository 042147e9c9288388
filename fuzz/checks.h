// checks.h: what the fuzz targets assert of one input, shared with the test suite, which
// replays every input the fuzzers ever found a fault with (tests/data/fuzz/).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace jello::fuzz {

// A world file's text: the reader either refuses it with a InputError or accepts it, the
// same way from memory and from a file descriptor (whose reading goes a block at a time); an
// accepted world is written and read back bit for bit. Aborts on any other outcome.
void checkWorldText(const std::uint8_t* data, std::size_t size);

// A createWorld field expression "fx; fy; fz": refused with a InputError or turned into a
// field of finite forces. Aborts on any other outcome.
void checkFieldExpression(const std::uint8_t* data, std::size_t size);

// jello's command line: the input split at NUL bytes into arguments, parsed (nothing is read
// or run). The parse goes on, prints help or version (status 0), or refuses (status 2); what
// it goes on with keeps every rule of the options (finite, positive steps and times, sizes in
// range, names not empty). Aborts on any other outcome, an exception among them.
void checkCommandLine(const std::uint8_t* data, std::size_t size);

// A scene file's text (parsed from memory, with `world` keys relative to the current folder):
// refused with a one-line InputError, or accepted as a scene whose every value the reader
// promises (obstacles, pins, a world that can be written) and whose forces are numbers.
void checkSceneText(const std::uint8_t* data, std::size_t size);

}  // namespace jello::fuzz
