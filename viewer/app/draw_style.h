#pragma once

// Colours, sizes and fonts of vantage-viewer's drawing. Value and marker colours come from
// vantage/plot/colormap.h so that the sphere matches `vantage plot`'s viewpoint map.

#include <imgui.h>

#include "vantage/plot/colormap.h"

namespace vantage::viewer::app {

inline ImU32 to_imgui(const plot::Rgb& c, int alpha = 255) {
  return IM_COL32(c.r, c.g, c.b, alpha);
}

/// c scaled by `light` in [0, 1] (a mild shade for depth), alpha 255.
inline ImU32 shaded(const plot::Rgb& c, double light) {
  return IM_COL32(static_cast<int>(c.r * light), static_cast<int>(c.g * light),
                  static_cast<int>(c.b * light), 255);
}

inline constexpr ImU32 kBackground = IM_COL32(28, 30, 36, 255);
inline constexpr ImU32 kHalo = IM_COL32(245, 245, 245, 235);
inline constexpr ImU32 kAxisGrey = IM_COL32(150, 150, 160, 255);
inline constexpr ImU32 kProbeColour = IM_COL32(255, 255, 255, 255);
inline constexpr ImU32 kSelectedColour = IM_COL32(255, 170, 0, 255);
inline constexpr ImU32 kWarningText = IM_COL32(255, 190, 60, 255);
inline constexpr ImU32 kErrorText = IM_COL32(255, 110, 100, 255);

// Markers on a body (docs/math.md §20): the lost viewpoints and the hidden markers are grey,
// apart from the viridis values of the sphere; the body is a translucent blue-grey.
inline constexpr plot::Rgb kLostGrey{150, 150, 150};  ///< untrackable viewpoints
inline constexpr plot::Rgb kOutsideGrey{78, 78, 84};  ///< viewpoints outside the workspace
inline constexpr ImU32 kHiddenMarker = IM_COL32(128, 128, 134, 255);
inline constexpr ImU32 kHiddenNormal = IM_COL32(100, 100, 106, 255);
inline constexpr ImU32 kNormalColour = IM_COL32(90, 200, 255, 255);
inline constexpr plot::Rgb kBodyColour{150, 165, 195};
inline constexpr int kBodyAlpha = 70;
inline constexpr ImU32 kBodyEdge = IM_COL32(175, 190, 215, 150);

/// c scaled by `light` in [0, 1], with `alpha`.
inline ImU32 with_light(const plot::Rgb& c, double light, int alpha) {
  return IM_COL32(static_cast<int>(c.r * light), static_cast<int>(c.g * light),
                  static_cast<int>(c.b * light), alpha);
}

inline constexpr float kFontSize = 16.0f;

/// Loads DejaVu Sans (Latin, Greek, a few math signs) when installed, else ImGui's default font,
/// and applies the dark style.
void setup_fonts_and_style();

}  // namespace vantage::viewer::app
