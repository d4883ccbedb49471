#pragma once

/// The §20 visibility of a direction under exact rays (docs/math.md §20, "What the certificate
/// covers"): marker i is seen from unit direction a iff nu_i . a >= cos(cone_i) and the ray from
/// p_i + eps nu_i along a (eps = 1e-6 of the mesh's size, as the occlusion grid's rays start)
/// meets no triangle of the body (Embree). The search certifies on the occlusion grid, whose
/// cells decide a whole patch of directions by one sample ray; this is the check of a single
/// direction that no grid stands in for.

#include <Eigen/Core>
#include <memory>

#include "vantage/analysis/mesh.h"
#include "vantage/visibility/visibility.h"

namespace vantage::body {
class RayCaster;
}

namespace vantage::visibility {

class ExactVisibility {
 public:
  /// For `problem`'s markers on `mesh` (both validated by the caller); builds the ray caster.
  ExactVisibility(const VisibilityProblem& problem, const Mesh& mesh);
  ~ExactVisibility();
  ExactVisibility(const ExactVisibility&) = delete;
  ExactVisibility& operator=(const ExactVisibility&) = delete;

  /// What unit direction a sees under exact rays: the visible markers, t and trackability.
  DirectionVisibility at(const Eigen::Vector3d& a) const;

 private:
  VisibilityProblem problem_;
  std::unique_ptr<body::RayCaster> caster_;
  double offset_ = 0.0;
};

}  // namespace vantage::visibility
