// export.cpp: surface meshes as OBJ or ASCII PLY files, and VTK XML unstructured grids (VTU) of
// the body's points and elements, numbered like the frames.

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
#include "model/elements.h"
#include "model/mat3.h"
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

// ---- VTU: VTK's XML UnstructuredGrid, ASCII ---------------------------------------------------

constexpr int kVtkTriangle = 5, kVtkTetra = 10;  // VTK's cell types

// `text` fit for an XML comment: printable (no newline), and no "--" (which would end it).
std::string commentText(const std::string& text) {
  std::string out;
  for (char c : printable(text)) {
    if (c == '-' && !out.empty() && out.back() == '-') out.push_back(' ');
    out.push_back(c);
  }
  return out;
}

// A DataArray of `values` (shortest round-trip numbers), a tuple of `components` a line.
void appendFloatArray(std::string* out, const char* name, int components,
                      const std::vector<double>& values) {
  *out +=
      textf("<DataArray type=\"Float64\" Name=\"%s\" NumberOfComponents=\"%d\" format=\"ascii\">\n",
            name, components);
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0) out->push_back(i % components == 0 ? '\n' : ' ');
    appendNumber(out, values[i]);
  }
  *out += "\n</DataArray>\n";
}

// A DataArray of integers of VTK type `type`, `perLine` a line.
void appendIntArray(std::string* out, const char* type, const char* name, int perLine,
                    const std::vector<int>& values) {
  *out += textf("<DataArray type=\"%s\" Name=\"%s\" format=\"ascii\">\n", type, name);
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0) out->push_back(i % perLine == 0 ? '\n' : ' ');
    *out += std::to_string(values[i]);
  }
  *out += "\n</DataArray>\n";
}

// The grid a VTU file describes: its points (the body's point numbers), its cells (each a list of
// places in `points`, and its VTK type), and the cells' values when the body has elements.
struct VtuGrid {
  std::vector<int> points;
  std::vector<int> connectivity, offsets, types;
  bool elements = false;
  std::vector<double> vonMises, volumeChange;  // Pa, and det F - 1, by cell
};

void addCell(VtuGrid* grid, const int* places, int count, int type) {
  grid->connectivity.insert(grid->connectivity.end(), places, places + count);
  grid->offsets.push_back(static_cast<int>(grid->connectivity.size()));
  grid->types.push_back(type);
}

// Every point of the body; every element as a tetrahedron with its stress and volume change; then
// the surface triangles of the points in no element (a scene's jellies of springs), valued 0.
VtuGrid elementGrid(const Body& body, const ElementTerm& elements, const double* positions) {
  VtuGrid grid;
  grid.elements = true;
  const int n = body.count();
  for (int q = 0; q < n; ++q) grid.points.push_back(q);
  std::vector<bool> inElement(n, false);
  for (int e = 0; e < elements.elementCount(); ++e) {
    const Tet& t = elements.element(e);
    addCell(&grid, t.data(), 4, kVtkTetra);
    for (int q : t) inElement[q] = true;
    grid.vonMises.push_back(elements.vonMises(e, positions));
    grid.volumeChange.push_back(determinant(elements.deformation(e, positions)) - 1);
  }
  for (const Triangle& t : body.surface) {
    if (inElement[t[0]]) continue;
    addCell(&grid, t.data(), 3, kVtkTriangle);
    grid.vonMises.push_back(0);
    grid.volumeChange.push_back(0);
  }
  return grid;
}

// The surface points and triangles, numbered as in OBJ (from 0).
VtuGrid surfaceGrid(const Body& body) {
  VtuGrid grid;
  grid.points = body.surfacePoints;
  for (const Triangle& t : body.surface) {
    const int places[3] = {body.surfaceVertexOf[t[0]], body.surfaceVertexOf[t[1]],
                           body.surfaceVertexOf[t[2]]};
    addCell(&grid, places, 3, kVtkTriangle);
  }
  return grid;
}

std::string vtuText(const Model& model, const State& state, const MeshStamp& stamp) {
  const Body& body = model.body();
  const ElementTerm* elements = model.forces.elements;
  const VtuGrid grid = elements ? elementGrid(body, *elements, state.p()) : surfaceGrid(body);
  const int n = body.count();
  std::vector<double> positions, velocities;
  for (int q : grid.points) {
    const Vec3 p = load(state.p(), q, n), v = load(state.v(), q, n);
    positions.insert(positions.end(), {p.x, p.y, p.z});
    velocities.insert(velocities.end(), {v.x, v.y, v.z});
  }
  std::string out = "<?xml version=\"1.0\"?>\n";
  out.reserve(256 * 1024);
  out += "<!-- jello mesh: world " + commentText(stamp.world) +
         textf(", step %lld, time %.17g s; metres, z up; ", stamp.step, stamp.time) +
         (grid.elements ? "every point, the elements as tetrahedra" : "the surface as triangles") +
         " -->\n";
  out += "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n";
  out += "<UnstructuredGrid>\n<FieldData>\n";
  out += "<DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" format=\"ascii\">\n";
  appendNumber(&out, stamp.time);
  out += "\n</DataArray>\n</FieldData>\n";
  out += textf("<Piece NumberOfPoints=\"%zu\" NumberOfCells=\"%zu\">\n", grid.points.size(),
               grid.types.size());
  out += "<PointData Vectors=\"velocity\">\n";
  appendFloatArray(&out, "velocity", 3, velocities);
  out += "</PointData>\n";
  if (grid.elements) {
    out += "<CellData Scalars=\"von_mises_stress\">\n";
    appendFloatArray(&out, "von_mises_stress", 1, grid.vonMises);
    appendFloatArray(&out, "volume_change", 1, grid.volumeChange);
    out += "</CellData>\n";
  }
  out += "<Points>\n";
  appendFloatArray(&out, "Points", 3, positions);
  out += "</Points>\n<Cells>\n";
  appendIntArray(&out, "Int32", "connectivity", grid.elements ? 4 : 3, grid.connectivity);
  appendIntArray(&out, "Int32", "offsets", 16, grid.offsets);
  appendIntArray(&out, "UInt8", "types", 32, grid.types);
  out += "</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  return out;
}

bool isMeshName(const char* name) {
  for (int i = 0; i < kFrameDigits; ++i)
    if (!std::isdigit(static_cast<unsigned char>(name[i]))) return false;
  for (const char* extension : {".obj", ".ply", ".vtu"})
    if (std::strcmp(name + kFrameDigits, extension) == 0) return true;
  return false;
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

const char* meshExtension(MeshFormat format) {
  switch (format) {
    case MeshFormat::Ply:
      return ".ply";
    case MeshFormat::Vtu:
      return ".vtu";
    case MeshFormat::Obj:
      break;
  }
  return ".obj";
}

const char* meshFormatName(MeshFormat format) {
  switch (format) {
    case MeshFormat::Ply:
      return "PLY";
    case MeshFormat::Vtu:
      return "VTU";
    case MeshFormat::Obj:
      break;
  }
  return "OBJ";
}

bool parseMeshFormat(std::string_view name, MeshFormat* out) {
  std::string lower;
  for (char c : name) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (MeshFormat format : {MeshFormat::Obj, MeshFormat::Ply, MeshFormat::Vtu})
    if (lower == meshExtension(format) + 1) {  // the extension less its dot
      *out = format;
      return true;
    }
  return false;
}

std::string meshText(MeshFormat format, const Model& model, const State& state,
                     const MeshStamp& stamp) {
  switch (format) {
    case MeshFormat::Ply:
      return plyText(model.body(), state.p(), stamp);
    case MeshFormat::Vtu:
      return vtuText(model, state, stamp);
    case MeshFormat::Obj:
      break;
  }
  return objText(model.body(), state.p(), stamp);
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

void MeshSequence::write(int index, const Model& model, const State& state,
                         const MeshStamp& stamp) {
  open();
  writeFileWhole(pathOf(index), meshText(format_, model, state, stamp), Existing::Refuse);
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
    sequence_.write(sequence_.written(), model, state, MeshStamp{world_, step, time});
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
