#pragma once

// Markers on an ellipsoid of half-axes (2, 1.5, 1) with its outward normals and 60-degree cones,
// from a seeded engine; with a mesh, the ellipsoid as 5040 triangles. Shared by the visibility
// and the pose CRB benchmarks.

#include <Eigen/Core>
#include <cmath>
#include <random>
#include <vector>

#include "vantage/analysis/common.h"
#include "vantage/analysis/layout.h"

namespace vantage_bench {

inline const Eigen::Vector3d kHalfAxes(2.0, 1.5, 1.0);
constexpr double kConeDeg = 60.0;
// Ellipsoid mesh: latitude bands x longitude steps (2 x 36 x 70 = 5040 triangles).
constexpr int kStacks = 36;
constexpr int kSlices = 70;

inline Eigen::Vector3d on_ellipsoid(double polar, double azimuth) {
  return Eigen::Vector3d(kHalfAxes.x() * std::sin(polar) * std::cos(azimuth),
                         kHalfAxes.y() * std::sin(polar) * std::sin(azimuth),
                         kHalfAxes.z() * std::cos(polar));
}

// n markers on the ellipsoid, normals its gradient, kConeDeg cones; with_body: the mesh too.
inline vantage::Layout ellipsoid_layout(int n, bool with_body) {
  std::mt19937 rng(20261202u + static_cast<unsigned>(n));
  std::normal_distribution<double> normal;
  vantage::Layout layout;
  layout.mode = vantage::LayoutMode::kPoints;
  layout.entries.resize(3, n);
  vantage::MarkerVisibility v;
  v.normals.resize(3, n);
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d d = Eigen::Vector3d(normal(rng), normal(rng), normal(rng)).normalized();
    const Eigen::Vector3d p = d.cwiseProduct(kHalfAxes);
    layout.entries.col(i) = p;
    v.normals.col(i) = p.cwiseQuotient(kHalfAxes.cwiseProduct(kHalfAxes)).normalized();
  }
  layout.weights = Eigen::VectorXd::Ones(n);
  v.cone_half_angle_deg = Eigen::VectorXd::Constant(n, kConeDeg);
  if (with_body) {
    vantage::Mesh mesh;
    mesh.vertices.resize(3, 2 + (kStacks - 1) * kSlices);
    mesh.vertices.col(0) = on_ellipsoid(0.0, 0.0);
    mesh.vertices.col(1) = on_ellipsoid(vantage::kPi, 0.0);
    for (int s = 1; s < kStacks; ++s) {
      for (int k = 0; k < kSlices; ++k) {
        mesh.vertices.col(2 + (s - 1) * kSlices + k) =
            on_ellipsoid(vantage::kPi * s / kStacks, 2 * vantage::kPi * k / kSlices);
      }
    }
    auto ring = [](int s, int k) { return 2 + (s - 1) * kSlices + (k % kSlices); };
    std::vector<Eigen::Vector3i> triangles;
    for (int k = 0; k < kSlices; ++k) {
      triangles.emplace_back(0, ring(1, k), ring(1, k + 1));
      triangles.emplace_back(1, ring(kStacks - 1, k + 1), ring(kStacks - 1, k));
      for (int s = 1; s + 1 < kStacks; ++s) {
        triangles.emplace_back(ring(s, k), ring(s + 1, k), ring(s + 1, k + 1));
        triangles.emplace_back(ring(s, k), ring(s + 1, k + 1), ring(s, k + 1));
      }
    }
    mesh.triangles.resize(3, static_cast<Eigen::Index>(triangles.size()));
    for (std::size_t t = 0; t < triangles.size(); ++t) {
      mesh.triangles.col(static_cast<Eigen::Index>(t)) = triangles[t];
    }
    v.body = mesh;
    v.body_path = "ellipsoid";
  }
  layout.visibility = v;
  return layout;
}

}  // namespace vantage_bench
