#pragma once
// What the two C APIs (hstmon_c.cpp, hstmon_circuit_c.cpp) share: the check of a caller's
// monitor buffer, and copying a matcher's ranked candidates and its events into the C structs.
#include <cstddef>
#include <cstdint>

#include "hstmon_c_types.h"

namespace hstmon::c_api {

/// True when buf can hold a T: not NULL, at least sizeof(T) bytes, aligned for T.
template <class T>
bool buffer_fits(const void* buf, std::size_t size) noexcept {
  return buf != nullptr && size >= sizeof(T) && reinterpret_cast<std::uintptr_t>(buf) % alignof(T) == 0;
}

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

/// Copies event e into out: its best HSTMON_EVENT_CANDIDATES candidates (the C struct's
/// room; the full ranking is read live with copy_candidates), the rest as they are.
template <class Event>
void copy_event(const Event& e, hstmon_event* out) noexcept {
  out->t_s = e.time;
  out->kind = static_cast<uint8_t>(e.kind);
  out->consistent = e.consistent;
  out->count = static_cast<uint8_t>(e.count < HSTMON_EVENT_CANDIDATES ? e.count : HSTMON_EVENT_CANDIDATES);
  for (int j = 0; j < HSTMON_EVENT_CANDIDATES; ++j) {
    out->candidate[j] = j < out->count ? hstmon_candidate{e.candidate[j].name, e.candidate[j].score}
                                       : hstmon_candidate{nullptr, 0.0f};
  }
}

/// Removes the oldest event queued in `mon` into out.
/// @return 1 if an event was written, 0 if the queue is empty (or out is NULL)
template <class Monitor>
int pop_event(Monitor& mon, hstmon_event* out) noexcept {
  if (out == nullptr) return 0;
  typename Monitor::Event e;
  if (!mon.pop_event(e)) return 0;
  copy_event(e, out);
  return 1;
}

}  // namespace hstmon::c_api
