// vantage.pose and vantage.orient: the estimators behind `vantage pose` and `vantage orient`,
// returning the fields of their --json output. vantage.pose goes through estimate_pose(), the
// front door `vantage pose` and `vantage simulate` use, and its object is the command's own
// conversion (commands/include/vantage/commands/pose_json.h).

#include "pose_commands.h"

#include <pybind11/stl.h>

#include <cmath>

#include "arrays.h"
#include "results.h"
#include "vantage/analysis/absolute_orientation.h"
#include "vantage/analysis/common.h"
#include "vantage/analysis/estimate_pose.h"
#include "vantage/analysis/pose_method.h"
#include "vantage/commands/pose_json.h"
#include "vantage/io/correspondence_file.h"

namespace vantage::python {

namespace {

/// free_vectors= (auto, all or spanning; only for the methods that use free vectors).
FreeVectorSet read_free_vectors(const py::object& free_vectors, PoseMethod method) {
  if (free_vectors.is_none()) return FreeVectorSet::kAuto;
  const std::string expected = "expected auto, all or spanning";
  if (!py::isinstance<py::str>(free_vectors)) throw InvalidArgument("free_vectors", expected);
  const std::string name = free_vectors.cast<std::string>();
  if (!uses_free_vectors(method)) {
    throw InvalidArgument("free_vectors",
                          "only affine, affine-refined, perspective, standard and full3d use free "
                          "vectors, not " +
                              std::string(to_string(method)));
  }
  if (name == "all") return FreeVectorSet::kAllPairs;
  if (name == "spanning") return FreeVectorSet::kMaxSpanningTree;
  if (name != "auto") throw InvalidArgument("free_vectors", expected);
  return FreeVectorSet::kAuto;
}

/// focal= and principal_point= (checked as the CLI checks --focal and --principal-point).
Camera read_camera(const py::object& focal, const py::object& principal_point, PoseMethod method) {
  Camera camera;
  const bool no_camera =
      pose_data(method) == PoseData::kMeasured || pose_data(method) == PoseData::kPlanar;
  if (!focal.is_none()) {
    if (!py::isinstance<py::float_>(focal) && !py::isinstance<py::int_>(focal)) {
      throw InvalidArgument("focal", "must be a finite number > 0");
    }
    camera.focal_length = focal.cast<double>();
    if (!(camera.focal_length > 0.0 && std::isfinite(camera.focal_length))) {
      throw InvalidArgument("focal", "must be a finite number > 0");
    }
    if (no_camera) {
      throw InvalidArgument("focal", std::string("not used by method='") + to_string(method) +
                                         "' (it measures without a camera)");
    }
  }
  if (!principal_point.is_none()) {
    camera.principal_point = pair_from_array(principal_point, "principal_point", "pixels");
    if (no_camera) {
      throw InvalidArgument("principal_point",
                            std::string("not used by method='") + to_string(method) + "'");
    }
  }
  return camera;
}

py::object pose(const py::object& model, const py::object& image, const std::string& method_name,
                const py::object& measured, const py::object& image1, const py::object& image2,
                const py::object& weights, const py::object& focal,
                const py::object& principal_point, const py::object& free_vectors) {
  const PoseMethod method = parse_pose_method_or_throw(method_name, "method");
  Correspondences data;
  if (!model.is_none()) data.model = rows_from_array<3>(model, "model");
  if (!measured.is_none()) data.measured = rows_from_array<3>(measured, "measured");
  if (!image.is_none()) data.image = rows_from_array<2>(image, "image");
  if (!image1.is_none()) data.image1 = rows_from_array<2>(image1, "image1");
  if (!image2.is_none()) data.image2 = rows_from_array<2>(image2, "image2");
  if (!weights.is_none()) data.weights = vector_from_array(weights, "weights");
  data.camera = read_camera(focal, principal_point, method);
  PoseOptions options;
  options.free_vectors = read_free_vectors(free_vectors, method);
  const PoseEstimate estimate = without_gil([&] { return estimate_pose(method, data, options); });
  const Eigen::Index n =
      pose_data(method) == PoseData::kTwoViews ? data.image1.cols() : data.model.cols();
  return result_or_raise(estimate.status != PoseStatus::kOk, to_string(estimate.status),
                         estimate.message, pose_json::estimate(estimate, n));
}

py::object orient(const py::object& model, const py::object& measured, const py::object& weights,
                  const std::string& method) {
  OrientationOptions options;
  const std::optional<OrientationMethod> parsed = parse_orientation_method(method);
  if (!parsed) {
    throw InvalidArgument("method: expected qmethod, svd or foam, got \"" + method + "\"");
  }
  options.method = *parsed;
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
  const io::CorrespondenceFile file = io::read_correspondences(path_from(path, "path"));
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
        for (PoseMethod method : kPoseMethods) names.push_back(to_string(method));
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
