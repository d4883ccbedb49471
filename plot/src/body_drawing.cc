#include "body_drawing.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <tuple>

#include "style.h"
#include "vantage/analysis/common.h"

namespace vantage::plot::internal {
namespace {

// Vertices closer than this fraction of the mesh's size are one vertex.
constexpr double kWeldFraction = 1e-9;
// Each face's opacity: a closed body seen through shows two layers, about 2 x this.
constexpr double kFaceAlpha = 0.10;
constexpr Rgb kFaceColour{120, 130, 140};

// Welded vertex indices: one per distinct position.
std::vector<int> weld(const Mesh& mesh) {
  const double cell = std::max(mesh.size(), 1e-300) * kWeldFraction;
  std::map<std::tuple<long long, long long, long long>, int> seen;
  std::vector<int> id(static_cast<std::size_t>(mesh.vertices.cols()));
  for (Eigen::Index v = 0; v < mesh.vertices.cols(); ++v) {
    const Eigen::Vector3d p = mesh.vertices.col(v) / cell;
    const auto key = std::make_tuple(std::llround(p.x()), std::llround(p.y()), std::llround(p.z()));
    id[static_cast<std::size_t>(v)] = seen.emplace(key, static_cast<int>(v)).first->second;
  }
  return id;
}

Eigen::Vector3d face_normal(const Mesh& mesh, Eigen::Index f) {
  const Eigen::Vector3d a = mesh.vertices.col(mesh.triangles(0, f));
  const Eigen::Vector3d b = mesh.vertices.col(mesh.triangles(1, f));
  const Eigen::Vector3d c = mesh.vertices.col(mesh.triangles(2, f));
  const Eigen::Vector3d n = (b - a).cross(c - a);
  const double length = n.norm();
  return length > 0.0 ? Eigen::Vector3d(n / length) : Eigen::Vector3d::Zero();
}

}  // namespace

std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> feature_edges(const Mesh& mesh) {
  const std::vector<int> id = weld(mesh);
  std::map<std::pair<int, int>, std::vector<Eigen::Index>> faces_of;
  for (Eigen::Index f = 0; f < mesh.triangles.cols(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const int a = id[static_cast<std::size_t>(mesh.triangles(k, f))];
      const int b = id[static_cast<std::size_t>(mesh.triangles((k + 1) % 3, f))];
      if (a == b) continue;
      faces_of[{std::min(a, b), std::max(a, b)}].push_back(f);
    }
  }
  const double cos_feature = std::cos(kFeatureEdgeDeg / kDegreesPerRadian);
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> edges;
  for (const auto& [edge, faces] : faces_of) {
    bool feature = faces.size() != 2;
    if (!feature) {
      // Orientation does not matter (a mesh need not be consistently wound): faces in one
      // plane, either way round, are no fold.
      const double c = face_normal(mesh, faces[0]).dot(face_normal(mesh, faces[1]));
      feature = std::abs(c) < cos_feature;
    }
    if (feature) edges.emplace_back(mesh.vertices.col(edge.first), mesh.vertices.col(edge.second));
  }
  return edges;
}

void draw_body(Canvas& canvas, const Mesh& mesh,
               const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& to_scene,
               const std::function<Eigen::Vector2d(const Eigen::Vector3d&)>& project,
               const Eigen::Vector3d& view) {
  const Eigen::Index faces = mesh.triangles.cols();
  std::vector<Eigen::Index> order(static_cast<std::size_t>(faces));
  std::iota(order.begin(), order.end(), Eigen::Index{0});
  std::vector<double> depth(static_cast<std::size_t>(faces));
  for (Eigen::Index f = 0; f < faces; ++f) {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k) centre += mesh.vertices.col(mesh.triangles(k, f));
    depth[static_cast<std::size_t>(f)] = to_scene(centre / 3.0).dot(view);
  }
  std::sort(order.begin(), order.end(), [&](Eigen::Index a, Eigen::Index b) {
    return depth[static_cast<std::size_t>(a)] < depth[static_cast<std::size_t>(b)];
  });
  for (Eigen::Index f : order) {
    std::vector<double> x(3), y(3);
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector2d p = project(to_scene(mesh.vertices.col(mesh.triangles(k, f))));
      x[k] = p.x();
      y[k] = p.y();
    }
    canvas.fill_polygon(x, y, kFaceColour, kFaceAlpha);
  }
  canvas.pls().col0(kPenBody);
  canvas.pls().width(0.9 * page_scale(canvas));
  for (const auto& [a, b] : feature_edges(mesh)) {
    const Eigen::Vector2d p = project(to_scene(a)), q = project(to_scene(b));
    canvas.pls().join(p.x(), p.y(), q.x(), q.y());
  }
}

}  // namespace vantage::plot::internal
