#pragma once

// The sensor a layout was placed for (Layout::sensor, the file's "sensor" block; docs/math.md
// §21, "Objectives"): made from `vantage place`'s camera or tracker objective, evaluated on a
// layout the way `vantage crb` and `vantage tre` would with the recorded settings, in words and
// as JSON. `vantage place` and `vantage analyze` both evaluate it here, so that the objective of
// the written layout is the value analyze reports on the file.

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "vantage/analysis/layout.h"
#include "vantage/camera/pose_crb.h"
#include "vantage/design/placement.h"
#include "vantage/tracker/tre_report.h"

namespace vantage::sensor_json {

using Json = nlohmann::ordered_json;

/// The camera objective's sensor (its aim must be resolved): its camera, statistic and distances.
LayoutSensor camera_sensor(const design::CameraObjective& camera);

/// The tracker objective's sensor: its FLE as an RMS when it was given as one, else its sigmas.
LayoutSensor tracker_sensor(const design::TrackerObjective& tracker);

/// The FLE of a tracker's sensor (FleModel::isotropic of its RMS, or its sigmas).
tracker::FleModel fle_model(const LayoutSensor& sensor);

/// The sensor in words, with the `vantage crb` or `vantage tre` options that reproduce its value.
std::string words(const LayoutSensor& sensor);

/// One distance of a camera's approach: `vantage crb --distance D`'s map and its statistic.
struct ApproachStep {
  double distance = 0.0;
  camera::PoseCrbMap map;
  double value = 0.0;  ///< the statistic of rot_rms (degrees), +inf when not trackable
};

/// A layout evaluated for its sensor.
struct Evaluation {
  LayoutSensor sensor;
  /// A camera: its options (threads as asked) and `vantage crb`'s map of the layout, at the
  /// distance that decides the value (the largest statistic; the first not trackable).
  std::optional<camera::PoseCrbOptions> camera;
  std::optional<camera::PoseCrbMap> crb;
  /// A camera with an approach (several distances): every distance, in the sensor's order.
  std::vector<ApproachStep> approach;
  /// A tracker: `vantage tre`'s report of the layout at the targets.
  std::optional<tracker::TreReport> tre;
  /// The camera's statistic of the rotation RMS (degrees; an approach: the largest over its
  /// distances), or the largest certified bound on the
  /// worst RMS TRE over the targets (layout units); +inf when not trackable or a target is
  /// tracked from no direction.
  double value = 0.0;
  /// The camera's map is trackable (at every distance), or every target's worst TRE is finite
  /// and certified.
  bool complete = false;
};

/// Evaluates `layout` for its sensor (layout.sensor must be set). Throws InvalidArgument naming
/// "sensor.<field>" for settings `vantage crb` or `vantage tre` refuses (e.g. a distance inside
/// the layout).
Evaluation evaluate(const Layout& layout, int threads);

/// The camera statistic of a map, degrees (+inf when not trackable).
double crb_statistic(const camera::PoseCrbMap& map, design::CrbStatistic statistic);

/// The largest certified bound on the worst RMS TRE over the targets (+inf when a target is
/// tracked from no direction), and whether every target's worst is certified.
double tre_objective(const tracker::TreReport& report);
bool tre_certified(const tracker::TreReport& report);

/// The camera's map in brief: status, trackable and unbounded fractions, and the worst
/// direction and percentiles when trackable (otherwise why not): `place --json`'s
/// objective.crb and analyze's sensor.crb.
Json crb_json(const camera::PoseCrbMap& map, double distance);

/// An approach's distances: each one's distance, value_deg (null when +inf) and crb block
/// (crb_json): analyze's sensor.approach and `place --json`'s objective.approach.
Json approach_json(const std::vector<ApproachStep>& approach);

/// `vantage analyze --json`'s "sensor": the settings, the words, "value_deg" (camera) or
/// "value" (tracker, layout units; null when +inf), complete, and the camera's worst direction
/// and percentiles or the tracker's worst per target.
Json to_json(const Evaluation& evaluation);

/// `vantage analyze`'s lines (each ends with a newline).
std::string to_text(const Evaluation& evaluation);

}  // namespace vantage::sensor_json
