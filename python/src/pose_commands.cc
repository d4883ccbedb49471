// vantage.pose and vantage.orient: the estimators behind `vantage pose` and `vantage orient`,
// returning the fields of their --json output. Each estimator is one row of kMethods; a new
// estimator whose result type is already converted below is one more row.

#include "pose_commands.h"

#include <pybind11/stl.h>

#include <cmath>
#include <functional>
#include <map>
#include <optional>

#include "arrays.h"
#include "results.h"
#include "vantage/analysis/absolute_orientation.h"
#include "vantage/analysis/affine_pose.h"
#include "vantage/analysis/common.h"
#include "vantage/analysis/orthogonal_iteration.h"
#include "vantage/analysis/two_view.h"
#include "vantage/io/correspondence_file.h"

namespace vantage::python {

namespace {

constexpr double kRadiansToDegrees = 180.0 / 3.14159265358979323846;

/// The correspondences and options of one vantage.pose call (absent arrays have no columns).
struct PoseInput {
  std::string method;
  Eigen::Matrix3Xd model;
  Eigen::Matrix3Xd measured;
  Eigen::Matrix2Xd image;
  Eigen::Matrix2Xd image1;
  Eigen::Matrix2Xd image2;
  Eigen::VectorXd weights;
  std::optional<double> focal;
  std::optional<std::string> free_vectors;

  void require(bool present, const char* field) const {
    if (!present) {
      throw InvalidArgument(std::string(field) + ": required by vantage.pose(method='" + method +
                            "')");
    }
  }
};

/// What one estimator produced: the --json object and whether the CLI would exit 1.
struct Outcome {
  Json json;
  bool failed = false;
};

Json json_rows(const Eigen::Matrix3d& m) {
  Json rows = Json::array();
  for (int i = 0; i < 3; ++i) rows.push_back({m(i, 0), m(i, 1), m(i, 2)});
  return rows;
}

Json json_vector(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

AffinePoseOptions affine_options(const PoseInput& in) {
  AffinePoseOptions options;
  options.free_vectors = in.free_vectors.value_or("all") == "spanning"
                             ? FreeVectorSet::kMaxSpanningTree
                             : FreeVectorSet::kAllPairs;
  options.focal_length = in.focal.value_or(0.0);
  return options;
}

Outcome affine_outcome(const PoseInput& in, const AffinePoseOptions& options,
                       const AffinePoseResult& pose) {
  const AffineOrientationResult& o = pose.orientation;
  Outcome outcome;
  outcome.failed = pose.status == AffineStatus::kDegenerate;
  Json& out = outcome.json;
  out["method"] = in.method;
  out["n"] = in.model.cols();
  out["R"] = json_rows(pose.R_camera_object);
  Json p = json_vector(pose.p_camera_object);
  if (!pose.depth_known) p[2] = nullptr;
  out["p"] = p;
  out["alpha"] = json_number(pose.alpha);
  out["depth_known"] = pose.depth_known;
  out["focal"] = in.focal ? Json(*in.focal) : Json(nullptr);
  out["status"] = to_string(pose.status);
  if (!pose.message.empty()) out["message"] = pose.message;
  out["residual"] = json_number(pose.residual);
  out["orientation_residual"] = json_number(o.residual);
  out["free_vectors"] = to_string(options.free_vectors);
  out["free_vector_count"] = pose.pairs.cols();
  out["sign_patterns"] = o.sign_patterns;
  out["ambiguity_margin"] = json_number(o.ambiguity_margin);
  out["runner_up_residual"] = json_number(o.runner_up_residual);
  out["runner_up_angle_deg"] = std::isfinite(o.runner_up_residual)
                                   ? json_number(o.runner_up_angle * kRadiansToDegrees)
                                   : Json(nullptr);
  if (pose.status == AffineStatus::kAmbiguous) {
    out["runner_up_R"] = json_rows(o.runner_up_R_camera_object);
  }
  out["clamped"] = o.clamped;
  out["in_plane"] = o.in_plane;
  out["eigen_gap"] = json_number(o.eigen_gap);
  return outcome;
}

/// Prop. 4 enumerates 2^m sign patterns: refuse before the library does, with the way out.
void check_free_vector_count(const PoseInput& in, const AffinePoseOptions& options) {
  const Eigen::Index n = in.model.cols();
  const Eigen::Index m = options.free_vectors == FreeVectorSet::kAllPairs ? n * (n - 1) / 2 : n - 1;
  if (m > options.orientation.max_vectors) {
    throw InvalidArgument("model: " + std::to_string(n) + " points give " + std::to_string(m) +
                          " free vectors, more than the limit " +
                          std::to_string(options.orientation.max_vectors) + " (Prop. 4 solves 2^" +
                          std::to_string(m) + " problems); use free_vectors='spanning'");
  }
}

Outcome run_affine(const PoseInput& in) {
  in.require(in.model.cols() > 0, "model");
  in.require(in.image.cols() > 0, "image");
  const AffinePoseOptions options = affine_options(in);
  const bool standard = in.method == "standard";
  if (!standard) check_free_vector_count(in, options);
  const AffinePoseResult pose = without_gil([&] {
    return standard ? standard_affine_pose(in.model, in.image, in.weights, options)
                    : affine_pose(in.model, in.image, in.weights, options);
  });
  return affine_outcome(in, options, pose);
}

Outcome run_full3d(const PoseInput& in) {
  in.require(in.model.cols() > 0, "model");
  in.require(in.measured.cols() > 0, "measured");
  if (in.focal) throw InvalidArgument("focal: not used by method='full3d' (3-D measurements)");
  const AffinePoseOptions options = affine_options(in);
  const PoseResult pose =
      without_gil([&] { return full_3d_pose(in.model, in.measured, in.weights, options); });
  const Eigen::Index n = in.model.cols();
  Outcome outcome;
  outcome.failed = pose.status != OrientationStatus::kOk;
  Json& out = outcome.json;
  out["method"] = in.method;
  out["n"] = n;
  out["R"] = json_rows(pose.R_camera_object);
  out["p"] = json_vector(pose.p_camera_object);
  out["alpha"] = json_number(pose.alpha);
  out["status"] = to_string(pose.status);
  if (!pose.message.empty()) out["message"] = pose.message;
  out["residual"] = json_number(pose.residual);
  out["free_vectors"] = to_string(options.free_vectors);
  out["free_vector_count"] =
      options.free_vectors == FreeVectorSet::kAllPairs ? n * (n - 1) / 2 : n - 1;
  out["eigen_gap"] = json_number(pose.eigen_gap);
  return outcome;
}

Outcome run_orthogonal_iteration(const PoseInput& in) {
  in.require(in.model.cols() > 0, "model");
  in.require(in.image.cols() > 0, "image");
  OrthogonalIterationOptions options;
  options.rotation_step =
      in.method == "oi-svd" ? OrientationMethod::kSvd : OrientationMethod::kFoam;
  if (in.focal) options.focal_length = *in.focal;
  const OrthogonalIterationResult pose = without_gil(
      [&] { return orthogonal_iteration_pose(in.model, in.image, in.weights, options); });
  Outcome outcome;
  outcome.failed = pose.status != OrthogonalIterationStatus::kConverged;
  Json& out = outcome.json;
  out["method"] = in.method;
  out["n"] = in.model.cols();
  out["R"] = json_rows(pose.R_camera_object);
  out["p"] = json_vector(pose.p_camera_object);
  out["alpha"] = nullptr;
  out["focal"] = options.focal_length;
  out["status"] = to_string(pose.status);
  if (!pose.message.empty()) out["message"] = pose.message;
  out["residual"] = json_number(pose.error);
  out["initial_residual"] = json_number(pose.initial_error);
  out["iterations"] = pose.iterations;
  out["rotation_step"] = to_string(options.rotation_step);
  out["points_behind_camera"] = pose.points_behind_camera;
  return outcome;
}

Outcome run_two_view(const PoseInput& in) {
  in.require(in.image1.cols() > 0, "image1");
  in.require(in.image2.cols() > 0, "image2");
  if (in.weights.size() != 0) {
    throw InvalidArgument(
        "weights: not used by vantage.pose(method='two-view') (the two-view "
        "algorithm is unweighted)");
  }
  TwoViewOptions options;
  if (in.focal) options.focal_length = *in.focal;
  const TwoViewResult pose =
      without_gil([&] { return two_view_pose(in.image1, in.image2, options); });
  Outcome outcome;
  outcome.failed = pose.status != TwoViewStatus::kOk;
  Json& out = outcome.json;
  out["method"] = in.method;
  out["n"] = in.image1.cols();
  out["R"] = json_rows(pose.R_camera2_camera1);
  out["p"] = json_vector(pose.t_camera2_camera1);
  out["T"] = json_vector(pose.t_camera2_camera1);
  out["alpha"] = nullptr;
  out["focal"] = options.focal_length;
  out["status"] = to_string(pose.status);
  if (!pose.message.empty()) out["message"] = pose.message;
  out["residual"] = json_number(pose.residual);
  out["essential"] = json_rows(pose.essential);
  out["null_space_ratio"] = json_number(pose.null_space_ratio);
  out["points_in_front"] = pose.points_in_front;
  return outcome;
}

/// The estimators of `vantage pose --method`, one row each.
const std::map<std::string, std::function<Outcome(const PoseInput&)>>& methods() {
  static const std::map<std::string, std::function<Outcome(const PoseInput&)>> kMethods = {
      {"affine", run_affine},
      {"standard", run_affine},
      {"full3d", run_full3d},
      {"oi-foam", run_orthogonal_iteration},
      {"oi-svd", run_orthogonal_iteration},
      {"two-view", run_two_view},
  };
  return kMethods;
}

std::string method_names() {
  std::string names;
  for (const auto& row : methods()) names += (names.empty() ? "" : ", ") + row.first;
  return names;
}

py::object pose(const py::object& model, const py::object& image, const std::string& method,
                const py::object& measured, const py::object& image1, const py::object& image2,
                const py::object& weights, const py::object& focal,
                const py::object& free_vectors) {
  const auto row = methods().find(method);
  if (row == methods().end()) {
    throw InvalidArgument("method: expected one of " + method_names() + ", got \"" + method + "\"");
  }
  PoseInput in;
  in.method = method;
  if (!model.is_none()) in.model = rows_from_array<3>(model, "model");
  if (!measured.is_none()) in.measured = rows_from_array<3>(measured, "measured");
  if (!image.is_none()) in.image = rows_from_array<2>(image, "image");
  if (!image1.is_none()) in.image1 = rows_from_array<2>(image1, "image1");
  if (!image2.is_none()) in.image2 = rows_from_array<2>(image2, "image2");
  if (!weights.is_none()) in.weights = vector_from_array(weights, "weights");
  if (!focal.is_none()) {
    if (!py::isinstance<py::float_>(focal) && !py::isinstance<py::int_>(focal)) {
      throw InvalidArgument("focal: must be a finite number > 0");
    }
    in.focal = focal.cast<double>();
    if (!(*in.focal > 0.0 && std::isfinite(*in.focal))) {
      throw InvalidArgument("focal: must be a finite number > 0");
    }
  }
  if (!free_vectors.is_none()) {
    if (!py::isinstance<py::str>(free_vectors)) {
      throw InvalidArgument("free_vectors: expected all or spanning");
    }
    in.free_vectors = free_vectors.cast<std::string>();
    if (*in.free_vectors != "all" && *in.free_vectors != "spanning") {
      throw InvalidArgument("free_vectors: expected all or spanning");
    }
    if (method != "affine" && method != "standard" && method != "full3d") {
      throw InvalidArgument(
          "free_vectors: only affine, standard and full3d use free vectors, "
          "not " +
          method);
    }
  }
  const Outcome outcome = row->second(in);
  return result_or_raise(outcome.failed, outcome.json["status"].get<std::string>(),
                         outcome.json.value("message", std::string()), outcome.json);
}

py::object orient(const py::object& model, const py::object& measured, const py::object& weights,
                  const std::string& method) {
  OrientationOptions options;
  if (method == "qmethod") {
    options.method = OrientationMethod::kQMethod;
  } else if (method == "svd") {
    options.method = OrientationMethod::kSvd;
  } else if (method == "foam") {
    options.method = OrientationMethod::kFoam;
  } else {
    throw InvalidArgument("method: expected qmethod, svd or foam, got \"" + method + "\"");
  }
  const Eigen::Matrix3Xd z = rows_from_array<3>(model, "model");
  const Eigen::Matrix3Xd q = rows_from_array<3>(measured, "measured");
  const Eigen::VectorXd w =
      weights.is_none() ? Eigen::VectorXd() : vector_from_array(weights, "weights");
  const PoseResult pose = without_gil([&] { return absolute_pose(z, q, w, options); });
  Json out;
  out["method"] = to_string(options.method);
  out["n"] = z.cols();
  out["R"] = json_rows(pose.R_camera_object);
  out["p"] = json_vector(pose.p_camera_object);
  out["alpha"] = pose.alpha;
  out["residual"] = pose.residual;
  out["eigen_gap"] = pose.eigen_gap;
  out["status"] = to_string(pose.status);
  if (!pose.message.empty()) out["message"] = pose.message;
  return result_or_raise(pose.status != OrientationStatus::kOk, to_string(pose.status),
                         pose.message, out);
}

/// The arrays of a correspondence file, keyed like the arguments of vantage.pose (absent fields
/// left out), so that vantage.pose(**vantage.load_correspondences(path), method=...) works.
py::dict load_correspondences(const py::object& path) {
  const io::CorrespondenceFile file = io::read_correspondences(path_from(path));
  py::dict out;
  if (file.has_model) out["model"] = array_from_columns(file.model);
  if (file.has_measured) out["measured"] = array_from_columns(file.measured);
  if (file.has_image) out["image"] = array_from_columns(file.image);
  if (file.has_image1) out["image1"] = array_from_columns(file.image1);
  if (file.has_image2) out["image2"] = array_from_columns(file.image2);
  if (file.weights.size() > 0) out["weights"] = array_from_vector(file.weights);
  return out;
}

}  // namespace

void bind_pose_commands(py::module_& module) {
  module.def("pose", &pose, py::arg("model") = py::none(), py::arg("image") = py::none(),
             py::kw_only(), py::arg("method") = "affine", py::arg("measured") = py::none(),
             py::arg("image1") = py::none(), py::arg("image2") = py::none(),
             py::arg("weights") = py::none(), py::arg("focal") = py::none(),
             py::arg("free_vectors") = py::none(),
             "One pose estimator (as `vantage pose --method M --json`): model n x 3 with image "
             "n x 2 (affine, standard, oi-foam, oi-svd) or measured n x 3 (full3d); image1 and "
             "image2 n x 2 (two-view). Raises NumericalError when the estimate is degenerate or "
             "did not converge.");
  module.def(
      "pose_methods",
      [] {
        std::vector<std::string> names;
        for (const auto& row : methods()) names.push_back(row.first);
        return names;
      },
      "The names vantage.pose accepts as method=.");
  module.def("load_correspondences", &load_correspondences, py::arg("path"),
             "The arrays of a correspondence file (model, measured, image, image1, image2, "
             "weights; n x 3 or n x 2), as keyword arguments for vantage.pose / vantage.orient.");
  module.def("orient", &orient, py::arg("model"), py::arg("measured"), py::kw_only(),
             py::arg("weights") = py::none(), py::arg("method") = "qmethod",
             "Rotation, translation and scale from 3-D correspondences, alpha * measured = R * "
             "model + p (as `vantage orient --json`).");
}

}  // namespace vantage::python
