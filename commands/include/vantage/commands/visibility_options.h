#pragma once

// The options that put a layout on its body (issue 18; docs/math.md §20): --normals radial,
// --cone-deg, --min-visible, --body and --workspace, and --seen-whole, which drops them all. They
// override the layout file's "normals", "visibility" and "workspace" fields. The CLI registers
// them (VisibilityInput, cli/visibility_input.h); vantage.place() applies its keywords with them.

#include <optional>
#include <string>

#include "vantage/analysis/layout.h"

namespace vantage::commands {

struct VisibilityOptions {
  std::string normals;  ///< "" (the file's) or "radial"
  std::optional<double> cone_deg;
  std::optional<int> min_visible;
  std::string body;         ///< a mesh path, as typed (relative to the working directory)
  std::string workspace;    ///< "AX,AY,AZ,DEG", as typed
  bool seen_whole = false;  ///< --seen-whole: drop the file's normals, cones, body, workspace

  /// Applies the options to a layout read from `path`. Throws InvalidArgument naming the option
  /// as typed (e.g. "--cone-deg: must be in [0.001, 180] degrees", "--body: ...: not a mesh").
  void apply(Layout* layout) const;
};

}  // namespace vantage::commands
