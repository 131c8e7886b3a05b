// A replaced global operator new that counts allocations while counting is
// on (include in exactly one TU of a test executable).
#pragma once

// The replacement delete frees what the replacement new malloc'ed; g++ cannot
// see that pairing through inlining and warns, hence the pragma (as in
// sat_traversal_test.cpp).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif

#include <atomic>
#include <cstdlib>
#include <new>

namespace sepax::test {
inline std::atomic<bool> g_count_allocations{false};
inline std::atomic<long> g_allocations{0};

/// Counts the allocations made while f runs.
template <class F>
long count_allocations(F&& f) {
  g_allocations = 0;
  g_count_allocations = true;
  f();
  g_count_allocations = false;
  return g_allocations.load();
}
}  // namespace sepax::test

void* operator new(std::size_t n) {
  if (sepax::test::g_count_allocations.load(std::memory_order_relaxed)) ++sepax::test::g_allocations;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n) { return ::operator new(n); }
// The nothrow forms too (Catch2 uses them): every delete below frees with
// std::free, so every new must malloc.
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  try {
    return ::operator new(n);
  } catch (...) {
    return nullptr;
  }
}
void* operator new[](std::size_t n, const std::nothrow_t& t) noexcept { return ::operator new(n, t); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
