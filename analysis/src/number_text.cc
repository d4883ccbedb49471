#include "vantage/analysis/internal/number_text.h"

#include <cstdio>
#include <cstdlib>

namespace vantage::internal {

std::string round_trip_number(double x) {
  char buffer[32];
  for (int digits = 15; digits <= 17; ++digits) {
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, x);
    if (std::strtod(buffer, nullptr) == x) break;
  }
  return buffer;
}

}  // namespace vantage::internal
