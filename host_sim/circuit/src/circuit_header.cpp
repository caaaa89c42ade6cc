#include "hstmon_circuit/circuit_header.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iterator>
#include <string>

#include "hstmon/circuit/stiffness.hpp"
#include "hstmon_circuit/circuit_faults.hpp"
#include "hstmon_host/circuit_units.hpp"
#include "hstmon_host/number_text.hpp"

namespace hstmon::circuit_tools {

namespace {

using circuit::RefKind;

// 17 significant digits: the double read back is the one written.
std::string num(double v) {
  if (std::isinf(v)) return v > 0 ? "kInf" : "-kInf";
  std::string s = host::number_text(v, 17);
  // A literal that reads as a double, not an int.
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

std::string ref(circuit::Ref r) {
  switch (r.kind) {
    case RefKind::kParam:
      return "circuit::param_ref(" + std::to_string(r.index) + ")";
    case RefKind::kInput:
      return "circuit::input_ref(" + std::to_string(r.index) + ")";
    default:
      return "{}";
  }
}

// The name of enumerator k, from the names of an enum numbered 0, 1, … in order; "?" past them.
template <class Enum, std::size_t N>
const char* enumerator(Enum k, const char* const (&names)[N]) {
  const auto i = static_cast<std::size_t>(k);
  return i < N ? names[i] : "?";
}

const char* element_kind(circuit::ElementKind k) {
  static constexpr const char* kNames[] = {"kOrifice",  "kLaminar", "kFlowSource", "kMachine",
                                           "kCompPump", "kPoppet",  "kTorque",     "kFriction"};
  static_assert(std::size(kNames) == static_cast<std::size_t>(circuit::ElementKind::kFriction) + 1);
  return enumerator(k, kNames);
}

const char* channel_kind(circuit::ChannelKind k) {
  static constexpr const char* kNames[] = {"kPressure", "kSpeed", "kFlow"};
  static_assert(std::size(kNames) == static_cast<std::size_t>(circuit::ChannelKind::kFlow) + 1);
  return enumerator(k, kNames);
}

// A C string literal of s (names are identifiers and dots; escape the rest anyway).
std::string str(const std::string& s) {
  std::string o = "\"";
  for (const char ch : s) {
    if (ch == '"' || ch == '\\') o += '\\';
    o += ch;
  }
  return o + "\"";
}

// `{a, b, c}` over n items given by f(i), with `pad` extra zero items.
template <class F>
std::string list(int n, F f, int pad = 0, const char* zero = "0.0") {
  std::string o = "{";
  for (int i = 0; i < n + pad; ++i) {
    if (i > 0) o += ", ";
    o += i < n ? f(i) : std::string(zero);
  }
  return o + "}";
}

}  // namespace

host::HostCircuit header_description(const LoadedCircuit& c, double tick, int* states) {
  host::HostCircuit desc = c.file.circuit;
  desc.stiff_mask = circuit::auto_stiff_mask<double>(desc, c.values.params, c.values.inputs, tick, 8.0, states);
  return desc;
}

TickRange same_mask_ticks(const LoadedCircuit& c, double tick) {
  const std::uint32_t mask = header_description(c, tick).stiff_mask;
  // Quarter octaves out to 2^±10 × tick, each way until the mask changes (a node turns
  // stiff as K·G_min·h grows, so the mask only changes at a threshold of the tick).
  constexpr int kSteps = 40;
  const auto at = [tick](int k) { return tick * std::exp2(0.25 * k); };
  TickRange r{tick, tick};
  for (int k = 1; k <= kSteps && header_description(c, at(-k)).stiff_mask == mask; ++k) r.lo = at(-k);
  for (int k = 1; k <= kSteps && header_description(c, at(k)).stiff_mask == mask; ++k) r.hi = at(k);
  return r;
}

namespace {

// kTick and the ticks the header's stiff mask holds for (same_mask_ticks).
std::string tick_lines(const LoadedCircuit& c, double tick) {
  const TickRange same = same_mask_ticks(c, tick);
  return "/// Observer tick the stiff mask was chosen for [s].\n"
         "inline constexpr double kTick = " +
         num(tick) +
         ";\n"
         "/// Ticks at which auto_stiff_mask picks this same mask, so this header serves an observer\n"
         "/// at any tick in [kTickMin, kTickMax] (quarter octaves from kTick, out to 2^±10 × kTick) [s].\n"
         "inline constexpr double kTickMin = " +
         num(same.lo) +
         ";\n"
         "inline constexpr double kTickMax = " +
         num(same.hi) + ";\n";
}

}  // namespace

std::string circuit_header(const LoadedCircuit& c, const CircuitHeaderOptions& o, std::string& error) {
  error.clear();
  const host::CircuitFile& f = c.file;
  const host::HostCircuit desc = header_description(c, o.tick);
  const host::HostCircuitModel check(desc, c.values.params, c.values.inputs);
  if (check.error() != circuit::CircuitError::kOk || !check.valid()) {
    error = "circuit " + f.name + ": its values do not make a physical circuit";
    return "";
  }
  const int n_in = desc.n_inputs, n_p = desc.n_params, n_ch = desc.n_channels;
  // The tight capacity: what this circuit uses (inputs even, at least 2; one parameter
  // and one state at least, as Capacity requires).
  const int cap_in = n_in < 2 ? 2 : n_in + (n_in % 2);
  const int cap_p = n_p < 1 ? 1 : n_p;
  const int cap_s = check.n_states() < 1 ? 1 : check.n_states();
  const int unknowns = check.n_states() + check.n_stiff();  // volume nodes + free shafts
  const int cap_u = unknowns < cap_s ? cap_s : unknowns;
  const circuit::CircuitUncertainty<double, host::CircuitCap> eps = circuit_uncertainty(c);

  std::string h;
  auto line = [&h](const std::string& s) { h += s + "\n"; };
  line("#pragma once");
  line("/// @file " + o.name + ".hpp");
  line("/// GENERATED by hstmon-circuit-header — do not edit; regenerate (docs/firmware.md).");
  line("/// Circuit \"" + f.name + "\" (" + o.source_note + ") at a " + num(o.tick) + " s tick:");
  line("/// the engine's description (constexpr, so it lives in flash), a capacity exactly as large");
  line("/// as the circuit, parameter values, nominal inputs, sensor noise and ranges (SI units).");
  line("");
  line("#include <limits>");
  line("");
  line("#include \"hstmon/circuit/circuit.hpp\"");
  line("");
  line("namespace hstmon::generated::" + o.name + " {");
  line("");
  line("inline constexpr double kInf = std::numeric_limits<double>::infinity();");
  line("");
  h += tick_lines(c, o.tick);
  line("");
  line("/// Capacity: " + std::to_string(desc.n_nodes) + " nodes, " + std::to_string(desc.n_shafts) + " shafts, " +
       std::to_string(desc.n_elements) + " elements, " + std::to_string(n_ch) + " channels, " + std::to_string(cap_in) +
       " inputs (" + std::to_string(n_in) + " used), " + std::to_string(cap_p) + " parameters, " +
       std::to_string(cap_s) + " states (" + std::to_string(check.n_stiff()) + " stiff nodes quasi-steady), " +
       std::to_string(cap_u) + " unknowns.");
  line("using Cap = circuit::Capacity<" + std::to_string(desc.n_nodes) + ", " + std::to_string(desc.n_shafts) + ", " +
       std::to_string(desc.n_elements) + ", " + std::to_string(n_ch) + ", " + std::to_string(cap_in) + ", " +
       std::to_string(cap_p) + ", " + std::to_string(cap_s) + ", " + std::to_string(cap_u) + ">;");
  line("");
  line("/// The description; stiff_mask from circuit::auto_stiff_mask<double> at kTick.");
  line("inline constexpr circuit::Circuit<Cap> kCircuit = {");
  line("    " + std::to_string(desc.n_nodes) + ", " + std::to_string(desc.n_shafts) + ", " +
       std::to_string(desc.n_elements) + ", " + std::to_string(n_ch) + ", " + std::to_string(n_in) + ", " +
       std::to_string(n_p) + ",  // nodes, shafts, elements, channels, inputs, params");
  line("    " + ref(desc.pressure_max) + ", " + ref(desc.speed_max) + ",  // envelope: pressure, speed");
  char mask[16];
  std::snprintf(mask, sizeof mask, "0x%08Xu", static_cast<unsigned>(desc.stiff_mask));
  line(std::string("    ") + mask + ",  // stiff nodes");
  line("    {");
  for (int i = 0; i < desc.n_nodes; ++i) {
    const circuit::Node& n = desc.nodes[i];
    line(std::string("        {circuit::NodeKind::") + (n.kind == circuit::NodeKind::kVolume ? "kVolume" : "kBoundary") +
         ", " + ref(n.K) + ", " + ref(n.beta) + ", " + ref(n.volume) + ", " + ref(n.pressure) + "},  // " +
         f.nodes[static_cast<std::size_t>(i)]);
  }
  line("    },");
  line("    {");
  for (int s = 0; s < desc.n_shafts; ++s) {
    const circuit::Shaft& sh = desc.shafts[s];
    line("        {" + ref(sh.J) + ", " + ref(sh.speed) + ", " + (sh.driven ? "true" : "false") + "},  // " +
         f.shafts[static_cast<std::size_t>(s)]);
  }
  line("    },");
  line("    {");
  for (int e = 0; e < desc.n_elements; ++e) {
    const circuit::Element& el = desc.elements[e];
    int last = -1;
    for (int k = 0; k < circuit::kSlots; ++k) {
      if (el.r[k].kind != RefKind::kNone) last = k;
    }
    line(std::string("        {circuit::ElementKind::") + element_kind(el.kind) + ", " + std::to_string(el.a) + ", " +
         std::to_string(el.b) + ", " + std::to_string(el.shaft) + ", " + std::to_string(el.opening_sign) + ", " +
         list(last + 1, [&](int k) { return ref(el.r[k]); }) + "},  // " + f.elements[static_cast<std::size_t>(e)]);
  }
  line("    },");
  line("    {");
  for (int ch = 0; ch < n_ch; ++ch) {
    const circuit::Channel& k = desc.channels[ch];
    line(std::string("        {circuit::ChannelKind::") + channel_kind(k.kind) + ", " + std::to_string(k.index) +
         "},  // " + f.sensors[static_cast<std::size_t>(ch)].name);
  }
  line("    },");
  line("};");
  line("");
  auto names = [&](const char* what, int n, int cap, auto name_of) {
    line(std::string("inline constexpr const char* const ") + what + "[" + std::to_string(cap) + "] = " +
         list(n, [&](int i) { return str(name_of(static_cast<std::size_t>(i))); }, cap - n, "\"\"") + ";");
  };
  line("/// Parameter values by index [SI unit of each parameter's quantity].");
  line("inline constexpr double kParams[" + std::to_string(cap_p) + "] = " +
       list(n_p, [&](int i) { return num(c.values.params.v[i]); }, cap_p - n_p) + ";");
  names("kParamNames", n_p, cap_p, [&](std::size_t i) { return f.params[i].name; });
  line("/// Relative uncertainty of each parameter for the model bound [-] (host circuit_uncertainty: the parameter file's, else the default).");
  line("inline constexpr double kUncertainty[" + std::to_string(cap_p) + "] = " +
       list(n_p, [&](int i) { return num(eps.rel[i]); }, cap_p - n_p) + ";");
  line("/// Nominal inputs by index [SI] (unused capacity 0).");
  line("inline constexpr double kInputs[" + std::to_string(cap_in) + "] = " +
       list(n_in, [&](int i) { return num(c.values.inputs.v[i]); }, cap_in - n_in) + ";");
  names("kInputNames", n_in, cap_in, [&](std::size_t i) { return f.inputs[i].name; });
  // SI per unit of the unit a column is read in when the log's header states none.
  auto default_scale = [](host::CircuitQuantity q, const std::string& unit) {
    const host::UnitResult u = host::parse_circuit_unit(q, unit);
    return u.ok() ? u.conversion.factor : 1.0;
  };
  // The log columns of items (the inputs or the sensors, n of cap) and the SI factor of a
  // column whose log header states no unit (the circuit file's unit), with their comments.
  auto column_tables = [&](const auto& items, int n, int cap, const char* columns, const std::string& columns_doc,
                           const char* scales, const std::string& scales_doc) {
    line(columns_doc);
    names(columns, n, cap, [&](std::size_t i) { return items[i].column; });
    line(scales_doc);
    line("inline constexpr double " + std::string(scales) + "[" + std::to_string(cap) + "] = " +
         list(
             n,
             [&](int i) {
               const auto& item = items[static_cast<std::size_t>(i)];
               return num(default_scale(item.quantity, item.unit));
             },
             cap - n) +
         ";");
  };
  column_tables(f.inputs, n_in, cap_in, "kInputColumns",
                "/// Log column of each input (matched without regard to case, as the host reader does).",
                "kInputUnitScale",
                "/// SI factor of each input column whose log header states no unit (the circuit file's unit).");
  line("/// Sensor noise standard deviation per channel [SI]; 0 where the file gives none.");
  line("inline constexpr double kNoiseSigma[" + std::to_string(n_ch) + "] = " +
       list(n_ch, [&](int i) { return num(f.sensors[static_cast<std::size_t>(i)].noise); }) + ";");
  line("/// Transmitter range per channel [SI]; ±kInf where the file gives none.");
  line("inline constexpr double kRangeLo[" + std::to_string(n_ch) + "] = " +
       list(n_ch, [&](int i) { return num(f.sensors[static_cast<std::size_t>(i)].lo); }) + ";");
  line("inline constexpr double kRangeHi[" + std::to_string(n_ch) + "] = " +
       list(n_ch, [&](int i) { return num(f.sensors[static_cast<std::size_t>(i)].hi); }) + ";");
  names("kChannelNames", n_ch, n_ch, [&](std::size_t i) { return f.sensors[i].name; });
  column_tables(f.sensors, n_ch, n_ch, "kChannelColumns",
                "/// Log column of each channel (matched without regard to case).", "kChannelUnitScale",
                "/// SI factor of each channel column whose log header states no unit (the circuit file's unit).");
  line("");
  line("}  // namespace hstmon::generated::" + o.name);
  return h;
}

}  // namespace hstmon::circuit_tools
