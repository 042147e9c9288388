// leniency.h: what a hand-in written for another compiler (Visual C++ on Windows, Xcode) needs
// read or rewritten to build here as it built there (docs/grading.md, "How a submission is
// built"), each returning the notes the report names it by; and the file helpers the build and
// these share.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace jello::grader {

// Source files by their extension: compiled (.cpp .cc .cxx .c), headers (.h .hpp .hh .hxx .inl).
bool isCompiled(const std::filesystem::path& path);
bool isHeader(const std::filesystem::path& path);
bool isSource(const std::filesystem::path& path);
std::string lower(std::string text);
// A name the compiler and the build script can only take for a file: letters, digits, '.', '_',
// '-' in each component, none starting with '-' or being "..".
bool plainPath(const std::string& relative);
std::string readWhole(const std::filesystem::path& path);

// A copy of Eigen or GLM the hand-in carries, replaced by the system's (a repository's copy often
// lacks files: a .gitignore's "core" drops Eigen/Core).
std::vector<std::string> serveLibraryCopies(const std::filesystem::path& build);
// Each #include that names no file as written but one in another case or with Windows'
// backslashes: a copy under the name as written in `caseDir`; a library named through a copied
// folder the hand-in does not carry: served from the system's copy.
std::vector<std::string> matchIncludeCase(const std::filesystem::path& build,
                                          const std::filesystem::path& standins,
                                          const std::filesystem::path& caseDir);
// Where the compiler's errors in `log` point: a pointer compared with the integer zero by < <=
// > >= (kept as Visual C++ compares it), and 'friend static' (read as 'friend').
std::vector<std::string> rewriteForVisualCpp(const std::filesystem::path& build,
                                             const std::string& log);
// Where GCC's warnings in `log` point: a C++ function that returns a value but ends without a
// return statement gets "return {};" (GCC's optimiser would run into the next function).
std::vector<std::string> rewriteMissingReturns(const std::filesystem::path& build,
                                               const std::string& log);

}  // namespace jello::grader
