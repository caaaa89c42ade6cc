#pragma once
/// @file operating_point.hpp
/// A steady operating point of the thesis model and the linear valve resistances of
/// eq. 2.11 there: the numbers that turn the temporal causal graph's signs into gains.

#include "hstmon/thesis_params.hpp"

namespace hstmon::fdi {

/// Steady operating point of equations 2.5–2.8 under (p, u).
struct OperatingPoint {
  ThesisParams<double> p;  ///< parameters
  ThesisInputs<double> u;  ///< inputs
  ThesisState<double> x;   ///< steady state: Pmi, Pmo, Ppp [Pa], ωm [rad/s]
  double Rin = 0.0;        ///< DCV inlet secant resistance √(Psupl − Pmi)/kf, eq. 2.11 [Pa·s/m³]
  double Rout = 0.0;       ///< DCV outlet secant resistance √(Pmo − Ps)/kf [Pa·s/m³]
  double Rpl = 0.0;        ///< PRV secant resistance √(Ppp − Pbp)/kp [Pa·s/m³]
  double g_in = 0.0;       ///< DCV inlet tangent conductance ∂Q/∂ΔP [m³/(s·Pa)]
  double g_out = 0.0;      ///< DCV outlet tangent conductance [m³/(s·Pa)]
  double g_prv = 0.0;      ///< PRV tangent conductance [m³/(s·Pa)]
};

/// Steady operating point from ThesisCircuitModel<double>::steady_state.
/// @throws std::invalid_argument if the inputs admit no steady state (e.g. kp = 0)
OperatingPoint operating_point(const ThesisParams<double>& p = ThesisParams<double>{},
                               const ThesisInputs<double>& u = ThesisInputs<double>{});

/// Steady state (Pmi, Pmo, Ppp [Pa], ωm [rad/s]) in channel order, from the reduced model.
/// @return false if the inputs admit none
bool steady_outputs(const ThesisParams<double>& p, const ThesisInputs<double>& u, double (&y)[4]);

}  // namespace hstmon::fdi
