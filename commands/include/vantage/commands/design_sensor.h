#pragma once

// `vantage design --objective camera|tracker` and vantage.design(objective=...) (README, "vantage
// design"; docs/math.md §21, "In design"): the K of a layout's candidates that, added to its
// markers, make the camera's or the tracker's objective best. It is `vantage place`'s search
// (design::place_markers, with its camera and tracker objectives) on the markers, kept, and the
// candidates as the sites, in design's model of the layout: seen whole (every marker seen from
// every direction of the layout's workspace; candidates carry no normals). The augmented layout
// records the sensor, so that `vantage analyze` on the written file reports the same value.

#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "vantage/analysis/layout.h"
#include "vantage/commands/place_json.h"
#include "vantage/commands/sensor_json.h"
#include "vantage/design/placement.h"

namespace vantage::design_sensor {

using Json = nlohmann::ordered_json;

/// The sites of the search: the layout's markers (the first `markers` columns, kept) and then
/// its candidates, as a point layout seen whole with the layout's workspace.
struct Sites {
  Layout layout;
  int markers = 0;
  std::vector<int> keep;  ///< 0 .. markers - 1
};

/// The layout's markers and candidates as the search's sites. Throws InvalidArgument naming the
/// layout's field: "vectors" for a layout of vectors, "candidates" for one without candidates,
/// "visibility" for one with a visibility model (normals, cones or a body: its candidates could
/// not share it).
Sites sites_of(const Layout& layout);

/// Checks `request` (place's checks, with markers = the layout's markers + `add`) and the layout
/// (coincident candidates, a distance difference its markers break: design::check_augmentation)
/// before any search. Errors name the flags as `vantage place` does, with "--add" for its
/// "--markers", and the layout's fields ("candidates[2]").
void check(const place_json::Request& request, const Sites& sites, int add, const Layout& layout);

/// The answer.
struct Outcome {
  design::PlacementResult result;  ///< over the sites (markers first, then the candidates)
  /// The layout with the chosen candidates appended as markers ("added1", ... in a named
  /// layout; weight 1), the others left as its candidates, and the sensor block.
  Layout augmented;
  std::vector<int> added;  ///< the chosen candidates' indices in the input layout
  /// The sensor's value of the layout as given (none with fewer than 3 markers).
  std::optional<sensor_json::Evaluation> initial;
  sensor_json::Evaluation final;  ///< of `augmented`, as `vantage analyze` evaluates it
  /// Covers the least coverage and the final value is complete (trackable, or certified at
  /// every target): only then is it written.
  bool complete = false;
};

/// The search (request.objective is "camera" or "tracker", checked by check()); `progress` (or
/// empty) gets the stages. Throws InvalidArgument naming --distance or --distances (a camera
/// inside the sites) and --min-distance-difference (no K candidates keep it).
Outcome design_for_sensor(const place_json::Request& request, const Layout& layout,
                          const Sites& sites, int add,
                          const std::function<void(const std::string&)>& progress);

/// Why an incomplete answer is not written.
std::string failure_message(const Outcome& outcome);

/// The JSON object of `vantage design --objective camera|tracker --json`; `source` is the
/// "layout" field (the file name, or null).
Json report(const Json& source, const place_json::Request& request, const Sites& sites,
            const Outcome& outcome);

}  // namespace vantage::design_sensor
