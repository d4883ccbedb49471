#pragma once

/// message_of(call): what a bad-input test asserts on. Runs `call` and returns the message of the
/// vantage::InvalidArgument it throws, or "no exception" when it throws none (so that a
/// HasSubstr(...) on the result fails loudly instead of matching an empty string). Any other
/// exception propagates and fails the test.

#include <string>
#include <utility>

#include "vantage/analysis/common.h"

namespace vantage::testing {

template <typename Call>
std::string message_of(Call&& call) {
  try {
    std::forward<Call>(call)();
  } catch (const InvalidArgument& error) {
    return error.what();
  }
  return "no exception";
}

}  // namespace vantage::testing
