// The directions of a workspace (docs/math.md §20, "Coverage"): the Fibonacci spiral of its cap.
// Filtering the sphere's lattice by the cap left a 3-degree workspace 14 points and a 0.2-degree
// one none.

#include "vantage/visibility/workspace_lattice.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "vantage/analysis/common.h"

namespace vantage::visibility {

WorkspaceLattice workspace_lattice(const std::optional<Workspace>& workspace, int count) {
  if (count < 1) throw InvalidArgument("samples", "must be >= 1");
  WorkspaceLattice out;
  if (!workspace || workspace->cos_half_angle <= -1.0) {
    out.directions = fibonacci_directions(count);
    out.spacing = std::sqrt(4.0 * kPi / count);
    return out;
  }
  if (!(workspace->cos_half_angle > -1.0 && workspace->cos_half_angle < 1.0)) {
    throw InvalidArgument("workspace.half_angle_deg", "must be in (0, 180] degrees");
  }
  const double height = 1.0 - workspace->cos_half_angle;  // of the cap along w, in (0, 2)
  const double share = std::ceil(count * height / 2.0);
  const int m = static_cast<int>(
      std::max(share, static_cast<double>(std::min(count, kMinWorkspaceDirections))));
  const Eigen::Matrix3d turn =
      Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), workspace->axis)
          .toRotationMatrix();
  const double golden = kPi * (3.0 - std::sqrt(5.0));
  out.directions.resize(3, m);
  for (int k = 0; k < m; ++k) {
    const double z = 1.0 - height * (2.0 * k + 1.0) / (2.0 * m);
    const double r = std::sqrt(std::max(0.0, (1.0 - z) * (1.0 + z)));
    out.directions.col(k) =
        turn * Eigen::Vector3d(r * std::cos(golden * k), r * std::sin(golden * k), z);
  }
  out.spacing = std::sqrt(2.0 * kPi * height / m);
  return out;
}

}  // namespace vantage::visibility
