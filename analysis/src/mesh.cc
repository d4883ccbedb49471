#include "vantage/analysis/mesh.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "vantage/analysis/common.h"

namespace vantage {
namespace {

/// The point of triangle (a, b, c) nearest to p (Ericson, Real-Time Collision Detection, 5.1.5:
/// Voronoi regions of the vertices, then the edges, then the face).
Eigen::Vector3d closest_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                    const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return a;
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + d1 / (d1 - d3) * ab;
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  }
  const double denominator = va + vb + vc;
  if (!(denominator > 0.0)) return a;  // a degenerate (zero-area) triangle: its first vertex
  return a + (vb / denominator) * ab + (vc / denominator) * ac;
}

}  // namespace

void Mesh::validate() const {
  if (triangles.cols() == 0) throw InvalidArgument("body", "the mesh has no triangles");
  for (Eigen::Index k = 0; k < vertices.cols(); ++k) {
    if (!vertices.col(k).allFinite()) {
      throw InvalidArgument("body", "vertex " + std::to_string(k) + " is not finite");
    }
  }
  for (Eigen::Index k = 0; k < triangles.cols(); ++k) {
    if (triangles.col(k).minCoeff() < 0 || triangles.col(k).maxCoeff() >= vertices.cols()) {
      throw InvalidArgument(
          "body", "triangle " + std::to_string(k) + " names a vertex the mesh does not have");
    }
  }
}

double Mesh::size() const {
  if (vertices.cols() == 0) return 0.0;
  return (vertices.rowwise().maxCoeff() - vertices.rowwise().minCoeff()).norm();
}

double Mesh::area() const {
  double total = 0.0;
  for (Eigen::Index k = 0; k < triangles.cols(); ++k) {
    const Eigen::Vector3d a = vertices.col(triangles(0, k));
    total +=
        0.5 * (vertices.col(triangles(1, k)) - a).cross(vertices.col(triangles(2, k)) - a).norm();
  }
  return total;
}

std::vector<int> first_identical_vertex(const Eigen::Matrix3Xd& vertices) {
  if (!vertices.allFinite()) throw InvalidArgument("vertices", "must be finite");
  const int n = static_cast<int>(vertices.cols());
  std::vector<int> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  // Lexicographic on (x, y, z), ties by index: each group of equal positions is contiguous and
  // starts at its first vertex.
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    for (int c = 0; c < 3; ++c) {
      if (vertices(c, a) != vertices(c, b)) return vertices(c, a) < vertices(c, b);
    }
    return a < b;
  });
  std::vector<int> first(static_cast<std::size_t>(n));
  for (std::size_t k = 0; k < order.size();) {
    std::size_t end = k + 1;
    while (end < order.size() && vertices.col(order[end]) == vertices.col(order[k])) ++end;
    for (std::size_t j = k; j < end; ++j) first[static_cast<std::size_t>(order[j])] = order[k];
    k = end;
  }
  return first;
}

void weld_identical_vertices(Mesh* mesh) {
  mesh->validate();
  const std::vector<int> first = first_identical_vertex(mesh->vertices);
  constexpr int kUnused = -1, kUsed = -2;
  std::vector<int> renumbered(first.size(), kUnused);
  for (Eigen::Index k = 0; k < mesh->triangles.size(); ++k) {
    renumbered[static_cast<std::size_t>(first[static_cast<std::size_t>(mesh->triangles(k))])] =
        kUsed;
  }
  int kept = 0;
  for (int& index : renumbered) {
    if (index == kUsed) index = kept++;
  }
  Eigen::Matrix3Xd vertices(3, kept);
  for (std::size_t v = 0; v < renumbered.size(); ++v) {
    if (renumbered[v] >= 0)
      vertices.col(renumbered[v]) = mesh->vertices.col(static_cast<Eigen::Index>(v));
  }
  for (Eigen::Index k = 0; k < mesh->triangles.size(); ++k) {
    mesh->triangles(k) =
        renumbered[static_cast<std::size_t>(first[static_cast<std::size_t>(mesh->triangles(k))])];
  }
  mesh->vertices = std::move(vertices);
}

double distance_to_mesh(const Mesh& mesh, const Eigen::Vector3d& point) {
  double best = std::numeric_limits<double>::infinity();
  for (Eigen::Index k = 0; k < mesh.triangles.cols(); ++k) {
    const Eigen::Vector3d q = closest_on_triangle(point, mesh.vertices.col(mesh.triangles(0, k)),
                                                  mesh.vertices.col(mesh.triangles(1, k)),
                                                  mesh.vertices.col(mesh.triangles(2, k)));
    best = std::min(best, (q - point).norm());
  }
  return best;
}

MeshPoint nearest_mesh_point(const Mesh& mesh, const Eigen::Vector3d& point) {
  MeshPoint best;
  for (Eigen::Index k = 0; k < mesh.triangles.cols(); ++k) {
    const Eigen::Vector3d a = mesh.vertices.col(mesh.triangles(0, k));
    const Eigen::Vector3d b = mesh.vertices.col(mesh.triangles(1, k));
    const Eigen::Vector3d c = mesh.vertices.col(mesh.triangles(2, k));
    const Eigen::Vector3d cross = (b - a).cross(c - a);
    const double longest =
        std::max({(b - a).squaredNorm(), (c - a).squaredNorm(), (c - b).squaredNorm()});
    if (!(cross.norm() > kSliverRatio * longest)) continue;
    const Eigen::Vector3d q = closest_on_triangle(point, a, b, c);
    const double distance = (q - point).norm();
    if (distance < best.distance) best = {q, cross.normalized(), k, distance};
  }
  return best;
}

}  // namespace vantage
