// libFuzzer target: the C API (float monitor) fed a stream of samples decoded from the
// input: arbitrary IEEE values (NaN, ±Inf, huge, denormal) in inputs and measurements,
// missing channels, ticks without a sample, resets, and time going backwards.
//
// Layout: byte 0 = configuration (tick, substep cap); then records, each an op byte:
//   bits 0-3  valid mask of the four channels
//   bits 4-5  0: sample near the operating point (1 byte per channel: offset in σ units;
//                1 byte: kp scale; then 1 byte: time step, bit 7 of the op = backwards)
//             1: raw sample: 4 + 4 floats (inputs, measurements) + float t, bit-exact
//             2: tick without a sample (hstmon_step(m, NULL))
//             3: reset (bit 6: steady, else rest) for inputs 1 raw float kp + defaults
// Invariants after every call: never crash; the report's estimate is finite, and
// residual[i] finite where residual_valid has bit i, unless the tick raised a health
// flag ("finite or flagged"); residual[i] is 0 where not valid; the tick counter advances by
// one per step; the match status and event kinds are in range; candidate names are
// non-null; at most HSTMON_MAX_FAULTS consistent hypotheses.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "hstmon_c.h"

namespace {

struct Reader {
  const std::uint8_t* p;
  std::size_t n;
  bool empty() const { return n == 0; }
  std::uint8_t byte() {
    if (n == 0) return 0;
    --n;
    return *p++;
  }
  float raw_float() {
    std::uint8_t b[4] = {byte(), byte(), byte(), byte()};
    float f;
    std::memcpy(&f, b, 4);
    return f;
  }
};

[[noreturn]] void fail(const char* what, int record) {
  std::fprintf(stderr, "fuzz_c_api invariant violated at record %d: %s\n", record, what);
  std::abort();
}

hstmon_monitor_storage storage;

void check_report(const hstmon_monitor* m, std::uint64_t ticks_expected, int rec) {
  hstmon_report r;
  hstmon_read(m, &r);
  if (r.ticks != ticks_expected) fail("tick counter did not advance by one", rec);
  for (int i = 0; i < HSTMON_CHANNELS; ++i) {
    // "Finite or flagged": a finite but absurd input (p_sup = 3e38 Pa) may make the
    // estimate ±Inf; the tick must then carry a health flag.
    if (!std::isfinite(r.estimate[i]) && r.last_health == 0) fail("non-finite estimate, tick not flagged", rec);
    if ((r.residual_valid >> i) & 1u) {
      if (!std::isfinite(r.residual[i]) && r.last_health == 0) fail("non-finite residual marked valid, tick not flagged", rec);
    } else if (r.residual[i] != 0.0f) {
      fail("residual not 0 where not valid", rec);
    }
  }
  if (ticks_expected > 0 && r.substeps < 1) fail("a tick with zero substeps", rec);
  const hstmon_match s = hstmon_match_status(m);
  if (static_cast<int>(s) < 0 || static_cast<int>(s) > 4) fail("match status out of range", rec);
  hstmon_candidate c[HSTMON_MAX_FAULTS];
  const int total = hstmon_candidates(m, c, HSTMON_MAX_FAULTS);
  if (total < 0 || total > HSTMON_MAX_FAULTS) fail("candidate count out of range", rec);
  if (s == HSTMON_MATCH_NOMINAL && total != 0) fail("candidates while nominal", rec);
  for (int k = 0; k < total; ++k) {
    if (c[k].name == nullptr) fail("candidate without a name", rec);
    if (!(c[k].score >= -1.001f && c[k].score <= 1.001f)) fail("candidate score outside [-1, 1] or NaN", rec);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool trace = std::getenv("HSTMON_FUZZ_TRACE") != nullptr;  // triage: one line per sample
  Reader in{data, size};
  hstmon_config cfg;
  hstmon_default_config(&cfg);
  const std::uint8_t c0 = in.byte();
  static const float ticks[4] = {1e-3f, 1e-2f, 5e-4f, 2e-3f};
  cfg.tick_s = ticks[c0 & 3u];
  cfg.max_substeps = (c0 & 4u) ? 8 : 256;
  hstmon_monitor* m = nullptr;
  if (hstmon_create(&storage, sizeof storage, &cfg, &m) != HSTMON_OK || m == nullptr) fail("create failed", -1);
  hstmon_inputs u0;
  hstmon_default_inputs(&u0);
  if (c0 & 8u) {
    if (hstmon_reset_steady(m, &u0) != HSTMON_OK) fail("reset_steady at defaults failed", -1);
  }
  hstmon_report r0;
  hstmon_read(m, &r0);
  float y0[HSTMON_CHANNELS];
  for (int i = 0; i < HSTMON_CHANNELS; ++i) y0[i] = r0.estimate[i];
  const float sigma[HSTMON_CHANNELS] = {5e3f, 5e3f, 5e3f, 0.0524f};

  std::uint64_t ticks_expected = 0;
  float t = 0.0f;
  for (int rec = 0; rec < 4096 && !in.empty(); ++rec) {
    const std::uint8_t op = in.byte();
    hstmon_sample s;
    std::memset(&s, 0, sizeof s);
    s.valid = op & 0x0Fu;
    switch ((op >> 4) & 3u) {
      case 0: {
        s.u = u0;
        for (int i = 0; i < HSTMON_CHANNELS; ++i) {
          const int off = static_cast<std::int8_t>(in.byte());
          s.y[i] = y0[i] + static_cast<float>(off) * sigma[i] * ((off & 1) ? 20.0f : 1.0f);
        }
        s.u.kp = u0.kp * (0.25f + static_cast<float>(in.byte()) / 128.0f);
        const float dt = static_cast<float>(in.byte()) * cfg.tick_s;
        t = (op & 0x80u) ? t - dt : t + dt;
        s.t_s = t;
        break;
      }
      case 1:
        s.u.p_sup = in.raw_float();
        s.u.p_s = in.raw_float();
        s.u.p_bp = in.raw_float();
        s.u.kp = in.raw_float();
        for (int i = 0; i < HSTMON_CHANNELS; ++i) s.y[i] = in.raw_float();
        s.t_s = in.raw_float();
        t = s.t_s;
        break;
      case 2:
        (void)hstmon_step(m, nullptr);
        ++ticks_expected;
        check_report(m, ticks_expected, rec);
        continue;
      default: {
        hstmon_inputs u = u0;
        u.kp = in.raw_float();
        const hstmon_status st = (op & 0x40u) ? hstmon_reset_steady(m, &u) : hstmon_reset_rest(m, &u);
        if (trace) {
          hstmon_report r;
          hstmon_read(m, &r);
          std::fprintf(stderr, "rec %d reset_%s kp=%g -> %d est={%g %g %g %g}\n", rec, (op & 0x40u) ? "steady" : "rest",
                       static_cast<double>(u.kp), static_cast<int>(st), static_cast<double>(r.estimate[0]),
                       static_cast<double>(r.estimate[1]), static_cast<double>(r.estimate[2]),
                       static_cast<double>(r.estimate[3]));
        }
        if (st == HSTMON_OK) {
          ticks_expected = 0;
          t = 0.0f;
        } else if (st != HSTMON_INVALID_INPUTS && st != HSTMON_NO_STEADY_STATE) {
          fail("reset returned an unexpected status", rec);
        }
        check_report(m, ticks_expected, rec);
        continue;
      }
    }
    (void)hstmon_step(m, &s);
    if (trace) {
      hstmon_report r;
      hstmon_read(m, &r);
      std::fprintf(stderr, "rec %d t=%g u={%g %g %g %g} y={%g %g %g %g} valid=%x -> health=%x est={%g %g %g %g}\n", rec,
                   static_cast<double>(s.t_s), static_cast<double>(s.u.p_sup), static_cast<double>(s.u.p_s),
                   static_cast<double>(s.u.p_bp), static_cast<double>(s.u.kp), static_cast<double>(s.y[0]),
                   static_cast<double>(s.y[1]), static_cast<double>(s.y[2]), static_cast<double>(s.y[3]), s.valid,
                   r.last_health, static_cast<double>(r.estimate[0]), static_cast<double>(r.estimate[1]),
                   static_cast<double>(r.estimate[2]), static_cast<double>(r.estimate[3]));
    }
    ++ticks_expected;
    check_report(m, ticks_expected, rec);
    hstmon_event e;
    int popped = 0;
    while (hstmon_pop_event(m, &e) != 0) {
      if (++popped > HSTMON_EVENT_QUEUE) fail("more events popped than the queue holds", rec);
      if (e.kind > HSTMON_EVENT_CLEARED) fail("event kind out of range", rec);
      if (e.count > HSTMON_EVENT_CANDIDATES) fail("event count out of range", rec);
      for (int k = 0; k < e.count; ++k) {
        if (e.candidate[k].name == nullptr) fail("event candidate without a name", rec);
      }
      (void)hstmon_event_name(static_cast<hstmon_event_kind>(e.kind));
    }
  }
  (void)hstmon_events_dropped(m);
  (void)hstmon_health(m);
  // The matcher queries with small or null outputs: they must write at most `max`
  // entries (ASan watches the one-element heap array) and accept NULL as documented.
  const hstmon_match s = hstmon_match_status(m);
  if (hstmon_match_name(s) == nullptr) fail("match name null", -2);
  auto* one = new hstmon_candidate[1];
  const int total = hstmon_candidates(m, one, 1);
  if (total != hstmon_candidates(m, nullptr, 0)) fail("candidate total depends on max", -2);
  delete[] one;
  if (hstmon_match_status(nullptr) != HSTMON_MATCH_NOMINAL) fail("status of NULL not nominal", -2);
  hstmon_event e;
  if (hstmon_pop_event(nullptr, &e) != 0 || hstmon_pop_event(m, nullptr) != 0) fail("pop_event with NULL", -2);
  // 7: unknown but inside the enum's value range (0…7), so valid in C++ too. (99 from C is
  // legal C, but hstmon_c.cpp loads it as the enum type: UBSan "invalid enum load";
  // docs/hardening.md, finding 3.)
  if (std::strcmp(hstmon_match_name(static_cast<hstmon_match>(7)), "?") != 0) fail("unknown status name", -2);
  return 0;
}
