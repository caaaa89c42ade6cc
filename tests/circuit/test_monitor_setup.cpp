// circuit/monitor_setup.hpp, the settings the host circuit replay and the firmware's
// circuit monitor both derive: a sensor's σ, the matcher's windows from the slowest time
// constant, and the start at the steady state when the first row reads it within noise.
// On the committed paper circuit header (what the firmware image runs), in double.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "hstmon/circuit/engine.hpp"
#include "hstmon/circuit/monitor_setup.hpp"
#include "hstmon/fault_matcher.hpp"
#include "hstmon/generated/paper_circuit.hpp"

namespace {

namespace gen = hstmon::generated::paper_circuit;
namespace circuit = hstmon::circuit;
using Model = circuit::CircuitModel<double, gen::Cap>;

Model paper_model() {
  Model::Params p;
  for (int i = 0; i < gen::Cap::kParams; ++i) p.v[i] = gen::kParams[i];
  Model::Inputs u;
  for (int i = 0; i < gen::Cap::kInputs; ++i) u.v[i] = gen::kInputs[i];
  return Model(gen::kCircuit, p, u);
}

Model::Inputs nominal() {
  Model::Inputs u;
  for (int i = 0; i < gen::Cap::kInputs; ++i) u.v[i] = gen::kInputs[i];
  return u;
}

TEST(MonitorSetup, SensorSigmaIsTheStatedNoiseElseOnePercentOfTheRange) {
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(circuit::sensor_sigma(5e3, 0.0, 250e5), 5e3);
  EXPECT_DOUBLE_EQ(circuit::sensor_sigma(0.0, 0.0, 250e5), 250e3);
  EXPECT_DOUBLE_EQ(circuit::sensor_sigma(std::nan(""), 0.0, 250e5), 250e3);
  EXPECT_DOUBLE_EQ(circuit::sensor_sigma(0.0, -inf, inf), 1.0);  // unbounded: 1 % of 100
}

TEST(MonitorSetup, StartsAtSteadyStateOnlyWhenEveryChannelReadsItWithinThreeSigma) {
  Model m = paper_model();
  Model::State xs;
  ASSERT_TRUE(m.steady_state(xs));
  Model::Output y = m.outputs(xs);
  double noise[gen::Cap::kChannels];
  for (int ch = 0; ch < gen::Cap::kChannels; ++ch) noise[ch] = gen::kNoiseSigma[ch];
  const int n = gen::kCircuit.n_channels;
  const unsigned all = (1u << n) - 1u;
  Model scratch = paper_model();
  EXPECT_TRUE(circuit::at_steady_within_noise(scratch, nominal(), y, all, noise, n));
  y[1] += 2.9 * noise[1];
  EXPECT_TRUE(circuit::at_steady_within_noise(scratch, nominal(), y, all, noise, n));
  y[1] += 0.2 * noise[1];  // 3.1 σ off
  EXPECT_FALSE(circuit::at_steady_within_noise(scratch, nominal(), y, all, noise, n));
  y = m.outputs(xs);
  EXPECT_FALSE(circuit::at_steady_within_noise(scratch, nominal(), y, all & ~2u, noise, n));  // a channel unread
  noise[0] = 0.0;  // no stated noise: no claim of being within it
  EXPECT_FALSE(circuit::at_steady_within_noise(scratch, nominal(), y, all, noise, n));
}

}  // namespace
