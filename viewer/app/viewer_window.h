#pragma once

// The GLFW window, the ImGui frame loop and the screenshot of vantage-viewer.

#include <string>

#include "vantage/viewer/camera.h"
#include "vantage/viewer/viewer_session.h"

namespace vantage::viewer::app {

struct WindowOptions {
  int width = 1400;  ///< window size, pixels
  int height = 900;  ///< pixels
  ViewPreset view = ViewPreset::kIso;
  std::string screenshot_path;     ///< non-empty: save a PNG and exit (no mouse or keyboard input)
  int frames = 3;                  ///< screenshot: frames drawn after the analysis is current
  double timeout_seconds = 600.0;  ///< screenshot: longest wait for the analysis
};

/// Opens the window and runs until it is closed (or the screenshot is written). Returns the exit
/// status: 0 done, 1 no display / no OpenGL context / screenshot failed / analysis timed out.
int run_window(ViewerSession& session, const WindowOptions& options);

}  // namespace vantage::viewer::app
