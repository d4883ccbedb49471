#pragma once

/// A library call on data read from a file, its errors reported against that file.

#include <string>

#include "vantage/analysis/common.h"

namespace vantage::commands {

/// Runs a library call on data read from `source`; its InvalidArgument (too few points,
/// coincident points, ...) is reported against the file: the same error, with the file as its
/// source. The library names the fields as the file does, so nothing is renamed.
template <typename Call>
auto against_source(const std::string& source, Call&& call) {
  try {
    return call();
  } catch (const InvalidArgument& e) {
    throw e.against(source);
  }
}

}  // namespace vantage::commands
