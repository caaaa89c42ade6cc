// The observer tick must not touch the heap: the trap of tests/support/heap_trap.hpp is
// armed around configure/reset/step and must count zero allocations.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "hstmon/hstmon.hpp"
#include "../support/heap_trap.hpp"

namespace {

TEST(NoHeap, TrapWorks) {
  SKIP_WITHOUT_TRAP();
  EXPECT_EQ(allocations_of_one_malloc(), 1);
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
  step_on_own_estimate(o, u, 5000);
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
