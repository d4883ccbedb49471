#pragma once

// Private helper of the text writers: a double as the shortest decimal text that reads back to
// the same double.

#include <string>

namespace vantage::io::internal {

/// The fewest of 15, 16 or 17 significant digits ("%.*g") that strtod reads back to x exactly
/// (17 always do).
std::string round_trip_number(double x);

}  // namespace vantage::io::internal
