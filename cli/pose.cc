// `vantage pose CORRESPONDENCES --method affine|affine-refined|perspective|standard|full3d|
// oi-foam|oi-svd|two-view [--focal F] [--principal-point CX CY] [--free-vectors auto|all|spanning]
// [--json]`: one pose estimator on a correspondence file. Affine image (McInroy et al.): Prop. 8,
// its refinement on the affine model and the paper's two baselines; perspective image: the
// pinhole refinement (LM from POSIT / IPPE) and orthogonal iteration (Wu & Wu); two views:
// Haralick's linear algorithm. Every method prints the same pose fields (json/pose_json.cc).

#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>
#include <vector>

#include "command.h"
#include "pose_json.h"
#include "vantage/analysis/affine_pose.h"
#include "vantage/analysis/common.h"
#include "vantage/analysis/orthogonal_iteration.h"
#include "vantage/analysis/refined_pose.h"
#include "vantage/analysis/two_view.h"
#include "vantage/io/correspondence_file.h"

namespace vantage::cli {
namespace {

constexpr double kRadiansToDegrees = 180.0 / 3.14159265358979323846;

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

  bool focal_given() const { return focal_option->count() > 0; }
  bool principal_point_given() const { return principal_point_option->count() > 0; }
  bool free_vectors_given() const { return free_vectors_option->count() > 0; }
  bool affine_family() const {
    return method == "affine" || method == "standard" || method == "affine-refined";
  }
  bool perspective_family() const {
    return method == "perspective" || method == "oi-foam" || method == "oi-svd";
  }
};

/// What one method produced: the JSON object, the readable report and whether it failed.
struct Outcome {
  Json json;
  std::string text;
  bool failed = false;
};

std::string purpose(const PoseArgs& args) { return "vantage pose --method " + args.method; }

/// Runs a library call; its InvalidArgument is reported against the file.
template <typename Call>
auto against_file(const io::CorrespondenceFile& file, Call&& call) {
  return against_source(file.source, std::forward<Call>(call));
}

/// The camera: the file's "camera" with --focal / --principal-point overriding it. Perspective
/// methods without any focal length read the image as normalised coordinates (f = 1).
Camera camera_of(const PoseArgs& args, const io::CorrespondenceFile& file) {
  Camera camera = file.camera;
  if (args.focal_given()) camera.focal_length = args.focal;
  if (args.principal_point_given()) {
    camera.principal_point << args.principal_point[0], args.principal_point[1];
  }
  if (args.perspective_family() && !camera.has_focal_length()) camera.focal_length = 1.0;
  return camera;
}

FreeVectorSet free_vector_set(const PoseArgs& args) {
  if (args.free_vectors == "all") return FreeVectorSet::kAllPairs;
  if (args.free_vectors == "spanning") return FreeVectorSet::kMaxSpanningTree;
  return FreeVectorSet::kAuto;
}

AffinePoseOptions affine_options(const PoseArgs& args, const io::CorrespondenceFile& file) {
  AffinePoseOptions options;
  options.free_vectors = free_vector_set(args);
  options.camera = camera_of(args, file);
  return options;
}

/// Prop. 4 enumerates 2^m sign patterns of the m free vectors: refuse an explicit set beyond the
/// limit before the library does, with the command-line way out.
void check_free_vector_count(const io::CorrespondenceFile& file, const AffinePoseOptions& options) {
  if (options.free_vectors == FreeVectorSet::kAuto) return;
  const Eigen::Index n = file.model.cols();
  const Eigen::Index m = free_vector_count(n, options.free_vectors);
  const int limit = options.orientation.max_vectors;
  if (m > limit) {
    std::ostringstream out;
    out << file.source << ": model: " << n << " points give " << m
        << " free vectors, more than the limit " << limit << " (Prop. 4 solves 2^" << m
        << " problems); use --free-vectors auto or spanning";
    throw InvalidArgument(out.str());
  }
}

std::string header(const PoseArgs& args, Eigen::Index n, const std::string& what) {
  return "vantage pose: " + std::to_string(n) + " correspondences from " + args.file + ", method " +
         args.method + "\n" + what + "\n";
}

std::string status_line(const std::string& status, const std::string& message) {
  return "status       " + status + (message.empty() ? "" : " (" + message + ")") + "\n";
}

/// The readable lines of pose_fields.
std::string pose_text(const PoseEstimate& pose) {
  std::ostringstream text;
  text << status_line(to_string(pose.status), pose.message) << "R_camera_object\n"
       << format_matrix(pose.R_camera_object, 4) << "p_camera_object  ";
  if (std::isfinite(pose.p_camera_object.z())) {
    text << format_vector(pose.p_camera_object) << "\n";
  } else {
    text << format_vector(pose.p_camera_object.head<2>()) << "  (p_z unknown: give --focal)\n";
  }
  text << "reprojection " << format_number(pose.reprojection_rms_px) << " px rms\n";
  if (pose.alternative) {
    text << "alternative  " << format_number(pose.alternative->reprojection_rms_px)
         << " px rms, rotation "
         << format_number(
                rotation_angle_between(pose.R_camera_object, pose.alternative->R_camera_object) *
                kRadiansToDegrees)
         << " deg away" << (pose.ambiguous ? ": ambiguous" : ": rejected") << "\n";
  }
  return text.str();
}

Outcome run_affine(const PoseArgs& args, const io::CorrespondenceFile& file) {
  file.require({"model", "image"}, purpose(args));
  const AffinePoseOptions options = affine_options(args, file);
  const bool standard = args.method == "standard";
  if (!standard) check_free_vector_count(file, options);
  const AffinePoseResult pose = against_file(file, [&] {
    return standard ? standard_affine_pose(file.model, file.image, file.weights, options)
                    : affine_pose(file.model, file.image, file.weights, options);
  });
  const AffineOrientationResult& o = pose.orientation;
  const bool has_runner_up = std::isfinite(o.runner_up_residual);

  Outcome outcome;
  outcome.failed = pose.status != PoseStatus::kOk;
  outcome.json = pose_json::affine(args.method, file.model.cols(), options, pose);

  std::ostringstream text;
  text << header(args, file.model.cols(),
                 standard ? "standard approach (Theorem 1 with v_z = 0, Eq. 36): "
                            "alpha * (image - c) = P (R * model + p)"
                          : "Prop. 8 (free vectors, Lemma 7, Eq. 36): "
                            "alpha * (image - c) = P (R * model + p)")
       << pose_text(pose) << "alpha        " << format_number(pose.alpha, 10)
       << "  (object units per pixel; p_z = alpha * focal, Eq. 37)\n"
       << "objective    " << format_number(pose.objective)
       << "  (J of Eq. 35: sum w |P (R z + p) - alpha (q - c)|^2)\n"
       << "free vectors " << pose.pairs.cols() << " (" << to_string(options.free_vectors) << "), "
       << o.sign_patterns << " sign patterns, " << o.in_plane << " in the image plane, "
       << o.clamped << " clamped\n";
  if (has_runner_up) {
    text << "runner-up    J_2d " << format_number(o.runner_up_residual) << " vs "
         << format_number(o.residual) << " (margin " << format_number(o.ambiguity_margin)
         << "), rotation " << format_number(o.runner_up_angle * kRadiansToDegrees) << " deg away\n";
  } else {
    text << "runner-up    none (a single sign pattern)\n";
  }
  outcome.text = text.str();
  return outcome;
}

Outcome run_refined(const PoseArgs& args, const io::CorrespondenceFile& file) {
  file.require({"model", "image"}, purpose(args));
  RefinedPoseOptions options;
  options.start = affine_options(args, file);
  options.camera = options.start.camera;
  check_free_vector_count(file, options.start);
  const bool perspective = args.method == "perspective";
  const RefinedPoseResult pose = against_file(file, [&] {
    return perspective ? perspective_pose(file.model, file.image, file.weights, options)
                       : affine_refined_pose(file.model, file.image, file.weights, options);
  });

  Outcome outcome;
  outcome.failed = pose.status != PoseStatus::kOk;
  outcome.json = pose_json::refined(args.method, file.model.cols(), options, pose);

  std::ostringstream text;
  text << header(args, file.model.cols(),
                 perspective ? "pinhole refinement (LM on SO(3) x R^3 from POSIT / IPPE): "
                               "image = c + f (x, y) / z of R * model + p"
                             : "affine refinement (LM on SO(3) x R^3 from Prop. 8): "
                               "alpha * (image - c) = P (R * model + p)")
       << pose_text(pose) << "alpha        " << format_number(pose.alpha, 10)
       << "  (object units per pixel)\n"
       << "branches     " << pose.branches << " (planarity " << format_number(pose.planarity)
       << "), " << pose.iterations << " iterations, start "
       << format_number(pose.start_reprojection_rms_px) << " px rms\n";
  outcome.text = text.str();
  return outcome;
}

Outcome run_full3d(const PoseArgs& args, const io::CorrespondenceFile& file) {
  file.require({"model", "measured"}, purpose(args));
  const AffinePoseOptions options = affine_options(args, file);
  const PoseResult pose = against_file(
      file, [&] { return full_3d_pose(file.model, file.measured, file.weights, options); });
  const Eigen::Index n = file.model.cols();

  Outcome outcome;
  outcome.failed = pose.status != OrientationStatus::kOk;
  outcome.json = pose_json::full3d(args.method, n, options, pose);

  std::ostringstream text;
  text << header(args, n,
                 "full 3-D baseline (free vectors, Theorem 1, Eq. 13): "
                 "alpha * measured = R * model + p")
       << status_line(to_string(pose.status), pose.message) << "R_camera_object\n"
       << format_matrix(pose.R_camera_object, 4) << "p_camera_object  "
       << format_vector(pose.p_camera_object) << "\n"
       << "alpha        " << format_number(pose.alpha, 10) << "\n"
       << "objective    " << format_number(pose.residual)
       << "  (J of Eq. 12: sum w |R z + p - alpha q|^2)\n"
       << "eigen gap    " << format_number(pose.eigen_gap)
       << "  (lambda1 - lambda2 of D: conditioning)\n";
  outcome.text = text.str();
  return outcome;
}

Outcome run_orthogonal_iteration(const PoseArgs& args, const io::CorrespondenceFile& file) {
  file.require({"model", "image"}, purpose(args));
  OrthogonalIterationOptions options;
  options.rotation_step =
      args.method == "oi-svd" ? OrientationMethod::kSvd : OrientationMethod::kFoam;
  options.camera = camera_of(args, file);
  const OrthogonalIterationResult pose = against_file(file, [&] {
    return orthogonal_iteration_pose(file.model, file.image, file.weights, options);
  });

  Outcome outcome;
  outcome.failed = pose.status != PoseStatus::kOk;
  outcome.json = pose_json::orthogonal_iteration(args.method, file.model.cols(), options, pose);

  std::ostringstream text;
  text << header(args, file.model.cols(),
                 std::string("orthogonal iteration with the ") + to_string(options.rotation_step) +
                     " step (Wu & Wu): image = c + f (x, y) / z of R * model + p, f " +
                     format_number(options.camera.focal_length))
       << pose_text(pose) << "objective    " << format_number(pose.objective)
       << "  (object-space collinearity error E; " << format_number(pose.initial_objective)
       << " at the weak-perspective start)\n"
       << "iterations   " << pose.iterations << " over " << pose.branches << " branch(es)\n"
       << "behind       " << pose.points_behind_camera << " points behind the camera\n";
  outcome.text = text.str();
  return outcome;
}

Outcome run_two_view(const PoseArgs& args, const io::CorrespondenceFile& file) {
  file.require({"image1", "image2"}, purpose(args));
  if (file.weights.size() != 0) {
    throw InvalidArgument(file.source + ": weights: not used by " + purpose(args) +
                          " (the two-view algorithm is unweighted)");
  }
  TwoViewOptions options;
  if (args.focal_given()) options.focal_length = args.focal;
  const TwoViewResult pose =
      against_file(file, [&] { return two_view_pose(file.image1, file.image2, options); });
  const Eigen::Index n = file.image1.cols();

  Outcome outcome;
  outcome.failed = pose.status != TwoViewStatus::kOk;
  outcome.json = pose_json::two_view(args.method, n, options, pose);

  std::ostringstream text;
  text << header(args, n,
                 "Haralick's linear two-view algorithm: x_camera2 = R * x_camera1 + T, |T| = 1")
       << status_line(to_string(pose.status), pose.message) << "R_camera2_camera1\n"
       << format_matrix(pose.R_camera2_camera1, 4) << "T (unit)     "
       << format_vector(pose.t_camera2_camera1) << "\n"
       << "epipolar     " << format_number(pose.residual) << "  (rms epipolar residual m2^T E m1)\n"
       << "null space   " << format_number(pose.null_space_ratio)
       << "  (sigma_9 / sigma_8: 0 for exact data)\n"
       << "in front     " << pose.points_in_front << " of " << n << " points in both views\n";
  outcome.text = text.str();
  return outcome;
}

void check_args(const PoseArgs& args) {
  if (args.focal_given()) {
    if (!(args.focal > 0.0 && std::isfinite(args.focal))) {
      throw InvalidArgument("--focal: must be a finite number > 0, got " +
                            format_number(args.focal));
    }
    if (args.method == "full3d") {
      throw InvalidArgument("--focal: not used by --method full3d (3-D measurements)");
    }
  }
  if (args.principal_point_given()) {
    if (!(std::isfinite(args.principal_point[0]) && std::isfinite(args.principal_point[1]))) {
      throw InvalidArgument("--principal-point: must be two finite numbers (pixels)");
    }
    if (args.method == "full3d" || args.method == "two-view") {
      throw InvalidArgument("--principal-point: not used by --method " + args.method);
    }
  }
  const bool uses_free_vectors =
      args.affine_family() || args.method == "full3d" || args.method == "perspective";
  if (args.free_vectors_given() && !uses_free_vectors) {
    throw InvalidArgument(
        "--free-vectors: only affine, affine-refined, perspective, standard and full3d use free "
        "vectors, not " +
        args.method);
  }
}

int run_pose(const PoseArgs& args) {
  check_args(args);
  const io::CorrespondenceFile file = io::read_correspondences(args.file);
  Outcome outcome;
  if (args.method == "affine" || args.method == "standard") {
    outcome = run_affine(args, file);
  } else if (args.method == "affine-refined" || args.method == "perspective") {
    outcome = run_refined(args, file);
  } else if (args.method == "full3d") {
    outcome = run_full3d(args, file);
  } else if (args.method == "two-view") {
    outcome = run_two_view(args, file);
  } else {
    outcome = run_orthogonal_iteration(args, file);
  }
  if (args.json) {
    print_json(outcome.json);
  } else {
    std::cout << outcome.text;
  }
  return outcome.failed ? kExitFailure : kExitOk;
}

}  // namespace

Command add_pose_command(CLI::App& root) {
  auto args = std::make_shared<PoseArgs>();
  CLI::App* sub = root.add_subcommand(
      "pose",
      "Pose from one image (affine: Prop. 8, its refinement and the paper's baselines; "
      "perspective: pinhole refinement and orthogonal iteration) or relative pose from two views");
  sub->add_option("CORRESPONDENCES", args->file,
                  "JSON file {\"model\": [[x,y,z]...], \"image\": [[u,v]...], \"weights\": [...], "
                  "\"camera\": {\"focal\": F, \"principal_point\": [cx, cy]}} (pixels; "
                  "\"measured\" [[x,y,z]...] for full3d, \"image1\"/\"image2\" for two-view)")
      ->required();
  sub->add_option("--method", args->method,
                  "affine (Prop. 8, the paper's estimator), affine-refined (exact on affine "
                  "images), perspective (pinhole maximum likelihood: the best answer for real "
                  "cameras), standard (Theorem 1 with v_z = 0), full3d (Theorem 1 + Eq. 13 on 3-D "
                  "measurements), oi-foam / oi-svd (orthogonal iteration), two-view (Haralick)")
      ->required()
      ->check(CLI::IsMember({"affine", "affine-refined", "perspective", "standard", "full3d",
                             "oi-foam", "oi-svd", "two-view"}));
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
                      "a spanning set of at most 12), all (every pair, the paper) or spanning "
                      "(n - 1 pairs of the maximum spanning tree)")
          ->check(CLI::IsMember({"auto", "all", "spanning"}))
          ->capture_default_str();
  sub->add_flag("--json", args->json, "print one JSON object instead of the report");
  return {sub, [args] { return run_pose(*args); }};
}

}  // namespace vantage::cli
