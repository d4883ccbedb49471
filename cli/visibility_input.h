#pragma once

// The options that put a layout on its body (issue 18; docs/math.md §20): --normals radial,
// --cone-deg, --min-visible, --body and --workspace, and --seen-whole, which drops them all. They
// override the layout file's "normals", "visibility" and "workspace" fields; LayoutInput registers
// and applies them.

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "vantage/analysis/layout.h"

namespace vantage::cli {

struct VisibilityInput {
  std::string normals;  ///< "" (the file's) or "radial"
  std::optional<double> cone_deg;
  std::optional<int> min_visible;
  std::string body;         ///< a mesh path, as typed (relative to the working directory)
  std::string workspace;    ///< "AX,AY,AZ,DEG", as typed
  bool seen_whole = false;  ///< --seen-whole: drop the file's normals, cones, body, workspace

  void add_options(CLI::App* sub);

  /// Applies the options to a layout read from `path`. Throws InvalidArgument naming the option
  /// as typed (e.g. "--cone-deg: must be in (0, 180]", "--body: ...: not a mesh").
  void apply(Layout* layout) const;
};

}  // namespace vantage::cli
