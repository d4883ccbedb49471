#include "screenshot.h"

#include <GL/gl.h>
#include <stb_image_write.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace vantage::viewer::app {

bool save_framebuffer_png(const std::string& path, int width, int height) {
  if (width <= 0 || height <= 0) return false;
  std::vector<std::uint8_t> pixels(static_cast<std::size_t>(width) * height * 3);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_BACK);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, pixels.data());
  if (glGetError() != GL_NO_ERROR) return false;
  const std::size_t stride = static_cast<std::size_t>(width) * 3;
  // OpenGL's first row is the bottom one; PNG's is the top one.
  std::vector<std::uint8_t> flipped(pixels.size());
  for (int row = 0; row < height; ++row) {
    std::copy_n(pixels.data() + (height - 1 - row) * stride, stride, flipped.data() + row * stride);
  }
  return stbi_write_png(path.c_str(), width, height, 3, flipped.data(), static_cast<int>(stride)) !=
         0;
}

}  // namespace vantage::viewer::app
