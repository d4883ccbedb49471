#include "vantage/sdp/certified_worst.h"

#include <algorithm>

#include "vantage/analysis/error_bounds.h"

namespace vantage::sdp {

CertifiedWorst certified_worst(const WorstViewpoint& worst, const Eigen::Matrix3Xd& vectors) {
  CertifiedWorst out;
  out.viewpoint = worst.viewpoint;
  out.viewpoints = worst.viewpoints;
  if (out.viewpoints.empty()) out.viewpoints.push_back(worst.viewpoint);
  out.t = worst.t;
  out.pbar_min = worst.pbar_min;
  out.max_worst_case_error_deg = max_worst_case_error_deg(vectors, out.viewpoints);
  out.certified = worst.certified();
  return out;
}

CertifiedWorst certified_worst_end_on(const Eigen::Vector3d& v) {
  CertifiedWorst out;
  out.viewpoint = upper_hemisphere(v.normalized());
  out.viewpoints = {out.viewpoint};
  out.t = 1.0;
  out.pbar_min = 0.0;
  out.max_worst_case_error_deg = 90.0;
  out.certified = true;
  return out;
}

double max_worst_case_error_deg(const Eigen::Matrix3Xd& vectors,
                                const std::vector<Eigen::Vector3d>& viewpoints) {
  double largest = 0.0;
  for (const Eigen::Vector3d& a : viewpoints) {
    largest = std::max(largest, worst_case_errors_deg(vectors, a).maxCoeff());
  }
  return largest;
}

}  // namespace vantage::sdp
