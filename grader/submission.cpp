// submission.cpp: finding and copying submissions (submission.h).
#include "grader/submission.h"

#include <dirent.h>
#include <fcntl.h>
#include <sys/fsuid.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <stdexcept>

#include "core/output.h"
#include "grader/sandbox.h"

namespace fs = std::filesystem;

namespace jello::grader {
namespace {

// What is copied out of a submission: its source files and, beside them, the files its program
// reads (pictures, worlds: any other regular file, each of at most kMostDataFileBytes), within
// these bounds. The folder that holds physics.cpp is copied first, then the rest: a copy of a
// library beside the program (hundreds of headers) never crowds out the course's files.
constexpr int kMostEntries = 20000;
constexpr int kMostFiles = 2000;
constexpr std::uintmax_t kMostBytes = 32u << 20;
constexpr int kMostDataFiles = 500;
constexpr std::uintmax_t kMostDataFileBytes = 8u << 20;
constexpr std::uintmax_t kMostDataBytes = 32u << 20;
constexpr int kDeepest = 8;  // folders below the submission's own
const std::set<std::string> kSourceExtensions = {".cpp", ".cc", ".cxx", ".c",  ".h",
                                                 ".hpp", ".hh", ".hxx", ".inl"};
// What a build leaves (Visual Studio's, Xcode's, make's), which no program reads as it starts:
// never taken as a file beside the program.
// A version control's or a tool's own folders: never the program's.
const std::set<std::string> kSkippedFolders = {".git", ".svn", ".hg", ".vs", "__MACOSX", ".idea"};
constexpr std::uintmax_t kMostBareHeaderBytes = 256u << 10;  // a header without an extension
const std::set<std::string> kBuildProducts = {
    ".obj", ".o",     ".pdb",    ".ilk",   ".exe",  ".dll", ".lib", ".a",    ".so",
    ".sdf", ".ncb",   ".ipch",   ".pch",   ".idb",  ".suo", ".db",  ".tlog", ".lastbuildstate",
    ".exp", ".dylib", ".opendb", ".vsidx", ".iobj", ".ipdb"};

std::string lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

bool hasSuffix(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

bool isArchive(const std::string& path) {
  return hasSuffix(path, ".zip") || hasSuffix(path, ".tar.gz") || hasSuffix(path, ".tgz");
}

// Opens files as the student would: as root, each open of a submission's folder runs with the
// file-system identity of the folder's owner (this thread only: setfsuid and the raw setgroups
// call act on the calling thread), so that a file its owner cannot read, hard-linked in, stays
// unread; the grader's own identity returns at once, for writing the copy.
class StudentRights {
 public:
  explicit StudentRights(const struct stat& top)
      : switching_(geteuid() == 0 && top.st_uid != 0), uid_(top.st_uid), gid_(top.st_gid) {
    if (!switching_) return;
    groups_.resize(static_cast<std::size_t>(std::max(0, getgroups(0, nullptr))));
    int count = getgroups(static_cast<int>(groups_.size()), groups_.data());
    groups_.resize(static_cast<std::size_t>(std::max(0, count)));
  }
  int openat(int dir, const char* name, int flags) const {
    if (!switching_) return ::openat(dir, name, flags);
    syscall(SYS_setgroups, 0, nullptr);
    setfsgid(gid_);
    setfsuid(uid_);
    int fd = ::openat(dir, name, flags);
    int error = errno;
    setfsuid(0);
    setfsgid(0);
    syscall(SYS_setgroups, groups_.size(), groups_.data());
    errno = error;
    return fd;
  }

 private:
  bool switching_;
  uid_t uid_;
  gid_t gid_;
  std::vector<gid_t> groups_;
};

struct CopyBudget {
  int entries = 0, files = 0, dataFiles = 0;
  std::uintmax_t bytes = 0, dataBytes = 0;
  bool full = false, dataFull = false, bigSkipped = false;
};

// The whole of a regular file open at `fd`, up to `most` bytes; false when larger or unreadable.
bool readAll(int fd, std::uintmax_t most, std::string& text) {
  char buffer[1 << 16];
  for (ssize_t n; (n = read(fd, buffer, sizeof buffer)) != 0;) {
    if (n < 0 || text.size() + static_cast<std::size_t>(n) > most) return false;
    text.append(buffer, static_cast<std::size_t>(n));
  }
  return true;
}

// The names in the folder open at `dir`, sorted.
std::vector<std::string> namesIn(int dir) {
  std::vector<std::string> names;
  DIR* listing = fdopendir(dup(dir));
  if (!listing) return names;
  rewinddir(listing);  // a duplicate shares the position of an earlier listing of `dir`
  while (dirent* entry = readdir(listing)) {
    std::string name = entry->d_name;
    if (name != "." && name != "..") names.push_back(name);
  }
  closedir(listing);
  std::sort(names.begin(), names.end());
  return names;
}

// The relative folder of the shallowest physics.cpp under the folder open at `dir` (searched
// level by level, links not followed), or "" when there is none.
fs::path physicsFolder(int top, const StudentRights& rights) {
  std::vector<std::pair<int, fs::path>> level = {{dup(top), ""}};
  int entries = 0;
  fs::path found;
  bool done = false;
  for (int depth = 0; depth <= kDeepest && !level.empty() && !done; ++depth) {
    std::vector<std::pair<int, fs::path>> next;
    for (auto& [dir, relative] : level) {
      for (const std::string& name : namesIn(dir)) {
        if (done || ++entries > kMostEntries) break;
        int fd = rights.openat(dir, name.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
        if (fd < 0) continue;
        struct stat info;
        bool known = fstat(fd, &info) == 0;
        if (known && S_ISREG(info.st_mode) && name == "physics.cpp") {
          found = relative;
          done = true;
        }
        if (known && S_ISDIR(info.st_mode) && depth < kDeepest && next.size() < 256)
          next.emplace_back(fd, relative / name);
        else
          close(fd);
      }
      close(dir);
    }
    level.swap(next);
  }
  for (auto& [dir, relative] : level) close(dir);
  return found;
}

// Copies the regular file open at `fd`, named `name`, to `to` when it is source (within the
// source's budget) or a file the program may read as it starts (a texture, a world: within the
// data's budget, never what a build leaves).
void copyFile(int fd, const std::string& name, const fs::path& to, std::uintmax_t size,
              CopyBudget& budget, std::vector<std::string>& notes) {
  // A header without an extension (a library's module header: Eigen/Core) is source too.
  std::string extension = fs::path(name).extension().string();
  if (kSourceExtensions.count(extension) > 0 ||
      (extension.empty() && size <= kMostBareHeaderBytes)) {
    std::string text;
    budget.bytes += size;
    if (++budget.files > kMostFiles || budget.bytes > kMostBytes ||
        !readAll(fd, kMostBytes, text)) {
      notes.push_back("more source than the grader takes (" + std::to_string(kMostFiles) +
                      " files, " + std::to_string(kMostBytes >> 20) + " MB): the rest ignored");
      budget.full = true;
    } else {
      writeText(to, text);
    }
    return;
  }
  if (budget.dataFull || kBuildProducts.count(lower(extension))) return;
  if (size > kMostDataFileBytes) {
    if (!budget.bigSkipped)
      notes.push_back("files beside the source over " + std::to_string(kMostDataFileBytes >> 20) +
                      " MB are left out (the first: " + name +
                      "): a program that reads one as it starts cannot find it");
    budget.bigSkipped = true;
    return;
  }
  std::string bytes;
  budget.dataBytes += size;
  if (++budget.dataFiles > kMostDataFiles || budget.dataBytes > kMostDataBytes ||
      !readAll(fd, kMostDataFileBytes, bytes)) {
    notes.push_back("more files beside the source than the grader takes (" +
                    std::to_string(kMostDataFiles) + " files, " +
                    std::to_string(kMostDataBytes >> 20) + " MB): the rest left out");
    budget.dataFull = true;
  } else {
    writeText(to, bytes);
  }
}

// Copies the source and data files of the folder open at `dir` into `to` / `relative`, keeping
// the layout: its files first, then its folders, the one on the way to `first` (physics.cpp's
// folder) before the others. Every step is an openat without following a link, and what is read
// is what was opened (fstat of the descriptor): no name is looked up twice.
void copyFolder(int dir, const fs::path& to, const fs::path& relative, const fs::path& first,
                int depth, const StudentRights& rights, CopyBudget& budget,
                std::vector<std::string>& notes) {
  std::vector<std::string> names = namesIn(dir);
  // The folder on the way to physics.cpp's comes first among the folders.
  std::string towards;
  fs::path rest = first.lexically_relative(relative);
  if (!rest.empty() && *rest.begin() != "..") towards = rest.begin()->string();
  std::stable_partition(names.begin(), names.end(),
                        [&](const std::string& name) { return name == towards; });
  std::vector<std::string> folders;  // opened again after the files, without following a link
  for (const std::string& name : names) {
    if (budget.full) break;
    if (++budget.entries > kMostEntries) {
      notes.push_back("more than " + std::to_string(kMostEntries) + " entries: the rest ignored");
      budget.full = true;
      break;
    }
    fs::path path = relative / name;
    int fd = rights.openat(dir, name.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
      if (errno == ELOOP)
        notes.push_back(printable(path.string()) + ": a symbolic link, not followed");
      continue;
    }
    struct stat info;
    bool known = fstat(fd, &info) == 0;
    if (known && S_ISDIR(info.st_mode) && depth < kDeepest) {
      if (!kSkippedFolders.count(name)) folders.push_back(name);
      close(fd);
      continue;
    }
    if (known && S_ISREG(info.st_mode))
      copyFile(fd, name, to / path, static_cast<std::uintmax_t>(info.st_size), budget, notes);
    close(fd);
  }
  for (const std::string& name : folders) {
    if (budget.full) break;
    int fd = rights.openat(dir, name.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (fd < 0) continue;
    copyFolder(fd, to, relative / name, first, depth + 1, rights, budget, notes);
    close(fd);
  }
}

// Copies the folder at `from` (never a link) as copyFolder does.
std::string copyTree(const std::string& from, const fs::path& to, bool asOwner,
                     std::vector<std::string>& notes) {
  int top = open(from.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
  struct stat info;
  if (top < 0 || fstat(top, &info) != 0) {
    if (top >= 0) close(top);
    return from + ": cannot open the folder: " + std::strerror(errno);
  }
  if (!asOwner) info.st_uid = 0;  // the sandbox's own output: read as the grader
  StudentRights rights(info);
  CopyBudget budget;
  fs::create_directories(to);
  copyFolder(top, to, "", physicsFolder(top, rights), 0, rights, budget, notes);
  close(top);
  return "";
}

// Unpacks an archive in the sandbox into `into`, by a fixed script: nothing of the archive's
// names reaches a shell outside the sandbox. The size counts every hard link (du -l): 54 kB of
// links can otherwise unpack to a gigabyte of copies.
std::string unpack(const Submission& submission, const Scratch& scratch, const fs::path& into,
                   std::vector<std::string>& notes) {
  // The archive is copied first, opened without following a link: the sandbox's user may not
  // reach where it lies.
  int in = open(submission.path.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
  std::string bytes;
  struct stat info;
  bool ok = in >= 0 && fstat(in, &info) == 0 && S_ISREG(info.st_mode) &&
            readAll(in, kMostArchiveBytes, bytes);
  if (in >= 0) close(in);
  if (!ok) return "the archive is larger than 64 MB, or unreadable";
  std::string copy = scratch.path() + "/submission-archive";
  writeText(copy, bytes);
  fs::permissions(copy, fs::perms(0644));
  std::string out = scratch.makeFolder("unpacked");
  bool zip = hasSuffix(submission.path, ".zip");
  std::string extract = zip ? "unzip -qq /in/submission -d x >/dev/null"
                            : "tar -xzf /in/submission -C x --no-same-owner --no-same-permissions";
  SandboxJob job;
  job.argv = {"/bin/sh", "-c",
              "cd /tmp && mkdir x && " + extract +
                  " && [ \"$(du -skl x | cut -f1)\" -le 65536 ] && cp -R x/. /out/"};
  job.hostDir = scratch.path();
  job.outputDir = out;
  job.readOnlyFiles = {{copy, "/in/submission"}};
  job.limits.wallSeconds = 30;
  job.limits.cpuSeconds = 30;
  SandboxResult result = runSandboxed(job);
  if (!result.exitedWith(0)) {
    return "cannot unpack " + std::string(zip ? "the zip" : "the tar.gz") + " archive (" +
           result.describe() + ", or more than 64 MB unpacked, hard links counted)";
  }
  return copyTree(out, into, false, notes);
}

// Whether the folder at `path` holds a physics.cpp, at most kDeepest folders down (links not
// followed).
bool holdsPhysics(const fs::path& path) {
  std::error_code error;
  for (fs::recursive_directory_iterator it(path, error), end; !error && it != end;
       it.increment(error)) {
    if (it.depth() >= kDeepest) it.disable_recursion_pending();
    if (it->path().filename() == "physics.cpp" && it->is_regular_file(error)) return true;
  }
  return false;
}

}  // namespace

std::string whyNotSubmission(const std::string& path) {
  struct stat info;
  if (path.empty()) return "an empty name is no submission";
  if (lstat(path.c_str(), &info) != 0) return path + ": " + std::strerror(errno);
  if (S_ISLNK(info.st_mode))
    return path +
           ": a symbolic link; name the folder or archive itself, so that the report "
           "names the student it grades";
  if (S_ISDIR(info.st_mode)) return "";
  if (S_ISREG(info.st_mode) && isArchive(path)) return "";
  return path + ": not a folder, .zip, .tar.gz or .tgz";
}

std::vector<std::string> expandClasses(const std::vector<std::string>& paths,
                                       std::vector<std::string>& notes) {
  std::vector<std::string> expanded;
  for (const auto& path : paths) {
    struct stat info;
    bool folder = lstat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode);
    std::error_code error;
    if (!folder || fs::is_regular_file(fs::path(path) / "physics.cpp", error)) {
      expanded.push_back(path);
      continue;
    }
    std::vector<std::string> members, left;
    for (const auto& entry : fs::directory_iterator(path, error)) {
      std::string name = entry.path().filename().string();
      if (entry.is_symlink(error)) {
        left.push_back(printable(entry.path().string()) + ": a symbolic link, not graded");
      } else if ((entry.is_directory(error) && holdsPhysics(entry.path())) ||
                 (entry.is_regular_file(error) && isArchive(name))) {
        members.push_back(entry.path().string());
      } else if (entry.is_directory(error)) {
        left.push_back(printable(entry.path().string()) + ": no physics.cpp, not graded");
      }
    }
    if (members.size() < 2) {  // one student's folder, whatever its layout
      expanded.push_back(path);
      continue;
    }
    std::sort(members.begin(), members.end());
    expanded.insert(expanded.end(), members.begin(), members.end());
    notes.push_back(printable(path) + ": a class of " + std::to_string(members.size()) +
                    " submissions");
    notes.insert(notes.end(), left.begin(), left.end());
  }
  return expanded;
}

std::vector<Submission> nameSubmissions(const std::vector<std::string>& paths) {
  std::vector<Submission> submissions;
  std::set<std::string> taken;
  for (const auto& path : paths) {
    std::string name = fs::path(path).lexically_normal().filename().string();
    if (name.empty()) name = fs::path(path).lexically_normal().parent_path().filename().string();
    for (const char* extension : {".zip", ".tar.gz", ".tgz"}) {
      if (hasSuffix(name, extension)) name.erase(name.size() - std::strlen(extension));
    }
    for (char& c : name) {
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '_' && c != '-') c = '_';
    }
    if (name.empty() || name[0] == '.') name = "submission" + name;
    // The names of the report's own files are not a submission's folder.
    for (const char* reserved : {"summary.md", "summary.csv", "junit.xml", "grading.txt",
                                 "CTestTestfile.cmake", ".jello-grade"}) {
      if (name == reserved) name += "-submission";
    }
    std::string unique = name;
    for (int n = 2; taken.count(unique); ++n) unique = name + "-" + std::to_string(n);
    taken.insert(unique);
    submissions.push_back({path, unique});
  }
  return submissions;
}

std::string copySubmission(const Submission& submission, const Scratch& scratch,
                           const std::string& into, std::vector<std::string>& notes) {
  if (isArchive(submission.path)) return unpack(submission, scratch, into, notes);
  return copyTree(submission.path, into, true, notes);
}

void writeText(const std::string& path, const std::string& text) {
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out) throw std::runtime_error(path + ": cannot write");
}

}  // namespace jello::grader
