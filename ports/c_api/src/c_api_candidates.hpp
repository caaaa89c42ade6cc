#pragma once
// What the two C APIs (hstmon_c.cpp, hstmon_circuit_c.cpp) share: copying a matcher's
// ranked candidates into the C struct.
#include "hstmon_c.h"

namespace hstmon::c_api {

/// Copies min(total, max) candidates of `mt` (best first) into out (may be NULL when max is 0).
/// @return the number of consistent hypotheses in total
template <class Matcher>
int copy_candidates(const Matcher& mt, hstmon_candidate* out, int max) noexcept {
  const int total = mt.candidate_count();
  for (int r = 0; out != nullptr && r < total && r < max; ++r) {
    const auto c = mt.candidate(r);
    out[r] = hstmon_candidate{c.name, c.score};
  }
  return total;
}

}  // namespace hstmon::c_api
