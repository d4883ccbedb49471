#pragma once

/// What a body mesh is, as read (docs/math.md §20, "The body's mesh report"): its size, whether
/// it closes a volume and whether its triangles agree on which side is out. Occlusion needs
/// neither, but a mesh that is open or wound inconsistently is often not the body it claims to
/// be (a missing part, a face exported twice), and normals sampled from it point either way.

#include <Eigen/Core>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "vantage/analysis/mesh.h"

namespace vantage {

/// The units a mesh's size suggests, from the largest extent L of its bounding box
/// (docs/math.md §20): kMetres for 0 < L <= 10, kMillimetres for L >= 30, kUnclear otherwise
/// (10 < L < 30: centimetres, inches, or a large body in metres; or L = 0).
enum class UnitsHint { kMetres, kMillimetres, kUnclear };

/// "metres", "millimetres", "unclear".
const char* to_string(UnitsHint hint);
std::optional<UnitsHint> parse_units_hint(std::string_view text);

/// The report of one mesh. Edges are taken between welded vertices (vertices at identical
/// positions are one, first_identical_vertex()); a triangle with two corners at one position is
/// degenerate and left out of the edges.
struct MeshReport {
  long triangles = 0;             ///< as the mesh holds them
  long vertices = 0;              ///< distinct positions among the mesh's vertices
  long degenerate_triangles = 0;  ///< with two or three corners at one position
  long boundary_edges = 0;        ///< edges of exactly one triangle
  long non_manifold_edges = 0;    ///< edges of more than two triangles
  /// Edges of exactly two triangles that both traverse it in the same direction (a consistently
  /// wound pair traverses its shared edge in opposite directions).
  long inconsistent_edges = 0;
  /// Triangles wound against their neighbours: in each patch of triangles joined by edges of
  /// exactly two triangles, the smaller of the two sets of triangles that agree with one another
  /// (0 when consistently wound; a one-sided patch, a Moebius strip, counts its propagation's).
  long triangles_against_neighbours = 0;
  bool closed = false;              ///< every edge is shared by exactly two triangles
  bool manifold = false;            ///< no edge is shared by more than two triangles
  bool consistently_wound = false;  ///< inconsistent_edges == 0
  Eigen::Vector3d bounding_box_size = Eigen::Vector3d::Zero();  ///< max - min per axis
  UnitsHint units_hint = UnitsHint::kUnclear;

  /// "" for a mesh that is closed and consistently wound; otherwise one line, e.g. "body
  /// drone.stl is open (124 boundary edges) and 40 triangles are wound against their
  /// neighbours: occlusion and sampled normals may be wrong", with `name` the body's name.
  std::string warning(const std::string& name) const;
};

/// The report of `mesh` (finite vertices). O(t log t) time and about 45 bytes per triangle of
/// temporary memory for t triangles.
MeshReport mesh_report(const Mesh& mesh);

/// The patches of a mesh (docs/math.md §21, "Sites"): the triangles joined by edges of exactly
/// two triangles (between welded vertices, as MeshReport's edges), each patch with one winding
/// that its triangles agree on where they can (the propagation of MeshReport's
/// triangles_against_neighbours).
struct MeshPatches {
  int count = 0;
  /// Per triangle: its patch in [0, count), or -1 for a degenerate triangle.
  std::vector<int> patch;
  /// Per triangle: wound against its patch's winding (its normal turned, it agrees).
  std::vector<char> flipped;
  /// Per patch: none of its triangles' edges is a boundary edge or shared by more than two
  /// triangles, so that the patch encloses a volume.
  std::vector<char> closed;
};

/// The patches of `mesh` (finite vertices). O(t log t) for t triangles.
MeshPatches mesh_patches(const Mesh& mesh);

}  // namespace vantage
