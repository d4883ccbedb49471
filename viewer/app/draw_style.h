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

inline constexpr float kFontSize = 16.0f;

/// Loads DejaVu Sans (Latin, Greek, a few math signs) when installed, else ImGui's default font,
/// and applies the dark style.
void setup_fonts_and_style();

}  // namespace vantage::viewer::app
