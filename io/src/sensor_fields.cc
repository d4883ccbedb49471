#include "sensor_fields.h"

#include <cmath>
#include <string>

#include "json_fields.h"
#include "vantage/analysis/internal/checks.h"

namespace vantage::io::internal {
namespace {

// The camera map's lattice: the range of PoseCrbOptions::samples.
constexpr long long kMinSamples = 100;
constexpr long long kMaxSamples = 10'000'000;

// sensor.<name>: a finite number > 0.
double read_positive(const nlohmann::json& s, const std::string& source, const std::string& name) {
  if (!s.contains(name)) fail(source, "sensor." + name + ": required");
  const nlohmann::json& v = s[name];
  if (!v.is_number() || !std::isfinite(v.get<double>()) || !(v.get<double>() > 0.0)) {
    fail(source, "sensor." + name + ": expected a finite number > 0");
  }
  return v.get<double>();
}

// sensor.distance, or sensor.distances: an approach of 2 to kMaxDistances numbers > 0.
void read_distances(const nlohmann::json& s, const std::string& source, LayoutSensor* out) {
  if (s.contains("distance") && s.contains("distances")) {
    fail(source, "sensor.distances: give distance or distances, not both");
  }
  if (!s.contains("distances")) {
    out->distances = {read_positive(s, source, "distance")};
    return;
  }
  const Eigen::VectorXd d = read_numbers(s["distances"], source, "sensor.distances");
  if (d.size() < 2 || d.size() > LayoutSensor::kMaxDistances || !(d.array() > 0.0).all()) {
    fail(source, "sensor.distances: expected 2 to " + std::to_string(LayoutSensor::kMaxDistances) +
                     " numbers > 0 (one: distance)");
  }
  out->distances.assign(d.data(), d.data() + d.size());
  if (const long k = vantage::internal::first_repeat(out->distances); k >= 0) {
    fail(source, "sensor.distances[" + std::to_string(k) + "]: repeats an earlier distance");
  }
}

void read_camera(const nlohmann::json& s, const std::string& source, LayoutSensor* out) {
  reject_unknown_fields(
      s, source,
      {"type", "distance", "distances", "focal_px", "noise_px", "samples", "aim", "statistic"});
  out->kind = LayoutSensor::Kind::kCamera;
  read_distances(s, source, out);
  out->focal_px = read_positive(s, source, "focal_px");
  out->noise_px = read_positive(s, source, "noise_px");
  if (!s.contains("samples") || !s["samples"].is_number_integer() ||
      s["samples"].get<long long>() < kMinSamples || s["samples"].get<long long>() > kMaxSamples) {
    fail(source, "sensor.samples: expected an integer in [" + std::to_string(kMinSamples) + ", " +
                     std::to_string(kMaxSamples) + "]");
  }
  out->samples = static_cast<int>(s["samples"].get<long long>());
  if (!s.contains("aim")) fail(source, "sensor.aim: required");
  const Eigen::VectorXd aim = read_numbers(s["aim"], source, "sensor.aim");
  if (aim.size() != 3) fail(source, "sensor.aim: expected [x, y, z]");
  out->aim = aim;
  if (!s.contains("statistic")) fail(source, "sensor.statistic: required");
  out->statistic = read_string(s["statistic"], source, "sensor.statistic");
  if (out->statistic != "worst" && out->statistic != "p95" && out->statistic != "median") {
    fail(source, "sensor.statistic: expected \"worst\", \"p95\" or \"median\", got \"" +
                     out->statistic + "\"");
  }
}

void read_tracker(const nlohmann::json& s, const std::string& source, LayoutSensor* out) {
  reject_unknown_fields(s, source, {"type", "targets", "fle_rms", "fle_sigma"});
  out->kind = LayoutSensor::Kind::kTracker;
  if (!s.contains("targets")) fail(source, "sensor.targets: required");
  const Eigen::Matrix3Xd targets = read_vectors<3>(s["targets"], source, "sensor.targets");
  if (targets.cols() == 0) fail(source, "sensor.targets: expected at least one [x, y, z]");
  for (Eigen::Index k = 0; k < targets.cols(); ++k) out->targets.push_back(targets.col(k));
  if (s.contains("fle_rms") == s.contains("fle_sigma")) {
    fail(source, "sensor.fle_rms: give fle_rms or fle_sigma, not both or neither");
  }
  if (s.contains("fle_rms")) {
    out->fle_rms = read_positive(s, source, "fle_rms");
    return;
  }
  const Eigen::VectorXd sigma = read_numbers(s["fle_sigma"], source, "sensor.fle_sigma");
  if (sigma.size() != 2 || (sigma.array() < 0.0).any() || (sigma.array() == 0.0).all()) {
    fail(source, "sensor.fle_sigma: expected [sigma_perp, sigma_axial], >= 0 and not both 0");
  }
  out->fle_sigma_perp = sigma(0);
  out->fle_sigma_axial = sigma(1);
}

}  // namespace

std::optional<LayoutSensor> read_sensor(const nlohmann::json& root, const std::string& source) {
  if (!root.contains("sensor")) return std::nullopt;
  const nlohmann::json& s = root["sensor"];
  if (!s.is_object()) fail(source, "sensor: expected an object");
  if (!s.contains("type")) fail(source, "sensor.type: required (\"camera\" or \"tracker\")");
  const std::string type = read_string(s["type"], source, "sensor.type");
  LayoutSensor out;
  if (type == "camera") {
    read_camera(s, source, &out);
  } else if (type == "tracker") {
    read_tracker(s, source, &out);
  } else {
    fail(source, "sensor.type: expected \"camera\" or \"tracker\", got \"" + type + "\"");
  }
  return out;
}

void write_sensor(const Layout& layout, nlohmann::ordered_json* out) {
  if (!layout.sensor) return;
  const LayoutSensor& s = *layout.sensor;
  nlohmann::ordered_json block;
  block["type"] = to_string(s.kind);
  if (s.kind == LayoutSensor::Kind::kCamera) {
    if (s.distances.size() == 1) {
      block["distance"] = s.distances.front();
    } else {
      block["distances"] = s.distances;
    }
    block["focal_px"] = s.focal_px;
    block["noise_px"] = s.noise_px;
    block["samples"] = s.samples;
    block["aim"] = {s.aim.x(), s.aim.y(), s.aim.z()};
    block["statistic"] = s.statistic;
  } else {
    Eigen::Matrix3Xd targets(3, static_cast<Eigen::Index>(s.targets.size()));
    for (std::size_t k = 0; k < s.targets.size(); ++k) {
      targets.col(static_cast<Eigen::Index>(k)) = s.targets[k];
    }
    block["targets"] = vector_rows(targets);
    if (s.fle_rms > 0.0) {
      block["fle_rms"] = s.fle_rms;
    } else {
      block["fle_sigma"] = {s.fle_sigma_perp, s.fle_sigma_axial};
    }
  }
  (*out)["sensor"] = block;
}

}  // namespace vantage::io::internal
