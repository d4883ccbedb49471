#pragma once

// Private to sdp: the visibility object of the layout report's one JSON writer.

#include <nlohmann/json.hpp>

#include "vantage/visibility/visibility_report.h"

namespace vantage::report::internal {

/// The "visibility" object (README, "vantage analyze"; the fixed names).
nlohmann::ordered_json visibility_json(const visibility::VisibilityReport& report);

}  // namespace vantage::report::internal
