#pragma once

// Private helper of the text writers: a double as the shortest decimal text that reads back to
// the same double (the libraries' one, analysis/internal/number_text.h).

#include "vantage/analysis/internal/number_text.h"

namespace vantage::io::internal {

using vantage::internal::round_trip_number;

}  // namespace vantage::io::internal
