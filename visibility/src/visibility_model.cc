#include "vantage/visibility/visibility_model.h"

#include "vantage/analysis/common.h"
#include "vantage/body/occlusion.h"
#include "vantage/visibility/visibility_report.h"

namespace vantage::visibility {

VisibilityModel VisibilityModel::of(const Layout& layout, double resolution_deg, int threads) {
  if (!(resolution_deg >= 0.45 && resolution_deg <= 30.0)) {
    throw InvalidArgument("occlusion_resolution_deg", "must be in [0.45, 30] degrees");
  }
  VisibilityModel model;
  model.problem_ = visibility_problem(layout, nullptr);
  if (layout.visibility->body) {
    body::OcclusionOptions options;
    options.resolution = resolution_deg / kDegreesPerRadian;
    options.threads = threads;
    model.grid_ = std::make_shared<const OcclusionGrid>(
        body::build_occlusion_grid(*layout.visibility->body, model.problem_.points,
                                   model.problem_.normals, model.problem_.cos_cone, options));
    model.problem_.occlusion = model.grid_.get();
  }
  return model;
}

std::optional<double> VisibilityModel::resolution_deg() const {
  if (!grid_) return std::nullopt;
  return grid_->resolution() * kDegreesPerRadian;
}

DirectionVisibility VisibilityModel::at(const Eigen::Vector3d& a) const {
  return direction_visibility(problem_, a);
}

}  // namespace vantage::visibility
