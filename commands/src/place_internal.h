#pragma once

// Private: the helpers that place_sites.cc, place_request.cc and place_json.cc share (the
// public interface is vantage/commands/place_json.h).

#include <Eigen/Core>
#include <string>

#include "vantage/analysis/common.h"
#include "vantage/commands/place_json.h"

namespace vantage::place_json::internal {

/// Throws InvalidArgument naming `field` (a CLI option, e.g. "--markers") with `message`.
[[noreturn]] void place_refuse(const std::string& field, const std::string& message);

/// The TRE's numeric range (docs/math.md §23) on the sites, before any search; refuses naming
/// --target, the FLE's option or the sites' option.
void check_tracker_range(const Request& request, const Eigen::Matrix3Xd& sites);

}  // namespace vantage::place_json::internal
