#pragma once

// `vantage place`: its arguments and its text report (the JSON report and the placement itself:
// vantage/commands/place_json.h) (README, "vantage place"; docs/math.md §21).

#include "command.h"
#include "layout_input.h"
#include "objective_input.h"
#include "vantage/commands/place_json.h"

namespace vantage::cli {

/// The placement's arguments (place_json::Request) and the CLI's own: the sites file's format and
/// the visibility options, --json and --quiet.
struct PlaceArgs : place_json::Request {
  LayoutInput input;             ///< --format of --sites and the visibility options
  ObjectiveArgs objective_args;  ///< the camera's and the tracker's options given as text
  bool json = false;
  bool quiet = false;
};

using place_json::PlacedLayout;

void print_place_report(const PlaceArgs& args, int n_candidates, int drawn, int excluded,
                        const place_json::Outcome& outcome, bool written);

}  // namespace vantage::cli
