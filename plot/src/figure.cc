#include "vantage/plot/figure.h"

#include "vantage/analysis/common.h"

namespace vantage::plot {

const char* to_string(Format format) {
  switch (format) {
    case Format::kPng:
      return "png";
    case Format::kSvg:
      return "svg";
    case Format::kPdf:
      return "pdf";
  }
  return "png";
}

Format parse_format(const std::string& name, const std::string& argument) {
  for (Format f : {Format::kPng, Format::kSvg, Format::kPdf}) {
    if (name == to_string(f)) return f;
  }
  throw InvalidArgument(argument + ": unknown format \"" + name + "\" (png, svg or pdf)");
}

FigureFiles figure_files(const std::string& name, const std::filesystem::path& directory,
                         Format format) {
  return {name, directory / (name + "." + to_string(format)), directory / (name + ".csv")};
}

bool FigureOptions::is_valid(std::string* why) const {
  auto fail = [why](const std::string& message) {
    if (why) *why = message;
    return false;
  };
  if (width < kMinFigureSide || width > kMaxFigureSide) {
    return fail("width must be in [" + std::to_string(kMinFigureSide) + ", " +
                std::to_string(kMaxFigureSide) + "], got " + std::to_string(width));
  }
  if (height < kMinFigureSide || height > kMaxFigureSide) {
    return fail("height must be in [" + std::to_string(kMinFigureSide) + ", " +
                std::to_string(kMaxFigureSide) + "], got " + std::to_string(height));
  }
  if (threads < 0) return fail("threads must be >= 0, got " + std::to_string(threads));
  return true;
}

}  // namespace vantage::plot
