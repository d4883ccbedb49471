#pragma once

// Private helper of the JSON layout reader and writer: the "placement" record of a layout that
// `vantage place` wrote (README, "File formats"; docs/math.md §21).

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "vantage/analysis/layout.h"

namespace vantage::io::internal {

/// The "placement" field, or none. Throws InvalidArgument against `source` naming
/// "placement.<field>" (a chosen site outside the sites, one entry per marker, normals per site).
std::optional<LayoutPlacement> read_placement(const nlohmann::json& root, const std::string& source,
                                              Eigen::Index markers);

/// Adds "placement" to `out` when the layout has one.
void write_placement(const Layout& layout, nlohmann::ordered_json* out);

}  // namespace vantage::io::internal
