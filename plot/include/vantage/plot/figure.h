#pragma once

/// What every figure of vantage::plot shares: the output format, the options, the files written
/// and the error a failed rendering throws.
///
/// Figures are drawn with PLplot (its C++ stream, the extcairo driver) on a cairo surface of the
/// requested format: PNG, SVG and PDF come from one code path. Each figure writes `<name>.<ext>`
/// and `<name>.csv` (a header line, then the numbers the figure draws) into an existing
/// directory; each file is written under a temporary name and renamed into place when complete,
/// so a failure leaves no partial file. PLplot's and cairo's own messages never reach the
/// terminal.

#include <filesystem>
#include <stdexcept>
#include <string>

namespace vantage::plot {

/// Image format of a figure.
enum class Format { kPng, kSvg, kPdf };

/// "png", "svg" or "pdf" (also the file extension).
const char* to_string(Format format);

/// The format named "png", "svg" or "pdf". Throws InvalidArgument naming `argument` otherwise.
Format parse_format(const std::string& name, const std::string& argument = "format");

/// Options shared by every figure.
struct FigureOptions {
  int width = 1000;  ///< pixels (PNG) or points (SVG, PDF), in [200, 8000]
  int height = 800;  ///< pixels (PNG) or points (SVG, PDF), in [200, 8000]
  Format format = Format::kPng;
  std::string title;  ///< replaces the figure's own title when non-empty
  int threads = 0;    ///< threads for sampling; 0 = all cores, >= 0

  /// True when every field is in range; otherwise *why names the field and the constraint.
  bool is_valid(std::string* why = nullptr) const;
};

/// Smallest and largest accepted width or height.
inline constexpr int kMinFigureSide = 200;
inline constexpr int kMaxFigureSide = 8000;

/// The files one figure wrote.
struct FigureFiles {
  std::string name;             ///< "viewpoint_map", "dropout", ...
  std::filesystem::path image;  ///< <directory>/<name>.<png|svg|pdf>
  std::filesystem::path csv;    ///< <directory>/<name>.csv
};

/// The files of figure `name` in `directory`: <name>.<png|svg|pdf> and <name>.csv.
FigureFiles figure_files(const std::string& name, const std::filesystem::path& directory,
                         Format format);

/// A figure could not be rendered or written (disk full, unwritable file, missing PLplot driver,
/// PLplot error). Bad caller input throws vantage::InvalidArgument instead.
class RenderError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace vantage::plot
