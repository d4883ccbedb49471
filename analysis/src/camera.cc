#include "vantage/analysis/camera.h"

#include <cmath>

namespace vantage {

bool Camera::is_valid(std::string* why) const {
  auto fail = [&](const char* text) {
    if (why) *why = text;
    return false;
  };
  if (!(focal_length >= 0.0 && std::isfinite(focal_length)))
    return fail("focal_length must be finite and >= 0 (pixels; 0: unknown)");
  if (!principal_point.allFinite()) return fail("principal_point must be finite (pixels)");
  return true;
}

}  // namespace vantage
