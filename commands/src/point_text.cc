#include "vantage/commands/point_text.h"

#include <cmath>
#include <cstdlib>

#include "vantage/analysis/common.h"
#include "vantage/analysis/scaling.h"

namespace vantage::commands {

std::optional<std::vector<double>> parse_numbers(const std::string& text) {
  std::vector<double> out;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    std::string field =
        text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    // Blanks around a number are allowed ("0, 0, -3"), as the stream parsers before allowed them.
    const std::size_t first = field.find_first_not_of(" \t");
    if (first == std::string::npos) return std::nullopt;
    field = field.substr(first, field.find_last_not_of(" \t") - first + 1);
    // Decimal notation only: strtod also reads hexadecimal ("0x1p3"), "inf" and "nan".
    if (field.find_first_not_of("0123456789+-.eE") != std::string::npos) return std::nullopt;
    char* end = nullptr;
    const double value = std::strtod(field.c_str(), &end);
    if (end != field.c_str() + field.size() || !std::isfinite(value)) return std::nullopt;
    out.push_back(value);
    if (comma == std::string::npos) return out;
    start = comma + 1;
  }
}

Eigen::Vector3d parse_point(const std::string& text, const std::string& option) {
  const std::optional<std::vector<double>> x = parse_numbers(text);
  if (!x || x->size() != 3) {
    throw InvalidArgument(option, "expected X,Y,Z, three finite numbers, got \"" + text + "\"");
  }
  return Eigen::Vector3d((*x)[0], (*x)[1], (*x)[2]);
}

Eigen::Vector3d parse_direction(const std::string& text, const std::string& option) {
  const std::optional<std::vector<double>> x = parse_numbers(text);
  const Eigen::Vector3d a = x && x->size() == 3
                                ? unit_direction(Eigen::Vector3d((*x)[0], (*x)[1], (*x)[2]))
                                : Eigen::Vector3d::Zero();
  if (a.isZero()) {
    throw InvalidArgument(
        option, "expected AX,AY,AZ, three finite numbers not all 0, got \"" + text + "\"");
  }
  return a;
}

}  // namespace vantage::commands
