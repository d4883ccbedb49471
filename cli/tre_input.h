#pragma once

// What `vantage tre` and `vantage plot --tre` share: the targets, the FLE and the line of sight
// as typed, their checks, and the library's field names as the command's options.

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "vantage/analysis/common.h"
#include "vantage/tracker/tre_report.h"

namespace vantage::cli {

/// --target (repeatable), --fle-rms, --fle-sigma, --direction.
struct TreTargetArgs {
  std::vector<std::string> targets;
  std::optional<double> fle_rms;
  std::string fle_sigma;
  std::string direction;
  CLI::Option* target_option = nullptr;
  CLI::Option* fle_rms_option = nullptr;
  CLI::Option* fle_sigma_option = nullptr;
  CLI::Option* direction_option = nullptr;

  /// Adds the four options to `sub` (--direction only `with_direction`).
  void add_options(CLI::App* sub, bool with_direction = true);
  /// The typed targets (at least one); InvalidArgument naming --target otherwise.
  std::vector<Eigen::Vector3d> parsed_targets() const;
  /// Exactly one of --fle-rms F (> 0) and --fle-sigma SP,SD; InvalidArgument naming it otherwise.
  tracker::FleModel parsed_fle() const;
  /// The unit --direction, or nothing when not given; InvalidArgument naming it otherwise.
  std::optional<Eigen::Vector3d> parsed_direction() const;
};

/// The library's field names ("target", "fle.sigma_perp", "direction", "radius") as the
/// command's options; any other error is the layout file's.
InvalidArgument tre_option_error(const InvalidArgument& e, const std::string& file);

}  // namespace vantage::cli
