#include "core/ordered_arena.h"

#include <sys/mman.h>

#include <cstdint>

namespace unfold {
namespace {
thread_local OrderedArena* current_arena = nullptr;
}  // namespace

OrderedArena::OrderedArena(std::size_t reserve_bytes) {
  // MAP_NORESERVE: address space only; the kernel backs pages on first write.
  void* p = mmap(nullptr, reserve_bytes, PROT_READ | PROT_WRITE,
                 MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
  if (p == MAP_FAILED) return;
  begin_ = next_ = static_cast<char*>(p);
  end_ = begin_ + reserve_bytes;
}

OrderedArena::~OrderedArena() {
  if (begin_) munmap(begin_, capacity());
}

void* OrderedArena::allocate(std::size_t bytes, std::size_t alignment) {
  const std::uintptr_t at =
      (reinterpret_cast<std::uintptr_t>(next_) + alignment - 1) & ~std::uintptr_t(alignment - 1);
  char* p = reinterpret_cast<char*>(at);
  if (!begin_ || p > end_ || bytes > std::size_t(end_ - p)) return nullptr;
  next_ = p + bytes;
  return p;
}

bool OrderedArena::owns(const void* p) const {
  const char* c = static_cast<const char*>(p);
  return c >= begin_ && c < end_;
}

OrderedArena* OrderedArena::current() { return current_arena; }

OrderedArena::Scope::Scope(OrderedArena* arena) : previous_(current_arena) {
  current_arena = arena;
}

OrderedArena::Scope::~Scope() { current_arena = previous_; }

}  // namespace unfold
