// The node solves of quasi_steady.hpp: the closed form of a one-orifice node against the
// safeguarded Newton on the same balance, where it declines, and the inline first Newton
// step against the bracketed solve it stands in front of (the same result bit for bit).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "hstmon/circuit/quasi_steady.hpp"
#include "hstmon/signed_root.hpp"

namespace {

namespace circuit = hstmon::circuit;

/// A node fed through one orifice from u [Pa] (k [m³/(s·√Pa)], transition x_t [Pa]) and
/// drained by a fixed flow q_out [m³/s] and a leak of conductance g [m³/(s·Pa)] to p_d [Pa].
template <typename T>
struct Node {
  T u, k, x_t, q_out, g, p_d;
  T balance(T p, T& dF) const {
    T s;
    const T q = k * hstmon::signed_root(u - p, x_t, s);
    dF = -k * s - g;
    return q - q_out - g * (p - p_d);
  }
  bool closed_form(T& p) const {
    T root;
    return circuit::solve_node_orifice(p, u, k, x_t, g * p_d - q_out, g, root);
  }
  // The balance leaves the node at the pressure it is evaluated at, as the solves require.
  bool newton(T& p) const {
    return circuit::solve_node_newton_bracketed(p, T(4e7), [&](T x, T& dF) {
      p = x;
      return balance(x, dF);
    });
  }
};

template <typename T>
void expect_closed_form_is_the_root(const Node<T>& n, const char* what) {
  SCOPED_TRACE(what);
  T pc = T(1e5), pn = T(1e5);
  ASSERT_TRUE(n.closed_form(pc));
  ASSERT_TRUE(n.newton(pn));
  const T eps = std::numeric_limits<T>::epsilon();
  EXPECT_NEAR(pc, pn, T(8) * eps * (std::fabs(pn) + std::fabs(n.u)));
  T dF;
  // The balance at the closed form's pressure is zero to the rounding of its largest term.
  const T scale = std::fabs(n.q_out) + std::fabs(n.g * (pc - n.p_d)) + n.k * std::sqrt(std::fabs(n.u - pc));
  EXPECT_LE(std::fabs(n.balance(pc, dF)), T(64) * eps * scale);
}

TEST(QuasiSteady, ClosedFormIsTheNewtonRootBothWays) {
  // Flow into the node (a DCV's P→A orifice feeding a motor), and out of it (the motor's
  // return through B→T: a negative drain is an inflow), with and without leakage.
  for (double g : {0.0, 1e-12, 3e-11}) {
    expect_closed_form_is_the_root(Node<double>{35e5, 1.2e-6, 1e3, 6e-4, g, 0.0}, "into, double");
    expect_closed_form_is_the_root(Node<double>{0.0, 1.2e-6, 1e3, -6e-4, g, 0.0}, "out of, double");
    expect_closed_form_is_the_root(Node<float>{35e5f, 1.2e-6f, 1e3f, 6e-4f, static_cast<float>(g), 0.0f}, "into, float");
    expect_closed_form_is_the_root(Node<float>{0.0f, 1.2e-6f, 1e3f, -6e-4f, static_cast<float>(g), 0.0f}, "out of, float");
  }
}

TEST(QuasiSteady, ClosedFormDeclinesWhereItDoesNotApply) {
  double p = 123.0;
  // A root in the laminar band (a drop of about 0.4 bar below a 1 bar transition): the cubic.
  const Node<double> laminar{35e5, 1.2e-6, 1e5, 1.2e-6 * 200.0, 0.0, 0.0};
  EXPECT_FALSE(laminar.closed_form(p));
  EXPECT_EQ(p, 123.0);
  double q = p;
  EXPECT_TRUE(laminar.newton(q));  // Newton, the caller's fallback, solves it
  // A shut orifice, no flow at all, and a value that is not finite.
  double root = -1.0;
  EXPECT_FALSE(circuit::solve_node_orifice(p, 35e5, 0.0, 1e3, -6e-4, 1e-12, root));
  EXPECT_FALSE(circuit::solve_node_orifice(p, 35e5, 1.2e-6, 1e3, 35e5 * 1e-12, 1e-12, root));
  EXPECT_FALSE(circuit::solve_node_orifice(p, 35e5, 1.2e-6, 1e3, std::nan(""), 1e-12, root));
  EXPECT_EQ(root, -1.0);
  EXPECT_EQ(p, 123.0);
}

TEST(QuasiSteady, FirstNewtonStepInlineEqualsTheBracketedSolve) {
  // From a warm start (one step converges: the inline path) and from cold starts (it
  // falls through to the bracketed solve), the result and the verdict are the bracketed
  // solve's own, bit for bit.
  const Node<float> n{35e5f, 1.2e-6f, 1e3f, 6e-4f, 1e-12f, 0.0f};
  float root = 1e5f;
  ASSERT_TRUE(n.newton(root));
  for (float start : {root, std::nextafter(root, 0.0f), 0.0f, 1e5f, 34.99e5f, -1e6f}) {
    float a = start, b = start;
    const bool ok_a = circuit::solve_node_newton(a, 4e7f, [&](float x, float& dF) {
      a = x;
      return n.balance(x, dF);
    });
    const bool ok_b = n.newton(b);
    EXPECT_EQ(ok_a, ok_b) << "from " << start;
    EXPECT_EQ(a, b) << "from " << start;
  }
}

}  // namespace
