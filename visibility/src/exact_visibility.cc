// One direction's visibility under exact rays (exact_visibility.h, docs/math.md §20).

#include "vantage/visibility/exact_visibility.h"

#include <vector>

#include "vantage/body/ray_caster.h"

namespace vantage::visibility {

ExactVisibility::ExactVisibility(const VisibilityProblem& problem, const Mesh& mesh)
    : problem_(problem),
      caster_(std::make_unique<body::RayCaster>(mesh)),
      offset_(body::kSurfaceOffset * mesh.size()) {
  problem_.occlusion = nullptr;
  problem_.occlusion_markers.clear();
}

ExactVisibility::~ExactVisibility() = default;

DirectionVisibility ExactVisibility::at(const Eigen::Vector3d& a) const {
  std::vector<int> visible;
  for (Eigen::Index i = 0; i < problem_.points.cols(); ++i) {
    if (problem_.normals.col(i).dot(a) < problem_.cos_cone(i)) continue;
    const Eigen::Vector3d origin = problem_.points.col(i) + offset_ * problem_.normals.col(i);
    if (caster_->occluded(origin, a)) continue;
    visible.push_back(static_cast<int>(i));
  }
  return seen_set(problem_, a, std::move(visible));
}

}  // namespace vantage::visibility
