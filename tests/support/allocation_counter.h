#pragma once

/// Counts heap allocations, to prove that hot paths allocate nothing (STYLE.md 16). The counter
/// sees the global operator new family and malloc/calloc/realloc; its definition lives in
/// tests/analysis/allocation_counter_test.cc (one per test binary that links it).

namespace vantage::testing {

/// Counts the heap allocations made since it was constructed (from any thread). Counters nest:
/// each reports its own scope, and allocations made while no counter is alive are never counted.
class CountAllocations {
 public:
  CountAllocations();
  ~CountAllocations();
  CountAllocations(const CountAllocations&) = delete;
  CountAllocations& operator=(const CountAllocations&) = delete;

  long count() const;

 private:
  long start_;
};

}  // namespace vantage::testing
