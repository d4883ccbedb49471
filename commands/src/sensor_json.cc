#include "vantage/commands/sensor_json.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

#include "vantage/analysis/common.h"
#include "vantage/commands/tre_json.h"
#include "vantage/report/json_number.h"

namespace vantage::sensor_json {
namespace {

Json vector_json(const Eigen::Vector3d& v) { return Json{v.x(), v.y(), v.z()}; }

// A library error named as the file names it: the camera's and tracker's settings as fields of
// the "sensor" block, anything else (the layout's own fields) unchanged.
[[noreturn]] void refuse(const InvalidArgument& e, const LayoutSensor& sensor) {
  const std::string& field = e.field();
  if (field == "distance" && sensor.distances.size() > 1) {
    throw e.renamed("sensor.distances", std::nullopt);
  }
  if (field == "distance" || field == "noise_px" || field == "samples" || field == "aim") {
    throw e.renamed("sensor." + field, std::nullopt);
  }
  if (field == "focal_length") throw e.renamed("sensor.focal_px", std::nullopt);
  if (field == "target") throw e.renamed("sensor.targets", e.index());
  if (field.rfind("fle", 0) == 0) {
    throw e.renamed(sensor.fle_rms > 0.0 ? "sensor.fle_rms" : "sensor.fle_sigma", std::nullopt);
  }
  throw e;
}

camera::PoseCrbOptions camera_options(const LayoutSensor& s, int threads) {
  camera::PoseCrbOptions out;
  out.distance = s.distances.front();
  out.focal_length = s.focal_px;
  out.noise_px = s.noise_px;
  out.samples = s.samples;
  out.aim = s.aim;
  out.threads = threads;
  return out;
}

// The map at each distance; the value and the map shown are those of the distance that decides
// (the first that tracks nothing, else the first unbounded, else the largest statistic).
void evaluate_camera(const Layout& layout, int threads, Evaluation* out) {
  out->camera = camera_options(out->sensor, threads);
  const design::CrbStatistic statistic = *design::parse_crb_statistic(out->sensor.statistic);
  std::vector<ApproachStep> steps;
  try {
    const camera::PoseCrbModel model(layout, *out->camera);
    for (double distance : out->sensor.distances) {
      ApproachStep step;
      step.distance = distance;
      step.map = camera::pose_crb_map(model, distance);
      step.value = crb_statistic(step.map, statistic);
      steps.push_back(std::move(step));
    }
  } catch (const InvalidArgument& e) {
    refuse(e, out->sensor);
  }
  // Worse first: a map that tracks nothing, then one whose worst is unbounded (+inf too), then
  // the larger value; the first of equals.
  const auto rank = [](const ApproachStep& step) {
    const int kind = step.map.status != camera::PoseCrbMap::Status::kOk ? 2
                     : std::isfinite(step.value)                        ? 0
                                                                        : 1;
    return std::make_pair(kind, kind == 0 ? step.value : 0.0);
  };
  std::size_t deciding = 0;
  for (std::size_t k = 1; k < steps.size(); ++k) {
    if (rank(steps[k]) > rank(steps[deciding])) deciding = k;
  }
  out->camera->distance = steps[deciding].distance;
  out->crb = steps[deciding].map;
  out->value = steps[deciding].value;
  out->complete = std::all_of(steps.begin(), steps.end(), [](const ApproachStep& step) {
    return step.map.status == camera::PoseCrbMap::Status::kOk;
  });
  if (steps.size() > 1) out->approach = std::move(steps);
}

void evaluate_tracker(const Layout& layout, int threads, Evaluation* out) {
  tracker::TreOptions options;
  options.fle = fle_model(out->sensor);
  options.threads = threads;
  try {
    out->tre = tracker::tre_report(layout, out->sensor.targets, options);
  } catch (const InvalidArgument& e) {
    refuse(e, out->sensor);
  }
  out->value = tre_objective(*out->tre);
  out->complete = std::isfinite(out->value) && tre_certified(*out->tre);
}

Json tracker_json(const Evaluation& e) {
  Json targets = Json::array();
  for (const tracker::TreTargetReport& t : e.tre->targets) {
    Json target = {{"target", vector_json(t.target)}};
    target["worst"] = tre_json::extreme(t.extremes.worst);
    targets.push_back(target);
  }
  return targets;
}

// A camera map in one line (without the newline).
std::string map_text(const camera::PoseCrbMap& map, const std::string& statistic, double value,
                     double distance) {
  std::ostringstream out;
  out.precision(6);
  if (map.status != camera::PoseCrbMap::Status::kOk) {
    out << "not trackable: " << camera::untrackable_reason(map, distance);
    return out.str();
  }
  if (statistic != "worst") out << statistic << " rot_rms " << value << " deg; ";
  if (map.worst.unbounded) {
    // Past the first-order limit: no figure (docs/math.md §22, "Unbounded").
    out << "worst rot_rms unbounded (the first-order bound means nothing there)";
  } else {
    out << "worst rot_rms " << map.worst.rot_rms_deg << " deg (trans_rms " << map.worst.trans_rms
        << ")";
  }
  out << ", median " << map.percentiles.p50 << " deg, trackable " << 100.0 * map.trackable_fraction
      << " % of the workspace";
  return out.str();
}

}  // namespace

Json approach_json(const std::vector<ApproachStep>& approach) {
  Json out = Json::array();
  for (const ApproachStep& step : approach) {
    out.push_back({{"distance", step.distance},
                   {"value_deg", report::json_number(step.value)},
                   {"crb", crb_json(step.map, step.distance)}});
  }
  return out;
}

Json crb_json(const camera::PoseCrbMap& map, double distance) {
  Json out = {{"status", camera::to_string(map.status)},
              {"trackable_fraction", map.trackable_fraction},
              {"unbounded_fraction", map.unbounded_fraction}};
  if (map.status == camera::PoseCrbMap::Status::kOk) {
    out["worst"] = {{"unbounded", map.worst.unbounded},
                    {"rot_rms_deg", report::json_number(map.worst.rot_rms_deg)},
                    {"trans_rms", report::json_number(map.worst.trans_rms)},
                    {"direction", vector_json(map.worst.direction)}};
    out["percentiles"] = {
        {"p50", map.percentiles.p50}, {"p95", map.percentiles.p95}, {"p99", map.percentiles.p99}};
  } else {
    out["reason"] = camera::untrackable_reason(map, distance);
  }
  return out;
}

LayoutSensor camera_sensor(const design::CameraObjective& camera) {
  LayoutSensor out;
  out.kind = LayoutSensor::Kind::kCamera;
  out.distances = camera.sample_distances();
  out.focal_px = camera.crb.focal_length;
  out.noise_px = camera.crb.noise_px;
  out.samples = camera.crb.samples;
  out.aim = camera.crb.aim.value_or(Eigen::Vector3d::Zero());
  out.statistic = design::to_string(camera.statistic);
  return out;
}

LayoutSensor tracker_sensor(const design::TrackerObjective& tracker) {
  LayoutSensor out;
  out.kind = LayoutSensor::Kind::kTracker;
  out.targets = tracker.targets;
  if (tracker.fle.from_rms) {
    out.fle_rms = tracker.fle.rms();
  } else {
    out.fle_sigma_perp = tracker.fle.sigma_perp;
    out.fle_sigma_axial = tracker.fle.sigma_axial;
  }
  return out;
}

tracker::FleModel fle_model(const LayoutSensor& sensor) {
  if (sensor.fle_rms > 0.0) return tracker::FleModel::isotropic(sensor.fle_rms);
  tracker::FleModel out;
  out.sigma_perp = sensor.fle_sigma_perp;
  out.sigma_axial = sensor.fle_sigma_axial;
  return out;
}

std::string words(const LayoutSensor& s) {
  std::ostringstream out;
  out.precision(17);
  if (s.kind == LayoutSensor::Kind::kCamera) {
    out << "camera: ";
    if (s.distances.size() > 1) {
      out << "the largest, over the approach's distances D = ";
      for (std::size_t k = 0; k < s.distances.size(); ++k) {
        out << (k > 0 ? ", " : "") << s.distances[k];
      }
      out << ", of ";
    }
    out << "the " << s.statistic << " rot_rms over the workspace of vantage crb --distance ";
    if (s.distances.size() > 1) {
      out << "D";
    } else {
      out << s.distances.front();
    }
    out << " --focal " << s.focal_px << " --noise-px " << s.noise_px << " --samples " << s.samples
        << " --aim " << s.aim.x() << "," << s.aim.y() << "," << s.aim.z();
    return out.str();
  }
  out << "tracker: the largest worst.rms_bound over the targets of vantage tre";
  for (const Eigen::Vector3d& t : s.targets) {
    out << " --target " << t.x() << "," << t.y() << "," << t.z();
  }
  if (s.fle_rms > 0.0) {
    out << " --fle-rms " << s.fle_rms;
  } else {
    out << " --fle-sigma " << s.fle_sigma_perp << "," << s.fle_sigma_axial;
  }
  return out.str();
}

Evaluation evaluate(const Layout& layout, int threads) {
  Evaluation out;
  out.sensor = *layout.sensor;
  if (out.sensor.kind == LayoutSensor::Kind::kCamera) {
    evaluate_camera(layout, threads, &out);
  } else {
    evaluate_tracker(layout, threads, &out);
  }
  return out;
}

double crb_statistic(const camera::PoseCrbMap& map, design::CrbStatistic statistic) {
  if (map.status != camera::PoseCrbMap::Status::kOk) return std::numeric_limits<double>::infinity();
  switch (statistic) {
    case design::CrbStatistic::kWorst:
      return map.worst.rot_rms_deg;
    case design::CrbStatistic::kP95:
      return map.percentiles.p95;
    case design::CrbStatistic::kMedian:
      return map.percentiles.p50;
  }
  return map.worst.rot_rms_deg;
}

double tre_objective(const tracker::TreReport& report) {
  double out = 0.0;
  for (const tracker::TreTargetReport& t : report.targets) {
    if (t.extremes.worst.status == tracker::TreExtreme::Status::kUntracked) {
      return std::numeric_limits<double>::infinity();
    }
    out = std::max(out, t.extremes.worst.rms_bound);
  }
  return out;
}

bool tre_certified(const tracker::TreReport& report) {
  return std::all_of(
      report.targets.begin(), report.targets.end(),
      [](const tracker::TreTargetReport& t) { return t.extremes.worst.certified(); });
}

Json to_json(const Evaluation& e) {
  const LayoutSensor& s = e.sensor;
  Json out;
  out["type"] = to_string(s.kind);
  out["objective"] = words(s);
  if (s.kind == LayoutSensor::Kind::kCamera) {
    out["statistic"] = s.statistic;
    out["value_deg"] = report::json_number(e.value);
    out["complete"] = e.complete;
    if (!e.approach.empty()) out["approach"] = approach_json(e.approach);
    out["crb"] = crb_json(*e.crb, e.camera->distance);
    return out;
  }
  out["value"] = report::json_number(e.value);
  out["complete"] = e.complete;
  out["targets"] = tracker_json(e);
  return out;
}

std::string to_text(const Evaluation& e) {
  std::ostringstream out;
  out.precision(6);
  out << "\nsensor (the layout's \"sensor\" block): " << words(e.sensor) << "\n";
  if (e.sensor.kind == LayoutSensor::Kind::kCamera) {
    if (e.approach.empty()) {
      out << "  " << map_text(*e.crb, e.sensor.statistic, e.value, e.camera->distance) << "\n";
      return out.str();
    }
    for (const ApproachStep& step : e.approach) {
      out << "  D " << step.distance << ": "
          << map_text(step.map, e.sensor.statistic, step.value, step.distance)
          << (step.distance == e.camera->distance ? " (decides)" : "") << "\n";
    }
    return out.str();
  }
  if (!std::isfinite(e.value)) {
    out << "  a target is tracked from no direction of the workspace\n";
    return out.str();
  }
  out << "  worst RMS TRE " << e.value << (e.complete ? " (certified)" : " (NOT certified)")
      << "\n";
  return out.str();
}

}  // namespace vantage::sensor_json
