// submission.h: a student's submission, found and copied out of reach of its author.
//
// A submission is a folder, or a .zip, .tar.gz or .tgz of one, holding the course's physics.cpp
// (anywhere inside: the shallowest one counts) and the rest of the student's program. A class is
// a folder of submissions: one without a physics.cpp of its own whose entries, two or more, are
// submissions. Only regular files are taken, opened without following a link at any step, and
// when the grader runs as root, with the rights of the folder's owner: symbolic links and files
// the student could not read are left behind, unread.
#pragma once

#include <string>
#include <vector>

namespace jello::grader {

struct Submission {
  std::string path;  // as given, or the class folder's entry
  std::string name;  // letters, digits, '.', '_', '-': for reports and test names; unique
};

// "" when `path` can be a submission or a class (a folder, or a regular file named .zip,
// .tar.gz or .tgz, neither of them a symbolic link); otherwise why not, in words.
std::string whyNotSubmission(const std::string& path);

// `paths` with each class folder among them replaced by its submissions, in name order; what
// was left out of a class (a symbolic link, an entry that is no submission) goes to `notes`.
std::vector<std::string> expandClasses(const std::vector<std::string>& paths,
                                       std::vector<std::string>& notes);

// The submissions for `paths`, named after their last component (without the archive's
// extension), made unique by "-2", "-3", ...
std::vector<Submission> nameSubmissions(const std::vector<std::string>& paths);

// Copies the submission's source files into the folder `into` (made): a folder by the safe copy
// above, an archive unpacked in the sandbox (at most kMostArchiveBytes unpacked, every hard link
// counted). Files left out go to `notes`. Returns "" or why nothing could be copied.
class Scratch;
std::string copySubmission(const Submission& submission, const Scratch& scratch,
                           const std::string& into, std::vector<std::string>& notes);

constexpr unsigned long long kMostArchiveBytes = 64ull << 20;

// Writes `text` to the file `path` (its folders made first), whole or with an exception: the
// grader's own files in a scratch folder, and the copies of a student's.
void writeText(const std::string& path, const std::string& text);

}  // namespace jello::grader
