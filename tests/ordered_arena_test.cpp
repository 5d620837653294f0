// OrderedArena: address order is allocation order, alignment holds, a full
// or unreservable arena gives nothing and the allocator falls back to
// operator new, and frees what is not the arena's.
#include "core/ordered_arena.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <map>
#include <vector>

namespace unfold {
namespace {

TEST(OrderedArena, HandsOutIncreasingAlignedAddresses) {
  OrderedArena arena(1 << 20);
  std::uintptr_t previous = 0;
  for (std::size_t bytes : {1, 3, 24, 7, 64, 5}) {
    for (std::size_t alignment : {1, 8, 16, 64}) {
      void* p = arena.allocate(bytes, alignment);
      ASSERT_NE(p, nullptr);
      const auto a = reinterpret_cast<std::uintptr_t>(p);
      EXPECT_EQ(a % alignment, 0u);
      EXPECT_GT(a, previous);
      EXPECT_TRUE(arena.owns(p));
      previous = a;
    }
  }
  int outside = 0;
  EXPECT_FALSE(arena.owns(&outside));
}

TEST(OrderedArena, AFullArenaGivesNothingAndTheAllocatorFallsBack) {
  OrderedArena arena(4096);
  EXPECT_NE(arena.allocate(4000, 8), nullptr);
  EXPECT_EQ(arena.allocate(200, 8), nullptr);
  OrderedArena unreservable(std::size_t(1) << 62);  // more than the address space
  EXPECT_EQ(unreservable.capacity(), 0u);
  EXPECT_EQ(unreservable.allocate(8, 8), nullptr);
  const OrderedArena::Scope scope(&arena);
  OrderedArenaAllocator<double> allocator;
  double* p = allocator.allocate(100);  // 800 bytes: no room left
  EXPECT_FALSE(arena.owns(p));
  p[99] = 1;
  allocator.deallocate(p, 100);  // operator delete's, under ASan a mismatch would show
}

TEST(OrderedArena, NodeContainersInAScopeAreOrderedByAllocation) {
  OrderedArena arena(1 << 24);
  const OrderedArena::Scope scope(&arena);
  EXPECT_EQ(OrderedArena::current(), &arena);
  std::vector<int*> made;
  {
    std::map<int, int, std::less<int>, OrderedArenaAllocator<std::pair<const int, int>>> m;
    for (int i = 0; i < 100; ++i) m[(i * 37) % 101] = i;
    OrderedArenaAllocator<int> allocator;
    for (int i = 0; i < 10; ++i) made.push_back(allocator.allocate(1));
    EXPECT_GT(arena.bytes_used(), 100 * sizeof(std::pair<const int, int>));
  }
  for (size_t k = 1; k < made.size(); ++k) EXPECT_LT(made[k - 1], made[k]);
  {
    const OrderedArena::Scope none(nullptr);
    EXPECT_EQ(OrderedArena::current(), nullptr);
  }
  EXPECT_EQ(OrderedArena::current(), &arena);
}

}  // namespace
}  // namespace unfold
