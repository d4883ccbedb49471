// The installed core used the way a user would: Theorem 1 recovers a known rotation and scale
// (vantage::analysis), the global worst viewpoint of the orthogonal triad is p-bar_min =
// sqrt(2/3) (vantage::sdp, so CSDP resolves through the package config), and its cross-check
// agrees when vantage has NLopt (NLopt resolves too) or says "built without NLopt" when the
// package config says vantage_WITH_NLOPT is OFF. Exit status 0 only when all of it holds.

#include <cmath>
#include <cstdio>

#include "vantage/analysis/absolute_orientation.h"
#include "vantage/analysis/build_options.h"
#include "vantage/analysis/quaternion.h"
#include "vantage/design/weights.h"
#include "vantage/io/layout_file.h"
#include "vantage/sdp/worst_viewpoint.h"

int main() {
  // Noise-free data: the solver must return the truth up to rounding.
  constexpr double kToleranceRadians = 1e-9;
  const Eigen::Vector4d eps = Eigen::Vector4d(0.2, -0.4, 0.5, 0.7).normalized();  // [e; eps4]
  const Eigen::Matrix3d R_true = vantage::rotation_from_quaternion(eps);
  const double alpha_true = 2.5;

  Eigen::Matrix3Xd z_object(3, 4);
  z_object << 1.0, 0.0, 0.0, 0.3,  //
      0.0, 1.0, 0.0, -0.7,         //
      0.0, 0.0, 1.0, 0.2;
  const Eigen::Matrix3Xd v_camera = R_true * z_object / alpha_true;

  const vantage::OrientationResult result = vantage::absolute_orientation(z_object, v_camera);
  const double error = vantage::rotation_angle_between(result.R_camera_object, R_true);
  std::printf("status %s, rotation error %.3g rad, alpha %.12g (true %.12g)\n",
              vantage::to_string(result.status), error, result.alpha, alpha_true);
  const bool orientation_ok = result.status == vantage::OrientationStatus::kOk &&
                              error < kToleranceRadians &&
                              std::abs(result.alpha - alpha_true) < kToleranceRadians * alpha_true;

  const vantage::Layout triad = vantage::io::parse_layout(
      R"({"name": "triad", "vectors": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]})", "consumer");
  const vantage::sdp::WorstViewpoint worst =
      vantage::sdp::global_worst_viewpoint(vantage::data_vectors(triad).vectors);
  const vantage::design::Weights weights = vantage::design::layout_weights(triad);
  std::printf("triad: pbar_min %.12g with %zu worst viewpoints; weights feasible: %s\n",
              worst.pbar_min, worst.viewpoints.size(), weights.feasible ? "yes" : "no");
  const bool worst_ok = std::abs(worst.pbar_min - std::sqrt(2.0 / 3.0)) < kToleranceRadians &&
                        worst.viewpoints.size() == 4 && !weights.feasible;

  const vantage::sdp::CrossCheck check = vantage::sdp::crosscheck_worst_viewpoint(
      vantage::data_vectors(triad).vectors, worst.t, {}, worst.viewpoints);
  std::printf(
      "cross-check: %s%s\n", check.skipped.empty() ? check.method.c_str() : "skipped: ",
      check.skipped.empty() ? (check.agrees ? " agrees" : " DISAGREES") : check.skipped.c_str());
  const bool nlopt_ok = vantage::built_with_nlopt() == (CONSUMER_WITH_NLOPT != 0) &&
                        (vantage::built_with_nlopt() ? check.skipped.empty() && check.agrees
                                                     : check.skipped == vantage::kWithoutNlopt);
  return orientation_ok && worst_ok && nlopt_ok ? 0 : 1;
}
