// How much of the workspace is trackable, and where the largest lost region is
// (docs/math.md §20, "Coverage"): Fibonacci directions, their untrackable neighbours joined.

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <tuple>

#include "vantage/analysis/common.h"
#include "vantage/visibility/visibility.h"
#include "vantage/visibility/workspace_lattice.h"

namespace vantage::visibility {
namespace {

// Lattice points closer than this many mean spacings are neighbours.
constexpr double kNeighbourSpacings = 2.5;

int find(std::vector<int>& parent, int k) {
  while (parent[k] != k) k = parent[k] = parent[parent[k]];
  return k;
}

}  // namespace

Eigen::Matrix3Xd fibonacci_directions(int count) {
  Eigen::Matrix3Xd out(3, count);
  const double golden = kPi * (3.0 - std::sqrt(5.0));
  for (int k = 0; k < count; ++k) {
    const double z = 1.0 - (2.0 * k + 1.0) / count;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    out.col(k) << r * std::cos(golden * k), r * std::sin(golden * k), z;
  }
  return out;
}

VisibilityCoverage visibility_coverage(const VisibilityProblem& problem, int samples) {
  problem.validate();
  if (samples < 100) throw InvalidArgument("samples", "must be >= 100");
  const WorkspaceLattice lattice = workspace_lattice(problem.workspace, samples);
  const Eigen::Matrix3Xd& a = lattice.directions;
  VisibilityCoverage out;
  out.samples = static_cast<int>(a.cols());
  std::vector<int> lost;
  for (int k = 0; k < out.samples; ++k) {
    if (!direction_visibility(problem, a.col(k)).trackable) lost.push_back(k);
  }
  if (out.samples == 0) return out;
  out.lost_fraction = static_cast<double>(lost.size()) / out.samples;
  out.trackable_fraction = 1.0 - out.lost_fraction;
  if (lost.empty()) return out;

  // Union-find over neighbours, found through a grid of cubes of the neighbour distance.
  const double reach = kNeighbourSpacings * lattice.spacing;  // chord ~ angle at this scale
  std::map<std::tuple<int, int, int>, std::vector<int>> buckets;
  auto key = [&](const Eigen::Vector3d& p) {
    return std::make_tuple(static_cast<int>(std::floor(p.x() / reach)),
                           static_cast<int>(std::floor(p.y() / reach)),
                           static_cast<int>(std::floor(p.z() / reach)));
  };
  for (std::size_t k = 0; k < lost.size(); ++k) {
    buckets[key(a.col(lost[k]))].push_back(static_cast<int>(k));
  }
  std::vector<int> parent(lost.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (std::size_t k = 0; k < lost.size(); ++k) {
    const Eigen::Vector3d p = a.col(lost[k]);
    const auto [x, y, z] = key(p);
    for (int dx = -1; dx <= 1; ++dx) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dz = -1; dz <= 1; ++dz) {
          const auto it = buckets.find({x + dx, y + dy, z + dz});
          if (it == buckets.end()) continue;
          for (int other : it->second) {
            if ((a.col(lost[static_cast<std::size_t>(other)]) - p).norm() <= reach) {
              parent[find(parent, static_cast<int>(k))] = find(parent, other);
            }
          }
        }
      }
    }
  }
  std::map<int, std::vector<int>> regions;
  for (std::size_t k = 0; k < lost.size(); ++k) {
    regions[find(parent, static_cast<int>(k))].push_back(lost[k]);
  }
  const std::vector<int>* largest = nullptr;
  for (const auto& [root, members] : regions) {
    if (largest == nullptr || members.size() > largest->size()) largest = &members;
  }
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (int k : *largest) centre += a.col(k);
  if (centre.norm() > 0.0) {
    centre.normalize();
    double radius = 0.0;
    for (int k : *largest) {
      radius = std::max(radius, std::atan2(a.col(k).cross(centre).norm(), a.col(k).dot(centre)));
    }
    out.largest_region_center = centre;
    out.largest_region_radius_deg = radius * kDegreesPerRadian;
  }
  return out;
}

}  // namespace vantage::visibility
