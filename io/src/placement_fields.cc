#include "placement_fields.h"

#include <cmath>
#include <limits>
#include <string>

#include "json_fields.h"

namespace vantage::io::internal {
namespace {

// An objective value of a camera or tracker placement: a finite number >= 0, or null for none
// (+inf: tracks nothing, or past the camera's first-order limit).
double read_objective(const nlohmann::json& v, const std::string& source,
                      const std::string& field) {
  if (v.is_null()) return std::numeric_limits<double>::infinity();
  if (!v.is_number() || !std::isfinite(v.get<double>()) || v.get<double>() < 0.0) {
    fail(source, field + ": expected a finite number >= 0, or null");
  }
  return v.get<double>();
}

nlohmann::ordered_json objective_json(double value) {
  return std::isfinite(value) ? nlohmann::ordered_json(value) : nlohmann::ordered_json(nullptr);
}

void read_random_baseline(const nlohmann::json& b, const std::string& source,
                          LayoutPlacement* out) {
  const std::string field = "placement.random_baseline";
  if (!b.is_object() || !b.contains("trials") || !b["trials"].is_number_integer() ||
      !b.contains("best_pbar_min") || !b["best_pbar_min"].is_number() ||
      !b.contains("median_pbar_min") || !b["median_pbar_min"].is_number()) {
    fail(source, field +
                     ": expected {\"trials\": integer, \"best_pbar_min\": number, "
                     "\"median_pbar_min\": number}");
  }
  reject_unknown_fields(
      b, source,
      {"trials", "best_pbar_min", "median_pbar_min", "best_objective", "median_objective"});
  const long long trials = b["trials"].get<long long>();
  if (trials < 0 || trials > 1'000'000'000) fail(source, field + ".trials: expected 0 or more");
  out->random_trials = static_cast<int>(trials);
  out->random_best_pbar_min = b["best_pbar_min"].get<double>();
  out->random_median_pbar_min = b["median_pbar_min"].get<double>();
  if (b.contains("best_objective") != b.contains("median_objective")) {
    fail(source, field + ": give best_objective and median_objective together, or neither");
  }
  if (b.contains("best_objective")) {
    out->random_best_objective =
        read_objective(b["best_objective"], source, field + ".best_objective");
  }
  if (b.contains("median_objective")) {
    out->random_median_objective =
        read_objective(b["median_objective"], source, field + ".median_objective");
  }
}

// placement.<name>: a finite length >= 0, or 0 when absent.
double read_length(const nlohmann::json& p, const std::string& source, const std::string& name) {
  if (!p.contains(name)) return 0.0;
  const nlohmann::json& v = p[name];
  if (!v.is_number() || !std::isfinite(v.get<double>()) || v.get<double>() < 0.0) {
    fail(source, "placement." + name + ": expected a finite length >= 0");
  }
  return v.get<double>();
}

}  // namespace

std::optional<LayoutPlacement> read_placement(const nlohmann::json& root, const std::string& source,
                                              Eigen::Index markers) {
  if (!root.contains("placement")) return std::nullopt;
  const nlohmann::json& p = root["placement"];
  if (!p.is_object()) fail(source, "placement: expected an object");
  reject_unknown_fields(
      p, source,
      {"sites", "chosen", "objective", "site_points", "site_normals", "min_separation",
       "marker_diameter", "steps", "random_baseline", "objective_value"});
  LayoutPlacement out;
  if (p.contains("sites")) out.sites = read_string(p["sites"], source, "placement.sites");
  if (p.contains("objective")) {
    out.objective = read_string(p["objective"], source, "placement.objective");
  }
  out.site_points = p.contains("site_points")
                        ? read_vectors<3>(p["site_points"], source, "placement.site_points")
                        : Eigen::Matrix3Xd(3, 0);
  out.site_normals = p.contains("site_normals")
                         ? read_vectors<3>(p["site_normals"], source, "placement.site_normals")
                         : Eigen::Matrix3Xd(3, 0);
  if (out.site_normals.cols() != out.site_points.cols()) {
    fail(source, "placement.site_normals: expected one per site (" +
                     std::to_string(out.site_points.cols()) + ")");
  }
  out.min_separation = read_length(p, source, "min_separation");
  out.marker_diameter = read_length(p, source, "marker_diameter");
  if (!p.contains("chosen") || !p["chosen"].is_array()) {
    fail(source, "placement.chosen: expected a list of site indices");
  }
  const nlohmann::json& chosen = p["chosen"];
  if (static_cast<Eigen::Index>(chosen.size()) != markers) {
    fail(source,
         "placement.chosen: expected one site per marker (" + std::to_string(markers) + ")");
  }
  for (std::size_t k = 0; k < chosen.size(); ++k) {
    const std::string field = "placement.chosen[" + std::to_string(k) + "]";
    if (!chosen[k].is_number_integer()) fail(source, field + ": expected an integer");
    const long long s = chosen[k].get<long long>();
    if (s < -1 || s >= out.site_points.cols()) {
      fail(source, field + ": not a site index (-1 for a kept marker)");
    }
    out.chosen.push_back(static_cast<int>(s));
  }
  if (p.contains("steps")) {
    if (!p["steps"].is_array()) fail(source, "placement.steps: expected a list");
    for (std::size_t k = 0; k < p["steps"].size(); ++k) {
      const nlohmann::json& step = p["steps"][k];
      const std::string field = "placement.steps[" + std::to_string(k) + "]";
      if (!step.is_object() || !step.contains("k") || !step["k"].is_number_integer() ||
          !step.contains("pbar_min") || !step["pbar_min"].is_number() ||
          !step.contains("coverage") || !step["coverage"].is_number()) {
        fail(source,
             field + ": expected {\"k\": integer, \"pbar_min\": number, \"coverage\": number}");
      }
      reject_unknown_fields(step, source, {"k", "pbar_min", "coverage", "objective"});
      out.steps.push_back(
          {step["k"].get<int>(), step["pbar_min"].get<double>(), step["coverage"].get<double>()});
      if (step.contains("objective")) {
        out.steps.back().objective =
            read_objective(step["objective"], source, field + ".objective");
      }
    }
  }
  if (p.contains("random_baseline")) read_random_baseline(p["random_baseline"], source, &out);
  if (p.contains("objective_value")) {
    out.objective_value = read_objective(p["objective_value"], source, "placement.objective_value");
  }
  return out;
}

void write_placement(const Layout& layout, nlohmann::ordered_json* out) {
  if (!layout.placement) return;
  const LayoutPlacement& p = *layout.placement;
  nlohmann::ordered_json block;
  block["sites"] = p.sites;
  block["chosen"] = p.chosen;
  block["objective"] = p.objective;
  block["min_separation"] = p.min_separation;
  block["marker_diameter"] = p.marker_diameter;
  // The objective's values only for a camera or tracker placement: affine files are unchanged.
  const bool objective = layout.sensor.has_value();
  if (objective && !std::isnan(p.objective_value)) {
    block["objective_value"] = objective_json(p.objective_value);
  }
  nlohmann::ordered_json steps = nlohmann::ordered_json::array();
  for (const LayoutPlacement::Step& step : p.steps) {
    nlohmann::ordered_json s = {
        {"k", step.k}, {"pbar_min", step.pbar_min}, {"coverage", step.coverage}};
    if (objective && !std::isnan(step.objective)) s["objective"] = objective_json(step.objective);
    steps.push_back(s);
  }
  block["steps"] = steps;
  if (p.random_trials > 0) {
    block["random_baseline"] = {{"trials", p.random_trials},
                                {"best_pbar_min", p.random_best_pbar_min},
                                {"median_pbar_min", p.random_median_pbar_min}};
    if (objective && !std::isnan(p.random_best_objective)) {
      block["random_baseline"]["best_objective"] = objective_json(p.random_best_objective);
      block["random_baseline"]["median_objective"] = objective_json(p.random_median_objective);
    }
  }
  block["site_points"] = vector_rows(p.site_points);
  block["site_normals"] = vector_rows(p.site_normals);
  (*out)["placement"] = block;
}

}  // namespace vantage::io::internal
