#pragma once

// The JSON objects of `vantage pose --json`, one per estimator family (the contract is the
// "vantage pose" section of README.md). Shared by the `vantage` command and the Python module
// (vantage.pose), so that both print exactly the same fields.

#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <string>

#include "vantage/analysis/affine_pose.h"
#include "vantage/analysis/orthogonal_iteration.h"
#include "vantage/analysis/refined_pose.h"
#include "vantage/analysis/two_view.h"

namespace vantage::pose_json {

using Json = nlohmann::ordered_json;

/// A 3 x 3 matrix as a list of its rows.
Json rows(const Eigen::Matrix3d& m);

/// A 3-vector as a list.
Json list(const Eigen::Vector3d& v);

/// A number, or null when it is not finite (NaN and infinities are never printed).
Json number(double x);

/// A vector with null for each entry that is not finite (an unknown depth p_z).
Json finite_list(const Eigen::VectorXd& v);

/// The camera as {"focal": F or null when unknown, "principal_point": [cx, cy]}.
Json camera(const Camera& camera);

/// affine and standard (Prop. 8 / Theorem 1 with v_z = 0) on n correspondences.
Json affine(const std::string& method, Eigen::Index n, const AffinePoseOptions& options,
            const AffinePoseResult& pose);

/// affine-refined and perspective (LM from Prop. 8) on n correspondences.
Json refined(const std::string& method, Eigen::Index n, const RefinedPoseOptions& options,
             const RefinedPoseResult& pose);

/// full3d (Theorem 1 + Eq. 13 on n 3-D measurements).
Json full3d(const std::string& method, Eigen::Index n, const AffinePoseOptions& options,
            const PoseResult& pose);

/// oi-foam and oi-svd (orthogonal iteration, Wu & Wu) on n correspondences.
Json orthogonal_iteration(const std::string& method, Eigen::Index n,
                          const OrthogonalIterationOptions& options,
                          const OrthogonalIterationResult& pose);

/// two-view (Haralick's linear algorithm) on n point pairs.
Json two_view(const std::string& method, Eigen::Index n, const TwoViewOptions& options,
              const TwoViewResult& pose);

}  // namespace vantage::pose_json
