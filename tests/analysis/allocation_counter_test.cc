#include "support/allocation_counter.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <memory>
#include <new>

namespace {
std::atomic<std::size_t> g_allocations{0};

void* counted_allocation(std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* pointer = std::malloc(size == 0 ? 1 : size)) return pointer;
  throw std::bad_alloc();
}
}  // namespace

void* operator new(std::size_t size) { return counted_allocation(size); }
void* operator new[](std::size_t size) { return counted_allocation(size); }
void operator delete(void* pointer) noexcept { std::free(pointer); }
void operator delete[](void* pointer) noexcept { std::free(pointer); }
void operator delete(void* pointer, std::size_t) noexcept { std::free(pointer); }
void operator delete[](void* pointer, std::size_t) noexcept { std::free(pointer); }

namespace vantage::testing {

std::size_t allocation_count() { return g_allocations.load(std::memory_order_relaxed); }

namespace {

TEST(AllocationCounter, CountsHeapAllocations) {
  const std::size_t before = allocation_count();
  auto value = std::make_unique<int>(42);
  EXPECT_EQ(*value, 42);
  EXPECT_EQ(allocation_count() - before, 1u);
}

}  // namespace
}  // namespace vantage::testing
