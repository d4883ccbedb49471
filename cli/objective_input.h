#pragma once

// The camera and tracker objectives' options, shared by `vantage place` and `vantage design
// --objective` (docs/math.md §21, "Objectives"): --objective; the camera's --distance,
// --distances, --focal, --noise-px, --statistic, --crb-samples and --aim; the tracker's --target,
// --fle-rms and --fle-sigma. Their numbers go into a place_json::Request, whose checks
// (place_json::check_request) both commands run.

#include <CLI/CLI.hpp>
#include <string>

#include "tre_input.h"
#include "vantage/commands/place_json.h"

namespace vantage::cli {

/// The options given as text, until parse() types them.
struct ObjectiveArgs {
  TreTargetArgs tre;           ///< --target, --fle-rms and --fle-sigma as typed
  std::string aim_text;        ///< --aim as typed
  std::string distances_text;  ///< --distances as typed
  CLI::Option* distances_option = nullptr;

  /// Adds the options to `sub`, the plain numbers read into `request`; `frame` names the frame
  /// of the targets in the help ("the sites'"), `aim_default` the default aim ("the centre of the
  /// sites' bounding box"). Returns --objective (for a command to word it its own way).
  CLI::Option* add_options(CLI::App* sub, place_json::Request* request, const std::string& frame,
                           const std::string& aim_default);
  /// The typed settings of the options given as text (after parsing): --aim, --distances (given
  /// empty, refused), the targets and the FLE.
  void parse(place_json::Request* request) const;
};

}  // namespace vantage::cli
