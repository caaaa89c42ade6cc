// The committed firmware header of thesis.json (lib/include/hstmon/generated/
// thesis_circuit.hpp) is the circuit file: the same description, values, sensors and
// names as circuit_tools::load_circuit gives, the stiff mask of the host replay at 1 ms,
// and in float the same model bit for bit (steady state, evaluations, an observer run)
// as the engine on the loaded file at the host's capacity.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <tuple>

#include "hstmon/circuit/engine.hpp"
#include "hstmon/generated/thesis_circuit.hpp"
#include "hstmon/observer.hpp"
#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_host/circuit_units.hpp"

namespace {

namespace gen = hstmon::generated::thesis_circuit;
namespace circuit = hstmon::circuit;
using HostCap = hstmon::host::CircuitCap;
using FwModel = circuit::CircuitModel<float, gen::Cap>;
using HostModel = circuit::CircuitModel<float, HostCap>;

bool same_ref(circuit::Ref a, circuit::Ref b) { return a.kind == b.kind && a.index == b.index; }

struct Fixture {
  hstmon::circuit_tools::LoadedCircuit c;
  hstmon::host::HostCircuit desc{};
  bool ok = false;
  Fixture() {
    ok = !hstmon::circuit_tools::load_circuit(std::string(HSTMON_SOURCE_DIR) + "/examples/circuits/thesis.json", "", c);
    desc = c.file.circuit;
    desc.stiff_mask = circuit::auto_stiff_mask<double>(desc, c.values.params, c.values.inputs, gen::kTick);
  }
};

// The header serves any tick in [kTickMin, kTickMax]: the mask is the same at both ends and
// changes a quarter octave beyond (where the scan did not stop at its 2^±10 limit).
TEST(GeneratedHeader, TickRangeKeepsTheMask) {
  const Fixture f;
  ASSERT_TRUE(f.ok);
  ASSERT_LE(gen::kTickMin, gen::kTick);
  ASSERT_GE(gen::kTickMax, gen::kTick);
  const auto mask_at = [&](double tick) {
    return circuit::auto_stiff_mask<double>(f.c.file.circuit, f.c.values.params, f.c.values.inputs, tick);
  };
  EXPECT_EQ(mask_at(gen::kTickMin), f.desc.stiff_mask);
  EXPECT_EQ(mask_at(gen::kTickMax), f.desc.stiff_mask);
  if (gen::kTickMin > gen::kTick / 1024.0 * 1.0001) {
    EXPECT_NE(mask_at(gen::kTickMin / std::exp2(0.25)), f.desc.stiff_mask);
  }
  if (gen::kTickMax < gen::kTick * 1024.0 / 1.0001) {
    EXPECT_NE(mask_at(gen::kTickMax * std::exp2(0.25)), f.desc.stiff_mask);
  }
}

TEST(GeneratedHeader, IsTheCircuitFile) {
  const Fixture f;
  ASSERT_TRUE(f.ok);
  const auto& d = f.desc;
  const auto& k = gen::kCircuit;
  // The header's circuit and the file's are different types: one accessor for both sides.
  const auto counts = [](const auto& circuit) {
    return std::make_tuple(circuit.n_nodes, circuit.n_shafts, circuit.n_elements, circuit.n_channels, circuit.n_inputs,
                           circuit.n_params);
  };
  ASSERT_EQ(counts(k), counts(d));
  EXPECT_EQ(k.stiff_mask, d.stiff_mask);
  EXPECT_TRUE(same_ref(k.pressure_max, d.pressure_max) && same_ref(k.speed_max, d.speed_max));
  for (int i = 0; i < d.n_nodes; ++i) {
    EXPECT_EQ(k.nodes[i].kind, d.nodes[i].kind) << i;
    EXPECT_TRUE(same_ref(k.nodes[i].K, d.nodes[i].K) && same_ref(k.nodes[i].beta, d.nodes[i].beta) &&
                same_ref(k.nodes[i].volume, d.nodes[i].volume) && same_ref(k.nodes[i].pressure, d.nodes[i].pressure))
        << "node " << i;
  }
  for (int s = 0; s < d.n_shafts; ++s) {
    EXPECT_EQ(k.shafts[s].driven, d.shafts[s].driven);
    EXPECT_TRUE(same_ref(k.shafts[s].J, d.shafts[s].J) && same_ref(k.shafts[s].speed, d.shafts[s].speed));
  }
  for (int e = 0; e < d.n_elements; ++e) {
    const auto &a = k.elements[e], &b = d.elements[e];
    EXPECT_TRUE(a.kind == b.kind && a.a == b.a && a.b == b.b && a.shaft == b.shaft && a.opening_sign == b.opening_sign)
        << "element " << e;
    for (int r = 0; r < circuit::kSlots; ++r) EXPECT_TRUE(same_ref(a.r[r], b.r[r])) << "element " << e << " slot " << r;
  }
  for (int ch = 0; ch < d.n_channels; ++ch) {
    EXPECT_TRUE(k.channels[ch].kind == d.channels[ch].kind && k.channels[ch].index == d.channels[ch].index);
  }
  // Values exactly (17 digits round-trip), names, sensors.
  for (int i = 0; i < d.n_params; ++i) {
    EXPECT_EQ(gen::kParams[i], f.c.values.params.v[i]) << gen::kParamNames[i];
    EXPECT_EQ(std::string(gen::kParamNames[i]), f.c.file.params[static_cast<std::size_t>(i)].name);
  }
  for (int i = 0; i < d.n_inputs; ++i) {
    EXPECT_EQ(gen::kInputs[i], f.c.values.inputs.v[i]);
    EXPECT_EQ(std::string(gen::kInputNames[i]), f.c.file.inputs[static_cast<std::size_t>(i)].name);
    EXPECT_EQ(std::string(gen::kInputColumns[i]), f.c.file.inputs[static_cast<std::size_t>(i)].column);
    const auto& in = f.c.file.inputs[static_cast<std::size_t>(i)];
    EXPECT_EQ(gen::kInputUnitScale[i], hstmon::host::parse_circuit_unit(in.quantity, in.unit).conversion.factor);
  }
  for (int ch = 0; ch < d.n_channels; ++ch) {
    const auto& s = f.c.file.sensors[static_cast<std::size_t>(ch)];
    EXPECT_EQ(gen::kNoiseSigma[ch], s.noise);
    EXPECT_EQ(gen::kRangeLo[ch], s.lo);
    EXPECT_EQ(gen::kRangeHi[ch], s.hi);
    EXPECT_EQ(std::string(gen::kChannelNames[ch]), s.name);
    EXPECT_EQ(std::string(gen::kChannelColumns[ch]), s.column);
    EXPECT_EQ(gen::kChannelUnitScale[ch], hstmon::host::parse_circuit_unit(s.quantity, s.unit).conversion.factor);
  }
  // The capacity is tight: the states and unknowns of this circuit, nothing more.
  const FwModel m(gen::kCircuit, FwModel::Params{}, FwModel::Inputs{});
  EXPECT_EQ(gen::Cap::kStates, m.n_states());
  EXPECT_EQ(gen::Cap::kUnknowns, m.n_states() + m.n_stiff());
}

TEST(GeneratedHeader, FloatModelIsTheHostsBitForBit) {
  const Fixture f;
  ASSERT_TRUE(f.ok);
  FwModel::Params pf;
  HostModel::Params ph;
  for (int i = 0; i < gen::Cap::kParams; ++i) pf.v[i] = ph.v[i] = static_cast<float>(gen::kParams[i]);
  FwModel::Inputs uf;
  HostModel::Inputs uh;
  for (int i = 0; i < gen::Cap::kInputs; ++i) uf.v[i] = uh.v[i] = static_cast<float>(gen::kInputs[i]);
  const FwModel fw(gen::kCircuit, pf, uf);
  const HostModel host(f.desc, ph, uh);
  ASSERT_TRUE(fw.valid() && host.valid());
  FwModel::State xf;
  HostModel::State xh;
  ASSERT_TRUE(fw.steady_state(xf) && host.steady_state(xh));
  ASSERT_EQ(fw.n_states(), host.n_states());
  for (int s = 0; s < fw.n_states(); ++s) EXPECT_EQ(xf[s], xh[s]) << "steady state " << s;
  // Evaluations away from the steady state, and an observer over 2 000 ticks from rest.
  FwModel::State x = FwModel::State::Zero();
  HostModel::State y = HostModel::State::Zero();
  x[0] = y[0] = 1.2e7f;
  x[1] = y[1] = 120.0f;
  const auto df = fw.derivative(x);
  const auto dh = host.derivative(y);
  for (int s = 0; s < fw.n_states(); ++s) EXPECT_EQ(df[s], dh[s]) << "derivative " << s;
  hstmon::Observer<FwModel> of;
  hstmon::Observer<HostModel> oh;
  typename hstmon::Observer<FwModel>::Config cf;
  typename hstmon::Observer<HostModel>::Config ch;
  cf.tick = ch.tick = static_cast<float>(gen::kTick);
  ASSERT_EQ(of.configure(gen::kCircuit, pf, cf), hstmon::Status::kOk);
  ASSERT_EQ(oh.configure(host, ch), hstmon::Status::kOk);
  ASSERT_EQ(of.reset_rest(uf), hstmon::Status::kOk);
  ASSERT_EQ(oh.reset_rest(uh), hstmon::Status::kOk);
  const typename hstmon::Observer<FwModel>::Measurement none_f;
  const typename hstmon::Observer<HostModel>::Measurement none_h;
  for (int k = 0; k < 2000; ++k) {
    (void)of.step(uf, none_f);
    (void)oh.step(uh, none_h);
  }
  for (int s = 0; s < fw.n_states(); ++s) EXPECT_EQ(of.state()[s], oh.state()[s]) << "observer state " << s;
  EXPECT_GT(of.state()[1], 100.0f);  // it did start
}

}  // namespace
