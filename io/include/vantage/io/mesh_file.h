#pragma once

/// Reading a body mesh (STL, OBJ, PLY, glTF, ... : whatever assimp reads) into a vantage::Mesh.

#include <string>

#include "vantage/analysis/mesh.h"

namespace vantage::io {

/// The triangles of every mesh in the file, node transforms applied, polygons triangulated and
/// vertices at identical positions joined (weld_identical_vertices()). Throws InvalidArgument
/// "<path>: <why>" when the file cannot be read or holds no triangles (points and lines are
/// ignored), when a vertex has a coordinate that is not finite ("triangle[k]: vertex c is not
/// finite (x, y, z)", k and c as the file gives them), when a PLY header declares more
/// elements than the file's size can hold (checked before assimp reads it), and when the mesh
/// does not fit in memory. Memory: about 150 bytes per triangle of a binary STL at its peak
/// (assimp's), 36 bytes per triangle of a closed mesh after (docs/benchmarks.md).
Mesh read_mesh(const std::string& path);

}  // namespace vantage::io
