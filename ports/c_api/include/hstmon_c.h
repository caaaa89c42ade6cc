/* hstmon C API: the thesis-rig monitor in float — observer, sensor checks, residual
 * evaluator and fault matcher over the generated 26-row signature table
 * (hstmon::ModelMonitor<Model, 26, 2, 1>) — behind plain C structs, for C firmware and for
 * PLC runtimes that call C (see hstmon_fb.st for an IEC 61131-3 wrapper).
 *
 * - Two libraries, one header and one behaviour: hstmon_c runs the thesis equations'
 *   hand-written specialisation (ThesisReducedModel, within the Cortex-M4F budgets);
 *   hstmon_c_engine (hosts) runs them on the circuit engine (ThesisCircuitModel,
 *   thesis.json compiled). The one difference: with the PRV shut (kp = 0) the engine
 *   finds the stall as a steady state, the specialisation reports none.
 * - No heap: the monitor lives in a caller-provided buffer of hstmon_monitor_size() bytes
 *   (at most HSTMON_MONITOR_STORAGE_BYTES), aligned to HSTMON_MONITOR_ALIGN; a static
 *   `hstmon_monitor_storage` object has both.
 * - Never blocks, never throws, never calls the C library's allocator; every function is
 *   O(1) except hstmon_reset_steady() (a bounded root search, ≤ ~300 model evaluations)
 *   and the first hstmon_step() after a reset or after an input has moved more than
 *   1 % (relative) from its value at the last bound, which recomputes the model bound
 *   of the thresholds (≈ 20 steady-state solves; docs/firmware.md has the
 *   cost). A tick with a sample also runs the fault matcher (O(26 rows) when it changes
 *   its candidate set, O(1) while nominal).
 * - Not thread-safe per monitor: one task steps one monitor; separate monitors are
 *   independent.
 * - Units are SI throughout: pressures in Pa (gauge), speed in rad/s, time in s.
 * - Channel order everywhere: HSTMON_CH_PMI, HSTMON_CH_PMO, HSTMON_CH_PPP, HSTMON_CH_WM.
 */
#ifndef HSTMON_C_H
#define HSTMON_C_H

#include <stddef.h>
#include <stdint.h>

#include "hstmon_c_types.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Bytes reserved by hstmon_monitor_storage; hstmon_monitor_size() is never larger
 *  (checked at compile time in hstmon_c.cpp): 1248 on 32-bit targets (the monitor's
 *  size on the Cortex-M4F), 1296 on 64-bit hosts (8-byte pointers, padding). Linked
 *  against hstmon_c_engine (the engine's thesis model; HSTMON_C_THESIS_ENGINE, which
 *  that library's users see defined): 1872 and 1920. */
#if defined(HSTMON_C_THESIS_ENGINE)
#if UINTPTR_MAX > 0xFFFFFFFFu
#define HSTMON_MONITOR_STORAGE_BYTES 1920u
#else
#define HSTMON_MONITOR_STORAGE_BYTES 1872u
#endif
#elif UINTPTR_MAX > 0xFFFFFFFFu
#define HSTMON_MONITOR_STORAGE_BYTES 1296u
#else
#define HSTMON_MONITOR_STORAGE_BYTES 1248u
#endif
/** Alignment the monitor buffer needs [bytes]: 16 for Eigen's vectorised fixed-size types
 *  on SSE/NEON hosts (4 would do on Cortex-M4, which has no SIMD unit Eigen uses). */
#define HSTMON_MONITOR_ALIGN 16
/** Measured channels. */
#define HSTMON_CHANNELS 4

/** Channel indices (ThesisChannel in lib/include/hstmon/thesis_reduced.hpp). */
enum {
  HSTMON_CH_PMI = 0, /**< motor inlet pressure Pmi [Pa] */
  HSTMON_CH_PMO = 1, /**< motor outlet pressure Pmo [Pa] */
  HSTMON_CH_PPP = 2, /**< loading-pump outlet pressure Ppp [Pa] */
  HSTMON_CH_WM = 3   /**< motor speed ωm [rad/s] */
};

/** Model parameters (thesis Table 2.2; hstmon_default_config() fills them). */
typedef struct hstmon_params {
  float Dm;        /**< motor displacement [m³/rad] */
  float Dp;        /**< loading-pump displacement [m³/rad] */
  float Rlkg;      /**< leakage resistance of each motor port to drain [Pa·s/m³] */
  float Ripl;      /**< cross-port leakage resistance of the motor [Pa·s/m³] */
  float Rf;        /**< shaft friction [N·m·s/rad] */
  float Rbl;       /**< fluid friction of the flow-control valves [N·m·s/rad] */
  float kf;        /**< DCV orifice coefficient, Q = kf·√ΔP [m³/(s·√Pa)] */
  float J;         /**< moment of inertia of motor + pump [kg·m²] */
  float K;         /**< bulk stiffness of each fluid volume [Pa/m³] */
  float dp_t_dcv;  /**< laminar transition ΔP of the DCV orifices [Pa] */
  float dp_t_prv;  /**< laminar transition ΔP of the PRV orifice [Pa] */
} hstmon_params;

/** Inputs, held over one tick. */
typedef struct hstmon_inputs {
  float p_sup;  /**< supply pressure upstream of the DCV [Pa] */
  float p_s;    /**< DCV return (tank) pressure [Pa] */
  float p_bp;   /**< booster pressure downstream of the PRV [Pa] */
  float kp;     /**< PRV orifice coefficient [m³/(s·√Pa)], ≥ 0 */
} hstmon_inputs;

/** Monitor configuration. */
typedef struct hstmon_config {
  hstmon_params params;   /**< model parameters */
  float tick_s;           /**< tick h [s], > 0 (1e-3 controller, 1e-2 PLC scan) */
  float lambda_h_max;     /**< largest |λ|·h per RK4 substep [-], in (0, 2.5]; 0.8 default */
  uint16_t max_substeps;  /**< substep cap per tick [-], ≥ 1; 256 default */
} hstmon_config;

/** One sample: inputs and measurements at the start of a tick. */
typedef struct hstmon_sample {
  float t_s;                    /**< sample time [s]; informational (the monitor counts ticks) */
  hstmon_inputs u;              /**< inputs */
  float y[HSTMON_CHANNELS];     /**< measurements Pmi, Pmo, Ppp [Pa], ωm [rad/s] */
  uint8_t valid;                /**< bit i set: y[i] was measured this tick */
} hstmon_sample;

/** What a monitor reports after a tick. */
typedef struct hstmon_report {
  float residual[HSTMON_CHANNELS];  /**< r = y − ŷ [Pa, Pa, Pa, rad/s]; 0 where not valid */
  float estimate[HSTMON_CHANNELS];  /**< model outputs ŷ at the tick's start [Pa, Pa, Pa, rad/s] */
  uint8_t residual_valid;           /**< bit i set: residual[i] was computed */
  uint16_t substeps;                /**< RK4 substeps of the last tick */
  uint32_t last_health;             /**< HSTMON_HEALTH_* bits of the last tick */
  uint32_t health;                  /**< HSTMON_HEALTH_* bits OR-ed since the last reset (latched) */
  uint64_t ticks;                   /**< ticks since the last reset */
} hstmon_report;

/** Fault rows of the signature table the monitor holds (its hypotheses). */
#define HSTMON_MAX_FAULTS 26
/** Events queued until popped; the oldest is dropped when full. One tick raises at most
 *  2 (detected and isolated together), so popping after every tick loses none. */
#define HSTMON_EVENT_QUEUE 2

/** Opaque monitor handle; points into the caller's buffer. */
typedef struct hstmon_monitor hstmon_monitor;

/** A buffer with the right size and alignment for one monitor; declare it static. */
typedef struct hstmon_monitor_storage {
  HSTMON_ALIGNAS(HSTMON_MONITOR_ALIGN) unsigned char bytes[HSTMON_MONITOR_STORAGE_BYTES];
} hstmon_monitor_storage;

/** Size a monitor needs [bytes], ≤ HSTMON_MONITOR_STORAGE_BYTES. */
size_t hstmon_monitor_size(void);

/** Fills cfg with Table 2.2, tick 1 ms, λh 0.8, 256 substeps. Never fails. */
void hstmon_default_config(hstmon_config* cfg);

/** Fills u with the thesis's nominal inputs (35 bar, 0 bar, 10 bar, kp = 4.41e-8). */
void hstmon_default_inputs(hstmon_inputs* u);

/** Constructs a monitor in buf (placement; no heap) with the generated fault-signature
 *  table and the default evaluator, sensor-check and matcher settings (those of
 *  `hstmon replay`), and resets it at rest for the default inputs. The buffer must stay valid while the monitor is used; there is no
 *  destroy (nothing to release): drop or reuse the buffer.
 *  @param buf   ≥ hstmon_monitor_size() bytes, aligned to HSTMON_MONITOR_ALIGN
 *  @param size  size of buf [bytes]
 *  @param cfg   configuration (copied)
 *  @param out   receives the handle on HSTMON_OK, NULL otherwise
 *  @return HSTMON_OK; HSTMON_INVALID_CONFIG for a NULL/small/misaligned buffer or a bad
 *          tick/substep setting; HSTMON_INVALID_PARAMS for bad parameters */
hstmon_status hstmon_create(void* buf, size_t size, const hstmon_config* cfg, hstmon_monitor** out);

/** Restarts from the first sample s (the usual start): the model starts from the measured
 *  states (Ppp = y[2], ωm = y[3]) when both are valid and plausible, else at rest or at
 *  the steady state for s->u, whichever the valid channels say; detection then holds off
 *  while the model's own start-up transient lasts (derived from its time constants at
 *  s->u, so a log that begins at rest, in a start-up or running is met alike). s is not
 *  evaluated: pass it to hstmon_step() as the first tick's sample.
 *  @param start  out, may be NULL: how the state was chosen (hstmon_start)
 *  @return HSTMON_OK or HSTMON_INVALID_INPUTS (monitor unchanged) */
hstmon_status hstmon_reset_measured(hstmon_monitor* m, const hstmon_sample* s, uint8_t* start);

/** Restarts at the steady state for inputs u (logs or machines already running).
 *  @return HSTMON_OK, HSTMON_INVALID_INPUTS or HSTMON_NO_STEADY_STATE (monitor unchanged) */
hstmon_status hstmon_reset_steady(hstmon_monitor* m, const hstmon_inputs* u);

/** Restarts at rest (ωm = 0, Ppp = p_bp) for inputs u.
 *  @return HSTMON_OK or HSTMON_INVALID_INPUTS (monitor unchanged) */
hstmon_status hstmon_reset_rest(hstmon_monitor* m, const hstmon_inputs* u);

/** Advances one tick with sample s: observer, sensor checks, residual evaluator and (if
 *  s->valid ≠ 0) the fault matcher. Non-finite inputs or measurements are flagged and
 *  skipped by the observer, never propagated; a non-finite measurement also flags its
 *  sensor, and the matcher then considers only that sensor's fault row.
 *  s->t_s is the time the matcher uses (windows, event times): non-decreasing, in
 *  seconds. As a float it resolves t·6e-8 s — 61 µs at 1 000 s, 1 ms at 16 000 s — so
 *  on a long run rebase it (e.g. to 0) while hstmon_match_status() is NOMINAL: the
 *  matcher keeps no time across episodes. s = NULL: no sample, the model advances with
 *  the last inputs (the matcher is not run).
 *  @return this tick's HSTMON_HEALTH_* bits (also latched into the report's health) */
uint32_t hstmon_step(hstmon_monitor* m, const hstmon_sample* s);

/** Copies the monitor's current report into r. */
void hstmon_read(const hstmon_monitor* m, hstmon_report* r);

/** Latched HSTMON_HEALTH_* bits since the last reset (cheaper than hstmon_read). */
uint32_t hstmon_health(const hstmon_monitor* m);

/** The fault matcher's status after the last tick (HSTMON_MATCH_NOMINAL for NULL). */
hstmon_match hstmon_match_status(const hstmon_monitor* m);

/** The consistent fault hypotheses now, best first.
 *  @param out  receives min(total, max) candidates (may be NULL when max is 0)
 *  @return     the number of consistent hypotheses in total (0 when nominal; may exceed max) */
int hstmon_candidates(const hstmon_monitor* m, hstmon_candidate* out, int max);

/** Removes the oldest queued event into out.
 *  @return 1 if an event was written, 0 if the queue is empty (or m/out is NULL) */
int hstmon_pop_event(hstmon_monitor* m, hstmon_event* out);

/** Events lost because the queue was full since the last reset. */
uint32_t hstmon_events_dropped(const hstmon_monitor* m);

#ifdef __cplusplus
}
#endif

#endif /* HSTMON_C_H */
