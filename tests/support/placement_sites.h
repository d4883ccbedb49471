// Candidate sites and a brute-force enumeration shared by the placement objective tests
// (tests/design/placement_*_test.cc): the truth they compare place_markers() against.

#pragma once

#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "vantage/analysis/common.h"
#include "vantage/analysis/layout.h"
#include "vantage/visibility/visibility.h"

namespace vantage::testing {

// n sites on a 2 x 1 x 0.5 box's top and sides (seeded), normals of their faces, cones 75 deg,
// min_visible 3, the workspace 60 deg about +z.
inline Layout box_sites(int n, unsigned seed) {
  std::mt19937 engine(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Layout out;
  out.mode = LayoutMode::kPoints;
  out.entries.resize(3, n);
  MarkerVisibility v;
  v.normals.resize(3, n);
  for (int i = 0; i < n; ++i) {
    const int face = i % 3;  // top, +x side, -y side
    if (face == 0) {
      out.entries.col(i) = Eigen::Vector3d(u(engine), 0.5 * u(engine), 0.25);
      v.normals.col(i) = Eigen::Vector3d::UnitZ();
    } else if (face == 1) {
      out.entries.col(i) = Eigen::Vector3d(1.0, 0.5 * u(engine), 0.25 * u(engine));
      v.normals.col(i) = Eigen::Vector3d::UnitX();
    } else {
      out.entries.col(i) = Eigen::Vector3d(u(engine), -0.5, 0.25 * u(engine));
      v.normals.col(i) = -Eigen::Vector3d::UnitY();
    }
  }
  out.weights = Eigen::VectorXd::Ones(n);
  v.cone_half_angle_deg = Eigen::VectorXd::Constant(n, 75.0);
  out.visibility = v;
  out.workspace = LayoutWorkspace{Eigen::Vector3d::UnitZ(), 60.0};
  return out;
}

// The sites as place_markers() takes them.
inline visibility::VisibilityProblem as_problem(const Layout& sites) {
  visibility::VisibilityProblem out;
  out.points = sites.entries;
  out.normals = sites.visibility->normals;
  out.cos_cone = (sites.visibility->cone_half_angle_deg * kPi / 180.0).array().cos();
  out.min_visible = sites.visibility->min_visible;
  out.workspace = visibility::Workspace{sites.workspace->axis,
                                        std::cos(sites.workspace->half_angle_deg * kPi / 180.0)};
  return out;
}

// The chosen sites as a layout of their own (unit weights).
inline Layout subset(const Layout& sites, const std::vector<int>& chosen) {
  Layout out = sites;
  const Eigen::Index k = static_cast<Eigen::Index>(chosen.size());
  out.entries.resize(3, k);
  out.weights = Eigen::VectorXd::Ones(k);
  out.visibility->normals.resize(3, k);
  out.visibility->cone_half_angle_deg.resize(k);
  for (Eigen::Index j = 0; j < k; ++j) {
    const int s = chosen[static_cast<std::size_t>(j)];
    out.entries.col(j) = sites.entries.col(s);
    out.visibility->normals.col(j) = sites.visibility->normals.col(s);
    out.visibility->cone_half_angle_deg(j) = sites.visibility->cone_half_angle_deg(s);
  }
  return out;
}

struct BestSubset {
  double value = std::numeric_limits<double>::infinity();
  std::vector<int> chosen;
};

// Every k-subset of n sites, lexicographic, scored by value(subset); the first of the least.
template <class Value>
BestSubset enumerate_subsets(int n, int k, Value value) {
  std::vector<int> idx(static_cast<std::size_t>(k));
  for (int i = 0; i < k; ++i) idx[static_cast<std::size_t>(i)] = i;
  BestSubset best;
  while (true) {
    const double v = value(idx);
    if (v < best.value) best = {v, idx};
    int i = k - 1;
    while (i >= 0 && idx[static_cast<std::size_t>(i)] == n - k + i) --i;
    if (i < 0) break;
    ++idx[static_cast<std::size_t>(i)];
    for (int j = i + 1; j < k; ++j)
      idx[static_cast<std::size_t>(j)] = idx[static_cast<std::size_t>(j - 1)] + 1;
  }
  return best;
}

}  // namespace vantage::testing
