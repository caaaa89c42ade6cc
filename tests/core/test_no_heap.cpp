// The observer tick must not touch the heap. This binary replaces the global
// operator new/delete and malloc/calloc/realloc/free with versions that count calls
// while armed; the test arms them around configure/reset/step and expects zero.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "hstmon/hstmon.hpp"

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

TEST(NoHeap, TrapWorks) {
  SKIP_WITHOUT_TRAP();
  long n;
  {
    Armed a;
    void* p = std::malloc(16);
    std::free(p);
    n = g_allocs;
  }
  EXPECT_EQ(n, 1);
}

template <typename Model>
long allocations_in_run() {
  using Obs = hstmon::Observer<Model>;
  Armed a;
  Obs o;
  typename Obs::Config c;
  c.tick = 1e-3f;
  c.gain(0, 0) = 0.1f;  // exercise the injection path too
  o.configure(Model{}, c);
  typename Model::Inputs u;
  typename Obs::Measurement m;
  m.valid = 0b1111;
  for (int i = 0; i < 5000; ++i) {
    m.y = o.estimate();
    o.step(u, m);
  }
  return g_allocs;
}

TEST(NoHeap, ThesisObserverStepDoesNotAllocate) {
  SKIP_WITHOUT_TRAP();
  EXPECT_EQ(allocations_in_run<hstmon::ThesisReducedModel<double>>(), 0);
  EXPECT_EQ(allocations_in_run<hstmon::ThesisReducedModel<float>>(), 0);
}

TEST(NoHeap, PaperObserverStepDoesNotAllocate) {
  SKIP_WITHOUT_TRAP();
  EXPECT_EQ(allocations_in_run<hstmon::PaperModel<double>>(), 0);
  EXPECT_EQ(allocations_in_run<hstmon::PaperModel<float>>(), 0);
}

TEST(NoHeap, SteadyStateSolveDoesNotAllocate) {
  SKIP_WITHOUT_TRAP();
  Armed a;
  hstmon::ThesisReducedModel<float> m;
  hstmon::ThesisReducedModel<float>::State x = hstmon::ThesisReducedModel<float>::State::Zero();
  EXPECT_TRUE(m.steady_state(x));
  EXPECT_EQ(g_allocs, 0);
}

}  // namespace
