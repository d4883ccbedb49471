#include "vantage/io/mesh_file.h"

#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <new>
#include <stdexcept>

#include "ply_header.h"
#include "vantage/analysis/common.h"
#include "vantage/io/printable.h"

namespace vantage::io {
namespace {

// Per-vertex data the body does not use, dropped by assimp before its scene is copied.
constexpr int kUnusedVertexData = aiComponent_NORMALS | aiComponent_TANGENTS_AND_BITANGENTS |
                                  aiComponent_COLORS | aiComponent_TEXCOORDS |
                                  aiComponent_BONEWEIGHTS;

bool finite(const aiVector3D& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

std::string coordinates(const aiVector3D& p) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.9g, %.9g, %.9g)", p.x, p.y, p.z);
  return text;
}

/// Throws for a vertex with a coordinate that is not finite, as the file gives it: before any
/// post-processing, which may move it (assimp's joining of identical vertices merged a NaN
/// vertex into a finite one). Names the first face that uses it, else the vertex.
void check_finite(const aiScene& scene) {
  const auto where = [&](unsigned m) {
    return scene.mNumMeshes > 1 ? " (mesh " + std::to_string(m) + " of the file)" : std::string();
  };
  for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
    const aiMesh& part = *scene.mMeshes[m];
    for (unsigned f = 0; f < part.mNumFaces; ++f) {
      const aiFace& face = part.mFaces[f];
      for (unsigned c = 0; c < face.mNumIndices; ++c) {
        const aiVector3D& p = part.mVertices[face.mIndices[c]];
        if (finite(p)) continue;
        throw InvalidArgument(
            face.mNumIndices == 3 ? "triangle" : "face", f,
            "vertex " + std::to_string(c) + " is not finite " + coordinates(p) + where(m));
      }
    }
    for (unsigned v = 0; v < part.mNumVertices; ++v) {
      if (!finite(part.mVertices[v])) {
        throw InvalidArgument("vertex", v,
                              "is not finite " + coordinates(part.mVertices[v]) +
                                  " (a vertex no face uses)" + where(m));
      }
    }
  }
}

/// The triangles of the (pre-transformed, triangulated) scene in its order, one vertex per
/// vertex of the file's meshes; faces that are points or lines are skipped.
Mesh triangles_of(const aiScene& scene) {
  long vertices = 0, triangles = 0;
  for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
    vertices += scene.mMeshes[m]->mNumVertices;
    for (unsigned f = 0; f < scene.mMeshes[m]->mNumFaces; ++f) {
      triangles += scene.mMeshes[m]->mFaces[f].mNumIndices == 3;
    }
  }
  Mesh mesh;
  mesh.vertices.resize(3, vertices);
  mesh.triangles.resize(3, triangles);
  long v = 0, t = 0;
  for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
    const aiMesh& part = *scene.mMeshes[m];
    const long first = v;
    for (unsigned k = 0; k < part.mNumVertices; ++k) {
      mesh.vertices.col(v++) << part.mVertices[k].x, part.mVertices[k].y, part.mVertices[k].z;
    }
    for (unsigned f = 0; f < part.mNumFaces; ++f) {
      const aiFace& face = part.mFaces[f];
      if (face.mNumIndices != 3) continue;
      mesh.triangles.col(t++) << static_cast<int>(first + face.mIndices[0]),
          static_cast<int>(first + face.mIndices[1]), static_cast<int>(first + face.mIndices[2]);
    }
  }
  return mesh;
}

Mesh read_with_assimp(const std::string& path) {
  Assimp::Importer importer;
  importer.SetPropertyInteger(AI_CONFIG_PP_RVC_FLAGS, kUnusedVertexData);
  if (importer.ReadFile(path, 0) == nullptr) {
    throw InvalidArgument("not a mesh assimp can read (" + printable(importer.GetErrorString()) +
                          ")");
  }
  check_finite(*importer.GetScene());
  const aiScene* scene = importer.ApplyPostProcessing(
      aiProcess_RemoveComponent | aiProcess_PreTransformVertices | aiProcess_Triangulate);
  if (scene == nullptr) {
    throw InvalidArgument("not a mesh assimp can read (" + printable(importer.GetErrorString()) +
                          ")");
  }
  Mesh mesh = triangles_of(*scene);
  importer.FreeScene();
  if (mesh.triangles.cols() == 0) throw InvalidArgument("the mesh has no triangles");
  // A node transform that is not finite makes vertices that are not.
  weld_identical_vertices(&mesh);
  return mesh;
}

}  // namespace

Mesh read_mesh(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw InvalidArgument(printable(path) + ": cannot open file (not a readable file)");
  }
  try {
    internal::check_ply_header(path);
    Mesh mesh = read_with_assimp(path);
    mesh.source = path;
    return mesh;
  } catch (const InvalidArgument& e) {
    throw e.against(printable(path));
  } catch (const std::bad_alloc&) {
    throw InvalidArgument(printable(path) + ": the mesh does not fit in memory");
  } catch (const std::length_error&) {
    throw InvalidArgument(printable(path) + ": the mesh does not fit in memory");
  }
}

}  // namespace vantage::io
