// export.h: the cube's surface mesh written as files (--export DIR, README: Exporting meshes):
// DIR/0000.obj, 0001.obj, ... (or .ply, or .vtu), one for each saved frame and numbered like the
// JPEG frames: the mesh of frame k is DIR/k.obj with k in kFrameDigits digits, whatever folder the
// frames go to. Ready for Blender (File > Import) and Houdini (a File SOP on DIR/$F4.obj); VTU for
// ParaView (File > Open shows the NNNN.vtu files as one time series).
//
// What an OBJ or PLY file holds (body.h; a VTU holds a jelly of elements whole, meshText): the
// body's surface points as vertices, in surfacePoints order (296 for the course cube), each with
// its unit normal (surfaceNormals); its surface triangles (588 for the course cube),
// counter-clockwise seen from outside. Positions in metres as simulated, in the simulator's frame:
// z up (x, y horizontal), exactly (numbers in shortest round-trip form: they read back as the same
// doubles).
//
// Files are written whole and the folder claimed for the run (core/output.h), as frames are.
#pragma once

#include <memory>
#include <string>
#include <string_view>

#include "app/headless.h"
#include "app/pictures.h"
#include "core/output.h"
#include "model/body.h"
#include "model/model.h"
#include "model/world.h"

namespace jello {

// When a mesh was taken, for its file's header.
struct MeshStamp {
  std::string world;  // the world file's name, as given
  long long step = 0;
  double time = 0;  // s
};

// ".obj", ".ply" or ".vtu".
const char* meshExtension(MeshFormat format);
// "OBJ", "PLY" or "VTU".
const char* meshFormatName(MeshFormat format);
// "obj", "ply" or "vtu" in any case; false for anything else.
bool parseMeshFormat(std::string_view name, MeshFormat* out);

// The text of one mesh file of `model`'s body at `state` (its positions, and for VTU its
// velocities). The counts below are the course cube's.
// OBJ: comment lines (the world, the step, the time, the axes), then 296 "v x y z", 296
// "vn nx ny nz" and 588 "f a//a b//b c//c" lines, indices from 1 (vertex a's normal is vn a).
// PLY: ASCII 1.0, comment lines as OBJ's, "element vertex 296" with double x y z nx ny nz,
// "element face 588" with "list uchar int vertex_indices" counted from 0.
// VTU: a VTK XML UnstructuredGrid (version 0.1, ASCII), the stamp in a comment after the XML
// declaration and the time (s) as the FieldData "TimeValue" ParaView reads a series' times from.
// For a model with elements (Model::forces.elements): every point of the body, in point order
// (Float64 "Points", m), and every tetrahedron as a VTK_TETRA cell (type 10) with CellData
// "von_mises_stress" (Pa, ElementTerm::vonMises) and "volume_change" (det F - 1); the surface
// triangles of a scene's jellies of springs follow as VTK_TRIANGLE cells (type 5), with 0 for
// both. For a body of springs only: its surface points, in surfacePoints order, and its surface
// triangles (type 5), no CellData. Either way PointData "velocity" (m/s) at each point written.
std::string meshText(MeshFormat format, const Model& model, const State& state,
                     const MeshStamp& stamp);

// A numbered sequence of mesh files in a folder; it never replaces exported meshes a user
// already has unless asked to.
class MeshSequence {
 public:
  MeshSequence(std::string dir, MeshFormat format, bool overwrite);

  // Makes the folder (and its parents) when missing and claims it for the run (output.h). When
  // it already holds exported meshes (NNNN.obj, NNNN.ply or NNNN.vtu, any format: an earlier
  // export),
  // refuses with an OutputError naming it, or, with overwrite, removes them so the new sequence
  // has no stale tail. `heldFolder` is a folder this run holds already (the frames'): when it is
  // this folder, no second claim is made, since it would refuse this very run. Throws
  // OutputError with a one-line message.
  void open(const std::string& heldFolder = "");

  // Writes mesh number `index` (pathOf(index)) whole; the caller gives the frame's number, so
  // that a mesh is named like its frame even after a failed write. Throws OutputError.
  void write(int index, const Model& model, const State& state, const MeshStamp& stamp);

  int written() const { return written_; }
  const std::string& dir() const { return dir_; }
  MeshFormat format() const { return format_; }
  std::string pathOf(int index) const;

 private:
  std::string dir_;
  MeshFormat format_;
  bool overwrite_;
  bool opened_ = false;
  FolderClaim claim_;
  int written_ = 0;
};

// The number of files named like exported meshes (NNNN.obj, NNNN.ply, NNNN.vtu) in dir; 0 when
// dir does not exist.
int countMeshes(const std::string& dir);

// The meshes of a headless run (--export): one for each frame the run saves, at the same steps
// (FrameClock of `pictures`), at most pictures.maxFrames. `worldPath` names the world in the
// headers; `heldFolder` is the frames' folder when frames are saved too ("" otherwise).
std::unique_ptr<FrameObserver> makeMeshExport(const PictureOptions& pictures,
                                              const std::string& worldPath,
                                              const std::string& heldFolder);

// Two observers as one: both begin, and both save every frame, `first` first (it claims its
// folder first, so that `second` can see a folder they share). Either may be null: the other is
// then returned alone.
std::unique_ptr<FrameObserver> bothObservers(std::unique_ptr<FrameObserver> first,
                                             std::unique_ptr<FrameObserver> second);

}  // namespace jello
