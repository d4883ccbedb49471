#include "vantage/viewer/viewpoint_readout.h"

#include <algorithm>
#include <cmath>

#include "vantage/analysis/common.h"
#include "vantage/analysis/error_bounds.h"

namespace vantage::viewer {
namespace {}  // namespace

ViewpointReadout read_viewpoint(const Eigen::Matrix3Xd& vectors, const Eigen::Vector3d& a) {
  if (vectors.cols() < 1) throw InvalidArgument("read_viewpoint: vectors is empty");
  ViewpointReadout readout;
  readout.viewpoint = a;
  readout.p = projected_fractions(vectors, a);
  readout.pbar_at = readout.p.maxCoeff(&readout.limiting);
  readout.errors_deg = worst_case_errors_deg(vectors, a);
  readout.max_error_deg = readout.errors_deg.maxCoeff();
  return readout;
}

SphereShading shade_sphere(const Eigen::Matrix3Xd& vectors, int rings, int segments) {
  if (rings < 2) throw InvalidArgument("shade_sphere: rings must be >= 2");
  if (segments < 3) throw InvalidArgument("shade_sphere: segments must be >= 3");
  SphereShading shading;
  const int columns = segments + 1;  // the seam is duplicated so each ring closes
  shading.vertices.resize(3, (rings + 1) * columns);
  for (int r = 0; r <= rings; ++r) {
    const double polar = kPi * r / rings;
    for (int s = 0; s <= segments; ++s) {
      const double azimuth = 2.0 * kPi * s / segments;
      shading.vertices.col(r * columns + s) =
          Eigen::Vector3d(std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth),
                          std::cos(polar))
              .normalized();
    }
  }
  for (int r = 0; r < rings; ++r) {
    for (int s = 0; s < segments; ++s) {
      const int v00 = r * columns + s;
      const int v01 = v00 + 1;
      const int v10 = v00 + columns;
      const int v11 = v10 + 1;
      if (r > 0) shading.triangles.push_back({v00, v10, v01});
      if (r < rings - 1) shading.triangles.push_back({v01, v10, v11});
    }
  }
  const Eigen::VectorXd pbar = pbar_at_viewpoints(vectors, shading.vertices);
  shading.error_deg = pbar.unaryExpr(
      [](double p) { return kDegreesPerRadian * std::acos(std::clamp(p, -1.0, 1.0)); });
  return shading;
}

}  // namespace vantage::viewer
