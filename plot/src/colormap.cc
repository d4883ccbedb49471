#include "vantage/plot/colormap.h"

#include <algorithm>
#include <cmath>

namespace vantage::plot {
namespace {

// Viridis sampled at fractions 0, 1/8, ..., 1 (the published map's values, rounded to 8 bits).
constexpr std::array<Rgb, kValueColourAnchors> kViridis{{
    {68, 1, 84},
    {72, 40, 120},
    {62, 73, 137},
    {49, 104, 142},
    {38, 130, 142},
    {31, 158, 137},
    {53, 183, 121},
    {110, 206, 88},
    {253, 231, 37},
}};

std::uint8_t mix(std::uint8_t a, std::uint8_t b, double f) {
  return static_cast<std::uint8_t>(std::lround(a + (b - a) * f));
}

}  // namespace

Rgb value_colour(double fraction) {
  if (!(fraction > 0.0)) return kViridis.front();
  if (fraction >= 1.0) return kViridis.back();
  const double x = fraction * (kValueColourAnchors - 1);
  const int i = std::min(static_cast<int>(x), kValueColourAnchors - 2);
  const double f = x - i;
  const Rgb& a = kViridis[i];
  const Rgb& b = kViridis[i + 1];
  return {mix(a.r, b.r, f), mix(a.g, b.g, f), mix(a.b, b.b, f)};
}

Rgb value_colour(double value, double lo, double hi) {
  if (!(hi > lo)) return value_colour(0.0);
  return value_colour((value - lo) / (hi - lo));
}

}  // namespace vantage::plot
