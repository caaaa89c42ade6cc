#pragma once
// Heap trap for the allocation-free tests: replaces the global operator new/delete and
// malloc/calloc/realloc/free with versions that count calls while an `Armed` object is
// alive. Include from exactly one translation unit of a test binary (it defines the
// replacements).
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

// ASan owns malloc and operator new; under it the trap is not installed and the tests
// are skipped (the plain debug and release builds run them).
#if defined(__SANITIZE_ADDRESS__)
#define HSTMON_HEAP_TRAP 0
#else
#define HSTMON_HEAP_TRAP 1
#endif

#if HSTMON_HEAP_TRAP
extern "C" void* __libc_malloc(std::size_t);
extern "C" void* __libc_calloc(std::size_t, std::size_t);
extern "C" void* __libc_realloc(void*, std::size_t);
extern "C" void __libc_free(void*);

namespace {
std::atomic<bool> g_armed{false};
std::atomic<long> g_allocs{0};
void note() {
  if (g_armed.load(std::memory_order_relaxed)) g_allocs.fetch_add(1, std::memory_order_relaxed);
}
}  // namespace

extern "C" void* malloc(std::size_t n) {
  note();
  return __libc_malloc(n);
}
extern "C" void* calloc(std::size_t a, std::size_t b) {
  note();
  return __libc_calloc(a, b);
}
extern "C" void* realloc(void* p, std::size_t n) {
  note();
  return __libc_realloc(p, n);
}
extern "C" void free(void* p) { __libc_free(p); }
void* operator new(std::size_t n) {
  note();
  if (void* p = __libc_malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n) { return operator new(n); }
void operator delete(void* p) noexcept { __libc_free(p); }
void operator delete[](void* p) noexcept { __libc_free(p); }
void operator delete(void* p, std::size_t) noexcept { __libc_free(p); }
void operator delete[](void* p, std::size_t) noexcept { __libc_free(p); }
#else
namespace {
std::atomic<bool> g_armed{false};
std::atomic<long> g_allocs{0};
}  // namespace
#endif

namespace {

#define SKIP_WITHOUT_TRAP() \
  if (!HSTMON_HEAP_TRAP) GTEST_SKIP() << "heap trap not installed under ASan"

struct Armed {
  Armed() {
    g_allocs = 0;
    g_armed = true;
  }
  ~Armed() { g_armed = false; }
};

/// The trap's own check: one malloc/free while armed, the count it gives (1 when it works).
inline long allocations_of_one_malloc() {
  Armed a;
  void* p = std::malloc(16);
  std::free(p);
  return g_allocs;
}

/// The workload armed around an observer: `ticks` steps of a configured observer, each on
/// its own estimate as the measurement (every channel valid), as on a quiet machine.
template <typename Obs, typename Inputs>
void step_on_own_estimate(Obs& o, const Inputs& u, int ticks) {
  typename Obs::Measurement y;
  y.valid = 0x0f;
  for (int k = 0; k < ticks; ++k) {
    y.y = o.estimate();
    o.step(u, y);
  }
}

}  // namespace
