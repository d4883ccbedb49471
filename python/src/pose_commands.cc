// vantage.pose and vantage.orient: the estimators behind `vantage pose` and `vantage orient`,
// returning the fields of their --json output (vantage pose's objects come from the command's
// own conversion, cli/json/pose_json.h). Each estimator is one row of kMethods.

#include "pose_commands.h"

#include <pybind11/stl.h>

#include <cmath>
#include <functional>
#include <map>
#include <optional>

#include "arrays.h"
#include "pose_json.h"
#include "results.h"
#include "vantage/analysis/absolute_orientation.h"
#include "vantage/analysis/affine_pose.h"
#include "vantage/analysis/common.h"
#include "vantage/analysis/free_vectors.h"
#include "vantage/analysis/orthogonal_iteration.h"
#include "vantage/analysis/refined_pose.h"
#include "vantage/analysis/two_view.h"
#include "vantage/io/correspondence_file.h"

namespace vantage::python {

namespace {

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
  std::optional<Eigen::Vector2d> principal_point;
  FreeVectorSet free_vectors = FreeVectorSet::kAuto;

  void require(bool present, const char* field) const {
    if (!present) {
      throw InvalidArgument(std::string(field) + ": required by vantage.pose(method='" + method +
                            "')");
    }
  }
  bool perspective_family() const {
    return method == "perspective" || method == "oi-foam" || method == "oi-svd";
  }
};

/// What one estimator produced: the --json object and whether the CLI would exit 1.
struct Outcome {
  Json json;
  bool failed = false;
};

/// The camera of `vantage pose`: focal and principal point as given; perspective methods without
/// a focal length read the image as normalised coordinates (f = 1).
Camera camera_of(const PoseInput& in) {
  Camera camera;
  camera.focal_length = in.focal.value_or(0.0);
  if (in.principal_point) camera.principal_point = *in.principal_point;
  if (in.perspective_family() && !camera.has_focal_length()) camera.focal_length = 1.0;
  return camera;
}

AffinePoseOptions affine_options(const PoseInput& in) {
  AffinePoseOptions options;
  options.free_vectors = in.free_vectors;
  options.camera = camera_of(in);
  return options;
}

/// Prop. 4 enumerates 2^m sign patterns: refuse an explicit set beyond the limit before the
/// library does, with the way out.
void check_free_vector_count(const PoseInput& in, const AffinePoseOptions& options) {
  if (options.free_vectors == FreeVectorSet::kAuto) return;
  const Eigen::Index n = in.model.cols();
  const Eigen::Index m = free_vector_count(n, options.free_vectors);
  if (m > options.orientation.max_vectors) {
    throw InvalidArgument("model: " + std::to_string(n) + " points give " + std::to_string(m) +
                          " free vectors, more than the limit " +
                          std::to_string(options.orientation.max_vectors) + " (Prop. 4 solves 2^" +
                          std::to_string(m) + " problems); use free_vectors='auto' or 'spanning'");
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
  return {pose_json::affine(in.method, in.model.cols(), options, pose),
          pose.status != PoseStatus::kOk};
}

Outcome run_refined(const PoseInput& in) {
  in.require(in.model.cols() > 0, "model");
  in.require(in.image.cols() > 0, "image");
  RefinedPoseOptions options;
  options.start = affine_options(in);
  options.camera = options.start.camera;
  check_free_vector_count(in, options.start);
  const RefinedPoseResult pose = without_gil([&] {
    return in.method == "perspective"
               ? perspective_pose(in.model, in.image, in.weights, options)
               : affine_refined_pose(in.model, in.image, in.weights, options);
  });
  return {pose_json::refined(in.method, in.model.cols(), options, pose),
          pose.status != PoseStatus::kOk};
}

Outcome run_full3d(const PoseInput& in) {
  in.require(in.model.cols() > 0, "model");
  in.require(in.measured.cols() > 0, "measured");
  const AffinePoseOptions options = affine_options(in);
  const PoseResult pose =
      without_gil([&] { return full_3d_pose(in.model, in.measured, in.weights, options); });
  return {pose_json::full3d(in.method, in.model.cols(), options, pose),
          pose.status != OrientationStatus::kOk};
}

Outcome run_orthogonal_iteration(const PoseInput& in) {
  in.require(in.model.cols() > 0, "model");
  in.require(in.image.cols() > 0, "image");
  OrthogonalIterationOptions options;
  options.rotation_step =
      in.method == "oi-svd" ? OrientationMethod::kSvd : OrientationMethod::kFoam;
  options.camera = camera_of(in);
  const OrthogonalIterationResult pose = without_gil(
      [&] { return orthogonal_iteration_pose(in.model, in.image, in.weights, options); });
  return {pose_json::orthogonal_iteration(in.method, in.model.cols(), options, pose),
          pose.status != PoseStatus::kOk};
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
  return {pose_json::two_view(in.method, in.image1.cols(), options, pose),
          pose.status != TwoViewStatus::kOk};
}

/// The estimators of `vantage pose --method`, one row each.
const std::map<std::string, std::function<Outcome(const PoseInput&)>>& methods() {
  static const std::map<std::string, std::function<Outcome(const PoseInput&)>> kMethods = {
      {"affine", run_affine},
      {"standard", run_affine},
      {"affine-refined", run_refined},
      {"perspective", run_refined},
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

/// focal= and principal_point= (checked as the CLI checks --focal and --principal-point).
void read_camera(const py::object& focal, const py::object& principal_point, PoseInput* in) {
  if (!focal.is_none()) {
    if (!py::isinstance<py::float_>(focal) && !py::isinstance<py::int_>(focal)) {
      throw InvalidArgument("focal: must be a finite number > 0");
    }
    in->focal = focal.cast<double>();
    if (!(*in->focal > 0.0 && std::isfinite(*in->focal))) {
      throw InvalidArgument("focal: must be a finite number > 0");
    }
    if (in->method == "full3d") {
      throw InvalidArgument("focal: not used by method='full3d' (3-D measurements)");
    }
  }
  if (!principal_point.is_none()) {
    const Eigen::Vector2d c = pair_from_array(principal_point, "principal_point", "pixels");
    if (in->method == "full3d" || in->method == "two-view") {
      throw InvalidArgument("principal_point: not used by method='" + in->method + "'");
    }
    in->principal_point = c;
  }
}

/// free_vectors= (auto, all or spanning; only for the methods that use free vectors).
void read_free_vectors(const py::object& free_vectors, PoseInput* in) {
  if (free_vectors.is_none()) return;
  const std::string expected = "free_vectors: expected auto, all or spanning";
  if (!py::isinstance<py::str>(free_vectors)) throw InvalidArgument(expected);
  const std::string name = free_vectors.cast<std::string>();
  if (name == "all") {
    in->free_vectors = FreeVectorSet::kAllPairs;
  } else if (name == "spanning") {
    in->free_vectors = FreeVectorSet::kMaxSpanningTree;
  } else if (name != "auto") {
    throw InvalidArgument(expected);
  }
  const std::string& m = in->method;
  if (m != "affine" && m != "standard" && m != "affine-refined" && m != "perspective" &&
      m != "full3d") {
    throw InvalidArgument(
        "free_vectors: only affine, affine-refined, perspective, standard and full3d use free "
        "vectors, not " +
        m);
  }
}

py::object pose(const py::object& model, const py::object& image, const std::string& method,
                const py::object& measured, const py::object& image1, const py::object& image2,
                const py::object& weights, const py::object& focal,
                const py::object& principal_point, const py::object& free_vectors) {
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
  read_camera(focal, principal_point, &in);
  read_free_vectors(free_vectors, &in);
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
  out["R"] = pose_json::rows(pose.R_camera_object);
  out["p"] = pose_json::list(pose.p_camera_object);
  out["alpha"] = pose.alpha;
  out["residual"] = pose.residual;
  out["eigen_gap"] = pose.eigen_gap;
  out["status"] = to_string(pose.status);
  if (!pose.message.empty()) out["message"] = pose.message;
  return result_or_raise(pose.status != OrientationStatus::kOk, to_string(pose.status),
                         pose.message, out);
}

/// The arrays of a correspondence file and its camera (focal, principal_point), keyed like the
/// arguments of vantage.pose (absent fields left out), so that
/// vantage.pose(**vantage.load_correspondences(path), method=...) works.
py::dict load_correspondences(const py::object& path) {
  const io::CorrespondenceFile file = io::read_correspondences(path_from(path));
  py::dict out;
  if (file.has_model) out["model"] = array_from_columns(file.model);
  if (file.has_measured) out["measured"] = array_from_columns(file.measured);
  if (file.has_image) out["image"] = array_from_columns(file.image);
  if (file.has_image1) out["image1"] = array_from_columns(file.image1);
  if (file.has_image2) out["image2"] = array_from_columns(file.image2);
  if (file.weights.size() > 0) out["weights"] = array_from_vector(file.weights);
  if (file.has_focal) out["focal"] = file.camera.focal_length;
  if (file.has_principal_point) {
    out["principal_point"] = array_from_vector(file.camera.principal_point);
  }
  return out;
}

}  // namespace

void bind_pose_commands(py::module_& module) {
  module.def("pose", &pose, py::arg("model") = py::none(), py::arg("image") = py::none(),
             py::kw_only(), py::arg("method") = "affine", py::arg("measured") = py::none(),
             py::arg("image1") = py::none(), py::arg("image2") = py::none(),
             py::arg("weights") = py::none(), py::arg("focal") = py::none(),
             py::arg("principal_point") = py::none(), py::arg("free_vectors") = py::none(),
             "One pose estimator (as `vantage pose --method M --json`): model n x 3 with image "
             "n x 2 in pixels (affine, affine-refined, perspective, standard, oi-foam, oi-svd) or "
             "measured n x 3 (full3d); image1 and image2 n x 2 (two-view). focal (pixels, > 0) "
             "and principal_point [cx, cy] (pixels) as --focal and --principal-point; "
             "free_vectors 'auto' (default), 'all' or 'spanning'. Raises NumericalError when the "
             "estimate is degenerate or did not converge.");
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
             "weights; n x 3 or n x 2) and its camera (focal, principal_point), as keyword "
             "arguments for vantage.pose / vantage.orient.");
  module.def("orient", &orient, py::arg("model"), py::arg("measured"), py::kw_only(),
             py::arg("weights") = py::none(), py::arg("method") = "qmethod",
             "Rotation, translation and scale from 3-D correspondences, alpha * measured = R * "
             "model + p (as `vantage orient --json`).");
}

}  // namespace vantage::python
