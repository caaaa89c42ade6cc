/// @file circuit_equations.cpp
/// A circuit's balance equations on its measured signals (circuit_equations.hpp).
#include "hstmon_gap/circuit_equations.hpp"

#include <algorithm>
#include <cmath>

#include "hstmon_ident/input_hold.hpp"
#include "local_fit.hpp"

namespace hstmon::gap {

namespace {

using Model = host::HostCircuitModel;
constexpr int kZ = Model::kZ;
constexpr int kNodes = Model::kNodes;

void add_read(std::vector<int>& reads, int z) {
  if (std::find(reads.begin(), reads.end(), z) == reads.end()) reads.push_back(z);
}

// Per full-vector entry, the first pressure or speed channel that measures it (−1: none).
std::vector<int> channel_of_z(const host::HostCircuit& d) {
  std::vector<int> ch(static_cast<std::size_t>(kZ), -1);
  for (int k = 0; k < d.n_channels; ++k) {
    const circuit::Channel& h = d.channels[k];
    int z = -1;
    if (h.kind == circuit::ChannelKind::kPressure) z = h.index;
    if (h.kind == circuit::ChannelKind::kSpeed) z = kNodes + h.index;
    if (z >= 0 && ch[static_cast<std::size_t>(z)] < 0) ch[static_cast<std::size_t>(z)] = k;
  }
  return ch;
}

bool fixed_entry(const host::HostCircuit& d, int z) {
  return z < kNodes ? d.nodes[z].kind == circuit::NodeKind::kBoundary : d.shafts[z - kNodes].driven;
}

bool logged(const circuit_tools::CircuitLog& log, int ch) {
  return ch >= 0 && static_cast<std::size_t>(ch) < log.sensors.size() &&
         log.sensors[static_cast<std::size_t>(ch)].size() == log.rows() && log.rows() > 0;
}

// What equation e lacks in log: every entry neither fixed nor measured by a logged channel.
std::string missing_of(const circuit_tools::LoadedCircuit& c, const circuit_tools::CircuitLog& log,
                       const std::vector<int>& ch_of_z, const CircuitEquation& e) {
  std::string out;
  for (int z : e.reads) {
    const int ch = ch_of_z[static_cast<std::size_t>(z)];
    if (fixed_entry(c.file.circuit, z) || logged(log, ch)) continue;
    std::string what;
    if (ch >= 0) {
      what = c.file.sensors[static_cast<std::size_t>(ch)].name + " (not in the log)";
    } else if (z < kNodes) {
      what = "pressure of " + c.file.nodes[static_cast<std::size_t>(z)] + " (no sensor)";
    } else {
      what = "speed of " + c.file.shafts[static_cast<std::size_t>(z - kNodes)] + " (no sensor)";
    }
    out += (out.empty() ? "" : ", ") + what;
  }
  return out;
}

// The model's inputs at row k: the log's where it has the column, else the values'.
void row_inputs(const circuit_tools::LoadedCircuit& c, const circuit_tools::CircuitLog& log, std::size_t k,
                Model::Inputs& u) {
  u = c.values.inputs;
  for (std::size_t i = 0; i < log.inputs.size() && i < c.file.inputs.size(); ++i) {
    if (log.inputs[i].size() == log.rows()) u.v[i] = log.inputs[i][k];
  }
}

// Input setting id per row: a logged input moves when it changes by more than 0.5 % of its
// value and more than its floor — 500 Pa for a pressure (the thesis rig's rule) and 8 of
// its own successive-difference σ (input_hold.hpp, the operating points' rule).
std::vector<int> input_segments(const circuit_tools::LoadedCircuit& c, const circuit_tools::CircuitLog& log) {
  const std::size_t n = log.rows();
  std::vector<double> floor(log.inputs.size(), 0.0);
  for (std::size_t i = 0; i < log.inputs.size() && i < c.file.inputs.size(); ++i) {
    const auto& x = log.inputs[i];
    if (x.size() != n) continue;
    const bool pressure = c.file.inputs[i].quantity == host::CircuitQuantity::kPressure;
    floor[i] = std::max(pressure ? 500.0 : 0.0, ident::kInputNoise * ident::column_noise(x));
  }
  std::vector<int> seg(n, 0);
  for (std::size_t k = 1; k < n; ++k) {
    bool moved = false;
    for (std::size_t i = 0; i < log.inputs.size() && !moved; ++i) {
      const auto& x = log.inputs[i];
      if (x.size() != n) continue;
      const double a = x[k], b = x[k - 1];
      moved = std::fabs(a - b) > std::max(ident::kInputRelative * std::max(std::fabs(a), std::fabs(b)), floor[i]);
    }
    seg[k] = seg[k - 1] + (moved ? 1 : 0);
  }
  return seg;
}

// The imbalance of every available equation at one row (z, zdot: the row's full vector
// and slopes) and its propagated noise (sm, sd: per entry the σ of a window mean and of a
// window slope, 0 where fixed).
void evaluate_row(const Model& m, const CircuitArrData& a, const double (&z)[kZ], const std::vector<double>& zdot,
                  const std::vector<double>& sm, const std::vector<double>& sd, std::vector<double>& r,
                  std::vector<double>& var) {
  double g[circuit::kExtent<Model::kU>];
  double J[circuit::kExtent<kZ>][circuit::kExtent<kZ>];
  m.unknowns_net(z, g);
  m.full_jacobian(z, J);
  for (std::size_t e = 0; e < a.equations.size(); ++e) {
    r[e] = 0.0;
    var[e] = 0.0;
    if (!a.available[e]) continue;
    const CircuitEquation& q = a.equations[e];
    const auto zi = static_cast<std::size_t>(q.z);
    const double C = 1.0 / m.node_stiffness(q.z);  // capacitance [m³/Pa] or inertia [kg·m²]
    r[e] = g[q.unknown] - C * zdot[zi];
    double v = std::pow(C * sd[zi], 2);
    for (int j : q.reads) v += std::pow(J[zi][static_cast<std::size_t>(j)] * sm[static_cast<std::size_t>(j)], 2);
    var[e] = v;
  }
}

}  // namespace

std::vector<CircuitEquation> circuit_equations(const circuit_tools::LoadedCircuit& c) {
  const host::HostCircuit& d = c.file.circuit;
  std::vector<CircuitEquation> out;
  int unknown = 0;
  for (int i = 0; i < d.n_nodes; ++i) {
    if (d.nodes[i].kind != circuit::NodeKind::kVolume) continue;
    CircuitEquation e{"flow:" + c.file.nodes[static_cast<std::size_t>(i)], "m^3/s", i, unknown++, false, {i}};
    for (int k = 0; k < d.n_elements; ++k) {
      const circuit::Element& el = d.elements[k];
      if (!circuit::has_ports(el.kind) || (el.a != i && el.b != i)) continue;
      add_read(e.reads, el.a == i ? el.b : el.a);
      if (el.shaft >= 0) add_read(e.reads, kNodes + el.shaft);
    }
    out.push_back(std::move(e));
  }
  for (int s = 0; s < d.n_shafts; ++s) {
    if (d.shafts[s].driven) continue;
    CircuitEquation e{
        "torque:" + c.file.shafts[static_cast<std::size_t>(s)], "N*m", kNodes + s, unknown++, true, {kNodes + s}};
    for (int k = 0; k < d.n_elements; ++k) {
      const circuit::Element& el = d.elements[k];
      if (!circuit::has_shaft(el.kind) || el.shaft != s || !circuit::has_ports(el.kind)) continue;
      add_read(e.reads, el.a);
      add_read(e.reads, el.b);
    }
    out.push_back(std::move(e));
  }
  return out;
}

CircuitArrData evaluate_circuit_arrs(const circuit_tools::LoadedCircuit& c, const circuit_tools::CircuitLog& log,
                                     const std::vector<double>& noise) {
  CircuitArrData a;
  const host::HostCircuit& d = c.file.circuit;
  a.equations = circuit_equations(c);
  const std::vector<int> ch_of_z = channel_of_z(d);
  for (const auto& e : a.equations) {
    a.missing.push_back(missing_of(c, log, ch_of_z, e));
    a.available.push_back(a.missing.back().empty());
  }
  const std::size_t ne = a.equations.size();
  a.r.assign(ne, {});
  a.sigma.assign(ne, {});
  const std::size_t n = log.rows();
  if (n < 3) return a;
  // The measured entries (z, channel) whose channels the log has.
  std::vector<std::pair<std::size_t, std::size_t>> measured;
  for (int z = 0; z < kZ; ++z) {
    const int ch = ch_of_z[static_cast<std::size_t>(z)];
    if (!fixed_entry(d, z) && logged(log, ch) && static_cast<std::size_t>(ch) < noise.size()) {
      measured.emplace_back(static_cast<std::size_t>(z), static_cast<std::size_t>(ch));
    }
  }
  const int m = detail::smoothing_half_width(log.t);
  a.half_window = m;
  const auto mu = static_cast<std::size_t>(m);
  const std::vector<int> seg = input_segments(c, log);
  Model model(d, c.values.params, c.values.inputs);
  Model::Inputs u{}, u_last{};
  bool have_inputs = false;
  std::vector<double> r(ne), var(ne), zdot(static_cast<std::size_t>(kZ)), sm(static_cast<std::size_t>(kZ)),
      sd(static_cast<std::size_t>(kZ));
  for (std::size_t k = mu + 1; k + mu < n; ++k) {  // the window leaves out row 0 (the initial condition)
    if (seg[k - mu] != seg[k + mu]) continue;
    const detail::Window win = detail::window_at(log.t, k, mu);
    double z[circuit::kExtent<kZ>];
    std::fill(zdot.begin(), zdot.end(), 0.0);
    std::fill(sm.begin(), sm.end(), 0.0);
    std::fill(sd.begin(), sd.end(), 0.0);
    bool bent = false;
    for (const auto& [zi, ch] : measured) {
      const std::vector<double>& y = log.sensors[ch];
      const auto at = [&y](std::size_t i) { return y[i]; };
      detail::line_fit(log.t, win, at, z[zi], zdot[zi]);
      bent = bent || detail::bends(log.t, win, at, z[zi], zdot[zi], noise[ch]);
      sm[zi] = noise[ch] / std::sqrt(win.N);
      sd[zi] = noise[ch] / std::sqrt(win.stt);
    }
    if (bent) continue;
    row_inputs(c, log, k, u);
    if (!have_inputs || !(u == u_last)) model.set_inputs(u);
    u_last = u;
    have_inputs = true;
    for (int zi = 0; zi < kZ; ++zi) {
      if (fixed_entry(d, zi)) {
        z[zi] = model.fixed_value(zi);
      } else if (std::none_of(measured.begin(), measured.end(),
                              [zi](const auto& p) { return p.first == static_cast<std::size_t>(zi); })) {
        z[zi] = 0.0;  // read by no available equation
      }
    }
    evaluate_row(model, a, z, zdot, sm, sd, r, var);
    a.rows.push_back(k);
    a.t_since_start.push_back(log.t[k] - log.t[0]);
    a.z.emplace_back(z, z + kZ);
    a.zdot.push_back(zdot);
    for (std::size_t e = 0; e < ne; ++e) {
      a.r[e].push_back(r[e]);
      a.sigma[e].push_back(std::sqrt(var[e]));
    }
  }
  return a;
}

std::vector<EquationStats> circuit_equation_stats(const CircuitArrData& a) {
  std::vector<EquationStats> out;
  for (std::size_t e = 0; e < a.equations.size(); ++e) {
    EquationStats s;
    s.equation = a.equations[e].name;
    s.unit = a.equations[e].unit;
    s.available = a.available[e] && !a.rows.empty();
    if (s.available) imbalance_stats(a.r[e], a.sigma[e], s);
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace hstmon::gap
