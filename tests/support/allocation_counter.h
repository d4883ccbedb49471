#pragma once

/// Counts heap allocations made through the global operator new, to prove that hot paths
/// allocate nothing (STYLE.md 16). The replacement operators are defined once per test binary in
/// tests/<module>/allocation_counter_test.cc.

#include <cstddef>

namespace vantage::testing {

/// Number of calls to the global operator new (all forms) since the program started.
std::size_t allocation_count();

}  // namespace vantage::testing
