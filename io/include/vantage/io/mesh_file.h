#pragma once

/// Reading a body mesh (STL, OBJ, PLY, glTF, ... : whatever assimp reads) into a vantage::Mesh.

#include <string>

#include "vantage/analysis/mesh.h"

namespace vantage::io {

/// The triangles of every mesh in the file, node transforms applied, polygons triangulated and
/// identical vertices joined. Throws InvalidArgument "<path>: <why>" when the file cannot be read
/// or holds no triangles (points and lines are ignored).
Mesh read_mesh(const std::string& path);

}  // namespace vantage::io
