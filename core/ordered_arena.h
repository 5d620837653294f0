// Memory handed out at increasing addresses from one reserved range. Some
// libraries order containers by the address of what they hold (CGAL's
// halfedge handles in a std::set decide the order of its skeletonization's
// edge collapses); with malloc's addresses, which depend on address-space
// randomisation, the same input then gives a different result on every run.
// Allocated from an arena, address order is allocation order: the same on
// every run. Nothing is returned to the arena before it is destroyed.
#pragma once

#include <cstddef>
#include <memory>
#include <new>

namespace unfold {

class OrderedArena {
 public:
  /// Reserves reserve_bytes of address space (not memory: pages are taken as
  /// they are first written). Where it cannot be reserved (a limit on the
  /// address space, ulimit -v) the arena has capacity 0 and gives nothing.
  explicit OrderedArena(std::size_t reserve_bytes);
  ~OrderedArena();
  OrderedArena(const OrderedArena&) = delete;
  OrderedArena& operator=(const OrderedArena&) = delete;

  /// The next bytes aligned to alignment (a power of two), or nullptr when
  /// the reserved range is used up.
  void* allocate(std::size_t bytes, std::size_t alignment);
  bool owns(const void* p) const;
  std::size_t bytes_used() const { return std::size_t(next_ - begin_); }
  std::size_t capacity() const { return std::size_t(end_ - begin_); }

  /// The arena this thread allocates from (OrderedArenaAllocator), or nullptr.
  static OrderedArena* current();

  /// Makes an arena this thread's current one for the scope's lifetime.
  class Scope {
   public:
    explicit Scope(OrderedArena* arena);
    ~Scope();
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

   private:
    OrderedArena* previous_;
  };

 private:
  char* begin_ = nullptr;
  char* next_ = nullptr;
  char* end_ = nullptr;
};

/// A standard allocator that takes memory from the thread's current
/// OrderedArena, and from operator new when there is none or it is full;
/// memory from an arena is freed with it.
template <class T>
struct OrderedArenaAllocator {
  using value_type = T;
  OrderedArenaAllocator() = default;
  template <class U>
  OrderedArenaAllocator(const OrderedArenaAllocator<U>&) {}
  template <class U>
  struct rebind {
    using other = OrderedArenaAllocator<U>;
  };

  T* allocate(std::size_t n) {
    if (OrderedArena* arena = OrderedArena::current())
      if (void* p = arena->allocate(n * sizeof(T), alignof(T))) return static_cast<T*>(p);
    return std::allocator<T>().allocate(n);
  }
  void deallocate(T* p, std::size_t n) {
    if (OrderedArena* arena = OrderedArena::current(); arena && arena->owns(p)) return;
    std::allocator<T>().deallocate(p, n);
  }
  template <class U>
  bool operator==(const OrderedArenaAllocator<U>&) const {
    return true;
  }
  template <class U>
  bool operator!=(const OrderedArenaAllocator<U>&) const {
    return false;
  }
};

}  // namespace unfold
