// The matcher tick must not touch the heap: evaluator, sensor check and matcher run a
// fault episode (detection, isolation, sensor flags, cleared) under the allocation trap of
// tests/support/heap_trap.hpp, in float and double, on a constexpr table.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <new>

#include "hstmon/hstmon.hpp"
#include "../support/heap_trap.hpp"
#include "test_table.hpp"

namespace {

TEST(MatcherNoHeap, TrapWorks) {
  SKIP_WITHOUT_TRAP();
  EXPECT_EQ(allocations_of_one_malloc(), 1);
}

template <typename T>
long allocations_in_episode(int& events) {
  Armed a;
  hstmon::ResidualEvaluator<T> ev;
  hstmon::SensorCheck<T> sc;
  hstmon::FaultMatcher<T> m;
  if (m.configure(hstmon_test::kTestTable, hstmon_test::kTestTableCount, {}) != hstmon::Status::kOk) return -1;
  hstmon::ThesisReducedModel<T> model;
  T bound[4];
  if (hstmon::thesis_model_bound(model, hstmon::ThesisUncertainty<T>{}, bound) != hstmon::Status::kOk) return -1;
  ev.set_model_bound(bound);
  const T dev[4] = {T(24.9), T(-24.9), T(1114), T(-1409)};
  unsigned lcg = 1;
  typename hstmon::FaultMatcher<T>::Event e;
  events = 0;
  for (int k = 0; k < 6000; ++k) {
    const T t = static_cast<T>(k) * T(1e-3);
    T r[4], y[4];
    for (int i = 0; i < 4; ++i) {
      lcg = lcg * 1664525u + 1013904223u;
      const T noise = static_cast<T>(lcg >> 8) / T(16777216) - T(0.5);
      const T fault = (k >= 1000 && k < 2000) ? dev[i] : T(0);
      r[i] = ev.sigma(i) * (noise + fault);
      y[i] = (i == 3 ? T(100) : T(1e6)) + r[i];  // a raw value that moves with the noise
    }
    if (k >= 3500 && k < 3700) y[2] = T(NAN);  // a sensor episode
    ev.update(r, 0xF);
    m.update(t, ev, sc.update(t, y, 0xF));
    while (m.pop_event(e)) {
      ++events;
      if (std::getenv("HSTMON_DEBUG_EVENTS")) std::printf("%d %s %.3f\n", static_cast<int>(sizeof(T)), hstmon::to_string(e.kind), static_cast<double>(e.time));
    }
  }
  return g_allocs;
}

TEST(MatcherNoHeap, EpisodeDoesNotAllocate) {
  SKIP_WITHOUT_TRAP();
  int events_d = 0, events_f = 0;
  EXPECT_EQ(allocations_in_episode<double>(events_d), 0);
  EXPECT_EQ(allocations_in_episode<float>(events_f), 0);
  EXPECT_GE(events_d, 4);  // detected, isolated, cleared, detected (+ isolated, cleared)
  EXPECT_GE(events_f, 4);
}

}  // namespace
