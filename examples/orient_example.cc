// Theorem 1 on a bundled correspondence set: reads model points and their measurements in the
// camera frame, solves alpha * measured = R * model + p, and checks the fit.
//
//   orient_example examples/correspondences/cube.json

#include <Eigen/Geometry>
#include <cstdio>
#include <exception>

#include "vantage/analysis/absolute_orientation.h"
#include "vantage/analysis/common.h"
#include "vantage/io/correspondence_file.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: orient_example CORRESPONDENCES.json\n");
    return 2;
  }
  try {
    const vantage::io::CorrespondenceFile file = vantage::io::read_correspondences(argv[1]);
    file.require({"model", "measured"}, "orient_example");

    vantage::OrientationOptions options;
    options.method = vantage::OrientationMethod::kQMethod;  // or kSvd, kFoam
    const vantage::PoseResult pose =
        vantage::absolute_pose(file.model, file.measured, file.weights, options);

    const Eigen::Vector3d angles =
        pose.R_camera_object.eulerAngles(2, 1, 0) * vantage::kDegreesPerRadian;
    std::printf("status %s, alpha %.6f, residual %.3g\n", vantage::to_string(pose.status),
                pose.alpha, pose.residual);
    std::printf("R (zyx Euler, deg) %.4f %.4f %.4f\n", angles(0), angles(1), angles(2));
    std::printf("p %.6f %.6f %.6f\n", pose.p_camera_object(0), pose.p_camera_object(1),
                pose.p_camera_object(2));
    return pose.status == vantage::OrientationStatus::kOk ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "orient_example: %s\n", e.what());
    return 2;
  }
}
