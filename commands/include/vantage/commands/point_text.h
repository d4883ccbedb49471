#pragma once

// Numbers as the front ends type them: "X,Y,Z" (crb and place --aim, tre --target), a direction
// "AX,AY,AZ" (crb, tre --direction, simulate --viewpoint) and the numbers of a comma list
// (--workspace AX,AY,AZ,DEG). Every finite double is accepted, subnormal ones included, and a
// direction is normalised by its own scale (vantage::unit_direction), as files and Python are.

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

namespace vantage::commands {

/// The comma-separated numbers of `text`, each a whole field in decimal notation ("-1.5e3";
/// not hexadecimal, "inf" or "nan") and finite (an underflow to a subnormal or to 0 is the
/// correctly rounded value and is kept); nullopt otherwise.
std::optional<std::vector<double>> parse_numbers(const std::string& text);

/// "X,Y,Z", three finite numbers; InvalidArgument naming `option` otherwise.
Eigen::Vector3d parse_point(const std::string& text, const std::string& option);

/// "AX,AY,AZ", three finite numbers not all 0, as a unit vector (1e-300 or 1e300 long alike);
/// InvalidArgument naming `option` otherwise.
Eigen::Vector3d parse_direction(const std::string& text, const std::string& option);

}  // namespace vantage::commands
