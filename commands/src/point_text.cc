#include "vantage/commands/point_text.h"

#include <sstream>

#include "vantage/analysis/common.h"

namespace vantage::commands {

Eigen::Vector3d parse_point(const std::string& text, const std::string& option) {
  std::istringstream in(text);
  Eigen::Vector3d x;
  char comma1 = 0, comma2 = 0;
  if (!(in >> x.x() >> comma1 >> x.y() >> comma2 >> x.z()) || comma1 != ',' || comma2 != ',' ||
      !(in >> std::ws).eof() || !x.allFinite()) {
    throw InvalidArgument(option, "expected X,Y,Z, three finite numbers, got \"" + text + "\"");
  }
  return x;
}

}  // namespace vantage::commands
