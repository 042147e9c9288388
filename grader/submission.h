// submission.h: a student's submission, found, copied and built in the sandbox.
//
// A submission is a folder, or a .zip, .tar.gz or .tgz of one, holding the course's physics.cpp
// (anywhere inside: the shallowest one counts) and whatever it brings. What is built: every C++
// file in physics.cpp's folder except the course's viewer files and files with a main(), with
// the grader's probe (grader/course/probe.cpp). Headers, in the order tried: the submission's
// own; its physics.h with the course API's jello.h (and empty stand-ins for the course's GL
// headers); the course API's jello.h and physics.h. Only regular files are taken: symbolic links
// are left behind, unread.
#pragma once

#include <string>
#include <vector>

namespace jello::grader {

struct Submission {
  std::string path;  // as given
  std::string name;  // letters, digits, '.', '_', '-': for reports and test names; unique
};

// "" when `path` can be a submission (a folder, or a regular file named .zip, .tar.gz or .tgz);
// otherwise why not, in words.
std::string whyNotSubmission(const std::string& path);
// The submissions for `paths`, named after their last component (without the archive's
// extension), made unique by "-2", "-3", ...
std::vector<Submission> nameSubmissions(const std::vector<std::string>& paths);

struct BuildResult {
  bool built = false;
  std::string diagnosis;           // when not built: the first error, or what is missing
  std::string headers;             // which headers served, in words
  std::vector<std::string> notes;  // files left out, links not followed
  std::string log;                 // every compiler's output
  double seconds = 0;
};

// Builds the submission in the sandbox and copies the program to `probePath`.
BuildResult buildSubmission(const Submission& submission, const std::string& probePath);

}  // namespace jello::grader
