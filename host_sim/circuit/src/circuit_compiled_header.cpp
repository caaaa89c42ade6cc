// hstmon-circuit-header --compiled: the circuit's hot path as straight-line C++ (the
// Kernel of lib/circuit compiled_model.hpp). Every loop of the interpreting CircuitModel
// over elements, incidence lists and channels is unrolled here, in the interpreter's order,
// so each sum is accumulated in the same order and the compiled model's numbers are the
// interpreter's bit for bit (but for the sign of a zero sum, see Sums); the laws themselves
// are called, never written out.
#include <cmath>
#include <cstdio>
#include <set>
#include <string>
#include <vector>

#include "hstmon_circuit/circuit_header.hpp"

namespace hstmon::circuit_tools {

namespace {

using circuit::ElementKind;
using circuit::NodeKind;

std::string s(int v) { return std::to_string(v); }

// How generated code reads entry k of the full vector: a fixed entry (boundary pressure,
// driven shaft speed) straight from the engine, a state or stiff node from z. fill then
// copies the states only: four fewer stores per evaluation on the thesis rig.
struct ZRef {
  std::vector<bool> fixed;
  std::string operator()(int k) const {
    return fixed[static_cast<std::size_t>(k)] ? "m.fixed_value(" + s(k) + ")" : "z[" + s(k) + "]";
  }
};

// The law call of element e (laws.hpp), writing into the Flow `f`, with full-vector
// entries a, b and shaft speed.
std::string flow_call(const circuit::Element& el, int e, int n_nodes, const ZRef& zr) {
  const std::string k = "m.coeffs(" + s(e) + ")";
  const std::string pa = zr(el.a), pb = zr(el.b);
  switch (el.kind) {
    case ElementKind::kOrifice: return "circuit::orifice_flow(" + k + ", " + pa + ", " + pb + ", f)";
    case ElementKind::kPoppet: return "circuit::poppet_flow(" + k + ", " + pa + ", " + pb + ", f)";
    case ElementKind::kLaminar: return "circuit::laminar_flow(" + k + ", " + pa + ", " + pb + ", f)";
    case ElementKind::kFlowSource: return "circuit::source_flow(" + k + ", f)";
    case ElementKind::kMachine: return "circuit::machine_flow(" + k + ", " + zr(n_nodes + el.shaft) + ", f)";
    case ElementKind::kCompPump: return "circuit::comp_pump_flow(" + k + ", " + pa + ", " + pb + ", f)";
    case ElementKind::kTorque:
    case ElementKind::kFriction: break;
  }
  return "(void)f";
}

const char* kind_name(ElementKind k) {
  switch (k) {
    case ElementKind::kOrifice: return "kOrifice";
    case ElementKind::kLaminar: return "kLaminar";
    case ElementKind::kFlowSource: return "kFlowSource";
    case ElementKind::kMachine: return "kMachine";
    case ElementKind::kCompPump: return "kCompPump";
    case ElementKind::kPoppet: return "kPoppet";
    case ElementKind::kTorque: return "kTorque";
    case ElementKind::kFriction: return "kFriction";
  }
  return "?";
}

// The torque call of element e on its shaft (laws.hpp element_torque, kind fixed), with
// slopes into da, db, dw.
std::string torque_call(const circuit::Element& el, int e, int n_nodes, const ZRef& zr) {
  const bool ports = circuit::has_ports(el.kind);
  const std::string pa = ports ? zr(el.a) : "T(0)", pb = ports ? zr(el.b) : "T(0)";
  return std::string("circuit::element_torque(circuit::ElementKind::") + kind_name(el.kind) + ", m.coeffs(" + s(e) +
         "), " + pa + ", " + pb + ", " + zr(n_nodes + el.shaft) + ", da, db, dw)";
}

// Sums written out term by term: the first term into a sum assigns it (acc = t, or
// acc = -(t)), later ones add. A sum started from T(0) costs an add per sum on every
// evaluation (0 + x is not x when x is −0, so the compiler must keep it): 34 instructions
// of the thesis tick on Cortex-M4. The result differs from the interpreter's T(0)-started
// sum only in the sign of a sum that is zero.
struct Sums {
  std::set<std::string> started;
  std::string add(const std::string& acc, char op, const std::string& t) {
    if (started.insert(acc).second) return acc + (op == '-' ? " = -(" + t + ");" : " = " + t + ";");
    return acc + " " + op + "= " + t + ";";
  }
};

std::string list(const std::vector<int>& v) {
  std::string o = "{";
  for (std::size_t i = 0; i < v.size(); ++i) o += (i > 0 ? ", " : "") + s(v[i]);
  if (v.empty()) o += "0";
  return o + "}";
}

// quasi_steady.hpp's schur_reduce for this circuit's structure, unrolled: the same
// operations in the same order, without the terms whose factors are structurally zero
// (there the interpreter adds ±0).
template <class Line>
void emit_schur(Line& line, std::vector<std::vector<bool>> nz, const std::vector<int>& ia, const std::vector<int>& ix) {
  auto at = [&](int r, int c) { return "G[" + s(r) + "][" + s(c) + "]"; };
  auto is = [&](int r, int c) { return static_cast<bool>(nz[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)]); };
  const int m = static_cast<int>(ia.size()), n = static_cast<int>(ix.size());
  auto A = [&](int k) { return ia[static_cast<std::size_t>(k)]; };
  auto X = [&](int k) { return ix[static_cast<std::size_t>(k)]; };
  line("  /// Reduced Jacobian jr = M⁻¹(G_xx − G_xa·G_aa⁻¹·G_ax) and the stiff block's contraction factor q");
  line("  /// (quasi_steady.hpp schur_reduce, unrolled); G's stiff rows are destroyed.");
  line("  template <typename T, std::size_t U, std::size_t S, std::size_t N>");
  line("  HSTMON_CIRCUIT_INLINE static void schur(T (&G)[U][U], const T (&inv_mass)[N], T (&jr)[S][S], T& q) noexcept {");
  line("    q = T(0);");
  for (int a = 0; a < m; ++a) {
    line("    {");
    line("      T off = T(0);");
    for (int b = 0; b < m; ++b) {
      if (b != a && is(A(a), A(b))) line("      off += std::fabs(" + at(A(a), A(b)) + ");");
    }
    line("      const T qa = off / std::fabs(" + at(A(a), A(a)) + ");");
    line("      if (qa > q) q = qa;");
    line("    }");
  }
  for (int k = 0; k < m; ++k) {
    bool any = false;
    for (int r = k + 1; r < m; ++r) any = any || is(A(r), A(k));
    if (!any) continue;
    line("    {");
    line("      const T inv = T(1) / " + at(A(k), A(k)) + ";");
    for (int r = k + 1; r < m; ++r) {
      if (!is(A(r), A(k))) continue;
      line("      {");
      line("        const T f = " + at(A(r), A(k)) + " * inv;");
      // A fill-in (structurally zero before this step) is assigned, -f·x rather than
      // 0 - f·x (the same number), and zeroed when f is 0: G need not start zeroed.
      std::vector<std::string> fills;
      line("        if (f != T(0)) {");
      auto update = [&](int col) {
        if (!is(A(k), col)) return;
        const bool fill = !is(A(r), col);
        line("          " + at(A(r), col) + (fill ? " = -f * " : " -= f * ") + at(A(k), col) + ";");
        if (fill) fills.push_back(at(A(r), col));
        nz[static_cast<std::size_t>(A(r))][static_cast<std::size_t>(col)] = true;
      };
      for (int c = k + 1; c < m; ++c) update(A(c));
      for (int t = 0; t < n; ++t) update(X(t));
      if (fills.empty()) {
        line("        }");
      } else {
        line("        } else {");
        for (const std::string& e : fills) line("          " + e + " = T(0);");
        line("        }");
      }
      line("      }");
    }
    line("    }");
  }
  for (int k = m - 1; k >= 0; --k) {
    for (int t = 0; t < n; ++t) {
      std::vector<std::string> terms;
      for (int c = k + 1; c < m; ++c) {
        if (is(A(k), A(c)) && is(A(c), X(t))) terms.push_back(at(A(k), A(c)) + " * " + at(A(c), X(t)));
      }
      if (!is(A(k), X(t)) && terms.empty()) continue;  // stays 0
      line("    {");
      line("      T v = " + (is(A(k), X(t)) ? at(A(k), X(t)) : std::string("T(0)")) + ";");
      for (const std::string& term : terms) line("      v -= " + term + ";");
      line("      " + at(A(k), X(t)) + " = v / " + at(A(k), A(k)) + ";");
      line("    }");
      nz[static_cast<std::size_t>(A(k))][static_cast<std::size_t>(X(t))] = true;
    }
  }
  for (int r = 0; r < n; ++r) {
    for (int t = 0; t < n; ++t) {
      std::vector<std::string> terms;
      for (int a = 0; a < m; ++a) {
        if (is(X(r), A(a)) && is(A(a), X(t))) terms.push_back(at(X(r), A(a)) + " * " + at(A(a), X(t)));
      }
      const std::string jr = "jr[" + s(r) + "][" + s(t) + "]";
      if (!is(X(r), X(t)) && terms.empty()) {
        line("    " + jr + " = T(0);");
        continue;
      }
      line("    {");
      line("      T v = " + (is(X(r), X(t)) ? at(X(r), X(t)) : std::string("T(0)")) + ";");
      for (const std::string& term : terms) line("      v -= " + term + ";");
      line("      " + jr + " = inv_mass[" + s(r) + "] * v;");
      line("    }");
    }
  }
  line("  }");
}

}  // namespace

std::string circuit_compiled_header(const LoadedCircuit& c, const CircuitHeaderOptions& o, std::string& error) {
  error.clear();
  const host::CircuitFile& f = c.file;
  const host::HostCircuit d = header_description(c, o.tick);
  const host::HostCircuitModel check(d, c.values.params, c.values.inputs);
  if (check.error() != circuit::CircuitError::kOk || !check.valid()) {
    error = "circuit " + f.name + ": its values do not make a physical circuit";
    return "";
  }
  const int nn = d.n_nodes;
  const int kz = nn + d.n_shafts;
  // Unknowns (volume nodes, then free shafts) as CircuitModel::bind numbers them.
  std::vector<int> unknown_of_z(static_cast<std::size_t>(kz), -1);
  int nu = 0;
  for (int i = 0; i < nn; ++i) {
    if (d.nodes[i].kind == NodeKind::kVolume) unknown_of_z[static_cast<std::size_t>(i)] = nu++;
  }
  for (int sh = 0; sh < d.n_shafts; ++sh) {
    if (!d.shafts[sh].driven) unknown_of_z[static_cast<std::size_t>(nn + sh)] = nu++;
  }
  auto uz = [&](int z) { return unknown_of_z[static_cast<std::size_t>(z)]; };
  std::vector<int> state_z, state_u, stiff_z, stiff_u;
  for (int st = 0; st < check.n_states(); ++st) {
    // The host model numbers shafts after its capacity's nodes; the header's, after n_nodes.
    const int hz = check.state_z(st);
    const int z = hz < host::CircuitCap::kNodes ? hz : nn + (hz - host::CircuitCap::kNodes);
    state_z.push_back(z);
    state_u.push_back(uz(z));
  }
  for (int j = 0; j < check.n_stiff(); ++j) {
    stiff_z.push_back(check.stiff_node(j));
    stiff_u.push_back(uz(check.stiff_node(j)));
  }
  auto is_stiff = [&](int i) { return i < nn && ((d.stiff_mask >> i) & 1u) != 0; };
  ZRef zr{std::vector<bool>(static_cast<std::size_t>(kz), true)};
  for (const int z : state_z) zr.fixed[static_cast<std::size_t>(z)] = false;
  for (const int z : stiff_z) zr.fixed[static_cast<std::size_t>(z)] = false;
  bool coupled = false;
  for (int e = 0; e < d.n_elements; ++e) {
    const circuit::Element& el = d.elements[e];
    if (circuit::has_ports(el.kind) && is_stiff(el.a) && is_stiff(el.b)) coupled = true;
  }
  auto z_name = [&](int z) {
    return z < nn ? f.nodes[static_cast<std::size_t>(z)] : f.shafts[static_cast<std::size_t>(z - nn)];
  };
  auto el_name = [&](int e) { return f.elements[static_cast<std::size_t>(e)]; };
  const int n = check.n_states(), m = check.n_stiff();
  const std::string zt = "T (&z)[" + s(kz) + "]", czt = "const T (&z)[" + s(kz) + "]";

  std::string h;
  auto line = [&h](const std::string& t) { h += t + "\n"; };
  // Structural nonzeros of the unknowns' Jacobian G, element by element as
  // unknowns_jacobian writes them: the rows the balances and rates capture, and the
  // reduction's structure.
  std::vector<std::vector<bool>> nz(static_cast<std::size_t>(nu), std::vector<bool>(static_cast<std::size_t>(nu), false));
  auto G = [&](int r, int col) {
    nz[static_cast<std::size_t>(r)][static_cast<std::size_t>(col)] = true;
    return "G[" + s(r) + "][" + s(col) + "]";
  };
  // The G entries of row r from element e's law values, named as in unknowns_jacobian
  // (Flow f; torque slopes da, db, dw), in unknowns_jacobian's order for that row.
  // sums: the captured row's entries so far (the row's first term into an entry assigns it).
  auto row_lines = [&](int r, const circuit::Element& el, const std::string& indent, Sums& sums) {
    std::vector<std::string> out;
    const bool ports = circuit::has_ports(el.kind);
    const int ua = ports ? uz(el.a) : -1, ub = ports ? uz(el.b) : -1;
    const int us = el.shaft >= 0 ? uz(nn + el.shaft) : -1;
    if (ports && r >= 0 && r == ua) {
      out.push_back(indent + sums.add(G(ua, ua), '-', "f.dpa"));
      if (ub >= 0) out.push_back(indent + sums.add(G(ua, ub), '-', "f.dpb"));
      if (us >= 0) out.push_back(indent + sums.add(G(ua, us), '-', "f.dw"));
    } else if (ports && r >= 0 && r == ub) {
      if (ua >= 0) out.push_back(indent + sums.add(G(ub, ua), '+', "f.dpa"));
      out.push_back(indent + sums.add(G(ub, ub), '+', "f.dpb"));
      if (us >= 0) out.push_back(indent + sums.add(G(ub, us), '+', "f.dw"));
    } else if (circuit::has_shaft(el.kind) && r >= 0 && r == us) {
      if (ports && ua >= 0) out.push_back(indent + sums.add(G(us, ua), '+', "da"));
      if (ports && ub >= 0) out.push_back(indent + sums.add(G(us, ub), '+', "db"));
      out.push_back(indent + sums.add(G(us, us), '+', "dw"));
    }
    return out;
  };
  for (int e = 0; e < d.n_elements; ++e) {
    Sums none;
    for (int r = 0; r < nu; ++r) (void)row_lines(r, d.elements[e], "", none);
  }
  // A captured row starts from zero on each evaluation (a solve evaluates a balance
  // several times; the last evaluation's row is the one kept).
  auto zero_row = [&](int r, const std::string& indent) {
    for (int col = 0; col < nu; ++col) {
      if (nz[static_cast<std::size_t>(r)][static_cast<std::size_t>(col)]) line(indent + G(r, col) + " = T(0);");
    }
  };
  line("#pragma once");
  line("/// @file " + o.name + "_compiled.hpp");
  line("/// GENERATED by hstmon-circuit-header --compiled — do not edit; regenerate (docs/circuits.md).");
  char tick[32];
  std::snprintf(tick, sizeof tick, "%g", o.tick);
  line("/// Circuit \"" + f.name + "\" (" + o.source_note + ") compiled for a " + s(n) + "-state observer at a " +
       tick + " s tick: the");
  line("/// topology of " + o.name + ".hpp as straight-line code (circuit::CompiledModel's Kernel), the");
  line("/// values resolved at run time as the interpreting CircuitModel resolves them.");
  line("");
  line("#include <cstddef>");
  line("#include <cstdint>");
  line("");
  line("#include \"hstmon/circuit/compiled_model.hpp\"");
  line("#include \"hstmon/generated/" + o.name + ".hpp\"");
  line("");
  line("namespace hstmon::generated::" + o.name + " {");
  line("");
  line("/// The hot path of kCircuit, straight-line; m is the CircuitModel<T, Cap> holding the values.");
  line("struct Kernel {");
  line("  using Cap = " + o.name + "::Cap;");
  line("  static constexpr const circuit::Circuit<Cap>& description() noexcept { return kCircuit; }");
  line("  static constexpr int kZ = " + s(kz) + ";  ///< full vector: nodes, then shafts");
  line("  static constexpr int kN = " + s(n) + ";  ///< states");
  line("  static constexpr int kM = " + s(m) + ";  ///< stiff nodes, quasi-steady");
  line("  static constexpr int kU = " + s(nu) + ";  ///< unknowns: volume nodes, then free shafts");
  line("  static constexpr std::uint8_t kStateZ[" + s(n < 1 ? 1 : n) + "] = " + list(state_z) + ";");
  line("  static constexpr std::uint8_t kStateU[" + s(n < 1 ? 1 : n) + "] = " + list(state_u) + ";");
  line("  static constexpr std::uint8_t kStiffZ[" + s(m < 1 ? 1 : m) + "] = " + list(stiff_z) + ";");
  line("  static constexpr std::uint8_t kStiffU[" + s(m < 1 ? 1 : m) + "] = " + list(stiff_u) + ";");
  line("");
  // fill: the states only. The fixed entries are read from the engine where used (ZRef),
  // and solve_stiff, which every caller of fill runs next, writes the stiff nodes first.
  line("  /// The states into the full vector at x (fixed entries: m.fixed_value; stiff nodes:");
  line("  /// solve_stiff, which every caller of fill runs next).");
  line("  template <class M, class X, typename T>");
  line("  HSTMON_CIRCUIT_INLINE static void fill(const M& m, const X& x, " + zt + ") noexcept {");
  line("    (void)m;");
  for (int i = 0; i < n; ++i) {
    const int k = state_z[static_cast<std::size_t>(i)];
    line("    z[" + s(k) + "] = x[" + s(i) + "];  // " + z_name(k));
  }
  line("  }");
  line("");
  // Node balances of the stiff nodes (CircuitModel::node_balance, incidence in element order).
  for (int j = 0; j < m; ++j) {
    const int i = stiff_z[static_cast<std::size_t>(j)];
    line("  /// Net inflow into " + z_name(i) + " [m³/s]; dF its slope by that pressure (≤ 0); with kRow,");
    line("  /// also its row of the unknowns' Jacobian into G (as unknowns_jacobian writes it).");
    line("  template <bool kRow, class M, typename T, class GM>");
    line("  HSTMON_CIRCUIT_INLINE static T balance_" + s(i) + "(const M& m, " + czt + ", T& dF, GM& G) noexcept {");
    line("    T F = T(0);");
    line("    dF = T(0);");
    line("    if constexpr (kRow) {");
    zero_row(uz(i), "      ");
    line("    } else {");
    line("      (void)G;");
    line("    }");
    Sums row;
    for (int e = 0; e < d.n_elements; ++e) {
      const circuit::Element& el = d.elements[e];
      if (!circuit::has_ports(el.kind) || (el.a != i && el.b != i)) continue;
      const bool out = el.a == i;
      line("    {  // " + el_name(e));
      line("      circuit::Flow<T> f;");
      line("      " + flow_call(el, e, nn, zr) + ";");
      line(out ? "      F -= f.q;" : "      F += f.q;");
      line(out ? "      dF -= f.dpa;" : "      dF += f.dpb;");
      line("      if constexpr (kRow) {");
      for (const std::string& t : row_lines(uz(i), el, "        ", row)) line(t);
      line("      }");
      line("    }");
    }
    line("    return F;");
    line("  }");
    line("");
  }
  // The Gauss–Seidel × Newton solve, nodes unrolled.
  line("  /// The quasi-steady solve (quasi_steady.hpp) from guess, which it updates when converged;");
  line("  /// with kRow, the stiff nodes' rows of the unknowns' Jacobian at the last evaluations into G.");
  line("  /// fold: where the closed-form solves' input-constant subexpressions come from — computed");
  line("  /// in place (circuit::Unfolded) or folded once per input change by fold() (circuit::Folded).");
  line("  template <bool kRow, class M, typename T, std::size_t NG, class GM, class Fold = circuit::Unfolded>");
  line("  HSTMON_CIRCUIT_INLINE static bool solve_stiff(const M& m, " + zt +
       ", T (&guess)[NG], GM& G, const Fold& fold = Fold{}) noexcept {");
  // fold(): each closed-form node's laminar terms to fixed pressures, B, c0² and 4·B,
  // written as solve_stiff computes them (the same expressions, so the same values).
  std::vector<std::string> folded;
  const auto fold_at = [&](const std::string& expr) {
    folded.push_back(expr);
    return "fold.at(" + s(static_cast<int>(folded.size()) - 1) + ", " + expr + ")";
  };
  std::vector<std::string> fold_body;
  line("    (void)fold;");
  if (m == 0) {
    line("    (void)m;");
    line("    (void)z;");
    line("    (void)guess;");
    line("    (void)G;");
    line("    return true;");
  } else {
    for (int j = 0; j < m; ++j) line("    z[" + s(stiff_z[static_cast<std::size_t>(j)]) + "] = guess[" + s(j) + "];");
    line("    const T p_env = m.pressure_envelope();");
    line(std::string("    const bool conv = circuit::gauss_seidel(p_env, ") + (coupled ? "true" : "false") +
         ", [&](circuit::Sweep<T>& w) HSTMON_CIRCUIT_LAMBDA_INLINE {");
    for (int j = 0; j < m; ++j) {
      const int iz = stiff_z[static_cast<std::size_t>(j)];
      const std::string i = s(iz);
      line("      w.node(z[" + i + "], [&]() HSTMON_CIRCUIT_LAMBDA_INLINE {");
      // CircuitModel::solve_node's closed form where the node's elements allow it: one
      // orifice, the rest linear in the pressure; the same terms in the same order.
      int orifice = -1;
      bool linear = true;
      for (int e = 0; e < d.n_elements; ++e) {
        const circuit::Element& el = d.elements[e];
        if (!circuit::has_ports(el.kind) || (el.a != iz && el.b != iz)) continue;
        if (el.kind == ElementKind::kOrifice) {
          linear = linear && orifice < 0;
          orifice = e;
        } else if (el.kind != ElementKind::kLaminar && el.kind != ElementKind::kMachine &&
                   el.kind != ElementKind::kFlowSource) {
          linear = false;
        }
      }
      if (linear && orifice >= 0) {
        line("        // One orifice (" + el_name(orifice) + ") and flows linear in the pressure: closed form.");
        line("        T lin = T(0), B = T(0);");
        Sums sums;
        std::vector<std::string> b_terms;
        fold_body.push_back("    {  // " + z_name(iz));
        for (int e = 0; e < d.n_elements; ++e) {
          const circuit::Element& el = d.elements[e];
          if (!circuit::has_ports(el.kind) || (el.a != iz && el.b != iz)) continue;
          const std::string c0 = "m.coeffs(" + s(e) + ").c[0]";
          const char sign = el.a == iz ? '-' : '+';
          switch (el.kind) {
            case ElementKind::kLaminar: {
              const int other = el.a == iz ? el.b : el.a;
              const std::string term = c0 + " * " + zr(other);
              std::string use = term;
              if (zr.fixed[static_cast<std::size_t>(other)]) {  // a laminar term to a fixed pressure
                use = fold_at(term);
                fold_body.push_back("      v[" + s(static_cast<int>(folded.size()) - 1) + "] = " + term + ";");
              }
              line("        " + sums.add("lin", '+', use) + "  // " + el_name(e));
              const std::string b = sums.add("B", '+', c0);
              b_terms.push_back(b);
              line("        " + b);
              break;
            }
            case ElementKind::kMachine:
              line("        " + sums.add("lin", sign, c0 + " * " + zr(nn + el.shaft)) + "  // " + el_name(e));
              break;
            case ElementKind::kFlowSource:
              line("        " + sums.add("lin", sign, c0) + "  // " + el_name(e));
              break;
            default: break;
          }
        }
        const circuit::Element& oe = d.elements[orifice];
        const std::string oc0 = "m.coeffs(" + s(orifice) + ").c[0]";
        line("        B = " + fold_at("B") + ";");
        const std::string c0sq = fold_at(oc0 + " * " + oc0);
        const std::string fourB = fold_at("T(4) * B");
        fold_body.push_back("      T B = T(0);");
        for (const std::string& b : b_terms) fold_body.push_back("      " + b);
        fold_body.push_back("      v[" + s(static_cast<int>(folded.size()) - 3) + "] = B;");
        fold_body.push_back("      v[" + s(static_cast<int>(folded.size()) - 2) + "] = " + oc0 + " * " + oc0 + ";");
        fold_body.push_back("      v[" + s(static_cast<int>(folded.size()) - 1) + "] = T(4) * B;");
        fold_body.push_back("    }");
        line("        T root;");
        line("        if (circuit::solve_node_orifice(z[" + i + "], " + zr(oe.a == iz ? oe.b : oe.a) + ", " + oc0 + ", " +
             c0sq + ", m.coeffs(" + s(orifice) + ").c[1], lin, B, " + fourB + ", root)) {");
        // The node's row from the closed form's own numbers: each law's slopes at the
        // solution (the orifice's c0/(2·root), turbulent there), in unknowns_jacobian's order.
        line("          if constexpr (kRow) {");
        zero_row(uz(iz), "            ");
        Sums row;
        for (int e = 0; e < d.n_elements; ++e) {
          const circuit::Element& el = d.elements[e];
          if (!circuit::has_ports(el.kind) || (el.a != iz && el.b != iz)) continue;
          const std::vector<std::string> rows = row_lines(uz(iz), el, "              ", row);
          if (rows.empty()) continue;
          const std::string c0 = "m.coeffs(" + s(e) + ").c[0]";
          line("            {  // " + el_name(e));
          line("              circuit::Flow<T> f;");
          if (el.kind == ElementKind::kOrifice) {
            line("              f.dpa = " + c0 + " * (T(0.5) / root);");
            line("              f.dpb = -f.dpa;");
          } else if (el.kind == ElementKind::kLaminar) {
            line("              f.dpa = " + c0 + ";");
            line("              f.dpb = -" + c0 + ";");
          } else if (el.kind == ElementKind::kMachine) {
            line("              f.dw = " + c0 + ";");
          }
          for (const std::string& t : rows) line(t);
          line("            }");
        }
        line("          } else {");
        line("            (void)root;");
        line("          }");
        line("          return true;");
        line("        }");
      }
      line("        return circuit::solve_node_newton(z[" + i + "], p_env, [&](T p, T& dF) HSTMON_CIRCUIT_LAMBDA_INLINE {");
      line("          z[" + i + "] = p;");
      line("          return balance_" + i + "<kRow>(m, z, dF, G);");
      line("        });");
      line("      });");
    }
    line("    });");
    line("    if (conv) {");
    for (int j = 0; j < m; ++j) line("      guess[" + s(j) + "] = z[" + s(stiff_z[static_cast<std::size_t>(j)]) + "];");
    line("    }");
    line("    return conv;");
  }
  line("  }");
  line("");
  line("  /// Number of values fold() writes (at least 1: an array's extent).");
  line("  static constexpr int kFolded = " + s(folded.empty() ? 1 : static_cast<int>(folded.size())) + ";");
  line("  /// solve_stiff's input-constant subexpressions under m's current values, computed as");
  line("  /// solve_stiff computes them (the same expressions: the same values), for circuit::Folded.");
  line("  template <class M, typename T>");
  line("  static void fold(const M& m, T (&v)[kFolded]) noexcept {");
  line("    (void)m;");
  if (folded.empty()) line("    v[0] = T(0);");
  for (const std::string& t : fold_body) line(t);
  line("  }");
  line("");
  // Rates (CircuitModel::rates).
  line("  /// The states' rates [Pa/s, rad/s²] into d; with kRow, the states' rows of the unknowns'");
  line("  /// Jacobian into G (as unknowns_jacobian writes them).");
  line("  template <bool kRow, class M, class D, typename T, class GM>");
  line("  HSTMON_CIRCUIT_INLINE static void rates(const M& m, " + czt + ", D& d, GM& G) noexcept {");
  line("    if constexpr (kRow) {");
  for (int st = 0; st < n; ++st) zero_row(state_u[static_cast<std::size_t>(st)], "      ");
  line("    } else {");
  line("      (void)G;");
  line("    }");
  for (int st = 0; st < n; ++st) {
    const int zs = state_z[static_cast<std::size_t>(st)];
    const int r = state_u[static_cast<std::size_t>(st)];
    line("    {  // " + z_name(zs));
    line("      T g = T(0);");
    Sums sums;  // g, and the state's row of G
    for (int e = 0; e < d.n_elements; ++e) {
      const circuit::Element& el = d.elements[e];
      if (zs < nn) {
        if (!circuit::has_ports(el.kind) || (el.a != zs && el.b != zs)) continue;
        line("      {  // " + el_name(e));
        line("        circuit::Flow<T> f;");
        line("        " + flow_call(el, e, nn, zr) + ";");
        line("        " + sums.add("g", el.a == zs ? '-' : '+', "f.q"));
      } else {
        if (!circuit::has_shaft(el.kind) || el.shaft != zs - nn) continue;
        line("      {  // " + el_name(e));
        line("        T da, db, dw;");
        line("        " + sums.add("g", '+', torque_call(el, e, nn, zr)));
      }
      const std::vector<std::string> rows = row_lines(r, el, "          ", sums);
      if (!rows.empty()) {
        line("        if constexpr (kRow) {");
        for (const std::string& t : rows) line(t);
        line("        }");
      }
      line("      }");
    }
    line("      d[" + s(st) + "] = m.node_stiffness(" + s(zs) + ") * g;");
    line("    }");
  }
  line("  }");
  line("");
  // Outputs (CircuitModel::outputs_at).
  line("  /// What each channel measures [SI] into y.");
  line("  template <class M, class Y, typename T>");
  line("  HSTMON_CIRCUIT_INLINE static void outputs(const M& m, " + czt + ", Y& y) noexcept {");
  bool uses_m = false;
  for (int ch = 0; ch < d.n_channels; ++ch) {
    const circuit::Channel& k = d.channels[ch];
    const std::string note = "  // " + f.sensors[static_cast<std::size_t>(ch)].name;
    if (k.kind == circuit::ChannelKind::kPressure || k.kind == circuit::ChannelKind::kSpeed) {
      const int z = k.kind == circuit::ChannelKind::kPressure ? k.index : nn + k.index;
      line("    y[" + s(ch) + "] = " + zr(z) + ";" + note);
      uses_m = uses_m || zr.fixed[static_cast<std::size_t>(z)];
    } else {
      line("    {" + note);
      line("      circuit::Flow<T> f;");
      line("      " + flow_call(d.elements[k.index], k.index, nn, zr) + ";");
      line("      y[" + s(ch) + "] = f.q;");
      line("    }");
      uses_m = true;
    }
  }
  if (!uses_m) line("    (void)m;");
  line("  }");
  line("");
  // The unknowns' Jacobian (CircuitModel::unknowns_jacobian), nonzeros in element order.
  line("  /// ∂(net of unknown r)/∂(unknown c) at z onto a zeroed G (CircuitModel::unknowns_jacobian).");
  line("  template <class M, typename T, std::size_t U>");
  line("  HSTMON_CIRCUIT_INLINE static void unknowns_jacobian(const M& m, " + czt + ", T (&G)[U][U]) noexcept {");
  for (int e = 0; e < d.n_elements; ++e) {
    const circuit::Element& el = d.elements[e];
    const bool ports = circuit::has_ports(el.kind);
    const int ua = ports ? uz(el.a) : -1, ub = ports ? uz(el.b) : -1;
    const int us = el.shaft >= 0 ? uz(nn + el.shaft) : -1;
    const bool flow_rows = ports && (ua >= 0 || ub >= 0);
    const bool torque_row = circuit::has_shaft(el.kind) && us >= 0;
    if (!flow_rows && !torque_row) continue;
    line("    {  // " + el_name(e));
    if (flow_rows) {
      line("      circuit::Flow<T> f;");
      line("      " + flow_call(el, e, nn, zr) + ";");
      if (ua >= 0) {
        line("      " + G(ua, ua) + " -= f.dpa;");
        if (ub >= 0) line("      " + G(ua, ub) + " -= f.dpb;");
      }
      if (ub >= 0) {
        if (ua >= 0) line("      " + G(ub, ua) + " += f.dpa;");
        line("      " + G(ub, ub) + " += f.dpb;");
      }
      if (el.shaft >= 0 && us >= 0) {
        if (ua >= 0) line("      " + G(ua, us) + " -= f.dw;");
        if (ub >= 0) line("      " + G(ub, us) + " += f.dw;");
      }
    }
    if (torque_row) {
      line("      T da, db, dw;");
      line("      (void)" + torque_call(el, e, nn, zr) + ";");
      if (ports) {
        if (ua >= 0) line("      " + G(us, ua) + " += da;");
        if (ub >= 0) line("      " + G(us, ub) + " += db;");
      }
      line("      " + G(us, us) + " += dw;");
    }
    line("    }");
  }
  line("  }");
  line("");
  emit_schur(line, nz, stiff_u, state_u);
  line("};");
  line("");
  line("/// The Observer's model of this circuit, compiled (float in firmware, double on the host).");
  line("template <typename T>");
  line("using CompiledModel = circuit::CompiledModel<T, Kernel>;");
  line("");
  line("}  // namespace hstmon::generated::" + o.name);
  return h;
}

}  // namespace hstmon::circuit_tools
