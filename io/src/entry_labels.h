#pragma once

// Private helper of the non-JSON readers: Layout::validate() names entries by their index in the
// JSON format ("points[4]"); these readers name them the way their file does (a CSV line, an
// AprilTag corner).

#include <string>
#include <vector>

#include "vantage/analysis/layout.h"

namespace vantage::io::internal {

/// Runs layout.validate(); its error, against `source`, names entry k of "points" as labels[k]
/// and of "weights" as "<labels[k]>, weight" (InvalidArgument::labelled(): the error's data,
/// not its text).
void validate_labelled(const Layout& layout, const std::string& source,
                       const std::vector<std::string>& labels);

}  // namespace vantage::io::internal
