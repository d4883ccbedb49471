#pragma once

// Private to vantage's libraries: a double as the shortest decimal text that reads back to the
// same double (the text writers' coordinates, and numbers a message invites the user to type).

#include <string>

namespace vantage::internal {

/// The fewest of 15, 16 or 17 significant digits ("%.*g") that strtod reads back to x exactly
/// (17 always do).
std::string round_trip_number(double x);

}  // namespace vantage::internal
