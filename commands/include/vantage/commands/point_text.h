#pragma once

// A point as the front ends type it: "X,Y,Z" (crb and place --aim, tre --target).

#include <Eigen/Core>
#include <string>

namespace vantage::commands {

/// "X,Y,Z", three finite numbers; InvalidArgument naming `option` otherwise.
Eigen::Vector3d parse_point(const std::string& text, const std::string& option);

}  // namespace vantage::commands
