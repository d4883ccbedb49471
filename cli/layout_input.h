#pragma once

// The layout-file options shared by every subcommand that reads a layout (analyze, design,
// weights, plot, simulate, experiment): --format and the AprilTag options. One line registers
// them on a subcommand, one line reads the layout with them (io::load_layout: every format).

#include <CLI/CLI.hpp>
#include <string>

#include "vantage/analysis/layout.h"
#include "visibility_input.h"

namespace vantage::cli {

/// The parsed layout options of one subcommand.
struct LayoutInput {
  std::string format = "auto";
  std::string tag_points = "corners";
  std::string bundle;
  /// The option that sets `format`, as registered (named in its errors).
  std::string format_option = "--format";
  /// The body options (--normals, --cone-deg, --min-visible, --body, --workspace).
  VisibilityInput visibility;

  /// Adds --format (or `format_flag`, for a subcommand whose --format is something else),
  /// --tag-points and --bundle to `sub`, and with `body_options` the body options.
  void add_options(CLI::App* sub, const std::string& format_flag = "--format",
                   bool body_options = true);

  /// Reads the layout at `path` in the chosen (or detected) format, at most kMaxFileBytes (with
  /// allow_large kMaxFileBytesAllowLarge, limits.h); InvalidArgument names the file, field and
  /// index (or the option) on bad input, io::FileTooLarge names --allow-large.
  Layout read(const std::string& path, bool allow_large = false) const;
};

}  // namespace vantage::cli
