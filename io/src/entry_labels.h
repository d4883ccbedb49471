#pragma once

// Private helper of the non-JSON readers: Layout::validate() names entries by their index in the
// JSON format ("points[4]"); these readers name them the way their file does (a CSV line, an
// AprilTag corner).

#include <string>
#include <vector>

#include "vantage/analysis/layout.h"

namespace vantage::io::internal {

/// `message` with every "points[k]" replaced by labels[k] and "weights[k]" by
/// "<labels[k]>, weight" (k in range; others stay).
std::string relabel_entries(const std::string& message, const std::vector<std::string>& labels);

/// Runs layout.validate(); its error becomes "<source>: <message with relabelled entries>".
void validate_labelled(const Layout& layout, const std::string& source,
                       const std::vector<std::string>& labels);

}  // namespace vantage::io::internal
