#pragma once

/// The colours vantage uses for values and for marked items, shared by `vantage plot` and
/// `vantage-viewer` so that a weak viewing direction looks the same in both.

#include <array>
#include <cstdint>

namespace vantage::plot {

/// An 8-bit sRGB colour.
struct Rgb {
  std::uint8_t r = 0;
  std::uint8_t g = 0;
  std::uint8_t b = 0;

  friend bool operator==(const Rgb& x, const Rgb& y) {
    return x.r == y.r && x.g == y.g && x.b == y.b;
  }
};

/// The sequential value map (viridis): dark blue-violet at 0, through teal and green, to yellow
/// at 1. Perceptually uniform and readable in grey scale and by most colour-blind readers. Used
/// for the worst-case angular error arccos p_bar(a): low error dark, high error bright.
/// fraction is clamped to [0, 1]; NaN maps to 0.
Rgb value_colour(double fraction);

/// value_colour((value - lo) / (hi - lo)), with hi <= lo mapping everything to 0.
Rgb value_colour(double value, double lo, double hi);

/// Number of anchor colours of value_colour (linear interpolation between them).
inline constexpr int kValueColourAnchors = 9;

/// Colours of marked items, chosen to stay apart from every colour of value_colour.
inline constexpr Rgb kWorstViewpointColour{228, 26, 28};  ///< red: a global worst viewpoint
inline constexpr Rgb kPaperLmiColour{255, 0, 255};        ///< magenta: the paper's single LMI
inline constexpr Rgb kDataVectorColour{33, 33, 33};       ///< near black: vectors and markers
inline constexpr Rgb kThresholdColour{255, 255, 255};     ///< white: an error-threshold contour
inline constexpr Rgb kNormalColour{217, 95, 2};           ///< orange: a marker's outward normal
/// green: the worst viewpoint of a layout on its body (only the markers it sees), beside the red
/// one of the layout seen whole.
inline constexpr Rgb kBodyWorstViewpointColour{27, 140, 70};

}  // namespace vantage::plot
