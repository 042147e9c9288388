// leniency.cpp: what a hand-in made for another compiler needs read or rewritten (leniency.h).
#include "grader/leniency.h"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "grader/submission.h"

namespace fs = std::filesystem;

namespace jello::grader {
namespace {

const std::set<std::string> kCompiledExtensions = {".cpp", ".cc", ".cxx", ".c"};
const std::set<std::string> kHeaderExtensions = {".h", ".hpp", ".hh", ".hxx", ".inl"};

}  // namespace

bool isCompiled(const fs::path& path) {
  return kCompiledExtensions.count(path.extension().string()) > 0;
}
bool isHeader(const fs::path& path) {
  return kHeaderExtensions.count(path.extension().string()) > 0;
}

bool isSource(const fs::path& path) {
  std::string extension = path.extension().string();
  return kCompiledExtensions.count(extension) || kHeaderExtensions.count(extension);
}

std::string lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

// A name the compiler and the script can only take for a file: letters, digits, '.', '_', '-'
// in each component, none starting with '-' or being "..".
bool plainPath(const std::string& relative) {
  std::stringstream parts(relative);
  std::string part;
  int count = 0;
  while (std::getline(parts, part, '/')) {
    ++count;
    if (part.empty() || part[0] == '-' || part == "." || part == "..") return false;
    for (char c : part) {
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '_' && c != '-')
        return false;
    }
  }
  return count > 0;
}

std::string readWhole(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

namespace {

// Whether `relative` below `base` passes through a symbolic link (one the grader made to a
// system library, whatever its name): nothing is written through one, so a path a student
// chooses (an #include, a #line) can never reach outside the scratch folder.
bool throughLink(const fs::path& base, const fs::path& relative) {
  fs::path at = base;
  for (const auto& part : relative) {
    at /= part;
    if (fs::is_symlink(fs::symlink_status(at))) return true;
  }
  return false;
}

// Every file under `dir` by its lower-case relative path.
std::map<std::string, std::string> byLowerCase(const fs::path& dir) {
  std::map<std::string, std::string> names;
  if (!fs::exists(dir)) return names;
  for (auto& entry : fs::recursive_directory_iterator(dir)) {
    if (entry.is_regular_file()) {
      std::string relative = fs::relative(entry.path(), dir).generic_string();
      names.emplace(lower(relative), relative);
    }
  }
  return names;
}

// The names of the #include lines of `text`, as written, read line by line (no pattern: one
// would recurse once per character of a long line).
std::vector<std::string> includesOf(const std::string& text) {
  std::vector<std::string> names;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    std::size_t at = line.find_first_not_of(" \t");
    if (at == std::string::npos || line[at] != '#') continue;
    at = line.find_first_not_of(" \t", at + 1);
    if (at == std::string::npos || line.compare(at, 7, "include") != 0) continue;
    at = line.find_first_not_of(" \t", at + 7);
    if (at == std::string::npos || (line[at] != '<' && line[at] != '"')) continue;
    std::size_t end = line.find(line[at] == '<' ? '>' : '"', at + 1);
    if (end != std::string::npos) names.push_back(line.substr(at + 1, end - at - 1));
  }
  return names;
}

// A library a hand-in names through a copy it does not carry ("eigen-3.4.0/Eigen/Dense",
// <Eigen/Dense> without -I, "glm-0.9.9/glm/glm.hpp"): the folder of the system's copy that holds
// the library's own top folder, and how many components of `wanted` stand before that folder.
struct SystemLibrary {
  const char* top;     // the library's own top folder, as its headers include each other
  const char* folder;  // the system's folder holding `top`
};
const SystemLibrary kSystemLibraries[] = {{"Eigen", "/usr/include/eigen3"},
                                          {"unsupported", "/usr/include/eigen3"},
                                          {"glm", "/usr/include"}};

// A link in `caseDir` that serves `wanted` from the system's copy of its library; the note, or ""
// when `wanted` names no such library or the system has no copy.
std::string serveSystemLibrary(const std::string& wanted, const fs::path& caseDir) {
  std::vector<std::string> parts;
  std::stringstream path(wanted);
  for (std::string part; std::getline(path, part, '/');) parts.push_back(part);
  for (std::size_t n = 0; n + 1 < parts.size(); ++n) {
    for (const SystemLibrary& library : kSystemLibraries) {
      if (parts[n] != library.top) continue;
      std::string suffix;
      for (std::size_t m = n; m < parts.size(); ++m) suffix += (m > n ? "/" : "") + parts[m];
      if (!fs::exists(fs::path(library.folder) / suffix)) continue;
      fs::path link = caseDir;
      for (std::size_t m = 0; m < n; ++m) link /= parts[m];
      fs::path target = fs::path(library.folder);
      if (n == 0) {
        link /= library.top;
        target /= library.top;
      }
      if (fs::exists(fs::symlink_status(link))) return "";
      if (throughLink(caseDir, link.lexically_relative(caseDir))) return "";
      fs::create_directories(link.parent_path());
      fs::create_directory_symlink(target, link);
      return "#include \"" + wanted + "\" served from the system's " + target.string() +
             " (the hand-in does not carry that copy of the library)";
    }
  }
  return "";
}

}  // namespace

// A lenient build: a copy of Eigen or GLM the hand-in carries (a folder Eigen/ holding Dense or
// Core, glm/ holding glm.hpp) is replaced by the system's copy: students' repositories often
// leave out some of its files (a .gitignore's "core" drops Eigen/Core). Returns the notes.
std::vector<std::string> serveLibraryCopies(const fs::path& build) {
  std::vector<std::string> notes;
  std::vector<std::pair<fs::path, fs::path>> copies;  // the copy, the system's folder
  for (auto it = fs::recursive_directory_iterator(build); it != fs::recursive_directory_iterator();
       ++it) {
    if (!it->is_directory() || it->is_symlink()) continue;
    std::string name = it->path().filename().string();
    for (const SystemLibrary& library : kSystemLibraries) {
      fs::path system = fs::path(library.folder) / library.top;
      bool marked = fs::exists(it->path() / "Dense") || fs::exists(it->path() / "Core") ||
                    fs::exists(it->path() / "glm.hpp") ||
                    (name == "unsupported" && fs::exists(it->path().parent_path() / "Eigen"));
      if (name == library.top && marked && fs::is_directory(system)) {
        copies.emplace_back(it->path(), system);
        it.disable_recursion_pending();
      }
    }
  }
  for (const auto& [copy, system] : copies) {
    std::string named = copy.lexically_relative(build).generic_string();
    fs::remove_all(copy);
    fs::create_directory_symlink(system, copy);
    notes.push_back(named + "/: the hand-in's copy of the library replaced by the system's " +
                    system.string() + " (a copy in a repository often lacks some of its files)");
  }
  return notes;
}

// A lenient build: each #include that names no file as written but one in another case or with
// Windows' backslashes (the student's own, or a stand-in: Windows does not tell case apart and
// reads \ as /) gets a copy under the name as written, in the folder /work/case; a library the
// hand-in names by a copied folder it does not carry is served from the system's copy. Returns
// the notes.
std::vector<std::string> matchIncludeCase(const fs::path& build, const fs::path& standins,
                                          const fs::path& caseDir) {
  std::vector<std::string> notes;
  std::map<std::string, std::string> own = byLowerCase(build);
  std::map<std::string, std::string> stood = byLowerCase(standins / "always");
  for (auto& [low, name] : byLowerCase(standins / "lenient")) stood.emplace(low, name);
  for (auto& entry : fs::recursive_directory_iterator(build)) {
    if (!entry.is_regular_file() || !isSource(entry.path())) continue;
    std::string from = fs::relative(entry.path(), build).generic_string();
    for (const std::string& wanted : includesOf(readWhole(entry.path()))) {
      std::string slashed = wanted;
      std::replace(slashed.begin(), slashed.end(), '\\', '/');
      fs::path here = entry.path().parent_path();
      if (!plainPath(slashed) || fs::exists(here / wanted) || fs::exists(build / wanted) ||
          fs::exists(fs::symlink_status(caseDir / wanted)) ||
          fs::exists(standins / "always" / wanted) || fs::exists(standins / "lenient" / wanted) ||
          fs::exists("/usr/include/" + wanted))
        continue;
      std::string local = fs::relative(here / slashed, build).lexically_normal().generic_string();
      std::string source;
      if (own.count(lower(local)))
        source = (build / own[lower(local)]).string();
      else if (own.count(lower(slashed)))
        source = (build / own[lower(slashed)]).string();
      else if (stood.count(lower(slashed)))
        source = fs::exists(standins / "always" / stood[lower(slashed)])
                     ? (standins / "always" / stood[lower(slashed)]).string()
                     : (standins / "lenient" / stood[lower(slashed)]).string();
      if (source.empty()) {
        std::string served = serveSystemLibrary(slashed, caseDir);
        if (!served.empty()) notes.push_back(served);
        continue;
      }
      if (throughLink(caseDir, wanted)) continue;
      writeText((caseDir / wanted).string(), readWhole(source));
      notes.push_back("#include \"" + wanted + "\" (" + from + ") read as " +
                      fs::path(source).filename().string() +
                      (slashed != wanted ? ": Windows reads \\ as / and ignores the case of names"
                                         : ": Windows ignores the case of names"));
    }
  }
  return notes;
}

namespace {

// A pointer compared with the integer zero by <, <=, > or >= (Visual C++ compares the address
// as a number; GCC refuses): the zero at `line`'s operator at `column` (1-based) made a null
// pointer of type const volatile void*, which keeps that meaning (p > 0: p is not null; p < 0:
// never). False when the line does not read so.
bool rewritePointerComparison(std::string& l, std::size_t column, std::string& how) {
  std::size_t at = l.find_first_of("<>", column - 1);
  if (at == std::string::npos) return false;
  std::size_t after = at + (at + 1 < l.size() && l[at + 1] == '=' ? 2 : 1);
  std::string op = l.substr(at, after - at);
  auto isZero = [&](std::size_t from, std::size_t to) {
    std::size_t b = l.find_first_not_of(" \t", from);
    return b != std::string::npos && b < to && l[b] == '0' &&
                   (b + 1 >= l.size() || !(std::isalnum(static_cast<unsigned char>(l[b + 1])) ||
                                           l[b + 1] == '.' || l[b + 1] == '_'))
               ? b
               : std::string::npos;
  };
  std::size_t zero = isZero(after, l.size());
  if (zero == std::string::npos) {
    // "0 < p": the zero just before the operator.
    std::size_t b = at;
    while (b > 0 && (l[b - 1] == ' ' || l[b - 1] == '\t')) --b;
    if (b == 0 || l[b - 1] != '0' ||
        (b >= 2 && (std::isalnum(static_cast<unsigned char>(l[b - 2])) || l[b - 2] == '_' ||
                    l[b - 2] == '.')))
      return false;
    zero = b - 1;
  }
  l.replace(zero, 1, "(const volatile void*)0");
  how = "a pointer compared with " + op +
        " 0 kept as Visual C++ compares it (the address as a "
        "number: p > 0 is p != 0, p < 0 is never true)";
  return true;
}

}  // namespace

// Two things Visual C++ allows that no compiler here does, rewritten where the compiler's own
// error points (a lenient build): a pointer compared with the integer zero by <, <=, > or >=,
// and a friend declared static (the static dropped). Returns the notes; none: nothing to
// rewrite.
std::vector<std::string> rewriteForVisualCpp(const fs::path& build, const std::string& log) {
  std::vector<std::string> notes;
  std::map<std::string, std::vector<std::string>> files;  // path -> lines
  std::set<std::string> done;                             // "path:line:column" rewritten
  std::istringstream logLines(log);
  for (std::string entry; std::getline(logLines, entry);) {
    // "./FILE:LINE:COLUMN: error: WHAT"
    bool comparison =
        entry.find(": error: ordered comparison of pointer with integer zero") != std::string::npos;
    bool friendStatic =
        entry.find(": error: storage class specifiers invalid in friend") != std::string::npos;
    if (entry.rfind("./", 0) != 0 || !(comparison || friendStatic)) continue;
    std::istringstream fields(entry.substr(2));
    std::string path, lineText, columnText;
    std::getline(fields, path, ':');
    std::getline(fields, lineText, ':');
    std::getline(fields, columnText, ':');
    std::size_t line = std::strtoul(lineText.c_str(), nullptr, 10);
    std::size_t column = std::strtoul(columnText.c_str(), nullptr, 10);
    if (!plainPath(path) || !isSource(path) || throughLink(build, path) ||
        !fs::exists(build / path))
      continue;
    // A header's error is reported once for each file that includes it: rewritten once.
    if (!done.insert(path + ":" + lineText + ":" + columnText).second) continue;
    if (!files.count(path)) {
      std::istringstream in(readWhole(build / path));
      for (std::string l; std::getline(in, l);) files[path].push_back(l);
    }
    std::vector<std::string>& lines = files[path];
    if (line == 0 || line > lines.size() || column == 0) continue;
    std::string& l = lines[line - 1];
    std::string where = path + ":" + std::to_string(line);
    if (comparison) {
      std::string how;
      if (rewritePointerComparison(l, column, how)) notes.push_back(where + ": " + how);
    } else {
      std::size_t at = l.find("static", column - 1);
      if (at == std::string::npos) continue;
      l.erase(at, 6);
      notes.push_back(where + ": 'friend static' read as 'friend' (Visual C++ allows it)");
    }
  }
  for (const auto& [path, lines] : files) {
    std::string joined;
    for (const auto& l : lines) joined += l + "\n";
    writeText(build / path, joined);
  }
  return notes;
}

// What a function GCC names (its line "FILE: In member function 'Vec& Vec::operator+=(...)':")
// gets where it ends without a return: "return {};" (a value built from nothing), or for a
// member function returning a reference "return *this;" (what such operators return); none for
// another function returning a reference, which no statement returns sensibly.
namespace {
const char* missingReturn(const std::string& function) {
  std::size_t open = function.find('\''), call = function.find('(', open + 1);
  if (open == std::string::npos || call == std::string::npos) return "return {}; ";
  std::size_t nameStart = function.rfind(' ', call);
  bool reference =
      nameStart != std::string::npos && nameStart > open + 1 && function[nameStart - 1] == '&';
  if (!reference) return "return {}; ";
  return function.find(": In member function '") != std::string::npos ? "return *this; " : nullptr;
}
}  // namespace

// A C++ function that returns a value but ends without a return statement: Visual C++ returns
// whatever the register holds, and the programs that do it never use the value; GCC's optimiser
// takes the end as unreachable and runs into the next function. Each such end, where GCC's
// warning points (the closing brace), gets "return {};" before it. Returns the notes.
std::vector<std::string> rewriteMissingReturns(const fs::path& build, const std::string& log) {
  std::vector<std::string> notes, places;
  std::map<std::string, std::vector<std::string>> files;
  std::set<std::string> done;
  std::istringstream logLines(log);
  std::string function;  // GCC's line before the warning: "FILE: In member function '...':"
  for (std::string entry; std::getline(logLines, entry);) {
    if (entry.find(": In function '") != std::string::npos ||
        entry.find(": In member function '") != std::string::npos)
      function = entry;
    if (entry.rfind("./", 0) != 0 ||
        (entry.find(": warning: no return statement in function returning non-void") ==
             std::string::npos &&
         entry.find(": warning: control reaches end of non-void function") == std::string::npos))
      continue;
    std::istringstream fields(entry.substr(2));
    std::string path, lineText, columnText;
    std::getline(fields, path, ':');
    std::getline(fields, lineText, ':');
    std::getline(fields, columnText, ':');
    std::string extension = fs::path(path).extension().string();
    if (!plainPath(path) || !isSource(path) || throughLink(build, path) ||
        !fs::exists(build / path) || extension == ".c")
      continue;
    if (!done.insert(path + ":" + lineText + ":" + columnText).second) continue;
    if (!files.count(path)) {
      std::istringstream in(readWhole(build / path));
      for (std::string l; std::getline(in, l);) files[path].push_back(l);
    }
    std::size_t line = std::strtoul(lineText.c_str(), nullptr, 10);
    std::size_t column = std::strtoul(columnText.c_str(), nullptr, 10);
    std::vector<std::string>& lines = files[path];
    if (line == 0 || line > lines.size() || column == 0 || column > lines[line - 1].size() ||
        lines[line - 1][column - 1] != '}')
      continue;
    const char* added = missingReturn(function);
    if (!added) continue;
    lines[line - 1].insert(column - 1, added);
    places.push_back(path + ":" + lineText);
  }
  if (!places.empty()) {
    std::string list;
    for (const auto& place : places) list += (list.empty() ? "" : ", ") + place;
    notes.push_back("functions that return a value end without a return statement (" + list +
                    "): \"return {};\" added there, \"return *this;\" in a member function "
                    "returning a reference (Visual C++ returns an undefined value; GCC's "
                    "optimiser runs into the next function)");
  }
  for (const auto& [path, lines] : files) {
    std::string joined;
    for (const auto& l : lines) joined += l + "\n";
    writeText(build / path, joined);
  }
  return notes;
}

}  // namespace jello::grader
