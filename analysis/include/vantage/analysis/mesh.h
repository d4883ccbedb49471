#pragma once

/// A body as a triangle mesh in the object frame: what shadows markers (docs/math.md §20) and
/// where markers may be placed. Read from STL, OBJ, PLY, glTF, ... by io::read_mesh().

#include <Eigen/Core>
#include <string>

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

/// The distance from `point` to the nearest point of the mesh's triangles (every triangle is
/// tested: O(triangles)).
double distance_to_mesh(const Mesh& mesh, const Eigen::Vector3d& point);

}  // namespace vantage
