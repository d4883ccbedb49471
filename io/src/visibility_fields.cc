#include "visibility_fields.h"

#include <cmath>
#include <string>

#include "json_fields.h"
#include "vantage/analysis/scaling.h"

namespace vantage::io::internal {
namespace {

int read_min_visible(const nlohmann::json& value, const std::string& source) {
  if (!value.is_number_integer()) fail(source, "visibility.min_visible: expected an integer");
  const long long k = value.get<long long>();
  if (k < 3 || k > 1'000'000) fail(source, "visibility.min_visible: must be >= 3");
  return static_cast<int>(k);
}

Eigen::VectorXd read_cones(const nlohmann::json& value, const std::string& source,
                           Eigen::Index markers) {
  const std::string field = "visibility.cone_half_angle_deg";
  if (value.is_number()) {
    const Eigen::VectorXd one = read_numbers(nlohmann::json::array({value}), source, field);
    return Eigen::VectorXd::Constant(markers, one(0));
  }
  return read_numbers(value, source, field);
}

}  // namespace

std::optional<MarkerVisibility> read_visibility(const nlohmann::json& root,
                                                const std::string& source, Eigen::Index markers) {
  if (!root.contains("normals")) {
    if (root.contains("visibility")) {
      fail(source, "visibility: needs \"normals\", one outward normal per point");
    }
    return std::nullopt;
  }
  MarkerVisibility out;
  const Eigen::Matrix3Xd given = read_vectors<3>(root["normals"], source, "normals");
  out.normals.resize(3, given.cols());
  for (Eigen::Index i = 0; i < given.cols(); ++i) out.normals.col(i) = unit_normal(given.col(i));
  for (Eigen::Index i = 0; i < given.cols(); ++i) {
    if (out.normals.col(i).isZero()) {
      fail(source, "normals[" + std::to_string(i) + "]: zero length (give the outward normal)");
    }
  }
  out.cone_half_angle_deg =
      Eigen::VectorXd::Constant(given.cols(), MarkerVisibility::kDefaultConeDeg);
  if (root.contains("visibility")) {
    const nlohmann::json& v = root["visibility"];
    if (!v.is_object()) fail(source, "visibility: expected an object");
    reject_unknown_fields(v, source, {"cone_half_angle_deg", "min_visible", "body"});
    if (v.contains("cone_half_angle_deg")) {
      out.cone_half_angle_deg = read_cones(v["cone_half_angle_deg"], source, markers);
    }
    if (v.contains("min_visible")) out.min_visible = read_min_visible(v["min_visible"], source);
    if (v.contains("body")) {
      out.body_path = read_string(v["body"], source, "visibility.body");
      // Issue 36: "" silently meant no body.
      if (out.body_path.empty()) {
        fail(source,
             "visibility.body: empty; give a mesh path, or leave the field out for no body");
      }
    }
  }
  return out;
}

std::optional<LayoutWorkspace> read_workspace(const nlohmann::json& root,
                                              const std::string& source) {
  if (!root.contains("workspace")) return std::nullopt;
  const nlohmann::json& w = root["workspace"];
  if (!w.is_object()) fail(source, "workspace: expected an object");
  reject_unknown_fields(w, source, {"axis", "half_angle_deg"});
  if (!w.contains("axis") || !w.contains("half_angle_deg")) {
    fail(source, "workspace: give \"axis\" [x, y, z] and \"half_angle_deg\"");
  }
  const Eigen::Matrix3Xd axis =
      read_vectors<3>(nlohmann::json::array({w["axis"]}), source, "workspace.axis");
  LayoutWorkspace out;
  out.axis = unit_direction(axis.col(0));
  if (out.axis.isZero()) fail(source, "workspace.axis: zero length");
  out.half_angle_deg = read_numbers(nlohmann::json::array({w["half_angle_deg"]}), source,
                                    "workspace.half_angle_deg")(0);
  return out;
}

void write_visibility(const Layout& layout, nlohmann::ordered_json* out) {
  if (layout.visibility) {
    const MarkerVisibility& v = *layout.visibility;
    (*out)["normals"] = vector_rows(v.normals);
    nlohmann::ordered_json block;
    const Eigen::VectorXd& cones = v.cone_half_angle_deg;
    if (cones.size() > 0 && (cones.array() == cones(0)).all()) {
      block["cone_half_angle_deg"] = cones(0);
    } else {
      block["cone_half_angle_deg"] = std::vector<double>(cones.data(), cones.data() + cones.size());
    }
    block["min_visible"] = v.min_visible;
    if (!v.body_path.empty()) block["body"] = v.body_path;
    (*out)["visibility"] = block;
  }
  if (layout.workspace) {
    const LayoutWorkspace& w = *layout.workspace;
    (*out)["workspace"] = {{"axis", {w.axis.x(), w.axis.y(), w.axis.z()}},
                           {"half_angle_deg", w.half_angle_deg}};
  }
}

}  // namespace vantage::io::internal
