/// @file forward.cpp
#include "hstmon_fdi/forward.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <stdexcept>

#include "hstmon_fdi/qual.hpp"

namespace hstmon::fdi {

namespace {

/// Nodes in an order where every instantaneous edge runs forward (Kahn's algorithm).
std::vector<int> instant_order(const CausalGraph& g) {
  const std::size_t n = g.nodes().size();
  std::vector<int> indegree(n, 0);
  for (const Edge& e : g.edges()) {
    if (e.type == EdgeType::kDerivative) throw std::invalid_argument("forward propagation: derivative edges are not supported");
    if (e.type == EdgeType::kInstant) ++indegree[static_cast<std::size_t>(e.to)];
  }
  std::vector<int> order;
  for (std::size_t i = 0; i < n; ++i) {
    if (indegree[i] == 0) order.push_back(static_cast<int>(i));
  }
  for (std::size_t k = 0; k < order.size(); ++k) {
    for (int ei : g.out_edges(order[k])) {
      const Edge& e = g.edges()[static_cast<std::size_t>(ei)];
      if (e.type == EdgeType::kInstant && --indegree[static_cast<std::size_t>(e.to)] == 0) order.push_back(e.to);
    }
  }
  if (order.size() != n) throw std::invalid_argument("forward propagation: algebraic loop in the causal graph");
  return order;
}

void check_fault(const CausalGraph& g, const std::vector<ParamStep>& fault) {
  for (const ParamStep& s : fault) {
    bool known = false;
    for (const Edge& e : g.edges()) known = known || e.param == s.param;
    const int n = g.find(s.param);
    known = known || (n >= 0 && g.nodes()[static_cast<std::size_t>(n)].kind == NodeKind::kSource);
    if (!known) throw std::invalid_argument("unknown parameter or source: " + s.param);
    if (s.sign != 1 && s.sign != -1) throw std::invalid_argument("parameter step sign must be +1 or -1");
  }
}

/// Signed step of edge/source `name` in the fault, or 0.
int step_of(const std::vector<ParamStep>& fault, const std::string& name) {
  int s = 0;
  for (const ParamStep& p : fault) {
    if (p.param == name) s += p.sign;
  }
  return s;
}

/// Qualitative values: signs.
struct QualAlgebra {
  using Value = QualSign;
  static Value zero() { return kQualZero; }
  static Value through(const Edge& e, Value v) { return qual_mul(e.sign, v); }
  static Value injected(const Edge& e, int step) { return qual_of(step * e.param_sign); }
  static Value source(const Node&, int step) { return qual_of(step); }
  static Value add(Value a, Value b) { return qual_add(a, b); }
  static QualSign sign(Value v) { return v; }
};

/// Weighted values: value and the sum of absolute contributions, to tell a cancellation from a value.
struct Weighted {
  double v = 0.0;
  double a = 0.0;
};
struct WeightedAlgebra {
  using Value = Weighted;
  static Value zero() { return {}; }
  static Value through(const Edge& e, Value x) { return {e.sign * e.gain * x.v, e.gain * x.a}; }
  static Value injected(const Edge& e, int step) { return {step * e.injection, std::fabs(e.injection)}; }
  static Value source(const Node& n, int step) { return {step * n.value, std::fabs(n.value)}; }
  static Value add(Value x, Value y) { return {x.v + y.v, x.a + y.a}; }
  static QualSign sign(Value x) { return qual_from_value(x.v, 1e-9 * x.a); }
};

/// Derivatives k = 0…max_order at 0+ of every node: value[k][node].
template <class Alg>
std::vector<ChannelPrediction> propagate(const CausalGraph& g, const std::vector<ParamStep>& fault, int max_order,
                                         const std::vector<std::string>& measured) {
  if (max_order < 0) throw std::invalid_argument("max_order must be >= 0");
  check_fault(g, fault);
  const std::vector<int> order = instant_order(g);
  const std::size_t n = g.nodes().size();
  std::vector<std::vector<typename Alg::Value>> d(static_cast<std::size_t>(max_order) + 1,
                                                  std::vector<typename Alg::Value>(n, Alg::zero()));
  for (int k = 0; k <= max_order; ++k) {
    std::vector<typename Alg::Value>& cur = d[static_cast<std::size_t>(k)];
    for (int node : order) {
      const Node& nd = g.nodes()[static_cast<std::size_t>(node)];
      typename Alg::Value v = Alg::zero();
      // A step in a source is a jump at 0+: it shows in the 0th derivative only.
      if (nd.kind == NodeKind::kSource && k == 0) {
        const int s = step_of(fault, nd.name);
        if (s != 0) v = Alg::source(nd, s);
      }
      for (int ei : g.in_edges(node)) {
        const Edge& e = g.edges()[static_cast<std::size_t>(ei)];
        const bool dt = e.type == EdgeType::kIntegral;
        // A dt edge feeds the (k−1)-th derivative of its source into the k-th of its target.
        if (!dt) v = Alg::add(v, Alg::through(e, cur[static_cast<std::size_t>(e.from)]));
        else if (k > 0) v = Alg::add(v, Alg::through(e, d[static_cast<std::size_t>(k - 1)][static_cast<std::size_t>(e.from)]));
        // A parameter step jumps an algebraic relation (k = 0) or the rate of a dt edge (k = 1).
        if (!e.param.empty() && k == (dt ? 1 : 0)) {
          const int s = step_of(fault, e.param);
          if (s != 0) v = Alg::add(v, Alg::injected(e, s));
        }
      }
      cur[static_cast<std::size_t>(node)] = v;
    }
  }
  std::vector<ChannelPrediction> r(measured.size());
  for (std::size_t c = 0; c < measured.size(); ++c) {
    const std::size_t m = static_cast<std::size_t>(g.at(measured[c]));
    ChannelPrediction& p = r[c];
    p.order = -1;
    p.slope = kQualZero;
    for (int k = 0; k <= max_order; ++k) {
      const QualSign s = Alg::sign(d[static_cast<std::size_t>(k)][m]);
      p.derivative.push_back(s);
      if (p.order < 0 && s != kQualZero) {
        p.order = k;
        p.slope = s;
      }
    }
    p.magnitude = p.slope;
  }
  return r;
}

/// Node values of the linearised graph for given integrated-node values (others follow
/// from instantaneous edges), with or without the fault's injections; also the rates of
/// the integrated nodes.
void evaluate_linear(const CausalGraph& g, const std::vector<int>& order, const std::vector<int>& states,
                     const Eigen::VectorXd& x, const std::vector<ParamStep>* fault, std::vector<double>& value,
                     Eigen::VectorXd& rate) {
  value.assign(g.nodes().size(), 0.0);
  for (std::size_t i = 0; i < states.size(); ++i) value[static_cast<std::size_t>(states[i])] = x[static_cast<Eigen::Index>(i)];
  for (int node : order) {
    const Node& nd = g.nodes()[static_cast<std::size_t>(node)];
    bool is_state = false;
    for (int s : states) is_state = is_state || s == node;
    if (is_state) continue;
    double v = 0.0;
    if (nd.kind == NodeKind::kSource && fault != nullptr) v += step_of(*fault, nd.name) * nd.value;
    for (int ei : g.in_edges(node)) {
      const Edge& e = g.edges()[static_cast<std::size_t>(ei)];
      v += e.sign * e.gain * value[static_cast<std::size_t>(e.from)];
      if (!e.param.empty() && fault != nullptr) v += step_of(*fault, e.param) * e.injection;
    }
    value[static_cast<std::size_t>(node)] = v;
  }
  for (std::size_t i = 0; i < states.size(); ++i) {
    double r = 0.0;
    for (int ei : g.in_edges(states[i])) {
      const Edge& e = g.edges()[static_cast<std::size_t>(ei)];
      r += e.sign * e.gain * value[static_cast<std::size_t>(e.from)];
      if (!e.param.empty() && fault != nullptr) r += step_of(*fault, e.param) * e.injection;
    }
    rate[static_cast<Eigen::Index>(i)] = r;
  }
}

}  // namespace

std::vector<ChannelPrediction> forward_qualitative_at(const CausalGraph& g, const std::vector<ParamStep>& fault,
                                                      int max_order, const std::vector<std::string>& measured) {
  return propagate<QualAlgebra>(g, fault, max_order, measured);
}

std::vector<ChannelPrediction> forward_weighted_at(const CausalGraph& g, const std::vector<ParamStep>& fault,
                                                   int max_order, const std::vector<std::string>& measured) {
  return propagate<WeightedAlgebra>(g, fault, max_order, measured);
}

std::vector<int> integrated_nodes(const CausalGraph& g) {
  std::vector<int> states;
  for (std::size_t i = 0; i < g.nodes().size(); ++i) {
    for (int ei : g.in_edges(static_cast<int>(i))) {
      if (g.edges()[static_cast<std::size_t>(ei)].type == EdgeType::kIntegral) {
        states.push_back(static_cast<int>(i));
        break;
      }
    }
  }
  return states;
}

std::vector<double> linear_steady_change_at(const CausalGraph& g, const std::vector<ParamStep>& fault,
                                            const std::vector<std::string>& measured) {
  check_fault(g, fault);
  const std::vector<int> states = integrated_nodes(g);
  const Eigen::Index n = static_cast<Eigen::Index>(states.size());
  if (n == 0) throw std::invalid_argument("linear_steady_change: the graph has no integrated nodes");
  const std::vector<int> order = instant_order(g);
  std::vector<double> value;
  Eigen::MatrixXd A(n, n);
  Eigen::VectorXd rate(n);
  for (Eigen::Index j = 0; j < n; ++j) {
    evaluate_linear(g, order, states, Eigen::VectorXd::Unit(n, j), nullptr, value, rate);
    A.col(j) = rate;
  }
  Eigen::VectorXd b(n);
  evaluate_linear(g, order, states, Eigen::VectorXd::Zero(n), &fault, value, b);
  // Pressures (1e6 Pa) and speed (1e2 rad/s) with K = 1e14 spread A's entries over ~20
  // decades: equilibrate rows and columns before the rank test.
  const Eigen::VectorXd row = A.cwiseAbs().rowwise().maxCoeff().cwiseInverse();
  const Eigen::MatrixXd Ar = row.asDiagonal() * A;
  const Eigen::VectorXd col = Ar.cwiseAbs().colwise().maxCoeff().transpose().cwiseInverse();
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(Ar * col.asDiagonal());
  if (!lu.isInvertible() || !col.allFinite() || !row.allFinite()) {
    throw std::invalid_argument("linear_steady_change: singular state matrix");
  }
  const Eigen::VectorXd x = col.asDiagonal() * lu.solve(-(row.asDiagonal() * b));
  evaluate_linear(g, order, states, x, &fault, value, rate);
  std::vector<double> y;
  for (const std::string& m : measured) y.push_back(value[static_cast<std::size_t>(g.at(m))]);
  return y;
}

std::string render_derivatives(const ChannelPrediction& c) {
  std::string s;
  for (QualSign q : c.derivative) {
    if (!s.empty()) s += ' ';
    s += qual_symbol(q);
  }
  return s;
}

}  // namespace hstmon::fdi
