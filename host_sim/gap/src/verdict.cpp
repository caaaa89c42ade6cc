/// @file verdict.cpp
/// The verdict and its sentence (see gap.hpp, docs/gap.md). Shrink ranks the effects; the
/// verdict asks what remains: `explained` only when every measured channel of the check
/// log is within kAtNoise × its noise after the top-ranked set.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "hstmon_gap/gap.hpp"
#include "load_bins.hpp"

namespace hstmon::gap {

namespace {

constexpr double kAtNoise = 2.0;       // "at noise level": check-log RMS ≤ 2× noise on every channel
constexpr double kPartly = 0.2;        // below this shrink nothing is explained even in part
constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

// Balance equations an effect unbalances when evaluated on the measured signals: the one
// it enters, or for a sensor effect every equation that reads the channel.
std::vector<int> effect_equations(Effect e, int offset_channel) {
  switch (e) {
    case Effect::kCoulombFriction:
    case Effect::kPressureTorqueLoss: return {kEqTorque};
    case Effect::kMotorLeakage: return {kEqFlowMi, kEqFlowMo};
    case Effect::kPrvCracking:
    case Effect::kAirEntrainment: return {kEqFlowPp};
    case Effect::kSupplyFlowLimit: return {kEqFlowMi};
    case Effect::kSensorLag: return {kEqFlowMi, kEqFlowMo, kEqFlowPp, kEqTorque};
    case Effect::kSensorOffset:
      if (offset_channel == 2) return {kEqFlowPp, kEqTorque};
      if (offset_channel == 3) return {kEqFlowMi, kEqFlowMo, kEqFlowPp, kEqTorque};
      return {kEqFlowMi, kEqFlowMo, kEqTorque};  // p_mi, p_mo
  }
  return {};
}

bool is_sensor(Effect e) { return e == Effect::kSensorLag || e == Effect::kSensorOffset; }

std::string fmt_channel(std::size_t c, double rms, double ratio) {
  char b[96];
  if (c == 3) {
    std::snprintf(b, sizeof b, "%s %.3g rpm RMS (%.1fx noise)", channel_names()[c], rms * 60.0 / (2.0 * M_PI), ratio);
  } else {
    std::snprintf(b, sizeof b, "%s %.3g bar RMS (%.1fx noise)", channel_names()[c], rms * 1e-5, ratio);
  }
  return b;
}

// A library set acting on another equation than the one out of balance: its physical
// reading is doubtful, whatever it shrinks.
std::string reading_note(const GapResult& r, const EffectFit& best) {
  const int eq = r.where_check.located;
  if (eq < 0) return {};
  bool enters = false, sensor = false;
  for (Effect e : best.effects) {
    const auto q = effect_equations(e, best.offset_channel);
    sensor = sensor || is_sensor(e);
    enters = enters || std::find(q.begin(), q.end(), eq) != q.end();
  }
  if (enters) return {};
  return std::string("; the imbalance is in ") + equation_names()[static_cast<std::size_t>(eq)] + ", which " +
         best.name + (sensor ? " reaches only through a sensor that equation does not read" : " does not enter") +
         ": its physical reading is doubtful";
}

}  // namespace

void decide_verdict(GapResult& r) {
  r.explained_by.clear();
  r.remaining_rms_w.fill(kNan);
  r.remaining_where.clear();
  if (!r.evidence_missing.empty()) {
    r.verdict = "insufficient_data";
    r.verdict_text = "insufficient data: " + r.evidence_missing + "; no gap is judged and no effect is named";
    return;
  }
  const bool significant = r.where_fit.significant || r.where_check.significant;
  if (!significant) {
    r.verdict = "no_significant_gap";
    r.verdict_text =
        "the nominal model matches both logs within the noise and its parameters' stated uncertainty; no effect is "
        "needed";
    return;
  }
  if (r.envelope.out) {
    r.verdict = "out_of_envelope";
    r.verdict_text = "out of envelope: " + r.envelope.text +
                     ". The model does not describe this machine, so no effect is named: identify its parameters "
                     "(hstmon identify on its steady data) or use a model of its circuit.";
    return;
  }
  // The withheld log already at noise with the nominal model, and no effect that shrinks it
  // noticeably: what made the fit log significant did not carry over, and nothing can be
  // said to explain a gap the check log does not show (a perfect model at 4.8 kHz, whose
  // integration error shows in a few transient rows of one log, lands here).
  bool check_at_noise = true;
  for (const auto& ch : r.where_check.channels)
    check_at_noise = check_at_noise && (!ch.present || ch.rms_w <= kAtNoise);
  if (check_at_noise && (r.ranking.empty() || r.ranking.front().shrink_check < kPartly)) {
    r.verdict = "no_significant_gap";
    char buf[300];
    std::snprintf(buf, sizeof buf,
                  "the nominal model meets the withheld (check) log within %.0fx its noise on every channel, and no "
                  "effect shrinks its residual by %.0f %% or more; no effect is needed",
                  kAtNoise, 100.0 * kPartly);
    r.verdict_text = buf;
    return;
  }
  std::string text;
  if (r.ranking.empty()) {
    r.verdict = "unexplained";
    text = "unexplained: no effect of the library reduces the gap on the fit log";
  } else {
    const EffectFit& best = r.ranking.front();
    // What remains on the check log, per channel and per load regime.
    bool at_noise = true;
    std::string remains;
    for (std::size_t c = 0; c < kChannels; ++c) {
      const auto& ch = r.where_check.channels[c];
      if (!ch.present || !std::isfinite(best.rms_after_check[c])) continue;
      const double ratio = best.rms_after_check[c] / ch.noise;
      r.remaining_rms_w[c] = ratio;
      if (ratio > kAtNoise) {
        at_noise = false;
        remains += (remains.empty() ? "" : ", ") + fmt_channel(c, best.rms_after_check[c], ratio);
      }
    }
    if (!at_noise && r.best_check.size() == r.data_check.size()) {
      double worst = -1;
      for (const auto& b : detail::load_bins(r.kp_check)) {
        double s = 0;
        std::size_t cnt = 0;
        for (std::size_t k = 0; k < b.mask.size(); ++k) {
          if (!b.mask[k]) continue;
          for (std::size_t c = 0; c < kChannels; ++c) {
            const auto& ch = r.where_check.channels[c];
            if (ch.present) s += std::pow((r.data_check[k][c] - r.best_check[k][c]) / ch.noise, 2);
          }
          ++cnt;
        }
        if (cnt > 0 && s / static_cast<double>(cnt) > worst) {
          worst = s / static_cast<double>(cnt);
          r.remaining_where = b.label;
        }
      }
    }
    char buf[400];
    if (at_noise) {
      r.verdict = best.effects.size() > 1 ? "explained_by_pair" : "explained";
      for (Effect e : best.effects) r.explained_by.push_back(effect_info(e).name);
      std::snprintf(buf, sizeof buf,
                    "%s: %s shrinks the check-log gap by %.0f %% (noise-weighted RMS %.3g -> %.3g) and leaves every "
                    "channel within %.0fx its noise",
                    r.verdict.c_str(), best.name.c_str(), 100.0 * best.shrink_check, best.rms_w_before_check,
                    best.rms_w_after_check, kAtNoise);
      text = buf;
      if (!r.cannot_tell_apart.empty()) text += "; other effects explain it as well - the data cannot tell them apart";
    } else {
      r.verdict = best.shrink_check >= kPartly ? "partly_explained" : "unexplained";
      std::snprintf(buf, sizeof buf, "%s: the best library set, %s, shrinks the check-log gap by %.0f %%, but ",
                    r.verdict.c_str(), best.name.c_str(), 100.0 * best.shrink_check);
      text = buf + std::string("what remains is above noise: ") + remains;
      if (!r.remaining_where.empty()) text += ", most at " + r.remaining_where;
    }
    text += reading_note(r, best);
  }
  for (const auto& d : r.discovered) {
    char buf[240];
    if (d.simulated) {
      double worst = 0;
      for (double v : d.channel_rms_w_after_check) {
        if (std::isfinite(v)) worst = std::max(worst, v);
      }
      std::snprintf(buf, sizeof buf,
                    "; added to the model it shrinks the check-log gap by %.0f %% (the imbalance of %s by %.0f %%)%s",
                    100.0 * d.model_shrink_check, d.equation.c_str(), 100.0 * d.shrink_check,
                    worst <= kAtNoise ? " and leaves every channel within 2x its noise" : "");
    } else {
      std::snprintf(buf, sizeof buf, "; it shrinks the check-log imbalance of %s by %.0f %%", d.equation.c_str(),
                    100.0 * d.shrink_check);
    }
    text += ". Beyond the library: " + d.reading + buf;
    // A library set that fits a little must not hide a better term it does not contain.
    if (d.simulated && !r.ranking.empty() && d.model_shrink_check > r.ranking.front().shrink_check + 0.05) {
      std::snprintf(buf, sizeof buf, " - better than %s (%.0f %%), whose physical reading is then doubtful",
                    r.ranking.front().name.c_str(), 100.0 * r.ranking.front().shrink_check);
      text += buf;
    }
  }
  r.verdict_text = text;
}

}  // namespace hstmon::gap
