// The one definition of the allocation counter of tests/support/allocation_counter.h for the
// analysis test binary: the replaceable global operator new/delete family, and malloc, calloc
// and realloc wrapped at link time (-Wl,--wrap, set in tests/CMakeLists.txt) so that Eigen's
// own allocations are seen too. Counting happens only inside a CountAllocations scope; the
// replacements always forward to malloc/free, so the sanitizers still see every allocation.

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <atomic>
#include <cstdlib>
#include <memory>
#include <new>
#include <vector>

#include "support/allocation_counter.h"

namespace {

std::atomic<bool> g_counting{false};
std::atomic<long> g_allocations{0};

void note_allocation() {
  if (g_counting.load(std::memory_order_relaxed)) g_allocations.fetch_add(1);
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

// malloc and friends, wrapped by the linker (-Wl,--wrap=malloc etc.): calls from this binary's
// own objects and static libraries (vantage::analysis, so Eigen's aligned_malloc) land here.
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

namespace vantage::testing {

CountAllocations::CountAllocations() {
  g_allocations = 0;
  g_counting = true;
}

CountAllocations::~CountAllocations() { g_counting = false; }

long CountAllocations::count() const { return g_allocations.load(); }

namespace {

TEST(AllocationCounter, SeesOperatorNewAndMalloc) {
  CountAllocations counter;
  auto value = std::make_unique<int>(42);
  std::vector<double> values(10, 1.0);
  Eigen::MatrixXd matrix = Eigen::MatrixXd::Ones(4, 4);
  EXPECT_EQ(*value + static_cast<int>(values.size() + matrix.size()), 68);
  EXPECT_GE(counter.count(), 3);
}

TEST(AllocationCounter, CountsNothingOutsideItsScope) {
  long count = 0;
  {
    CountAllocations counter;
    count = counter.count();
  }
  auto value = std::make_unique<int>(1);
  EXPECT_EQ(count, 0);
  EXPECT_EQ(*value, 1);
}

}  // namespace
}  // namespace vantage::testing
