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


// Writes the Kernel of one circuit, section by section in the header's order. The sections
// share what the circuit's structure fixes (unknown numbering, states, stiff nodes, which
// entries are fixed) and two things that grow as they are written: the structural nonzeros
// of G (nz) and the values fold() computes (folded, fold_body).
class KernelWriter {
 public:
  KernelWriter(const host::CircuitFile& f, const CircuitHeaderOptions& o, const host::HostCircuit& d,
               const host::HostCircuitModel& check)
      : f_(f), o_(o), d_(d), nn_(d.n_nodes), kz_(d.n_nodes + d.n_shafts), n_(check.n_states()), m_(check.n_stiff()),
        zt_("T (&z)[" + s(kz_) + "]"), czt_("const T (&z)[" + s(kz_) + "]") {
    number_unknowns();
    list_states_and_stiff_nodes(check);
    mark_jacobian_structure();
  }

  /// The whole header text.
  std::string write() {
    write_preamble();
    write_fill();
    for (int j = 0; j < m_; ++j) write_balance(stiff_z_[static_cast<std::size_t>(j)]);
    write_solve_stiff();
    write_fold();
    write_rates();
    write_outputs();
    write_unknowns_jacobian();
    auto put = [this](const std::string& t) { line(t); };
    emit_schur(put, nz_, stiff_u_, state_u_);
    write_epilogue();
    return h_;
  }

 private:
  // Unknowns (volume nodes, then free shafts) as CircuitModel::bind numbers them.
  void number_unknowns() {
    unknown_of_z_.assign(static_cast<std::size_t>(kz_), -1);
    for (int i = 0; i < nn_; ++i) {
      if (d_.nodes[i].kind == NodeKind::kVolume) unknown_of_z_[static_cast<std::size_t>(i)] = nu_++;
    }
    for (int sh = 0; sh < d_.n_shafts; ++sh) {
      if (!d_.shafts[sh].driven) unknown_of_z_[static_cast<std::size_t>(nn_ + sh)] = nu_++;
    }
  }

  void list_states_and_stiff_nodes(const host::HostCircuitModel& check) {
    for (int st = 0; st < n_; ++st) {
      // The host model numbers shafts after its capacity's nodes; the header's, after n_nodes.
      const int hz = check.state_z(st);
      const int z = hz < host::CircuitCap::kNodes ? hz : nn_ + (hz - host::CircuitCap::kNodes);
      state_z_.push_back(z);
      state_u_.push_back(uz(z));
    }
    for (int j = 0; j < m_; ++j) {
      stiff_z_.push_back(check.stiff_node(j));
      stiff_u_.push_back(uz(check.stiff_node(j)));
    }
    zr_.fixed.assign(static_cast<std::size_t>(kz_), true);
    for (const int z : state_z_) zr_.fixed[static_cast<std::size_t>(z)] = false;
    for (const int z : stiff_z_) zr_.fixed[static_cast<std::size_t>(z)] = false;
    for (int e = 0; e < d_.n_elements; ++e) {
      const circuit::Element& el = d_.elements[e];
      if (circuit::has_ports(el.kind) && is_stiff(el.a) && is_stiff(el.b)) coupled_ = true;
    }
  }

  // Structural nonzeros of the unknowns' Jacobian G, element by element as
  // unknowns_jacobian writes them: the rows the balances and rates capture, and the
  // reduction's structure.
  void mark_jacobian_structure() {
    nz_.assign(static_cast<std::size_t>(nu_), std::vector<bool>(static_cast<std::size_t>(nu_), false));
    for (int e = 0; e < d_.n_elements; ++e) {
      Sums none;
      for (int r = 0; r < nu_; ++r) (void)row_lines(r, d_.elements[e], "", none);
    }
  }

  int uz(int z) const { return unknown_of_z_[static_cast<std::size_t>(z)]; }
  bool is_stiff(int i) const { return i < nn_ && ((d_.stiff_mask >> i) & 1u) != 0; }
  /// Whether element el has a port on node i.
  static bool on_node(const circuit::Element& el, int i) {
    return circuit::has_ports(el.kind) && (el.a == i || el.b == i);
  }
  const std::string& z_name(int z) const {
    return z < nn_ ? f_.nodes[static_cast<std::size_t>(z)] : f_.shafts[static_cast<std::size_t>(z - nn_)];
  }
  const std::string& el_name(int e) const { return f_.elements[static_cast<std::size_t>(e)]; }
  void line(const std::string& t) { h_ += t + "\n"; }

  std::string G(int r, int col) {
    nz_[static_cast<std::size_t>(r)][static_cast<std::size_t>(col)] = true;
    return "G[" + s(r) + "][" + s(col) + "]";
  }

  // The G entries of row r from element e's law values, named as in unknowns_jacobian
  // (Flow f; torque slopes da, db, dw), in unknowns_jacobian's order for that row.
  // sums: the captured row's entries so far (the row's first term into an entry assigns it).
  std::vector<std::string> row_lines(int r, const circuit::Element& el, const std::string& indent, Sums& sums) {
    std::vector<std::string> out;
    const bool ports = circuit::has_ports(el.kind);
    const int ua = ports ? uz(el.a) : -1, ub = ports ? uz(el.b) : -1;
    const int us = el.shaft >= 0 ? uz(nn_ + el.shaft) : -1;
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
  }

  // A captured row starts from zero on each evaluation (a solve evaluates a balance
  // several times; the last evaluation's row is the one kept).
  void zero_row(int r, const std::string& indent) {
    for (int col = 0; col < nu_; ++col) {
      if (nz_[static_cast<std::size_t>(r)][static_cast<std::size_t>(col)]) line(indent + G(r, col) + " = T(0);");
    }
  }

  // An input-constant subexpression of solve_stiff: fold() computes it; solve_stiff reads it.
  std::string fold_at(const std::string& expr) {
    folded_.push_back(expr);
    return "fold.at(" + s(last_folded()) + ", " + expr + ")";
  }
  int last_folded() const { return static_cast<int>(folded_.size()) - 1; }

  void write_preamble() {
    line("#pragma once");
    line("/// @file " + o_.name + "_compiled.hpp");
    line("/// GENERATED by hstmon-circuit-header --compiled — do not edit; regenerate (docs/circuits.md).");
    char tick[32];
    std::snprintf(tick, sizeof tick, "%g", o_.tick);
    line("/// Circuit \"" + f_.name + "\" (" + o_.source_note + ") compiled for a " + s(n_) + "-state observer at a " +
         tick + " s tick: the");
    line("/// topology of " + o_.name + ".hpp as straight-line code (circuit::CompiledModel's Kernel), the");
    line("/// values resolved at run time as the interpreting CircuitModel resolves them.");
    line("");
    line("#include <cstddef>");
    line("#include <cstdint>");
    line("");
    line("#include \"hstmon/circuit/compiled_model.hpp\"");
    line("#include \"hstmon/generated/" + o_.name + ".hpp\"");
    line("");
    line("namespace hstmon::generated::" + o_.name + " {");
    line("");
    line("/// The hot path of kCircuit, straight-line; m is the CircuitModel<T, Cap> holding the values.");
    line("struct Kernel {");
    line("  using Cap = " + o_.name + "::Cap;");
    line("  static constexpr const circuit::Circuit<Cap>& description() noexcept { return kCircuit; }");
    line("  static constexpr int kZ = " + s(kz_) + ";  ///< full vector: nodes, then shafts");
    line("  static constexpr int kN = " + s(n_) + ";  ///< states");
    line("  static constexpr int kM = " + s(m_) + ";  ///< stiff nodes, quasi-steady");
    line("  static constexpr int kU = " + s(nu_) + ";  ///< unknowns: volume nodes, then free shafts");
    line("  static constexpr std::uint8_t kStateZ[" + s(n_ < 1 ? 1 : n_) + "] = " + list(state_z_) + ";");
    line("  static constexpr std::uint8_t kStateU[" + s(n_ < 1 ? 1 : n_) + "] = " + list(state_u_) + ";");
    line("  static constexpr std::uint8_t kStiffZ[" + s(m_ < 1 ? 1 : m_) + "] = " + list(stiff_z_) + ";");
    line("  static constexpr std::uint8_t kStiffU[" + s(m_ < 1 ? 1 : m_) + "] = " + list(stiff_u_) + ";");
    line("");
  }

  // fill: the states only. The fixed entries are read from the engine where used (ZRef),
  // and solve_stiff, which every caller of fill runs next, writes the stiff nodes first.
  void write_fill() {
    line("  /// The states into the full vector at x (fixed entries: m.fixed_value; stiff nodes:");
    line("  /// solve_stiff, which every caller of fill runs next).");
    line("  template <class M, class X, typename T>");
    line("  HSTMON_CIRCUIT_INLINE static void fill(const M& m, const X& x, " + zt_ + ") noexcept {");
    line("    (void)m;");
    for (int i = 0; i < n_; ++i) {
      const int k = state_z_[static_cast<std::size_t>(i)];
      line("    z[" + s(k) + "] = x[" + s(i) + "];  // " + z_name(k));
    }
    line("  }");
    line("");
  }

  // Node balance of stiff node i (CircuitModel::node_balance, incidence in element order).
  void write_balance(int i) {
    line("  /// Net inflow into " + z_name(i) + " [m³/s]; dF its slope by that pressure (≤ 0); with kRow,");
    line("  /// also its row of the unknowns' Jacobian into G (as unknowns_jacobian writes it).");
    line("  template <bool kRow, class M, typename T, class GM>");
    line("  HSTMON_CIRCUIT_INLINE static T balance_" + s(i) + "(const M& m, " + czt_ + ", T& dF, GM& G) noexcept {");
    line("    T F = T(0);");
    line("    dF = T(0);");
    line("    if constexpr (kRow) {");
    zero_row(uz(i), "      ");
    line("    } else {");
    line("      (void)G;");
    line("    }");
    Sums row;
    for (int e = 0; e < d_.n_elements; ++e) {
      const circuit::Element& el = d_.elements[e];
      if (!on_node(el, i)) continue;
      const bool out = el.a == i;
      line("    {  // " + el_name(e));
      line("      circuit::Flow<T> f;");
      line("      " + flow_call(el, e, nn_, zr_) + ";");
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
  void write_solve_stiff() {
    line("  /// The quasi-steady solve (quasi_steady.hpp) from guess, which it updates when converged;");
    line("  /// with kRow, the stiff nodes' rows of the unknowns' Jacobian at the last evaluations into G.");
    line("  /// fold: where the closed-form solves' input-constant subexpressions come from — computed");
    line("  /// in place (circuit::Unfolded) or folded once per input change by fold() (circuit::Folded).");
    line("  template <bool kRow, class M, typename T, std::size_t NG, class GM, class Fold = circuit::Unfolded>");
    line("  HSTMON_CIRCUIT_INLINE static bool solve_stiff(const M& m, " + zt_ +
         ", T (&guess)[NG], GM& G, const Fold& fold = Fold{}) noexcept {");
    line("    (void)fold;");
    if (m_ == 0) {
      line("    (void)m;");
      line("    (void)z;");
      line("    (void)guess;");
      line("    (void)G;");
      line("    return true;");
    } else {
      for (int j = 0; j < m_; ++j) line("    z[" + s(stiff_z_[static_cast<std::size_t>(j)]) + "] = guess[" + s(j) + "];");
      line("    const T p_env = m.pressure_envelope();");
      line(std::string("    const bool conv = circuit::gauss_seidel(p_env, ") + (coupled_ ? "true" : "false") +
           ", [&](circuit::Sweep<T>& w) HSTMON_CIRCUIT_LAMBDA_INLINE {");
      for (int j = 0; j < m_; ++j) write_node_solve(stiff_z_[static_cast<std::size_t>(j)]);
      line("    });");
      line("    if (conv) {");
      for (int j = 0; j < m_; ++j) line("      guess[" + s(j) + "] = z[" + s(stiff_z_[static_cast<std::size_t>(j)]) + "];");
      line("    }");
      line("    return conv;");
    }
    line("  }");
    line("");
  }

  // One stiff node's step of the sweep: the closed form where it applies, else Newton on its balance.
  void write_node_solve(int iz) {
    const std::string i = s(iz);
    line("      w.node(z[" + i + "], [&]() HSTMON_CIRCUIT_LAMBDA_INLINE {");
    const int orifice = closed_form_orifice(iz);
    if (orifice >= 0) write_closed_form(iz, orifice);
    line("        return circuit::solve_node_newton(z[" + i + "], p_env, [&](T p, T& dF) HSTMON_CIRCUIT_LAMBDA_INLINE {");
    line("          z[" + i + "] = p;");
    line("          return balance_" + i + "<kRow>(m, z, dF, G);");
    line("        });");
    line("      });");
  }

  // CircuitModel::solve_node's closed form applies where the node's elements allow it: one
  // orifice, the rest linear in the pressure. The orifice's element number, or -1.
  int closed_form_orifice(int iz) const {
    int orifice = -1;
    bool linear = true;
    for (int e = 0; e < d_.n_elements; ++e) {
      const circuit::Element& el = d_.elements[e];
      if (!on_node(el, iz)) continue;
      if (el.kind == ElementKind::kOrifice) {
        linear = linear && orifice < 0;
        orifice = e;
      } else if (el.kind != ElementKind::kLaminar && el.kind != ElementKind::kMachine &&
                 el.kind != ElementKind::kFlowSource) {
        linear = false;
      }
    }
    return linear ? orifice : -1;
  }

  // The closed form: the same terms in the same order as solve_node; fold(): the node's laminar
  // terms to fixed pressures, B, c0² and 4·B, written as solve_stiff computes them (the same
  // expressions, so the same values).
  void write_closed_form(int iz, int orifice) {
    line("        // One orifice (" + el_name(orifice) + ") and flows linear in the pressure: closed form.");
    line("        T lin = T(0), B = T(0);");
    fold_body_.push_back("    {  // " + z_name(iz));
    const std::vector<std::string> b_terms = write_linear_terms(iz);
    const circuit::Element& oe = d_.elements[orifice];
    const std::string oc0 = "m.coeffs(" + s(orifice) + ").c[0]";
    line("        B = " + fold_at("B") + ";");
    const std::string c0sq = fold_at(oc0 + " * " + oc0);
    const std::string fourB = fold_at("T(4) * B");
    fold_body_.push_back("      T B = T(0);");
    for (const std::string& b : b_terms) fold_body_.push_back("      " + b);
    fold_body_.push_back("      v[" + s(last_folded() - 2) + "] = B;");
    fold_body_.push_back("      v[" + s(last_folded() - 1) + "] = " + oc0 + " * " + oc0 + ";");
    fold_body_.push_back("      v[" + s(last_folded()) + "] = T(4) * B;");
    fold_body_.push_back("    }");
    line("        T root;");
    line("        if (circuit::solve_node_orifice(z[" + s(iz) + "], " + zr_(oe.a == iz ? oe.b : oe.a) + ", " + oc0 +
         ", " + c0sq + ", m.coeffs(" + s(orifice) + ").c[1], lin, B, " + fourB + ", root)) {");
    write_closed_form_row(iz);
    line("          return true;");
    line("        }");
  }

  // The sums lin (flows linear in the pressure, without it) and B (their slopes) of node iz;
  // returns B's statements, which fold() repeats.
  std::vector<std::string> write_linear_terms(int iz) {
    Sums sums;
    std::vector<std::string> b_terms;
    for (int e = 0; e < d_.n_elements; ++e) {
      const circuit::Element& el = d_.elements[e];
      if (!on_node(el, iz)) continue;
      const std::string c0 = "m.coeffs(" + s(e) + ").c[0]";
      const char sign = el.a == iz ? '-' : '+';
      switch (el.kind) {
        case ElementKind::kLaminar: {
          const int other = el.a == iz ? el.b : el.a;
          const std::string term = c0 + " * " + zr_(other);
          std::string use = term;
          if (zr_.fixed[static_cast<std::size_t>(other)]) {  // a laminar term to a fixed pressure
            use = fold_at(term);
            fold_body_.push_back("      v[" + s(last_folded()) + "] = " + term + ";");
          }
          line("        " + sums.add("lin", '+', use) + "  // " + el_name(e));
          const std::string b = sums.add("B", '+', c0);
          b_terms.push_back(b);
          line("        " + b);
          break;
        }
        case ElementKind::kMachine:
          line("        " + sums.add("lin", sign, c0 + " * " + zr_(nn_ + el.shaft)) + "  // " + el_name(e));
          break;
        case ElementKind::kFlowSource:
          line("        " + sums.add("lin", sign, c0) + "  // " + el_name(e));
          break;
        default: break;
      }
    }
    return b_terms;
  }

  // The node's row from the closed form's own numbers: each law's slopes at the
  // solution (the orifice's c0/(2·root), turbulent there), in unknowns_jacobian's order.
  void write_closed_form_row(int iz) {
    line("          if constexpr (kRow) {");
    zero_row(uz(iz), "            ");
    Sums row;
    for (int e = 0; e < d_.n_elements; ++e) {
      const circuit::Element& el = d_.elements[e];
      if (!on_node(el, iz)) continue;
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
  }

  // After write_solve_stiff, which collects what fold() computes.
  void write_fold() {
    line("  /// Number of values fold() writes (at least 1: an array's extent).");
    line("  static constexpr int kFolded = " + s(folded_.empty() ? 1 : static_cast<int>(folded_.size())) + ";");
    line("  /// solve_stiff's input-constant subexpressions under m's current values, computed as");
    line("  /// solve_stiff computes them (the same expressions: the same values), for circuit::Folded.");
    line("  template <class M, typename T>");
    line("  static void fold(const M& m, T (&v)[kFolded]) noexcept {");
    line("    (void)m;");
    if (folded_.empty()) line("    v[0] = T(0);");
    for (const std::string& t : fold_body_) line(t);
    line("  }");
    line("");
  }

  // Rates (CircuitModel::rates).
  void write_rates() {
    line("  /// The states' rates [Pa/s, rad/s²] into d; with kRow, the states' rows of the unknowns'");
    line("  /// Jacobian into G (as unknowns_jacobian writes them).");
    line("  template <bool kRow, class M, class D, typename T, class GM>");
    line("  HSTMON_CIRCUIT_INLINE static void rates(const M& m, " + czt_ + ", D& d, GM& G) noexcept {");
    line("    if constexpr (kRow) {");
    for (int st = 0; st < n_; ++st) zero_row(state_u_[static_cast<std::size_t>(st)], "      ");
    line("    } else {");
    line("      (void)G;");
    line("    }");
    for (int st = 0; st < n_; ++st) write_state_rate(st);
    line("  }");
    line("");
  }

  // State st's rate: the net flow into its node or the net torque on its shaft, times its stiffness.
  void write_state_rate(int st) {
    const int zs = state_z_[static_cast<std::size_t>(st)];
    const int r = state_u_[static_cast<std::size_t>(st)];
    line("    {  // " + z_name(zs));
    line("      T g = T(0);");
    Sums sums;  // g, and the state's row of G
    for (int e = 0; e < d_.n_elements; ++e) {
      const circuit::Element& el = d_.elements[e];
      if (zs < nn_) {
        if (!on_node(el, zs)) continue;
        line("      {  // " + el_name(e));
        line("        circuit::Flow<T> f;");
        line("        " + flow_call(el, e, nn_, zr_) + ";");
        line("        " + sums.add("g", el.a == zs ? '-' : '+', "f.q"));
      } else {
        if (!circuit::has_shaft(el.kind) || el.shaft != zs - nn_) continue;
        line("      {  // " + el_name(e));
        line("        T da, db, dw;");
        line("        " + sums.add("g", '+', torque_call(el, e, nn_, zr_)));
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

  // Outputs (CircuitModel::outputs_at).
  void write_outputs() {
    line("  /// What each channel measures [SI] into y.");
    line("  template <class M, class Y, typename T>");
    line("  HSTMON_CIRCUIT_INLINE static void outputs(const M& m, " + czt_ + ", Y& y) noexcept {");
    bool uses_m = false;
    for (int ch = 0; ch < d_.n_channels; ++ch) {
      const circuit::Channel& k = d_.channels[ch];
      const std::string note = "  // " + f_.sensors[static_cast<std::size_t>(ch)].name;
      if (k.kind == circuit::ChannelKind::kPressure || k.kind == circuit::ChannelKind::kSpeed) {
        const int z = k.kind == circuit::ChannelKind::kPressure ? k.index : nn_ + k.index;
        line("    y[" + s(ch) + "] = " + zr_(z) + ";" + note);
        uses_m = uses_m || zr_.fixed[static_cast<std::size_t>(z)];
      } else {
        line("    {" + note);
        line("      circuit::Flow<T> f;");
        line("      " + flow_call(d_.elements[k.index], k.index, nn_, zr_) + ";");
        line("      y[" + s(ch) + "] = f.q;");
        line("    }");
        uses_m = true;
      }
    }
    if (!uses_m) line("    (void)m;");
    line("  }");
    line("");
  }

  // The unknowns' Jacobian (CircuitModel::unknowns_jacobian), nonzeros in element order.
  void write_unknowns_jacobian() {
    line("  /// ∂(net of unknown r)/∂(unknown c) at z onto a zeroed G (CircuitModel::unknowns_jacobian).");
    line("  template <class M, typename T, std::size_t U>");
    line("  HSTMON_CIRCUIT_INLINE static void unknowns_jacobian(const M& m, " + czt_ + ", T (&G)[U][U]) noexcept {");
    for (int e = 0; e < d_.n_elements; ++e) write_element_jacobian(e);
    line("  }");
    line("");
  }

  // Element e's terms of the unknowns' Jacobian: its flow's slopes into its ports' rows, its
  // torque's into its shaft's row.
  void write_element_jacobian(int e) {
    const circuit::Element& el = d_.elements[e];
    const bool ports = circuit::has_ports(el.kind);
    const int ua = ports ? uz(el.a) : -1, ub = ports ? uz(el.b) : -1;
    const int us = el.shaft >= 0 ? uz(nn_ + el.shaft) : -1;
    const bool flow_rows = ports && (ua >= 0 || ub >= 0);
    const bool torque_row = circuit::has_shaft(el.kind) && us >= 0;
    if (!flow_rows && !torque_row) return;
    line("    {  // " + el_name(e));
    if (flow_rows) {
      line("      circuit::Flow<T> f;");
      line("      " + flow_call(el, e, nn_, zr_) + ";");
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
      line("      (void)" + torque_call(el, e, nn_, zr_) + ";");
      if (ports) {
        if (ua >= 0) line("      " + G(us, ua) + " += da;");
        if (ub >= 0) line("      " + G(us, ub) + " += db;");
      }
      line("      " + G(us, us) + " += dw;");
    }
    line("    }");
  }

  void write_epilogue() {
    line("};");
    line("");
    line("/// The Observer's model of this circuit, compiled (float in firmware, double on the host).");
    line("template <typename T>");
    line("using CompiledModel = circuit::CompiledModel<T, Kernel>;");
    line("");
    line("}  // namespace hstmon::generated::" + o_.name);
  }

  const host::CircuitFile& f_;
  const CircuitHeaderOptions& o_;
  const host::HostCircuit& d_;
  const int nn_;   ///< nodes
  const int kz_;   ///< full vector: nodes, then shafts
  const int n_;    ///< states
  const int m_;    ///< stiff nodes
  const std::string zt_, czt_;  ///< the parameter z, writable and read-only
  int nu_ = 0;     ///< unknowns
  std::vector<int> unknown_of_z_, state_z_, state_u_, stiff_z_, stiff_u_;
  ZRef zr_;
  bool coupled_ = false;  ///< two stiff nodes share an element: the sweep iterates
  std::vector<std::vector<bool>> nz_;
  std::vector<std::string> folded_;     ///< fold()'s values, in order
  std::vector<std::string> fold_body_;  ///< fold()'s statements
  std::string h_;
};

}  // namespace

std::string circuit_compiled_header(const LoadedCircuit& c, const CircuitHeaderOptions& o, std::string& error) {
  error.clear();
  const host::HostCircuit d = header_description(c, o.tick);
  const host::HostCircuitModel check(d, c.values.params, c.values.inputs);
  if (check.error() != circuit::CircuitError::kOk || !check.valid()) {
    error = "circuit " + c.file.name + ": its values do not make a physical circuit";
    return "";
  }
  return KernelWriter(c.file, o, d, check).write();
}

}  // namespace hstmon::circuit_tools
