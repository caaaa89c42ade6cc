#pragma once
/// @file envelope_result.hpp
/// The envelope check's verdict (hstmon/envelope_check.hpp) in words, for every replay:
/// the same sentence whichever model the monitor ran.

#include <string>
#include <vector>

#include "hstmon/envelope_check.hpp"
#include "hstmon_host/replay_event.hpp"

namespace hstmon::host {

/// The verdict of the envelope check, as a replay reports it.
struct EnvelopeResult {
  bool checked = false;       ///< a steady stretch was found and judged
  bool out = false;           ///< the machine lies outside the model's envelope there
  /// Not checked, and a fault was detected before the machine was ever seen to match the
  /// model: the data cannot tell that fault from a model that does not fit the machine.
  bool unverified = false;
  double t0 = 0.0, t1 = 0.0;  ///< the window judged [s]
  std::string text;           ///< one sentence: where and by how much, or why it was not checked
};

/// How one channel is named in the sentence.
struct EnvelopeChannel {
  std::string name;       ///< "p_mi"
  std::string unit;       ///< display unit, "bar"
  double per_si = 1.0;    ///< display value per SI value [unit/SI]
};

/// What a check found, without its model: per channel, whether it was judged, its mean
/// residual and its tolerance [SI].
struct EnvelopeFigures {
  EnvelopeVerdict verdict = EnvelopeVerdict::kPending;
  double t0 = 0.0, t1 = 0.0, t_detected = -1.0;  ///< window; first detection (< 0: none) [s]
  double window = 0.5;                            ///< steady seconds a judgement takes [s]
  std::vector<bool> judged;
  std::vector<double> mean, tolerance;
};

/// The figures of a check of any model.
template <class Model>
EnvelopeFigures envelope_figures(const EnvelopeCheck<Model>& check) {
  EnvelopeFigures f;
  f.verdict = check.verdict();
  f.t0 = static_cast<double>(check.t0());
  f.t1 = static_cast<double>(check.t1());
  f.t_detected = static_cast<double>(check.detected_at());
  f.window = static_cast<double>(check.config().window);
  for (int ch = 0; ch < EnvelopeCheck<Model>::kChannels; ++ch) {
    f.judged.push_back(check.judged(ch));
    f.mean.push_back(static_cast<double>(check.mean(ch)));
    f.tolerance.push_back(static_cast<double>(check.tolerance(ch)));
  }
  return f;
}

/// The verdict in one sentence. `channels` names the check's channels (fewer: the rest are
/// not reported); `remedy` ends an out-of-envelope sentence, e.g. "Run `hstmon identify`
/// on healthy steady data, or `hstmon gap`".
EnvelopeResult envelope_result(const EnvelopeFigures& f, const std::vector<EnvelopeChannel>& channels,
                               const std::string& remedy);

/// The event that replaces a replay's diagnosis at t [s] when the check finds the machine
/// outside the model's envelope ("out_of_envelope") or cannot verify that the model
/// describes it ("unverified"): `why` is the check's sentence, and says what the events
/// `before` it (withdrawn) had named. A fault present before the machine was first seen
/// steady looks like a model that does not fit, and only a check on a healthy log (identify,
/// gap) tells the two apart.
ReplayEvent envelope_event(double t, const EnvelopeResult& envelope, const std::vector<ReplayEvent>& before);

}  // namespace hstmon::host
