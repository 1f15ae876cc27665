// tests/support/allocation_counter.hpp — counts the process's global allocations, so a test can
// prove that a steady state allocates nothing (a warm cache hit, a second paint, a reused
// flattening).
//
// It REPLACES the global operator new and delete: include it from exactly one source file of a
// test executable (each *_test.cpp is its own executable), never from a header. The replacement
// pair is malloc/free on both sides; g++ 12 with the sanitizers inlines the two into a test's code
// and then warns that free() meets operator new's pointer (-Wmismatched-new-delete), wrongly: here
// that pairing is the definition.
#pragma once

#include <atomic>
#include <cstdlib>
#include <new>

#pragma GCC diagnostic ignored "-Wmismatched-new-delete"

namespace bezel::test {
// Allocations through the global operator new since the program started.
inline std::atomic<long> g_allocations{0};
}  // namespace bezel::test

void* operator new(std::size_t n) {
    bezel::test::g_allocations.fetch_add(1, std::memory_order_relaxed);
    if (void* p = std::malloc(n ? n : 1)) return p;
    throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
