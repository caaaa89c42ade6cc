#pragma once
/// @file replay_event.hpp
/// What a replay says happened: the monitor's events with their ranked candidates.

#include <limits>
#include <string>
#include <vector>

namespace hstmon::host {

/// A ranked fault hypothesis of an event.
struct ReplayCandidate {
  std::string fault;   ///< "kp-", "sensor_p_pp", …
  double score = 0.0;  ///< matcher score in [0, 1] (higher is better; the matcher's cosine, a negative one shown as 0) [-]
  /// The fault's estimated size, when a fit over the steady windows gave one: the factor
  /// on the parameter or input [-] (0.9 = 10 % low), or a sensor's offset [SI]; NaN if none.
  double size = std::numeric_limits<double>::quiet_NaN();
  double size_lo = std::numeric_limits<double>::quiet_NaN();  ///< lower end of its interval [same]
  double size_hi = std::numeric_limits<double>::quiet_NaN();  ///< upper end [same]
  std::string size_text;  ///< the size in an engineer's words ("Dm: −15 % ± 2 %"); empty if none
};

/// A matcher event: an episode detected, isolated, ambiguous, unexplained or cleared; or
/// the envelope check's out_of_envelope (the model does not describe the machine) or
/// unverified (detected before the machine was seen to match the model); `why` says why.
struct ReplayEvent {
  double t = 0.0;                          ///< log time [s]
  std::string event;                       ///< "detected", "isolated", "ambiguous", "unexplained", "cleared", "out_of_envelope", "unverified", "out_of_envelope"
  int consistent = 0;                      ///< hypotheses still consistent (may exceed candidates.size())
  std::vector<ReplayCandidate> candidates; ///< best first (empty for "cleared", and for a detection without a ranking yet)
  /// What raised the event when not the matcher: e.g. "a step in p_mi while the inputs
  /// held still" (the candidates then follow from the first steady window); "" otherwise.
  std::string why;
};

}  // namespace hstmon::host
