// output.h: the one way jello and createWorld write a file or claim a folder, and the one way
// they print an error line. The README's "Reliability" section states these rules to users:
//
// - A file is written whole: its bytes go to a temporary file in the same folder
//   (".jello-XXXXXX"), are flushed to the disk (fsync), then take the file's name in one step
//   (rename; link where nothing may be replaced). A reader never sees half a file, and a full
//   disk leaves no empty or partial file behind.
// - Nothing that is not a regular file is ever replaced: not a device, a folder, a FIFO or a
//   symbolic link. A read-only file (no write permission bit) is never replaced either.
// - A regular file is replaced only where the caller says Existing::Replace: an option that
//   names the file (--dump FILE), or --overwrite.
// - The temporary file of a write under way is removed when the write fails and when the
//   program is stopped by SIGINT, SIGTERM or SIGHUP (installSignalCleanup).
// - An output folder is claimed for the run (claimFolder): made when missing, and held with an
//   exclusive lock, so that a second run naming the same folder is refused while the first runs.
#pragma once

#include <cstdio>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace jello {

// A file or folder that cannot be written under the rules above. what() is one line
// "PATH: what is wrong".
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// What a write does when a regular file already holds the name.
enum class Existing { Refuse, Replace };

// Whether `path` can be written under the rules: checked before a long run, so that a run is
// not lost to a name it cannot write at the end.
struct WriteCheck {
  std::string why;             // why not, in words; "" when it can be written
  bool alreadyExists = false;  // the reason is only that a regular file holds the name and
                               // Existing::Refuse was asked: the one a caller can offer a remedy
                               // for (--force, --overwrite)
  bool writable() const { return why.empty(); }
};
WriteCheck checkWritable(const std::string& path, Existing existing);
// checkWritable's reason alone: "" when `path` can be written.
std::string whyNotWritable(const std::string& path, Existing existing);

// Writes `bytes` to `path` whole (see above). Throws OutputError.
void writeFileWhole(const std::string& path, std::string_view bytes, Existing existing);
// The same, for output made piece by piece: `fill` writes into the open temporary file and
// throws (any std::exception, whose what() becomes the message) when it cannot.
void writeFileWhole(const std::string& path, const std::function<void(std::FILE*)>& fill,
                    Existing existing);

// Removes dir/NAME for each of `names` (an earlier run's frames or meshes, for --overwrite),
// each checked first under the rules above: when one is not a regular, writable file (a link,
// a FIFO, a read-only file), none is removed and OutputError names it.
void removeOutputs(const std::string& dir, const std::vector<std::string>& names);

// A temporary file name in `dir`, made (empty, mode 0600) and registered for removal on a
// signal, for output a child program writes (gnuplot's PNG). `suffix` ends the name (".png").
// Finish with publishTemporary or discardTemporary. Throws OutputError.
std::string makeTemporary(const std::string& dir, const std::string& suffix);
// Gives a finished temporary file its name under the rules (an empty file is refused: it is
// no picture). Throws OutputError; the temporary file is removed either way.
void publishTemporary(const std::string& temporary, const std::string& path, Existing existing);
void discardTemporary(const std::string& temporary);

// An output folder held for one run; the lock goes with the object (and with the process).
class FolderClaim {
 public:
  FolderClaim() = default;
  FolderClaim(FolderClaim&& other) noexcept;
  FolderClaim& operator=(FolderClaim&& other) noexcept;
  FolderClaim(const FolderClaim&) = delete;
  FolderClaim& operator=(const FolderClaim&) = delete;
  ~FolderClaim();
  bool held() const { return fd_ >= 0; }

 private:
  friend FolderClaim claimFolder(const std::string& dir);
  int fd_ = -1;
};
// Makes `dir` (and its parents) when missing and locks it. Throws OutputError when it cannot be
// made or written, or when another run holds it.
FolderClaim claimFolder(const std::string& dir);

// The folder a file's path lies in: "." for a bare name, "/" for a file at the root.
std::string folderOf(const std::string& path);

// Whether another run holds the folder `dir` (claimFolder) now. A run asks before it writes a
// file into a folder it did not claim (--dump into another run's frames).
bool heldByAnotherRun(const std::string& dir);

// Makes a new folder under `parent` (made too when missing) and returns its name: parent/STEM-001,
// parent/STEM-002, ..., the first that did not exist. mkdir decides, so two runs never get the
// same folder. Throws OutputError.
std::string makeNewFolder(const std::string& parent, const std::string& stem);

// Claims `dir` for a run that will write the files `names` into it, and checks each of them
// now, before the work (whyNotWritable). Throws OutputError naming the first that cannot be
// written, e.g. "rep/report.gp: already exists; choose another folder, or add --overwrite".
FolderClaim claimOutputs(const std::string& dir, const std::vector<std::string>& names,
                         Existing existing);

// A child program writing into a temporary file (gnuplot drawing a picture): killed, and waited
// for, when a signal stops this program, before the temporary files are removed (else it would
// write its file again after). Forget it once it has ended.
void rememberChild(int pid);
void forgetChild(int pid);

// Removes the temporary files of writes under way when SIGINT, SIGTERM or SIGHUP arrives, then
// lets the signal end the program as it would have. Called once by each main, and by the
// graphics library as it loads (it holds a copy of this file, and of its list, of its own): the
// handlers chain, each cleaning its own list.
void installSignalCleanup();

// True when both names lead to the same file (same device and inode).
bool sameFile(const std::string& a, const std::string& b);

// `text` with every control character and every byte that is not part of valid UTF-8 shown as
// \xNN (a backslash as \\): safe to print in one line and to put in JSON or a script's string.
std::string printable(std::string_view text);
// Whether `text` is valid UTF-8 (no overlong forms, no surrogates): what a TOML string may hold.
bool isUtf8(std::string_view text);

// After a program's last output: "" when all of its standard output was written, otherwise the
// line saying it was not (a closed or full standard output is a failure, not a success).
std::string unwrittenStandardOutput();

// The name errors begin with ("jello", "createWorld"); set once by main.
void setProgramName(const char* name);
// Prints "NAME: message" on stderr as exactly one line (the message through printable).
void printError(std::string_view message);

}  // namespace jello
