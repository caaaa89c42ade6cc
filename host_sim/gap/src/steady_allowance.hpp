#pragma once
/// @file steady_allowance.hpp
/// The thesis rig's steady settings in a log (held inputs, less the settle time), and how
/// much of the nominal model's gap there the stated parameter uncertainty accounts for
/// (param_allowance.hpp with the uncertainty of residual_bounds.hpp: ±2 % on Dm, Dp,
/// Rlkg, Ripl, Rf, Rbl, kf). The move found on the steady means is applied to every row
/// of its setting (a transient heads for the moved steady state) for a first estimate;
/// run_gap then simulates the moved model (moved_params) and takes the channels' RMS
/// again: what is left is the gap the parameters cannot make.
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "hstmon/thesis_params.hpp"
#include "hstmon_gap/effects.hpp"
#include "param_allowance.hpp"

namespace hstmon::gap::detail {

/// One steady setting: rows [first, end) of a held-input run, `steady` of them after the settle time.
struct Setting {
  std::size_t first = 0, end = 0, steady_from = 0;
  std::size_t steady() const { return end - steady_from; }
};

/// The held-input runs of u (split where input_step says a transient starts).
std::vector<Setting> settings_of(const InputSeries& u, const std::vector<char>& transient);

struct SteadyAllowance {
  Allowance a;
  std::array<double, kChannels> rms_w_within{};  ///< RMS/noise per channel after the move (NaN: absent)
  std::vector<std::pair<std::string, double>> moves;  ///< parameter, relative move ε·δ*
};

/// p with the relative moves applied (names as in SteadyAllowance::moves).
ThesisParams<double> moved_params(const ThesisParams<double>& p, const std::vector<std::pair<std::string, double>>& moves);

SteadyAllowance thesis_allowance(const ThesisParams<double>& p, const InputSeries& u,
                                 const std::vector<std::array<double, kChannels>>& y,
                                 const std::vector<std::array<double, kChannels>>& model,
                                 const std::array<bool, kChannels>& present, const std::array<double, kChannels>& noise,
                                 const std::vector<char>& transient);

}  // namespace hstmon::gap::detail
