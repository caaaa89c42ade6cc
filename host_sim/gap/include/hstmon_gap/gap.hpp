#pragma once
/// @file gap.hpp
/// `hstmon gap`: where the thesis model and a machine's logs disagree (residual
/// decomposition per channel, load regime, steady/transient, frequency band), which
/// unmodelled effect of the library explains it (fit on one log, rank by the shrink on a
/// second, withheld log, BIC-penalised), and how far the gap shrinks. docs/gap.md.
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "hstmon/thesis_params.hpp"
#include "hstmon_gap/effects.hpp"
#include "hstmon_gap/discover.hpp"
#include "hstmon_gap/envelope.hpp"
#include "hstmon_gap/equations.hpp"
#include "hstmon_host/log_reader.hpp"

namespace hstmon::gap {

/// Settings of run_gap.
struct GapOptions {
  bool refit_nominal = false;          ///< also re-fit kf and Rf + Rbl (factors) with each effect
  int pair_candidates = 3;             ///< pairs are tried among this many best single effects
  std::vector<Effect> effects = all_effects();  ///< library to try
  SimOptions sim{};                    ///< simulator settings
  double significance = 1.5;           ///< gap significant when a channel's RMS exceeds this × its noise
  double settle_time = 0.3;            ///< rows this long after an input change count as transient [s]
};

/// Residual statistics of one channel (SI; rms_w in units of the channel's noise).
struct ChannelStats {
  bool present = false;
  double mean = 0, rms = 0, noise = 0, rms_w = 0;
  double rms_w_within = 0;  ///< rms_w once the parameters move within their uncertainty (significance)
  double noise_white = 0, adc_step = 0, noise_spread = 0;  ///< the noise estimates (noise_floor.hpp) [SI]
};

/// Weighted RMS (noise units) per channel in one part of a log; NaN where no rows.
struct PartStats {
  std::string label;
  double fraction = 0;  ///< share of the log's rows
  std::array<double, kChannels> rms_w{};
};

/// Where the nominal model and one log disagree.
struct Where {
  std::array<ChannelStats, kChannels> channels{};
  std::vector<PartStats> load_bins;   ///< by PRV setting kp (heavier load = smaller kp)
  std::vector<PartStats> phases;      ///< "steady", "transient"
  std::vector<PartStats> bands;       ///< "slow" (< 2 Hz, 0.5 s mean), "fast"
  double rms_w_total = 0;             ///< pooled over present channels [noise units]
  bool significant = false;           ///< some channel's rms_w_within above the significance
  double uncertainty_z = 0;           ///< steady gap left beyond noise and parameter uncertainty [noise units]
  std::vector<std::pair<std::string, double>> parameter_moves;  ///< the most likely relative moves [-]
  std::size_t steady_settings = 0;    ///< settings with enough steady samples (evidence)
  double sample_period = 0;           ///< median [s]
  std::vector<EquationStats> equations;  ///< balance-equation imbalances on the measured signals
  int located = -1;                   ///< equation with the largest imbalance over noise (-1: none)
};

/// One fitted parameter.
struct ParamEstimate {
  std::string effect, name, unit;
  double value = 0, se = 0;   ///< SI; se from the linearised covariance × √τ (∞ if not identifiable)
  bool identified = true;     ///< se < |value|
};

/// A fitted effect set (one effect, or a pair) and how it does on the check log.
struct EffectFit {
  std::vector<Effect> effects;
  std::string name;                   ///< "coulomb_friction" or "a+b"
  int offset_channel = -1;            ///< channel of sensor_offset, if in the set
  std::vector<ParamEstimate> params;
  int k = 0;                          ///< fitted parameters
  double delta_bic_fit = 0;           ///< BIC(set) − BIC(nominal) on the fit log (< 0: better)
  double shrink_fit = 0;              ///< share of the fit log's gap above the noise removed (shrink.hpp)
  double shrink_check = 0;            ///< same on the check log
  std::array<double, kChannels> rms_before_check{}, rms_after_check{};  ///< SI, NaN if absent
  double rms_w_before_check = 0, rms_w_after_check = 0;
  bool converged = false;
  int evaluations = 0;
  double autocorrelation_time = 1;    ///< τ of the fit-log residuals: SEs use n/τ samples
  ExtendedModel model;                ///< nominal + fitted effects
};

/// Effect the data cannot identify, and why.
struct NotIdentifiable {
  Effect effect;
  std::string reason;
};

/// Everything run_gap finds.
struct GapResult {
  bool ok = false;
  std::string error;
  Where where_fit, where_check;
  std::string start_fit, start_check;  ///< how each run started: "measured", "rest" or "steady"
  double step_lead_fit = 0, step_lead_check = 0;  ///< the logger's step timing (InputSeries::step_lead)
  std::vector<EffectFit> ranking;     ///< best first (accepted pairs, then single effects)
  std::vector<EffectFit> rejected;    ///< tried but not improving the fit log, or pairs not needed
  std::vector<NotIdentifiable> not_identifiable;
  Envelope envelope;                  ///< operating points vs what the model and its effects can reach
  std::vector<Discovery> discovered;  ///< missing terms proposed beyond the library
  std::array<double, kChannels> remaining_rms_w{};  ///< check log after the top-ranked set, RMS/noise (NaN: absent)
  std::string remaining_where;        ///< load regime where most remains
  std::string evidence_missing;       ///< what the logs lack for a verdict (insufficient_data), else empty
  std::string verdict;                ///< insufficient_data | no_significant_gap | out_of_envelope | explained | explained_by_pair | partly_explained | unexplained
  std::vector<std::string> explained_by;
  std::vector<std::string> cannot_tell_apart;  ///< effects that explain the check log equally well
  std::string verdict_text;           ///< one sentence
  double seconds = 0;                 ///< wall time
  std::vector<std::pair<std::string, double>> stage_seconds;  ///< wall time per stage, in order
  int simulations = 0;
  // Series for the report (check log): time, kp, data, nominal model, top-ranked model.
  std::vector<double> t_check, kp_check;
  std::vector<std::array<double, kChannels>> data_check, nominal_check, best_check;
  std::vector<double> t_fit, kp_fit;
  std::vector<std::array<double, kChannels>> data_fit, nominal_fit;
};

/// Logged inputs (p_sup, p_s, p_bp, kp), falling back to `defaults` for absent columns.
InputSeries inputs_from_log(const host::LogData& log, const ThesisInputs<double>& defaults);

/// Runs the analysis: fit on `fit`, check on `check` (the effect's evidence is withheld
/// from the fit). Never throws for bad data; sets error instead.
GapResult run_gap(const host::LogData& fit, const host::LogData& check, const ThesisParams<double>& params,
                  const ThesisInputs<double>& defaults, const GapOptions& options = {});

/// Sets verdict, explained_by and verdict_text from the rest of the result (docs/gap.md:
/// `explained` only when every check-log channel is within 2× its noise after the fit).
void decide_verdict(GapResult& r);

/// The result as one JSON object (SI units), `{"where":…,"ranking":[…],"verdict":…}`.
std::string to_json(const GapResult& r, int indent = -1);

/// Human-readable summary.
std::string to_text(const GapResult& r);

/// The report in `dir` (created): report.md, and report.html (one self-contained page,
/// the verdict first, tables and the PNG plots embedded), the plots as PNG files, their
/// data (fit.dat, check.dat) and gnuplot script (plots.gp).
/// @param plot_warning  out, when given: why the plots are missing (gnuplot absent or
///                      failed; the reports say so too), else empty
/// @return "" or an error (the directory or a file could not be written)
std::string write_report(const GapResult& r, const std::string& dir, const std::string& fit_name,
                         const std::string& check_name, std::string* plot_warning = nullptr);

}  // namespace hstmon::gap
