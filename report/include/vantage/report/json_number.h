#pragma once

/// The one JSON number of every result writer (report/, commands/, and so `--json` and Python's
/// to_dict()): JSON has no NaN or infinity, so a value that is not finite is written as null.

#include <cmath>
#include <nlohmann/json.hpp>

namespace vantage::report {

/// x as a JSON number when it is finite; null for NaN and +-infinity.
inline nlohmann::ordered_json json_number(double x) {
  return std::isfinite(x) ? nlohmann::ordered_json(x) : nlohmann::ordered_json(nullptr);
}

}  // namespace vantage::report
