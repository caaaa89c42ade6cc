#include "hstmon_host/envelope_result.hpp"

#include <cmath>
#include <cstdio>

#include "hstmon_host/number_text.hpp"

namespace hstmon::host {

namespace {

// "(t = 0.1 … 0.6 s)"
std::string span(double t0, double t1) {
  char b[80];
  std::snprintf(b, sizeof b, "(t = %.3g … %.3g s)", t0, t1);
  return b;
}

// "p_mi +1.03 bar from the model (it may be 0.379 bar)"
std::string off_by(const EnvelopeChannel& c, double mean, double tolerance) {
  char b[160];
  std::snprintf(b, sizeof b, "%s %+.3g %s from the model (it may be %.3g %s)", c.name.c_str(), mean * c.per_si,
                c.unit.c_str(), 0.5 * tolerance * c.per_si, c.unit.c_str());
  return b;
}

}  // namespace

EnvelopeResult envelope_result(const EnvelopeFigures& f, const std::vector<EnvelopeChannel>& channels,
                               const std::string& remedy) {
  EnvelopeResult r;
  r.t0 = f.t0;
  r.t1 = f.t1;
  switch (f.verdict) {
    case EnvelopeVerdict::kPending:
      r.text = "not checked: no stretch of held inputs long enough to settle and judge (" + number_text(f.window) +
               " s after 3 time constants)";
      return r;
    case EnvelopeVerdict::kGivenUp:
      r.text = "not checked: a fault was detected (t = " + number_text(f.t_detected, 4) +
               " s) before the machine held steady, so no stretch shows the machine as it was";
      return r;
    case EnvelopeVerdict::kUnverified:
      r.unverified = true;
      r.text = "unverified: a fault was detected (t = " + number_text(f.t_detected, 4) +
               " s) before the machine was seen to match the model, and no steady stretch followed to judge it, so "
               "the data cannot tell a fault from a model that does not fit this machine; no fault is named. " +
               remedy;
      return r;
    case EnvelopeVerdict::kWithin:
    case EnvelopeVerdict::kOutside: break;
  }
  r.checked = true;
  r.out = f.verdict == EnvelopeVerdict::kOutside;
  if (!r.out) {
    r.text = "within the model's envelope at its first steady stretch " + span(f.t0, f.t1);
    return r;
  }
  std::string beyond;
  for (std::size_t ch = 0; ch < channels.size() && ch < f.judged.size(); ++ch) {
    const double tol = f.tolerance[ch];
    if (!f.judged[ch] || !(tol > 0.0) || !(std::fabs(f.mean[ch]) > tol)) continue;
    beyond += (beyond.empty() ? "" : ", ") + off_by(channels[ch], f.mean[ch], tol);
  }
  r.text = "the model does not describe this machine: at its first steady stretch " + span(f.t0, f.t1) + " " + beyond +
           "; no fault is named. " + remedy;
  return r;
}

ReplayEvent envelope_event(double t, const EnvelopeResult& envelope, const std::vector<ReplayEvent>& before) {
  ReplayEvent e;
  e.t = t;
  e.event = envelope.unverified ? "unverified" : "out_of_envelope";
  e.why = envelope.text;
  if (before.empty()) return e;
  e.why += " (it withdraws the " + std::to_string(before.size()) + " diagnosis event(s) before it";
  const ReplayEvent* named = nullptr;
  for (const ReplayEvent& b : before) {
    if (!b.candidates.empty()) named = &b;
  }
  if (named != nullptr) {
    std::string names;
    for (std::size_t j = 0; j < named->candidates.size() && j < 3; ++j) {
      names += (j == 0 ? "" : ", ") + named->candidates[j].fault;
    }
    e.why += ", which named " + names +
             ": a fault present before the machine was first seen steady cannot be told from a model that does not "
             "fit it";
  }
  e.why += ")";
  return e;
}

}  // namespace hstmon::host
