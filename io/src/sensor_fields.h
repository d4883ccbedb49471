#pragma once

// Private helper of the JSON layout reader and writer: the "sensor" block of a layout that
// `vantage place --objective camera|tracker` wrote (README, "File formats"; docs/math.md §21,
// "Objectives"), which `vantage analyze` evaluates.

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "vantage/analysis/layout.h"

namespace vantage::io::internal {

/// The "sensor" field, or none. Throws InvalidArgument against `source` naming
/// "sensor.<field>": an unknown type, a missing or out-of-range setting, a camera field in a
/// tracker's block or the reverse, both or neither of fle_rms and fle_sigma.
std::optional<LayoutSensor> read_sensor(const nlohmann::json& root, const std::string& source);

/// Adds "sensor" to `out` when the layout has one.
void write_sensor(const Layout& layout, nlohmann::ordered_json* out);

}  // namespace vantage::io::internal
