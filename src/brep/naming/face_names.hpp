#pragma once
// Carrying face names through OCCT operations by their history (Modified / Generated / IsDeleted), never
// by geometry: a face split or trimmed keeps the name of the face it came from (see named_shape.hpp).
#include <BRepBuilderAPI_MakeShape.hxx>
#include <NCollection_DataMap.hxx>
#include <TopTools_ShapeMapHasher.hxx>
#include <TopoDS_Shape.hxx>

#include <string>
#include <vector>

#include "src/brep/named_shape.hpp"
#include "src/brep/solid_integrals.hpp"

namespace cg::features {

/// Face -> name (faces compared with IsSame: same TShape and location, any orientation).
class FaceNames {
 public:
  FaceNames() = default;
  explicit FaceNames(const std::vector<brep::NamedFace>& faces) { add(faces); }
  void add(const std::vector<brep::NamedFace>& faces);
  void set(const TopoDS_Shape& face, const std::string& name);
  /// Adds (or overwrites with) every name of `other`.
  void merge(const FaceNames& other);
  bool has(const TopoDS_Shape& face) const { return map_.IsBound(face); }
  /// The name, or "" when the face is not named.
  std::string get(const TopoDS_Shape& face) const;
  /// Names carried to the faces of `result` through `op`'s history: each named input face's pieces
  /// (Modified, or the face itself when kept unchanged) that are faces of `result`.
  FaceNames carried(BRepBuilderAPI_MakeShape& op, const TopoDS_Shape& result) const;
  /// Every face of `shape` with its name; throws AlgorithmFailure naming `what` if a face has none.
  std::vector<brep::NamedFace> list(const TopoDS_Shape& shape, const std::string& what) const;

 private:
  NCollection_DataMap<TopoDS_Shape, std::string, TopTools_ShapeMapHasher> map_;
};

/// Faces of a shape (each once).
std::vector<TopoDS_Shape> faces_of(const TopoDS_Shape& shape);
/// Solids of a shape (each once).
std::vector<TopoDS_Shape> solids_of(const TopoDS_Shape& shape);
/// One solid from cells that share faces: the faces used by exactly one cell form its shell (each
/// with the orientation it has in its cell). Used to merge the cells of one chamber system again after
/// faces were split for naming. Throws AlgorithmFailure when the faces do not form one closed shell.
TopoDS_Shape merge_cells(const std::vector<TopoDS_Shape>& cells);

/// The volume checks of the features use brep::volume_of (src/brep/solid_integrals.hpp).
using brep::volume_of;
using brep::volumes_of;

}  // namespace cg::features
