#pragma once

#include <string>

namespace vantage::viewer::app {

/// Reads the current OpenGL back buffer (width x height pixels) and writes it to `path` as an
/// RGB PNG (stb_image_write), top row first. False when reading or writing fails.
bool save_framebuffer_png(const std::string& path, int width, int height);

}  // namespace vantage::viewer::app
