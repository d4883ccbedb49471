#include "vantage/io/mesh_file.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#include <filesystem>

#include "vantage/analysis/common.h"
#include "vantage/io/printable.h"

namespace vantage::io {

Mesh read_mesh(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw InvalidArgument(printable(path) + ": cannot open file (not a readable file)");
  }
  Assimp::Importer importer;
  // Points and lines are dropped (the body is its surface): only triangles remain.
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE,
                              aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  const aiScene* scene =
      importer.ReadFile(path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                                  aiProcess_PreTransformVertices | aiProcess_SortByPType);
  if (scene == nullptr) {
    throw InvalidArgument(printable(path) + ": not a mesh assimp can read (" +
                          printable(importer.GetErrorString()) + ")");
  }
  Mesh mesh;
  mesh.source = path;
  long vertices = 0, triangles = 0;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    vertices += scene->mMeshes[m]->mNumVertices;
    for (unsigned f = 0; f < scene->mMeshes[m]->mNumFaces; ++f) {
      triangles += scene->mMeshes[m]->mFaces[f].mNumIndices == 3;
    }
  }
  mesh.vertices.resize(3, vertices);
  mesh.triangles.resize(3, triangles);
  long v = 0, t = 0;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* part = scene->mMeshes[m];
    const long first = v;
    for (unsigned k = 0; k < part->mNumVertices; ++k) {
      mesh.vertices.col(v++) << part->mVertices[k].x, part->mVertices[k].y, part->mVertices[k].z;
    }
    for (unsigned f = 0; f < part->mNumFaces; ++f) {
      const aiFace& face = part->mFaces[f];
      if (face.mNumIndices != 3) continue;
      mesh.triangles.col(t++) << static_cast<int>(first + face.mIndices[0]),
          static_cast<int>(first + face.mIndices[1]), static_cast<int>(first + face.mIndices[2]);
    }
  }
  if (triangles == 0) throw InvalidArgument(printable(path) + ": the mesh has no triangles");
  try {
    mesh.validate();
  } catch (const InvalidArgument& e) {
    throw e.against(printable(path));
  }
  return mesh;
}

}  // namespace vantage::io
