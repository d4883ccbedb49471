#pragma once

// The JSON object of `vantage pose --json` (the contract is the "vantage pose" section of
// README.md), from the one PoseEstimate every method returns. Shared by the `vantage` command and
// the Python module (vantage.pose), so that both print exactly the same fields.

#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <string>

#include "vantage/analysis/camera.h"
#include "vantage/analysis/pose_estimate.h"

namespace vantage::pose_json {

using Json = nlohmann::ordered_json;

/// A 3 x 3 matrix as a list of its rows.
Json rows(const Eigen::Matrix3d& m);

/// A 3-vector as a list.
Json list(const Eigen::Vector3d& v);

/// A vector with null for each entry that is not finite (an unknown depth p_z).
Json finite_list(const Eigen::VectorXd& v);

/// The camera as {"focal": F or null when unknown, "principal_point": [cx, cy]}.
Json camera(const Camera& camera);

/// `vantage pose --json` for any method: method, n, R, p, alpha, status, ambiguous,
/// reprojection_rms_px, objective, iterations, camera, message (when any), alternative (when
/// evaluated), then the method's diagnostics (README, "vantage pose"). n is the number of
/// correspondences.
Json estimate(const PoseEstimate& pose, Eigen::Index n);

}  // namespace vantage::pose_json
