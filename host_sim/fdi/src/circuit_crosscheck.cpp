/// @file circuit_crosscheck.cpp
#include "hstmon_fdi/circuit_crosscheck.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>

#include "hstmon/circuit/circuit_bound.hpp"
#include "hstmon/circuit/laws.hpp"
#include "hstmon_circuit/circuit_faults.hpp"
#include "hstmon_fdi/circuit_tcg.hpp"
#include "hstmon_fdi/forward.hpp"
#include "hstmon_fdi/qual.hpp"

namespace hstmon::fdi {

namespace {

using Model = host::HostCircuitModel;

/// The fault `name` × factor applied to (p, u), the nominal values, as the fault table
/// applies it (circuit_tools::apply_param_fault); false if c has no such input or parameter.
bool scale_value(const host::CircuitFile& f, const std::string& name, double factor, Model::Params& p, Model::Inputs& u) {
  const int i = f.input_index(name);
  if (i >= 0) {
    u.v[i] *= factor;
    return true;
  }
  const int k = f.param_index(name);
  if (k >= 0) {
    const Model::Params nominal = p;
    circuit_tools::apply_param_fault(f, p, nominal, static_cast<std::size_t>(k), factor);
    return true;
  }
  return false;
}

/// Size of the largest terms of each state equation at z [Pa/s or rad/s²]: K·Σ|Q| at a node,
/// Σ|τ|/J on a shaft. A difference below 1e-12 of it is the steady solve's rounding.
std::vector<double> equation_scale(const Model& m, const std::vector<double>& z) {
  const host::HostCircuit& d = *m.description();
  std::vector<double> zs(static_cast<std::size_t>(Model::kZ), 0.0);
  for (int e = 0; e < d.n_elements; ++e) {
    const circuit::Element& el = d.elements[e];
    const double w = el.shaft >= 0 ? z[static_cast<std::size_t>(Model::kNodes + el.shaft)] : 0.0;
    if (circuit::has_ports(el.kind)) {
      const double q = std::fabs(circuit::element_flow(el.kind, m.coeffs(e), z[el.a], z[el.b], w).q);
      zs[el.a] += q;
      zs[el.b] += q;
    }
    if (circuit::has_shaft(el.kind)) {
      double da, db, dw;
      const bool ports = circuit::has_ports(el.kind);
      zs[static_cast<std::size_t>(Model::kNodes + el.shaft)] += std::fabs(circuit::element_torque(
          el.kind, m.coeffs(e), ports ? z[el.a] : 0.0, ports ? z[el.b] : 0.0, w, da, db, dw));
    }
  }
  std::vector<double> r;
  for (int s = 0; s < m.n_states(); ++s) {
    const int k = m.state_z(s);
    r.push_back(m.node_stiffness(k) * zs[static_cast<std::size_t>(k)]);  // node_stiffness(kNodes + shaft) is 1/J
  }
  return r;
}

/// First non-zero derivative at 0+ of each output channel after the values change from
/// m0's to m1's at m0's steady state x0 (first order in the fault): the states' derivatives
/// are d1 = Δf(x0), d(k+1) = J1·dk; an output's 0th is its jump Δy(x0) (a flow sensor on
/// the faulty element), its k-th C·dk with C = ∂y/∂x (central differences).
void taylor(const Model& m0, const Model& m1, const Model::State& x0, const std::vector<double>& z0, int max_order,
            std::vector<int>& order, std::vector<QualSign>& slope) {
  const int n = m0.n_states(), ny = m0.n_outputs();
  const Model::State f0 = m0.derivative(x0);
  const Model::State f1 = m1.derivative(x0);
  Model::StateMatrix J;
  m1.jacobian(x0, J);
  const std::vector<double> term = equation_scale(m1, z0);
  // C = ∂y/∂x: a pressure or speed channel is its state's row (exact); a flow a slope.
  const Model::Output y0 = m0.outputs(x0), y1 = m1.outputs(x0);
  std::vector<std::vector<double>> C(static_cast<std::size_t>(ny), std::vector<double>(static_cast<std::size_t>(n), 0.0));
  for (int j = 0; j < n; ++j) {
    Model::State xp = x0, xm = x0;
    const double h = 1e-7 * (std::fabs(x0[j]) + 1.0);
    xp[j] += h;
    xm[j] -= h;
    const Model::Output yp = m1.outputs(xp), ym = m1.outputs(xm);
    for (int c = 0; c < ny; ++c) {
      const std::size_t cu = static_cast<std::size_t>(c), ju = static_cast<std::size_t>(j);
      int measured = -1;  // the state channel c reads, if it reads one
      for (int k = 0; k < n; ++k) {
        if (m1.state_channel(k) == c) measured = k;
      }
      C[cu][ju] = measured >= 0 ? (measured == j ? 1.0 : 0.0) : (yp[c] - ym[c]) / (2.0 * h);
    }
  }
  std::vector<double> d(static_cast<std::size_t>(n)), a(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    const std::size_t u = static_cast<std::size_t>(i);
    d[u] = f1[i] - f0[i];
    if (std::fabs(d[u]) <= 1e-12 * term[u]) d[u] = 0.0;
    a[u] = std::fabs(d[u]);
  }
  order.assign(static_cast<std::size_t>(ny), -1);
  slope.assign(static_cast<std::size_t>(ny), kQualZero);
  for (int c = 0; c < ny; ++c) {
    const QualSign s0 = qual_from_value(y1[c] - y0[c], 1e-12 * std::fabs(y0[c]));
    if (s0 != kQualZero) {
      order[static_cast<std::size_t>(c)] = 0;
      slope[static_cast<std::size_t>(c)] = s0;
    }
  }
  for (int k = 1; k <= max_order; ++k) {
    for (std::size_t c = 0; c < static_cast<std::size_t>(ny); ++c) {
      double v = 0.0, av = 0.0;
      for (std::size_t j = 0; j < d.size(); ++j) {
        v += C[c][j] * d[j];
        av += std::fabs(C[c][j]) * a[j];
      }
      const QualSign s = qual_from_value(v, 1e-9 * av);
      if (order[c] < 0 && s != kQualZero) {
        order[c] = k;
        slope[c] = s;
      }
    }
    std::vector<double> dn(d.size(), 0.0), an(d.size(), 0.0);
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) {
        dn[static_cast<std::size_t>(i)] += J(i, j) * d[static_cast<std::size_t>(j)];
        an[static_cast<std::size_t>(i)] += std::fabs(J(i, j)) * a[static_cast<std::size_t>(j)];
      }
    }
    d = dn;
    a = an;
  }
}

/// The engine's steady state polished by Newton steps on the net flows and torques: the
/// pseudo-transient stops at ~1e-12 relative, the size of the thesis rig's smallest real
/// effects (Ripl on Pmi), and K or J faults must read as no change at all.
bool polished_steady(const Model& m, std::vector<double>& z) {
  double zz[circuit::kExtent<Model::kZ>];
  if (!m.valid() || !m.steady_full(zz)) return false;
  const host::HostCircuit& d = *m.description();
  std::vector<int> unknown;  // the engine's unknown order: volume nodes, then free shafts
  for (int i = 0; i < d.n_nodes; ++i) {
    if (d.nodes[i].kind == circuit::NodeKind::kVolume) unknown.push_back(i);
  }
  for (int s = 0; s < d.n_shafts; ++s) {
    if (!d.shafts[s].driven) unknown.push_back(Model::kNodes + s);
  }
  const Eigen::Index n = static_cast<Eigen::Index>(unknown.size());
  double J[circuit::kExtent<Model::kU>][circuit::kExtent<Model::kU>];
  double g[circuit::kExtent<Model::kU>];
  for (int it = 0; it < 4 && n > 0; ++it) {
    m.unknowns_net(zz, g);
    m.unknowns_jacobian(zz, J);
    Eigen::MatrixXd A(n, n);
    Eigen::VectorXd b(n);
    for (Eigen::Index r = 0; r < n; ++r) {
      b[r] = -g[r];
      for (Eigen::Index c = 0; c < n; ++c) A(r, c) = J[r][c];
    }
    // Rows in m³/s and N·m, columns in Pa and rad/s: equilibrate before solving.
    const Eigen::VectorXd row = A.cwiseAbs().rowwise().maxCoeff().cwiseInverse();
    const Eigen::MatrixXd Ar = row.asDiagonal() * A;
    const Eigen::VectorXd col = Ar.cwiseAbs().colwise().maxCoeff().transpose().cwiseInverse();
    const Eigen::FullPivLU<Eigen::MatrixXd> lu(Ar * col.asDiagonal());
    if (!lu.isInvertible() || !row.allFinite() || !col.allFinite()) break;
    const Eigen::VectorXd dx = col.asDiagonal() * lu.solve(row.asDiagonal() * b);
    if (!dx.allFinite()) break;
    for (Eigen::Index k = 0; k < n; ++k) zz[unknown[static_cast<std::size_t>(k)]] += dx[k];
  }
  z.assign(std::begin(zz), std::end(zz));
  return true;
}

double step_for(const CircuitCrosscheckOptions& opt, const std::string& name) {
  for (const auto& s : opt.steps) {
    if (s.first == name) return s.second;
  }
  return opt.step;
}

}  // namespace

std::vector<CircuitCase> default_circuit_cases(const circuit_tools::LoadedCircuit& c) {
  std::vector<CircuitCase> r{{"nominal", {}}};
  for (std::size_t i = 0; i < c.file.inputs.size(); ++i) {
    if (c.values.inputs.v[i] == 0.0) continue;
    const std::string& n = c.file.inputs[i].name;
    r.push_back({n + " x 0.8", {{n, 0.8}}});
    r.push_back({n + " x 1.2", {{n, 1.2}}});
    break;
  }
  return r;
}

CircuitCrosscheck run_circuit_crosscheck(const circuit_tools::LoadedCircuit& c, const CircuitCrosscheckOptions& opt) {
  CircuitCrosscheck x;
  for (const host::CircuitSensor& s : c.file.sensors) x.channels.push_back(s.name);
  const std::vector<CircuitCase> cases = opt.cases.empty() ? default_circuit_cases(c) : opt.cases;
  for (const CircuitCase& cs : cases) {
    Model::Params p0 = c.values.params;
    Model::Inputs u0 = c.values.inputs;
    for (const auto& [name, factor] : cs.scale) {
      if (!scale_value(c.file, name, factor, p0, u0)) throw std::invalid_argument("case " + cs.name + ": no input or parameter " + name);
    }
    CircuitOperatingPoint op;
    if (const auto err = circuit_operating_point(c, p0, u0, op)) throw std::runtime_error(cs.name + ": " + *err);
    (void)polished_steady(op.model, op.z);
    const CircuitTcg t = circuit_tcg(c, op);
    double z0[circuit::kExtent<Model::kZ>];
    for (std::size_t k = 0; k < op.z.size(); ++k) z0[k] = op.z[k];
    const Model::State x0 = op.model.from_z(z0);
    const Model::Output y0 = op.model.outputs(x0);
    const std::vector<std::string> faults = circuit_graph_faults(t);
    if (&cs == &cases.front()) {
      auto on_graph = [&](const std::string& n) {
        for (const std::string& f : faults) {
          if (f == n) return true;
        }
        return false;
      };
      for (const host::CircuitParam& p : c.file.params) {
        if (!p.literal && !on_graph(p.name)) x.notes.push_back(p.name + ": not on the graph (a secondary number of an element, or a valve shut here)");
      }
      for (const host::CircuitInput& in : c.file.inputs) {
        if (!on_graph(in.name)) x.notes.push_back(in.name + ": not on the graph (a secondary number of an element, or a valve shut here)");
      }
    }
    for (const std::string& fault : faults) {
      const int in = c.file.input_index(fault);
      const double nominal = in >= 0 ? u0.v[in] : p0.v[c.file.param_index(fault)];
      if (nominal == 0.0) {
        if (&cs == &cases.front()) x.notes.push_back(fault + ": nominal value 0, a relative step changes nothing");
        continue;
      }
      const double step = step_for(opt, fault);
      for (int dir : {-1, 1}) {
        CircuitCrosscheckRow row;
        row.case_name = cs.name;
        row.fault = fault + (dir > 0 ? "+" : "-");
        const bool wanted = opt.faults.empty() ||
                            std::find(opt.faults.begin(), opt.faults.end(), row.fault) != opt.faults.end();
        if (!wanted) continue;
        row.step = step;
        Model::Params p1 = p0;
        Model::Inputs u1 = u0;
        (void)scale_value(c.file, fault, 1.0 + dir * step, p1, u1);
        const Model m1(c.file.circuit, p1, u1);
        std::vector<double> z1;
        if (!polished_steady(m1, z1)) {
          x.notes.push_back(row.fault + "@" + cs.name + ": no steady state, no row");
          continue;
        }
        double z1a[circuit::kExtent<Model::kZ>];
        for (std::size_t k = 0; k < z1.size(); ++k) z1a[k] = z1[k];
        const Model::Output y1 = m1.outputs(m1.from_z(z1a));
        std::vector<int> order;
        std::vector<QualSign> slope;
        taylor(op.model, m1, x0, op.z, opt.max_order, order, slope);
        const std::vector<ParamStep> steps = circuit_fault_steps(t, fault, dir);
        const std::vector<ChannelPrediction> q = forward_qualitative_at(t.graph, steps, opt.max_order, t.measured);
        const std::vector<ChannelPrediction> w = forward_weighted_at(t.graph, steps, opt.max_order, t.measured);
        const std::vector<double> lin = linear_steady_change_at(t.graph, steps, t.measured);
        for (int ch = 0; ch < op.model.n_outputs(); ++ch) {
          const std::size_t k = static_cast<std::size_t>(ch);
          CircuitChannelCheck cc;
          const double scale = std::fabs(y0[ch]) > 0.0 ? std::fabs(y0[ch]) : 1.0;
          const double dy = y1[ch] - y0[ch];
          cc.ss = qual_from_value(dy, opt.ss_zero_rel * scale);
          cc.ss_rel = dy / scale;
          cc.slope0 = slope[k];
          cc.order0 = order[k];
          cc.tcg_slope = q[k].slope;
          cc.tcg_order = q[k].order;
          cc.tcg_weighted = w[k].slope;
          cc.lin = qual_from_value(lin[k], 1e-12 * scale);
          row.channel.push_back(cc);
        }
        x.rows.push_back(std::move(row));
      }
    }
  }
  return x;
}

CircuitAgreement circuit_agreement(const CircuitCrosscheck& x) {
  CircuitAgreement a;
  for (const CircuitCrosscheckRow& r : x.rows) {
    for (const CircuitChannelCheck& c : r.channel) {
      ++a.readings;
      a.magnitude += c.tcg_slope == c.ss;
      a.linear += c.lin == c.ss;
      a.slope += qual_agrees(c.tcg_slope, c.slope0);
      a.order += c.tcg_order == c.order0;
      a.weighted += c.tcg_weighted == c.slope0;
    }
  }
  return a;
}

}  // namespace hstmon::fdi
