// The one definition of the allocation counter of tests/support/allocation_counter.h for the
// analysis test binary: the replaceable global operator new/delete family, and malloc, calloc
// and realloc wrapped at link time (-Wl,--wrap, set in tests/CMakeLists.txt when the linker has
// it) so that Eigen's own allocations are seen too. Counting happens only inside a CountAllocations
// scope; the replacements always forward to malloc/free, so the sanitizers still see every
// allocation.

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <atomic>
#include <cstdlib>
#include <memory>
#include <new>
#include <vector>

#include "support/allocation_counter.h"

namespace {

// Live CountAllocations objects, and the allocations made while at least one was alive (never
// reset: each counter reports the difference since its construction).
std::atomic<int> g_live_counters{0};
std::atomic<long> g_allocations{0};

void note_allocation() {
  if (g_live_counters.load(std::memory_order_relaxed) > 0) g_allocations.fetch_add(1);
}

void* counted_new(std::size_t size) {
  note_allocation();
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}

void* counted_aligned_new(std::size_t size, std::align_val_t alignment) {
  note_allocation();
  const std::size_t align = static_cast<std::size_t>(alignment);
  const std::size_t rounded = (size + align - 1) / align * align;
  if (void* p = std::aligned_alloc(align, rounded == 0 ? align : rounded)) return p;
  throw std::bad_alloc();
}

}  // namespace

// The replaceable global allocation functions ([new.delete]), all forwarding to malloc/free.
void* operator new(std::size_t size) { return counted_new(size); }
void* operator new[](std::size_t size) { return counted_new(size); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  note_allocation();
  return std::malloc(size == 0 ? 1 : size);
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
  note_allocation();
  return std::malloc(size == 0 ? 1 : size);
}
void* operator new(std::size_t size, std::align_val_t alignment) {
  return counted_aligned_new(size, alignment);
}
void* operator new[](std::size_t size, std::align_val_t alignment) {
  return counted_aligned_new(size, alignment);
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }

#if defined(VANTAGE_COUNTS_MALLOC)
// malloc and friends, wrapped by the linker (-Wl,--wrap=malloc etc., tests/CMakeLists.txt, when
// the linker has --wrap): calls from this binary's own objects and static libraries
// (vantage::analysis, so Eigen's aligned_malloc) land here.
extern "C" {
void* __real_malloc(std::size_t size);
void* __real_calloc(std::size_t count, std::size_t size);
void* __real_realloc(void* p, std::size_t size);
void* __wrap_malloc(std::size_t size) {
  note_allocation();
  return __real_malloc(size);
}
void* __wrap_calloc(std::size_t count, std::size_t size) {
  note_allocation();
  return __real_calloc(count, size);
}
void* __wrap_realloc(void* p, std::size_t size) {
  note_allocation();
  return __real_realloc(p, size);
}
}
#endif

namespace vantage::testing {

CountAllocations::CountAllocations() : start_(g_allocations.load()) { ++g_live_counters; }

CountAllocations::~CountAllocations() { --g_live_counters; }

long CountAllocations::count() const { return g_allocations.load() - start_; }

namespace {

TEST(AllocationCounter, SeesOperatorNewAndMalloc) {
  CountAllocations counter;
  auto value = std::make_unique<int>(42);
  std::vector<double> values(10, 1.0);
  const long after_new = counter.count();
  EXPECT_GE(after_new, 2);
  Eigen::MatrixXd matrix = Eigen::MatrixXd::Ones(4, 4);  // Eigen's aligned_malloc calls malloc
  EXPECT_EQ(*value + static_cast<int>(values.size() + matrix.size()), 68);
#if defined(VANTAGE_COUNTS_MALLOC)
  EXPECT_GT(counter.count(), after_new);
#endif
}

TEST(AllocationCounter, CountsNothingOutsideItsScope) {
  // An outer counter sees three allocations; the inner one, alive for the middle one only, must
  // count exactly that one: not the allocation before it was made (no stale count), and its end
  // must not stop the outer counter (the allocation after it is still seen).
  long per_allocation = 0;  // operator new may also pass through the wrapped malloc
  {
    CountAllocations probe;
    auto one = std::make_unique<int>(0);
    per_allocation = probe.count();
    EXPECT_EQ(*one, 0);
  }
  ASSERT_GE(per_allocation, 1);
  CountAllocations outer;
  auto before = std::make_unique<int>(1);
  long inner_count = -1;
  {
    CountAllocations inner;
    auto during = std::make_unique<int>(2);
    inner_count = inner.count();
    EXPECT_EQ(*during, 2);
  }
  auto after = std::make_unique<int>(3);
  const long outer_count = outer.count();
  EXPECT_EQ(inner_count, per_allocation);
  EXPECT_GE(outer_count, 3 * per_allocation);
  EXPECT_EQ(*before + *after, 4);
}

}  // namespace
}  // namespace vantage::testing
