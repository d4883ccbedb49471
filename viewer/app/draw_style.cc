#include "draw_style.h"

#include <filesystem>

namespace vantage::viewer::app {

void setup_fonts_and_style() {
  ImGuiIO& io = ImGui::GetIO();
  static const ImWchar kRanges[] = {
      0x0020, 0x00FF,  // Latin-1: degree sign
      0x0300, 0x036F,  // combining marks: the bar of p-bar
      0x0370, 0x03FF,  // Greek: theta, pi
      0x2026, 0x2026,  // ellipsis
      0x2190, 0x2193,  // arrows
      0x2208, 0x2208,  // element of
      0x2264, 0x2265,  // <= >=
      0x22A5, 0x22A5,  // up tack (perpendicular)
      0,
  };
  const char* kFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
  std::error_code ec;
  if (!std::filesystem::exists(kFont, ec) ||
      io.Fonts->AddFontFromFileTTF(kFont, kFontSize, nullptr, kRanges) == nullptr) {
    io.Fonts->AddFontDefault();
  }
  ImGui::StyleColorsDark();
  ImGuiStyle& style = ImGui::GetStyle();
  style.WindowRounding = 4.0f;
  style.FrameRounding = 3.0f;
  style.WindowPadding = ImVec2(10, 8);
  style.ItemSpacing = ImVec2(8, 5);
  style.Colors[ImGuiCol_WindowBg].w = 0.96f;
}

}  // namespace vantage::viewer::app
