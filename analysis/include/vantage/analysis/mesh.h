#pragma once

/// A body as a triangle mesh in the object frame: what shadows markers (docs/math.md §20) and
/// where markers may be placed. Read from STL, OBJ, PLY, glTF, ... by io::read_mesh().

#include <Eigen/Core>
#include <limits>
#include <string>
#include <vector>

namespace vantage {

/// A triangle mesh. Orientation of the triangles does not matter to the visibility model.
struct Mesh {
  Eigen::Matrix3Xd vertices;   ///< one vertex per column, object frame, finite
  Eigen::Matrix3Xi triangles;  ///< vertex indices of each triangle, one per column
  std::string source;          ///< the file it was read from (empty when built in memory)

  /// Throws InvalidArgument ("body: ...") for a mesh without triangles, a non-finite vertex or
  /// an index outside the vertices.
  void validate() const;

  /// The diagonal of the vertices' bounding box (0 for an empty mesh).
  double size() const;

  /// Total area of the triangles.
  double area() const;
};

/// For each vertex (finite, one per column), the index of the first vertex at the identical
/// position (coordinates equal as numbers: -0 equals +0): vertices that share a position share
/// the index. O(n log n).
std::vector<int> first_identical_vertex(const Eigen::Matrix3Xd& vertices);

/// Joins the vertices of `mesh` at identical positions (first_identical_vertex()) and drops the
/// vertices no triangle uses; the vertices kept stay in their order, the triangles unchanged but
/// for their indices. Throws InvalidArgument ("body: ...") as Mesh::validate() does.
void weld_identical_vertices(Mesh* mesh);

/// The distance from `point` to the nearest point of the mesh's triangles (every triangle is
/// tested: O(triangles)).
double distance_to_mesh(const Mesh& mesh, const Eigen::Vector3d& point);

/// A point of a mesh's surface and the triangle it lies on.
struct MeshPoint {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  /// The unit normal of the triangle, signed by its winding (which may not point outward).
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  Eigen::Index triangle = -1;  ///< -1: the mesh has no triangle with a normal
  double distance = std::numeric_limits<double>::infinity();  ///< from the point asked about
};

/// Below this ratio of |(b - a) x (c - a)| to the square of the longest edge a triangle is a
/// sliver without a normal of its own (its sides are parallel to rounding).
inline constexpr double kSliverRatio = 1e-12;

/// The point nearest to `point` on the triangles that have a normal (not slivers, see
/// kSliverRatio); of equally near triangles, the first. Every triangle is tested: O(triangles).
MeshPoint nearest_mesh_point(const Mesh& mesh, const Eigen::Vector3d& point);

}  // namespace vantage
