// The engine's tick, the quasi-steady solve and the steady-state solve never touch the
// heap: the trap of tests/support/heap_trap.hpp is armed around an observer on each
// shipped circuit (the circuit files themselves are read before, on the host).
#include <gtest/gtest.h>

#include "../support/heap_trap.hpp"
#include "circuit_fixture.hpp"
#include "hstmon/observer.hpp"

namespace {

template <typename T>
long allocations(const circuit_test::Loaded& l) {
  using M = hstmon::circuit::CircuitModel<T, hstmon::circuit::HostCapacity>;
  typename M::Params p;
  typename M::Inputs u;
  for (int i = 0; i < hstmon::circuit::HostCapacity::kParams; ++i) p.v[i] = static_cast<T>(l.values.params.v[i]);
  for (int i = 0; i < hstmon::circuit::HostCapacity::kInputs; ++i) u.v[i] = static_cast<T>(l.values.inputs.v[i]);
  Armed a;
  M m(l.file.circuit, p, u);
  hstmon::Observer<M, false> o;
  typename hstmon::Observer<M, false>::Config cfg;
  cfg.tick = T(1e-3);
  cfg.gain(0, 0) = T(0.01);  // the injection path too
  o.configure(m, cfg);
  o.reset_steady(u);
  o.reset_rest(u);
  step_on_own_estimate(o, u, 500);
  return g_allocs;
}

TEST(CircuitNoHeap, ObserverOnEveryShippedCircuit) {
  SKIP_WITHOUT_TRAP();
  for (const char* name : {"thesis", "paper", "closed_loop_hst", "test_stand"}) {
    const circuit_test::Loaded l = circuit_test::load(name, 1e-3);
    ASSERT_TRUE(l.ok);
    EXPECT_EQ(allocations<double>(l), 0) << name;
    EXPECT_EQ(allocations<float>(l), 0) << name << " (float)";
  }
}

}  // namespace
