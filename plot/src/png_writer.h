#pragma once

// PNG encoding of a cairo RGB24 image surface with fast settings (zlib level 1, the Sub filter):
// cairo_surface_write_to_png compresses at libpng's defaults, which cost most of the time of a
// figure. Private to vantage::plot.

#include <cairo.h>

#include "output_file.h"

namespace vantage::plot::internal {

/// Writes the surface (CAIRO_FORMAT_RGB24) as an 8-bit RGB PNG to `file`. Returns false on a
/// libpng error.
bool write_png(cairo_surface_t* surface, OutputFile& file);

}  // namespace vantage::plot::internal
