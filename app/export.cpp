// export.cpp: surface meshes as OBJ or ASCII PLY files, numbered like the frames.

#include "app/export.h"

#include <dirent.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <vector>

#include "model/body.h"
#include "model/term.h"

namespace jello {

namespace {

// Appends `value` in shortest round-trip form ("0.14285714285714285", "1e-05"): it reads back
// as the same double, in every importer that reads decimal numbers.
void appendNumber(std::string* out, double value) {
  char text[32];
  const std::to_chars_result end = std::to_chars(text, text + sizeof text, value);
  out->append(text, end.ptr);
}

void appendVector(std::string* out, const char* prefix, Vec3 v) {
  out->append(prefix);
  appendNumber(out, v.x);
  out->push_back(' ');
  appendNumber(out, v.y);
  out->push_back(' ');
  appendNumber(out, v.z);
  out->push_back('\n');
}

// The header's two comment lines, each after `comment` ("# " or "comment "). The world's name
// goes through printable(): a newline in it cannot end the comment and start a line of data.
void appendHeader(std::string* out, const char* comment, const Body& body, const MeshStamp& stamp) {
  char when[96];
  std::snprintf(when, sizeof when, ", step %lld, time %.17g s\n", stamp.step, stamp.time);
  *out += comment + std::string("jello surface mesh: world ") + printable(stamp.world) + when;
  *out += comment + textf(
                        "metres, z up; %zu vertices with unit normals, %zu triangles "
                        "counter-clockwise seen from outside\n",
                        body.surfacePoints.size(), body.surface.size());
}

std::string objText(const Body& body, const double* positions, const MeshStamp& stamp) {
  const std::vector<Vec3> normals = surfaceNormals(body, positions);
  const int n = body.count();
  std::string out;
  out.reserve(64 * 1024);
  appendHeader(&out, "# ", body, stamp);
  for (int q : body.surfacePoints) appendVector(&out, "v ", load(positions, q, n));
  for (int q : body.surfacePoints) appendVector(&out, "vn ", normals[q]);
  const std::vector<int>& vertexOf = body.surfaceVertexOf;
  int part = -1;  // several jellies: an object each, its faces after its name
  for (const Triangle& t : body.surface) {
    if (body.joined() && body.partOf(t[0]) != part) {
      part = body.partOf(t[0]);
      out += "o jelly-" + std::to_string(part + 1) + "\n";
    }
    out += "f";
    for (int q : t) {
      const std::string v = std::to_string(vertexOf[q] + 1);  // OBJ counts from 1
      out += " " + v + "//" + v;
    }
    out += "\n";
  }
  return out;
}

std::string plyText(const Body& body, const double* positions, const MeshStamp& stamp) {
  const std::vector<Vec3> normals = surfaceNormals(body, positions);
  const int n = body.count();
  std::string out = "ply\nformat ascii 1.0\n";
  out.reserve(64 * 1024);
  appendHeader(&out, "comment ", body, stamp);
  out += "element vertex " + std::to_string(body.surfacePoints.size()) + "\n";
  for (const char* name : {"x", "y", "z", "nx", "ny", "nz"})
    out += std::string("property double ") + name + "\n";
  out += "element face " + std::to_string(body.surface.size()) + "\n";
  out += "property list uchar int vertex_indices\nend_header\n";
  for (int q : body.surfacePoints) {
    std::string line;
    appendVector(&line, "", load(positions, q, n));
    line.back() = ' ';
    appendVector(&line, "", normals[q]);
    out += line;
  }
  const std::vector<int>& vertexOf = body.surfaceVertexOf;
  for (const Triangle& t : body.surface)  // PLY counts from 0
    out += "3 " + std::to_string(vertexOf[t[0]]) + " " + std::to_string(vertexOf[t[1]]) + " " +
           std::to_string(vertexOf[t[2]]) + "\n";
  return out;
}

bool isMeshName(const char* name) {
  for (int i = 0; i < kFrameDigits; ++i)
    if (!std::isdigit(static_cast<unsigned char>(name[i]))) return false;
  return std::strcmp(name + kFrameDigits, ".obj") == 0 ||
         std::strcmp(name + kFrameDigits, ".ply") == 0;
}

std::vector<std::string> meshNames(const std::string& dir) {
  std::vector<std::string> names;
  DIR* d = ::opendir(dir.c_str());
  if (!d) return names;
  while (dirent* entry = ::readdir(d))
    if (isMeshName(entry->d_name)) names.push_back(entry->d_name);
  ::closedir(d);
  return names;
}

}  // namespace

const char* meshExtension(MeshFormat format) { return format == MeshFormat::Ply ? ".ply" : ".obj"; }

const char* meshFormatName(MeshFormat format) { return format == MeshFormat::Ply ? "PLY" : "OBJ"; }

bool parseMeshFormat(std::string_view name, MeshFormat* out) {
  std::string lower;
  for (char c : name) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (lower == "obj") *out = MeshFormat::Obj;
  if (lower == "ply") *out = MeshFormat::Ply;
  return lower == "obj" || lower == "ply";
}

std::string meshText(MeshFormat format, const Body& body, const double* positions,
                     const MeshStamp& stamp) {
  return format == MeshFormat::Ply ? plyText(body, positions, stamp)
                                   : objText(body, positions, stamp);
}

MeshSequence::MeshSequence(std::string dir, MeshFormat format, bool overwrite)
    : dir_(std::move(dir)), format_(format), overwrite_(overwrite) {
  while (dir_.size() > 1 && dir_.back() == '/') dir_.pop_back();
}

std::string MeshSequence::pathOf(int index) const {
  char name[32];
  std::snprintf(name, sizeof name, "/%0*d%s", kFrameDigits, index, meshExtension(format_));
  return dir_ + name;
}

void MeshSequence::open(const std::string& heldFolder) {
  if (opened_) return;
  if (heldFolder.empty() || !sameFile(dir_, heldFolder)) claim_ = claimFolder(dir_);
  const std::vector<std::string> old = meshNames(dir_);
  if (!old.empty() && !overwrite_) {
    throw OutputError(dir_ + " already holds " + std::to_string(old.size()) +
                      " exported meshes; choose another folder, or add --overwrite to replace "
                      "them");
  }
  removeOutputs(dir_, old);
  opened_ = true;
}

void MeshSequence::write(int index, const Body& body, const double* positions,
                         const MeshStamp& stamp) {
  open();
  writeFileWhole(pathOf(index), meshText(format_, body, positions, stamp), Existing::Refuse);
  ++written_;
}

int countMeshes(const std::string& dir) { return static_cast<int>(meshNames(dir).size()); }

namespace {

class MeshExport : public FrameObserver {
 public:
  MeshExport(const PictureOptions& pictures, std::string worldPath, std::string heldFolder)
      : options_(pictures),
        sequence_(pictures.exportDir, pictures.exportFormat, pictures.overwrite),
        world_(std::move(worldPath)),
        held_(std::move(heldFolder)) {}

  const PictureOptions& options() const override { return options_; }
  void begin() override { sequence_.open(held_); }
  void frame(const Model& model, const State& state, long long step, double time) override {
    sequence_.write(sequence_.written(), model.body(), state.p(), MeshStamp{world_, step, time});
  }
  bool wantsMore() const override { return sequence_.written() < options_.maxFrames; }
  int framesDone() const override { return sequence_.written(); }
  std::string describe() const override {
    return std::to_string(sequence_.written()) + " meshes (" + meshFormatName(sequence_.format()) +
           ") in " + folders();
  }
  std::string folders() const override { return sequence_.dir() + "/"; }

 private:
  PictureOptions options_;
  MeshSequence sequence_;
  std::string world_, held_;
};

class BothObservers : public FrameObserver {
 public:
  BothObservers(std::unique_ptr<FrameObserver> first, std::unique_ptr<FrameObserver> second)
      : first_(std::move(first)), second_(std::move(second)) {}

  const PictureOptions& options() const override { return first_->options(); }
  void begin() override {
    first_->begin();
    second_->begin();
  }
  void frame(const Model& model, const State& state, long long step, double time) override {
    if (first_->wantsMore()) first_->frame(model, state, step, time);
    if (second_->wantsMore()) second_->frame(model, state, step, time);
  }
  bool wantsMore() const override { return first_->wantsMore() || second_->wantsMore(); }
  int framesDone() const override { return first_->framesDone(); }
  std::string describe() const override { return first_->describe() + "; " + second_->describe(); }
  std::string folders() const override { return first_->folders() + " and " + second_->folders(); }

 private:
  std::unique_ptr<FrameObserver> first_, second_;
};

}  // namespace

std::unique_ptr<FrameObserver> makeMeshExport(const PictureOptions& pictures,
                                              const std::string& worldPath,
                                              const std::string& heldFolder) {
  return std::make_unique<MeshExport>(pictures, worldPath, heldFolder);
}

std::unique_ptr<FrameObserver> bothObservers(std::unique_ptr<FrameObserver> first,
                                             std::unique_ptr<FrameObserver> second) {
  if (!first) return second;
  if (!second) return first;
  return std::make_unique<BothObservers>(std::move(first), std::move(second));
}

}  // namespace jello
