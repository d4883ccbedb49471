#pragma once

/// Shared vocabulary of vantage: the error types, the invariant check and the one constant pi.
///
/// Three kinds of failure (STYLE.md 7):
///  - expected numerical outcomes (degenerate data, no convergence) are a Status in a result;
///  - bad caller input throws InvalidArgument "<arg>: <problem>" (see internal/checks.h);
///  - broken internal invariants throw vantage::InternalError through VANTAGE_CHECK, which stays
///    on in Release builds.

#include <stdexcept>
#include <string>

namespace vantage {

/// pi, the one definition every module uses (docs/math.md §1).
inline constexpr double kPi = 3.14159265358979323846;
/// Degrees per radian: an angle in radians times this is in degrees.
inline constexpr double kDegreesPerRadian = 180.0 / kPi;

/// Thrown when a caller passes input that violates a documented precondition.
class InvalidArgument : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

/// Thrown when an internal invariant does not hold (a bug in vantage, not in the input).
class InternalError : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

namespace internal {
[[noreturn]] void throw_check_failure(const char* condition, const char* file, int line,
                                      const std::string& message);
}  // namespace internal

}  // namespace vantage

/// Invariant check that is never compiled out. Throws vantage::InternalError.
#define VANTAGE_CHECK(condition, message)                                                  \
  do {                                                                                     \
    if (!(condition)) {                                                                    \
      ::vantage::internal::throw_check_failure(#condition, __FILE__, __LINE__, (message)); \
    }                                                                                      \
  } while (false)
