#pragma once

// What `vantage crb` and `vantage plot --crb` share: the camera's options, the typed direction and
// distance sweep, and the library's field names as the command's options.

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "vantage/analysis/common.h"
#include "vantage/camera/pose_crb.h"

namespace vantage::cli {

/// --distance, --focal, --noise-px, --principal-point, --aim, --sweep-distance, --samples,
/// --threads.
struct CrbCameraArgs {
  double distance = 0.0;
  double focal = 0.0;
  double noise_px = 0.0;
  std::vector<double> principal_point;
  std::string sweep_distance;
  int samples = 10000;
  int threads = 0;
  std::string aim;  ///< --aim X,Y,Z, or empty (the markers' centroid)
  CLI::Option* distance_option = nullptr;
  CLI::Option* focal_option = nullptr;
  CLI::Option* noise_option = nullptr;

  /// Adds the options to `sub`; `required` makes the first three required by CLI11.
  void add_options(CLI::App* sub, bool required);
  /// The library's options from the typed ones.
  camera::PoseCrbOptions options() const;
  /// The typed --sweep-distance, or nothing when not given.
  std::optional<camera::PoseCrbSweep> sweep() const;
};

/// "D1:D2:N" as typed; InvalidArgument naming --sweep-distance otherwise.
camera::PoseCrbSweep parse_sweep(const std::string& text);

/// The library's field names ("distance", "focal_length", ...) as the command's options; any
/// other error is the layout file's.
InvalidArgument crb_option_error(const InvalidArgument& e, const std::string& file);

}  // namespace vantage::cli
