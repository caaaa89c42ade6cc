/* hstmon circuit C API: the float monitor of ONE circuit — observer, sensor checks,
 * residual evaluator and fault matcher (hstmon::circuit::CircuitMonitor) — built at
 * compile time from two headers generated from the circuit file:
 *   hstmon-circuit-header C.json --tick H --name C_circuit --out DIR/hstmon/generated/C_circuit.hpp
 *   hstmon-fdi table --circuit C.json --name C_signatures --out DIR/hstmon/generated/C_signatures.hpp
 * (docs/firmware.md "A circuit's C API"; the CMake function hstmon_add_circuit_c_api()
 * builds one library per circuit). Channel and input counts, names and units come from
 * the circuit: ask hstmon_circuit_channels(), hstmon_circuit_channel_column(), … .
 *
 * - No heap: a monitor lives in a buffer the caller owns (as hstmon_c.h's), of
 *   hstmon_circuit_monitor_size() bytes aligned to HSTMON_CIRCUIT_MONITOR_ALIGN; a static
 *   `hstmon_circuit_monitor_storage` has both. Its size, HSTMON_CIRCUIT_MONITOR_BYTES, is
 *   set where the library is built (hstmon_add_circuit_c_api(... MONITOR_BYTES n)) and
 *   checked against the monitor at compile time. The monitor lives as long as its buffer:
 *   nothing to release.
 * - Never blocks, never throws. Not thread-safe per monitor.
 * - Units are SI: pressures in Pa (gauge), speeds in rad/s, flows in m³/s, orifice areas
 *   in m², time in s. A log column's factor to SI is hstmon_circuit_*_unit_scale().
 * - Status codes, matcher states, events, candidates and health bits are the shared C
 *   types (hstmon_c_types.h), as in the thesis rig's API (hstmon_c.h).
 */
#ifndef HSTMON_CIRCUIT_C_H
#define HSTMON_CIRCUIT_C_H

#include <stddef.h>
#include <stdint.h>

#include "hstmon_c_types.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Room for channels in a sample (a circuit has at most 8: channel masks are 8 bits). */
#define HSTMON_CIRCUIT_MAX_CHANNELS 8
/** Room for inputs in a sample (the library refuses to build for a circuit with more). */
#define HSTMON_CIRCUIT_MAX_INPUTS 16

/** One sample: inputs and measurements at the start of a tick. */
typedef struct hstmon_circuit_sample {
  float t_s;                                /**< sample time [s], non-decreasing (matcher windows, event times) */
  float u[HSTMON_CIRCUIT_MAX_INPUTS];       /**< inputs in circuit order [SI]; the first hstmon_circuit_inputs() used */
  float y[HSTMON_CIRCUIT_MAX_CHANNELS];     /**< measurements in channel order [SI] */
  uint8_t valid;                            /**< bit i set: y[i] was measured this tick */
} hstmon_circuit_sample;

/** What a monitor reports after a tick. */
typedef struct hstmon_circuit_report {
  float residual[HSTMON_CIRCUIT_MAX_CHANNELS];  /**< r = y − ŷ [SI]; 0 where not valid */
  float estimate[HSTMON_CIRCUIT_MAX_CHANNELS];  /**< model outputs ŷ at the tick's start [SI] */
  uint8_t residual_valid;                       /**< bit i set: residual[i] was computed */
  uint16_t substeps;                            /**< RK4 substeps of the last tick */
  uint32_t last_health;                         /**< HSTMON_HEALTH_* bits of the last tick */
  uint32_t health;                              /**< HSTMON_HEALTH_* bits since the last start (latched) */
  uint64_t ticks;                               /**< ticks since the last start */
} hstmon_circuit_report;

/** Bytes of hstmon_circuit_monitor_storage: the library's MONITOR_BYTES (a compile
 *  definition its users see; hstmon_circuit_monitor_size() is never larger). */
#ifndef HSTMON_CIRCUIT_MONITOR_BYTES
#error "HSTMON_CIRCUIT_MONITOR_BYTES comes with the library: link the target hstmon_add_circuit_c_api() made"
#endif
/** Alignment a monitor buffer needs [bytes] (Eigen's fixed-size types on SIMD hosts). */
#define HSTMON_CIRCUIT_MONITOR_ALIGN 16

/** Opaque monitor handle; points into the caller's buffer. */
typedef struct hstmon_circuit_monitor hstmon_circuit_monitor;

/** A buffer with the right size and alignment for one monitor; declare it static. */
typedef struct hstmon_circuit_monitor_storage {
  HSTMON_ALIGNAS(HSTMON_CIRCUIT_MONITOR_ALIGN) unsigned char bytes[HSTMON_CIRCUIT_MONITOR_BYTES];
} hstmon_circuit_monitor_storage;

/** Bytes one monitor takes (with the model its setup solves on), ≤ HSTMON_CIRCUIT_MONITOR_BYTES. */
size_t hstmon_circuit_monitor_size(void);

/** The generated circuit header the library was built with ("paper_circuit", …). */
const char* hstmon_circuit_name(void);
/** The tick the library was generated for [s]: samples must come at this interval. */
float hstmon_circuit_tick(void);
/** Measured channels, ≤ HSTMON_CIRCUIT_MAX_CHANNELS. */
int hstmon_circuit_channels(void);
/** Inputs, ≤ HSTMON_CIRCUIT_MAX_INPUTS. */
int hstmon_circuit_inputs(void);
/** Fault hypotheses (rows of the generated signature table). */
int hstmon_circuit_faults(void);
/** Log column name of channel / input i ("p_mi", "a_dcv", …), NULL when out of range. */
const char* hstmon_circuit_channel_column(int i);
const char* hstmon_circuit_input_column(int i);
/** SI value of one unit of the circuit file's unit for channel / input i (1e5 for bar,
 *  π/30 for rpm, …) [SI per file unit]; 0 when out of range. */
double hstmon_circuit_channel_unit_scale(int i);
double hstmon_circuit_input_unit_scale(int i);
/** Fills u[0 … hstmon_circuit_inputs()−1] with the circuit's nominal inputs [SI]. */
void hstmon_circuit_nominal_inputs(float* u);

/** Constructs a monitor in buf (placement; no heap), configures it from the generated
 *  values as `hstmon replay --circuit` does (sensor noise and ranges, parameter
 *  uncertainty, the circuit allowances, matcher windows from the slowest time constant at
 *  first->u) and starts it from the first sample as `--init auto` does: from the measured
 *  states, or at the steady state when every channel reads within 3σ of it, else at rest.
 *  Pass `first` to hstmon_circuit_step() as the first tick's sample too. Costs a few
 *  hundred steady-state solves (the bound and the start); never call it on a tick
 *  deadline. The buffer must stay valid while the monitor is used; there is no destroy:
 *  drop or reuse the buffer.
 *  @param buf    ≥ hstmon_circuit_monitor_size() bytes, aligned to HSTMON_CIRCUIT_MONITOR_ALIGN
 *  @param size   size of buf [bytes]
 *  @param first  the first sample (inputs and measurements) [SI]
 *  @param out    receives the handle on HSTMON_OK, NULL otherwise
 *  @param start  out, may be NULL: how the state was chosen (hstmon_start)
 *  @return HSTMON_OK; HSTMON_INVALID_CONFIG for NULL pointers or a small or misaligned
 *          buffer; HSTMON_INVALID_PARAMS when the generated values make no circuit;
 *          HSTMON_INVALID_INPUTS when first->u is refused */
hstmon_status hstmon_circuit_create(void* buf, size_t size, const hstmon_circuit_sample* first,
                                    hstmon_circuit_monitor** out, uint8_t* start);

/** Restarts an existing monitor at the steady state for inputs u (a machine known to be
 *  running; no measurement needed).
 *  @param u  hstmon_circuit_inputs() inputs [SI]
 *  @return HSTMON_OK, HSTMON_INVALID_INPUTS or HSTMON_NO_STEADY_STATE (monitor unchanged) */
hstmon_status hstmon_circuit_reset_steady(hstmon_circuit_monitor* m, const float* u);

/** Restarts an existing monitor from sample s as hstmon_circuit_create() starts it. */
hstmon_status hstmon_circuit_restart(hstmon_circuit_monitor* m, const hstmon_circuit_sample* s, uint8_t* start);

/** Advances one tick with sample s (NULL: no sample, inputs held, the matcher does not
 *  run). As hstmon_step(): non-finite values are flagged, never propagated.
 *  @return this tick's HSTMON_HEALTH_* bits */
uint32_t hstmon_circuit_step(hstmon_circuit_monitor* m, const hstmon_circuit_sample* s);

/** Copies the monitor's current report into r. */
void hstmon_circuit_read(const hstmon_circuit_monitor* m, hstmon_circuit_report* r);

/** The fault matcher's status after the last tick (HSTMON_MATCH_NOMINAL for NULL). */
hstmon_match hstmon_circuit_match_status(const hstmon_circuit_monitor* m);

/** The consistent fault hypotheses now, best first; names are the circuit's parameter
 *  names with + or − ("Dm-", "A_prv+") and sensor_<channel>.
 *  @return the number in total (may exceed max) */
int hstmon_circuit_candidates(const hstmon_circuit_monitor* m, hstmon_candidate* out, int max);

/** Removes the oldest queued event into out; 1 if one was written, else 0. */
int hstmon_circuit_pop_event(hstmon_circuit_monitor* m, hstmon_event* out);

/** Events lost because the queue was full since the last start. */
uint32_t hstmon_circuit_events_dropped(const hstmon_circuit_monitor* m);

#ifdef __cplusplus
}
#endif

#endif /* HSTMON_CIRCUIT_C_H */
