#pragma once

// Private helper of the JSON layout reader and writer: the "normals", "visibility" and
// "workspace" fields of a point layout (README, "File formats"; docs/math.md §20).

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "vantage/analysis/layout.h"

namespace vantage::io::internal {

/// The markers' visibility from `root` ("normals", with "visibility" optional), or none when the
/// file has no normals. A "visibility" without "normals" is an error naming "visibility". The
/// normals are normalised here (each by its own scale); "body" is kept as the file gives it
/// (read_layout() loads it relative to the file). Throws InvalidArgument against `source`.
std::optional<MarkerVisibility> read_visibility(const nlohmann::json& root,
                                                const std::string& source, Eigen::Index markers);

/// The "workspace" field, or none. The axis is normalised here.
std::optional<LayoutWorkspace> read_workspace(const nlohmann::json& root,
                                              const std::string& source);

/// Adds "normals", "visibility" and "workspace" to `out` when the layout has them.
void write_visibility(const Layout& layout, nlohmann::ordered_json* out);

}  // namespace vantage::io::internal
