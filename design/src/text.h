#pragma once

// Private to vantage::design: numbers in the augmenter's plain-words notes and messages.

#include <sstream>
#include <string>

namespace vantage::design::internal {

/// v with 6 significant digits, as std::ostream prints it by default.
inline std::string fmt(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

}  // namespace vantage::design::internal
