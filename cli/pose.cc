// `vantage pose CORRESPONDENCES --method affine|standard|full3d|oi-foam|oi-svd|two-view
// [--focal F] [--free-vectors all|spanning] [--json]`: one pose estimator on a correspondence
// file. Affine image (McInroy et al.): Prop. 8 and the paper's two baselines; perspective image:
// orthogonal iteration with FOAM or SVD (Wu & Wu); two views: Haralick's linear algorithm.

#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>

#include "command.h"
#include "vantage/analysis/affine_pose.h"
#include "vantage/analysis/common.h"
#include "vantage/analysis/orthogonal_iteration.h"
#include "vantage/analysis/two_view.h"
#include "vantage/io/correspondence_file.h"

namespace vantage::cli {
namespace {

constexpr double kRadiansToDegrees = 180.0 / 3.14159265358979323846;

struct PoseArgs {
  std::string file;
  std::string method;
  double focal = 0.0;
  std::string free_vectors = "all";
  bool json = false;
  CLI::Option* focal_option = nullptr;
  CLI::Option* free_vectors_option = nullptr;

  bool focal_given() const { return focal_option->count() > 0; }
  bool free_vectors_given() const { return free_vectors_option->count() > 0; }
};

/// What one method produced: the JSON object, the readable report and whether it failed.
struct Outcome {
  Json json;
  std::string text;
  bool failed = false;
};

/// A number, or null when it is not finite (NaN and infinities are never printed).
Json json_number(double x) { return std::isfinite(x) ? Json(x) : Json(nullptr); }

std::string purpose(const PoseArgs& args) { return "vantage pose --method " + args.method; }

/// Runs a library call; its InvalidArgument is reported against the file.
template <typename Call>
auto against_file(const io::CorrespondenceFile& file, Call&& call) {
  return against_source(file.source, std::forward<Call>(call));
}

void reject_weights(const io::CorrespondenceFile& file, const PoseArgs& args) {
  if (file.weights.size() != 0) {
    throw InvalidArgument(file.source + ": weights: not used by " + purpose(args) +
                          " (the two-view algorithm is unweighted)");
  }
}

AffinePoseOptions affine_options(const PoseArgs& args) {
  AffinePoseOptions options;
  options.free_vectors =
      args.free_vectors == "spanning" ? FreeVectorSet::kMaxSpanningTree : FreeVectorSet::kAllPairs;
  options.focal_length = args.focal_given() ? args.focal : 0.0;
  return options;
}

/// Prop. 4 enumerates 2^m sign patterns of the m free vectors: refuse before the library does,
/// with the command-line way out.
void check_free_vector_count(const io::CorrespondenceFile& file, const AffinePoseOptions& options) {
  const Eigen::Index n = file.model.cols();
  const Eigen::Index m = options.free_vectors == FreeVectorSet::kAllPairs ? n * (n - 1) / 2 : n - 1;
  const int limit = options.orientation.max_vectors;
  if (m > limit) {
    std::ostringstream out;
    out << file.source << ": model: " << n << " points give " << m
        << " free vectors, more than the limit " << limit << " (Prop. 4 solves 2^" << m
        << " problems); use --free-vectors spanning";
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

Outcome run_affine(const PoseArgs& args, const io::CorrespondenceFile& file) {
  file.require({"model", "image"}, purpose(args));
  const AffinePoseOptions options = affine_options(args);
  const bool standard = args.method == "standard";
  if (!standard) check_free_vector_count(file, options);
  const AffinePoseResult pose = against_file(file, [&] {
    return standard ? standard_affine_pose(file.model, file.image, file.weights, options)
                    : affine_pose(file.model, file.image, file.weights, options);
  });
  const AffineOrientationResult& o = pose.orientation;
  const bool has_runner_up = std::isfinite(o.runner_up_residual);

  Outcome outcome;
  outcome.failed = pose.status == AffineStatus::kDegenerate;
  Json& out = outcome.json;
  out["method"] = args.method;
  out["n"] = file.model.cols();
  out["R"] = json_rows(pose.R_camera_object);
  Json p = json_list(pose.p_camera_object);
  if (!pose.depth_known) p[2] = nullptr;
  out["p"] = p;
  out["alpha"] = json_number(pose.alpha);
  out["depth_known"] = pose.depth_known;
  out["focal"] = args.focal_given() ? Json(args.focal) : Json(nullptr);
  out["status"] = to_string(pose.status);
  if (!pose.message.empty()) out["message"] = pose.message;
  out["residual"] = json_number(pose.residual);
  out["orientation_residual"] = json_number(o.residual);
  out["free_vectors"] = to_string(options.free_vectors);
  out["free_vector_count"] = pose.pairs.cols();
  out["sign_patterns"] = o.sign_patterns;
  out["ambiguity_margin"] = json_number(o.ambiguity_margin);
  out["runner_up_residual"] = json_number(o.runner_up_residual);
  out["runner_up_angle_deg"] =
      has_runner_up ? json_number(o.runner_up_angle * kRadiansToDegrees) : Json(nullptr);
  if (pose.status == AffineStatus::kAmbiguous) {
    out["runner_up_R"] = json_rows(o.runner_up_R_camera_object);
  }
  out["clamped"] = o.clamped;
  out["in_plane"] = o.in_plane;
  out["eigen_gap"] = json_number(o.eigen_gap);

  std::ostringstream text;
  text << header(args, file.model.cols(),
                 standard ? "standard approach (Theorem 1 with v_z = 0, Eq. 36): "
                            "alpha * image = P (R * model + p)"
                          : "Prop. 8 (free vectors, Lemma 7, Eq. 36): "
                            "alpha * image = P (R * model + p)")
       << status_line(to_string(pose.status), pose.message) << "R_camera_object\n"
       << format_matrix(pose.R_camera_object, 4) << "p_camera_object  ";
  if (pose.depth_known) {
    text << format_vector(pose.p_camera_object) << "  (p_z = alpha * focal, Eq. 37)\n";
  } else {
    text << format_vector(pose.p_camera_object.head<2>()) << "  (p_z unknown: give --focal)\n";
  }
  text << "alpha        " << format_number(pose.alpha, 10) << "  (object units per image unit)\n"
       << "residual     " << format_number(pose.residual)
       << "  (J of Eq. 35: sum w |P (R z + p) - alpha q|^2)\n"
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

Outcome run_full3d(const PoseArgs& args, const io::CorrespondenceFile& file) {
  file.require({"model", "measured"}, purpose(args));
  const AffinePoseOptions options = affine_options(args);
  const PoseResult pose = against_file(
      file, [&] { return full_3d_pose(file.model, file.measured, file.weights, options); });
  const Eigen::Index n = file.model.cols();

  Outcome outcome;
  outcome.failed = pose.status != OrientationStatus::kOk;
  Json& out = outcome.json;
  out["method"] = args.method;
  out["n"] = n;
  out["R"] = json_rows(pose.R_camera_object);
  out["p"] = json_list(pose.p_camera_object);
  out["alpha"] = json_number(pose.alpha);
  out["status"] = to_string(pose.status);
  if (!pose.message.empty()) out["message"] = pose.message;
  out["residual"] = json_number(pose.residual);
  out["free_vectors"] = to_string(options.free_vectors);
  out["free_vector_count"] =
      options.free_vectors == FreeVectorSet::kAllPairs ? n * (n - 1) / 2 : n - 1;
  out["eigen_gap"] = json_number(pose.eigen_gap);

  std::ostringstream text;
  text << header(args, n,
                 "full 3-D baseline (free vectors, Theorem 1, Eq. 13): "
                 "alpha * measured = R * model + p")
       << status_line(to_string(pose.status), pose.message) << "R_camera_object\n"
       << format_matrix(pose.R_camera_object, 4) << "p_camera_object  "
       << format_vector(pose.p_camera_object) << "\n"
       << "alpha        " << format_number(pose.alpha, 10) << "\n"
       << "residual     " << format_number(pose.residual)
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
  if (args.focal_given()) options.focal_length = args.focal;
  const OrthogonalIterationResult pose = against_file(file, [&] {
    return orthogonal_iteration_pose(file.model, file.image, file.weights, options);
  });

  Outcome outcome;
  outcome.failed = pose.status != OrthogonalIterationStatus::kConverged;
  Json& out = outcome.json;
  out["method"] = args.method;
  out["n"] = file.model.cols();
  out["R"] = json_rows(pose.R_camera_object);
  out["p"] = json_list(pose.p_camera_object);
  out["alpha"] = nullptr;
  out["focal"] = options.focal_length;
  out["status"] = to_string(pose.status);
  if (!pose.message.empty()) out["message"] = pose.message;
  out["residual"] = json_number(pose.error);
  out["initial_residual"] = json_number(pose.initial_error);
  out["iterations"] = pose.iterations;
  out["rotation_step"] = to_string(options.rotation_step);
  out["points_behind_camera"] = pose.points_behind_camera;

  std::ostringstream text;
  text << header(args, file.model.cols(),
                 std::string("orthogonal iteration with the ") + to_string(options.rotation_step) +
                     " step (Wu & Wu): image ~ (R * model + p) projected, focal " +
                     format_number(options.focal_length))
       << status_line(to_string(pose.status), pose.message) << "R_camera_object\n"
       << format_matrix(pose.R_camera_object, 4) << "p_camera_object  "
       << format_vector(pose.p_camera_object) << "\n"
       << "residual     " << format_number(pose.error) << "  (object-space collinearity error E; "
       << format_number(pose.initial_error) << " at the weak-perspective start)\n"
       << "iterations   " << pose.iterations << "\n"
       << "behind       " << pose.points_behind_camera << " points behind the camera\n";
  outcome.text = text.str();
  return outcome;
}

Outcome run_two_view(const PoseArgs& args, const io::CorrespondenceFile& file) {
  file.require({"image1", "image2"}, purpose(args));
  reject_weights(file, args);
  TwoViewOptions options;
  if (args.focal_given()) options.focal_length = args.focal;
  const TwoViewResult pose =
      against_file(file, [&] { return two_view_pose(file.image1, file.image2, options); });
  const Eigen::Index n = file.image1.cols();

  Outcome outcome;
  outcome.failed = pose.status != TwoViewStatus::kOk;
  Json& out = outcome.json;
  out["method"] = args.method;
  out["n"] = n;
  out["R"] = json_rows(pose.R_camera2_camera1);
  out["p"] = json_list(pose.t_camera2_camera1);
  out["T"] = json_list(pose.t_camera2_camera1);
  out["alpha"] = nullptr;
  out["focal"] = options.focal_length;
  out["status"] = to_string(pose.status);
  if (!pose.message.empty()) out["message"] = pose.message;
  out["residual"] = json_number(pose.residual);
  out["essential"] = json_rows(pose.essential);
  out["null_space_ratio"] = json_number(pose.null_space_ratio);
  out["points_in_front"] = pose.points_in_front;

  std::ostringstream text;
  text << header(args, n,
                 "Haralick's linear two-view algorithm: x_camera2 = R * x_camera1 + T, |T| = 1")
       << status_line(to_string(pose.status), pose.message) << "R_camera2_camera1\n"
       << format_matrix(pose.R_camera2_camera1, 4) << "T (unit)     "
       << format_vector(pose.t_camera2_camera1) << "\n"
       << "residual     " << format_number(pose.residual) << "  (rms epipolar residual m2^T E m1)\n"
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
  const bool uses_free_vectors =
      args.method == "affine" || args.method == "standard" || args.method == "full3d";
  if (args.free_vectors_given() && !uses_free_vectors) {
    throw InvalidArgument(
        "--free-vectors: only affine, standard and full3d use free vectors, not " + args.method);
  }
}

int run_pose(const PoseArgs& args) {
  check_args(args);
  const io::CorrespondenceFile file = io::read_correspondences(args.file);
  Outcome outcome;
  if (args.method == "affine" || args.method == "standard") {
    outcome = run_affine(args, file);
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
      "Pose from one image (affine: Prop. 8 and the paper's baselines; perspective: orthogonal "
      "iteration) or relative pose from two views");
  sub->add_option("CORRESPONDENCES", args->file,
                  "JSON file {\"model\": [[x,y,z]...], \"image\": [[u,v]...], \"weights\": [...]} "
                  "(\"measured\" [[x,y,z]...] for full3d, \"image1\"/\"image2\" for two-view)")
      ->required();
  sub->add_option("--method", args->method,
                  "affine (Prop. 8), standard (Theorem 1 with v_z = 0), full3d (Theorem 1 + "
                  "Eq. 13 on 3-D measurements), oi-foam / oi-svd (orthogonal iteration), "
                  "two-view (Haralick's linear algorithm)")
      ->required()
      ->check(CLI::IsMember({"affine", "standard", "full3d", "oi-foam", "oi-svd", "two-view"}));
  args->focal_option = sub->add_option(
      "--focal", args->focal,
      "focal length in image units, > 0: affine/standard give p_z = alpha f (Eq. 37); "
      "oi-*/two-view divide the image points by it (default 1: normalised coordinates)");
  args->free_vectors_option =
      sub->add_option("--free-vectors", args->free_vectors,
                      "free vectors of affine/standard/full3d: all (every pair, the paper) or "
                      "spanning (n - 1 pairs of the maximum spanning tree)")
          ->check(CLI::IsMember({"all", "spanning"}))
          ->capture_default_str();
  sub->add_flag("--json", args->json, "print one JSON object instead of the report");
  return {sub, [args] { return run_pose(*args); }};
}

}  // namespace vantage::cli
