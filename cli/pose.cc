// `vantage pose CORRESPONDENCES --method M [--focal F] [--principal-point CX CY]
// [--free-vectors auto|all|spanning] [--json]`: one pose estimator on a correspondence file,
// through the one front door estimate_pose() (analysis/include/vantage/analysis/estimate_pose.h).
// The CLI reads the file, applies the options and formats the PoseEstimate; it computes nothing.

#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>
#include <vector>

#include "command.h"
#include "vantage/analysis/common.h"
#include "vantage/analysis/estimate_pose.h"
#include "vantage/analysis/layout.h"
#include "vantage/analysis/pose_method.h"
#include "vantage/commands/pose_json.h"
#include "vantage/io/correspondence_file.h"

namespace vantage::cli {
namespace {

struct PoseArgs {
  std::string file;
  std::string method;
  double focal = 0.0;
  std::vector<double> principal_point;
  std::string free_vectors = "auto";
  bool json = false;
  CLI::Option* focal_option = nullptr;
  CLI::Option* principal_point_option = nullptr;
  CLI::Option* free_vectors_option = nullptr;
};

FreeVectorSet free_vector_set(const std::string& name) {
  if (name == "all") return FreeVectorSet::kAllPairs;
  if (name == "spanning") return FreeVectorSet::kMaxSpanningTree;
  return FreeVectorSet::kAuto;
}

/// Options that the method does not use are refused, naming the option as typed.
void check_args(const PoseArgs& args, PoseMethod method) {
  if (args.focal_option->count() > 0) {
    if (!(args.focal > 0.0 && args.focal <= Layout::kMaxLength)) {
      throw InvalidArgument(
          "--focal", "must be a finite number in (0, 1e150], got " + format_number(args.focal));
    }
    if (pose_data(method) == PoseData::kMeasured || pose_data(method) == PoseData::kPlanar) {
      throw InvalidArgument("--focal", std::string("not used by --method ") + to_string(method) +
                                           " (it measures without a camera)");
    }
  }
  if (args.principal_point_option->count() > 0) {
    if (!(std::isfinite(args.principal_point[0]) && std::isfinite(args.principal_point[1]))) {
      throw InvalidArgument("--principal-point", "must be two finite numbers (pixels)");
    }
    if (pose_data(method) == PoseData::kMeasured || pose_data(method) == PoseData::kPlanar) {
      throw InvalidArgument("--principal-point",
                            std::string("not used by --method ") + to_string(method));
    }
  }
  if (args.free_vectors_option->count() > 0 && !uses_free_vectors(method)) {
    throw InvalidArgument("--free-vectors",
                          "only affine, affine-refined, perspective, standard and full3d use free "
                          "vectors, not " +
                              args.method);
  }
}

/// The file's fields, with --focal / --principal-point overriding its camera.
Correspondences correspondences_of(const PoseArgs& args, const io::CorrespondenceFile& file) {
  Correspondences data;
  data.model = file.model;
  data.image = file.image;
  data.measured = file.measured;
  data.image1 = file.image1;
  data.image2 = file.image2;
  data.weights = file.weights;
  data.camera = file.camera;
  if (args.focal_option->count() > 0) data.camera.focal_length = args.focal;
  if (args.principal_point_option->count() > 0) {
    data.camera.principal_point << args.principal_point[0], args.principal_point[1];
  }
  return data;
}

/// The model each method fits, for the report's second line.
const char* model_line(PoseMethod method) {
  switch (method) {
    case PoseMethod::kAffine:
      return "Prop. 8 (free vectors, Lemma 7, Eq. 36): alpha * (image - c) = P (R * model + p)";
    case PoseMethod::kStandard:
      return "standard approach (Theorem 1 with v_z = 0, Eq. 36): alpha * (image - c) = P (R * "
             "model + p)";
    case PoseMethod::kAffineRefined:
      return "affine refinement (LM on SO(3) x R^3 from Prop. 8): alpha * (image - c) = P (R * "
             "model + p)";
    case PoseMethod::kPerspective:
      return "pinhole refinement (LM on SO(3) x R^3 from POSIT / IPPE): image = c + f (x, y) / z "
             "of R * model + p";
    case PoseMethod::kFull3d:
      return "full 3-D baseline (free vectors, Theorem 1, Eq. 13): alpha * measured = R * model + "
             "p";
    case PoseMethod::kOiFoam:
    case PoseMethod::kOiSvd:
      return "orthogonal iteration (Wu & Wu): image = c + f (x, y) / z of R * model + p";
    case PoseMethod::kTwoView:
      return "Haralick's linear two-view algorithm: x_camera2 = R * x_camera1 + T, |T| = 1";
    case PoseMethod::kHaralick2d:
      return "Haralick's 2-D pose: image = R * model + t in the plane";
    case PoseMethod::kHaralick3d:
      return "Haralick's 3-D pose (SVD): alpha * measured = R * model + p";
  }
  return "";
}

/// The lines every method prints: status, R, p, the fit and the other branch.
void print_pose(const PoseEstimate& pose, std::ostream& text) {
  const bool two_view = pose.method == PoseMethod::kTwoView;
  text << "status       " << to_string(pose.status)
       << (pose.message.empty() ? "" : " (" + pose.message + ")") << "\n"
       << (two_view ? "R_camera2_camera1\n" : "R_camera_object\n")
       << format_matrix(pose.R_camera_object, 4);
  if (two_view) {
    text << "T (unit)     " << format_vector(pose.p_camera_object) << "\n";
  } else if (!std::isfinite(pose.p_camera_object.x())) {
    text << "p_camera_object  (no translation: direction data)\n";
  } else if (!std::isfinite(pose.p_camera_object.z())) {
    text << "p_camera_object  " << format_vector(pose.p_camera_object.head<2>())
         << "  (p_z unknown: give --focal)\n";
  } else {
    text << "p_camera_object  " << format_vector(pose.p_camera_object) << "\n";
  }
  if (std::isfinite(pose.alpha)) {
    text << "alpha        " << format_number(pose.alpha, 10) << "  (object units per "
         << (pose_data(pose.method) == PoseData::kMeasured ? "measured unit" : "pixel") << ")\n";
  }
  if (std::isfinite(pose.reprojection_rms_px)) {
    text << "reprojection " << format_number(pose.reprojection_rms_px) << " px rms\n";
  }
  if (pose.alternative) {
    text << "alternative  " << format_number(pose.alternative->reprojection_rms_px)
         << " px rms, rotation "
         << format_number(
                rotation_angle_between(pose.R_camera_object, pose.alternative->R_camera_object) *
                kDegreesPerRadian)
         << " deg away" << (pose.ambiguous ? ": ambiguous" : ": rejected") << "\n";
  }
}

/// The method's own diagnostics.
void print_diagnostics(const PoseEstimate& pose, Eigen::Index n, std::ostream& text) {
  const PoseDiagnostics& d = pose.diagnostics;
  switch (pose.method) {
    case PoseMethod::kAffine:
    case PoseMethod::kStandard:
      text << "objective    " << format_number(pose.objective)
           << "  (J of Eq. 35: sum w |P (R z + p) - alpha (q - c)|^2)\n"
           << "free vectors " << d.free_vector_count << " ("
           << to_string(d.free_vectors.value_or(FreeVectorSet::kAuto)) << "), " << d.sign_patterns
           << " sign patterns, " << d.in_plane << " in the image plane, " << d.clamped
           << " clamped\n";
      if (std::isfinite(d.runner_up_residual)) {
        text << "runner-up    J_2d " << format_number(d.runner_up_residual) << " vs "
             << format_number(d.orientation_residual) << " (margin "
             << format_number(d.ambiguity_margin) << "), rotation "
             << format_number(d.runner_up_angle_rad * kDegreesPerRadian) << " deg away\n";
      } else {
        text << "runner-up    none (a single sign pattern)\n";
      }
      break;
    case PoseMethod::kAffineRefined:
    case PoseMethod::kPerspective:
      text << "branches     " << d.branches << " (planarity " << format_number(d.planarity) << "), "
           << pose.iterations << " iterations, start " << format_number(d.start_reprojection_rms_px)
           << " px rms\n";
      break;
    case PoseMethod::kFull3d:
    case PoseMethod::kHaralick3d:
      text << "objective    " << format_number(pose.objective)
           << "  (J of Eq. 12: sum w |R z + p - alpha q|^2)\n"
           << "eigen gap    " << format_number(d.eigen_gap)
           << "  (lambda1 - lambda2 of D: conditioning)\n";
      break;
    case PoseMethod::kOiFoam:
    case PoseMethod::kOiSvd:
      text << "objective    " << format_number(pose.objective)
           << "  (object-space collinearity error E; " << format_number(d.initial_objective)
           << " at the weak-perspective start)\n"
           << "iterations   " << pose.iterations << " over " << d.branches << " branch(es), "
           << to_string(d.rotation_step.value_or(OrientationMethod::kFoam)) << " step, f "
           << format_number(pose.camera.focal_length) << "\n"
           << "behind       " << d.points_behind_camera << " points behind the camera\n";
      break;
    case PoseMethod::kTwoView:
      text << "epipolar     " << format_number(pose.objective)
           << "  (rms epipolar residual m2^T E m1)\n"
           << "null space   " << format_number(d.null_space_ratio)
           << "  (sigma_9 / sigma_8: 0 for exact data)\n"
           << "in front     " << d.points_in_front << " of " << n << " points in both views\n";
      break;
    case PoseMethod::kHaralick2d:
      text << "objective    " << format_number(pose.objective) << "  (eps^2 of [H] Sec. 2)\n";
      break;
  }
}

int run_pose(const PoseArgs& args) {
  const PoseMethod method = parse_pose_method_or_throw(args.method, "--method");
  check_args(args, method);
  const io::CorrespondenceFile file = io::read_correspondences(args.file);
  PoseOptions options;
  options.free_vectors = free_vector_set(args.free_vectors);
  const Correspondences data = correspondences_of(args, file);
  const PoseEstimate pose =
      against_source(file.source, [&] { return estimate_pose(method, data, options); });
  const Eigen::Index n =
      pose_data(method) == PoseData::kTwoViews ? data.image1.cols() : data.model.cols();
  if (args.json) {
    print_json(pose_json::estimate(pose, n));
  } else {
    std::ostringstream text;
    text << "vantage pose: " << n << " correspondences from " << args.file << ", method "
         << args.method << "\n"
         << model_line(method) << "\n";
    print_pose(pose, text);
    print_diagnostics(pose, n, text);
    std::cout << text.str();
  }
  if (pose.status == PoseStatus::kOk) return kExitOk;
  std::cerr << "vantage: pose: " << to_string(pose.status) << ": "
            << (pose.message.empty() ? "no reason given" : pose.message) << std::endl;
  return kExitFailure;
}

std::vector<std::string> pose_cli_methods() {
  std::vector<std::string> names;
  for (PoseMethod method : kPoseMethods) names.push_back(to_string(method));
  return names;
}

}  // namespace

Command add_pose_command(CLI::App& root) {
  auto args = std::make_shared<PoseArgs>();
  CLI::App* sub = root.add_subcommand(
      "pose",
      "Pose from one image (affine: Prop. 8, its refinement and the paper's baselines; "
      "perspective: pinhole refinement and orthogonal iteration), from 3-D measurements, or "
      "relative pose from two views");
  sub->add_option("CORRESPONDENCES", args->file,
                  "JSON file {\"model\": [[x,y,z]...], \"image\": [[u,v]...], \"weights\": [...], "
                  "\"camera\": {\"focal\": F, \"principal_point\": [cx, cy]}} (pixels; "
                  "\"measured\" [[x,y,z]...] for full3d and haralick-3d, \"image1\"/\"image2\" "
                  "for two-view)")
      ->required();
  sub->add_option("--method", args->method,
                  "affine (Prop. 8, the paper's estimator), affine-refined (exact on affine "
                  "images), perspective (pinhole maximum likelihood: the best answer for real "
                  "cameras), standard (Theorem 1 with v_z = 0), full3d (Theorem 1 + Eq. 13 on 3-D "
                  "measurements), oi-foam / oi-svd (orthogonal iteration), two-view, haralick-2d "
                  "and haralick-3d (Haralick et al.)")
      ->required()
      ->check(CLI::IsMember(pose_cli_methods()));
  args->focal_option = sub->add_option(
      "--focal", args->focal,
      "focal length in pixels, > 0 (overrides the file's camera.focal): affine methods give "
      "p_z = alpha f (Eq. 37); perspective, oi-* and two-view project with it (without any "
      "focal length they read the image as normalised coordinates, f = 1)");
  args->principal_point_option =
      sub->add_option("--principal-point", args->principal_point,
                      "principal point CX CY in pixels (overrides the file's "
                      "camera.principal_point; default 0 0)")
          ->expected(2);
  args->free_vectors_option =
      sub->add_option("--free-vectors", args->free_vectors,
                      "free vectors of the affine estimate: auto (all pairs up to 5 points, then "
                      "12: the maximum spanning tree, the pair that sets the LUB scale and the "
                      "longest other pairs), all (every pair, the paper) or spanning (n - 1 "
                      "pairs of the maximum spanning tree)")
          ->check(CLI::IsMember({"auto", "all", "spanning"}))
          ->capture_default_str();
  sub->add_flag("--json", args->json, "print one JSON object instead of the report");
  return {sub, [args] { return run_pose(*args); }};
}

}  // namespace vantage::cli
