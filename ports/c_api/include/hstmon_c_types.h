/* hstmon C API types shared by the thesis rig's API (hstmon_c.h) and a circuit's API
 * (hstmon_circuit_c.h): status codes, health bits, start kinds, matcher states, events and
 * candidates, and their names. Units are SI; every value mirrors a core type named in its
 * comment (hstmon::Status, hstmon::HealthFlag, …), which the libraries check at compile time.
 */
#ifndef HSTMON_C_TYPES_H
#define HSTMON_C_TYPES_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/** Result of a configuration call (hstmon::Status). */
typedef enum hstmon_status {
  HSTMON_OK = 0,             /**< accepted */
  HSTMON_INVALID_PARAMS = 1, /**< a model parameter is non-finite or out of range */
  HSTMON_INVALID_CONFIG = 2, /**< tick/substep limits invalid, or a NULL, small or misaligned buffer */
  HSTMON_INVALID_INPUTS = 3, /**< an input is non-finite or out of its range (e.g. an orifice coefficient < 0) */
  HSTMON_NO_STEADY_STATE = 4 /**< the inputs admit no steady state (e.g. a relief path shut) */
} hstmon_status;

/** Health flag bits of a tick (hstmon::HealthFlag); 0 = healthy. */
enum {
  HSTMON_HEALTH_INPUT_NON_FINITE = 1u << 0,    /**< an input was NaN/Inf or out of range; last good inputs held */
  HSTMON_HEALTH_MEAS_NON_FINITE = 1u << 1,     /**< a valid-marked channel was NaN/Inf; treated as missing */
  HSTMON_HEALTH_SUBSTEPS_CLIPPED = 1u << 2,    /**< stiffness needed more substeps than allowed */
  HSTMON_HEALTH_STATE_NON_FINITE = 1u << 3,    /**< model state became NaN/Inf; reset to last good */
  HSTMON_HEALTH_STATE_OUT_OF_BOUNDS = 1u << 4, /**< a state (a speed or pressure) beyond its physical bound */
  HSTMON_HEALTH_ALGEBRAIC_DIVERGED = 1u << 5   /**< a quasi-steady node's solve not contracting */
};

/** How a monitor chose its initial state at a start (hstmon::InitialState). */
typedef enum hstmon_start {
  HSTMON_START_MEASURED = 0, /**< both states from their measurements */
  HSTMON_START_REST = 1,     /**< at rest (measured states set to their readings) */
  HSTMON_START_STEADY = 2    /**< at the steady state (measured states set to their readings) */
} hstmon_start;

/** Diagnosis status of the fault matcher (hstmon::MatchStatus). */
typedef enum hstmon_match {
  HSTMON_MATCH_NOMINAL = 0,    /**< no channel in alarm, no sensor flagged */
  HSTMON_MATCH_DETECTED = 1,   /**< an episode is running; evidence still arriving, > 1 candidate */
  HSTMON_MATCH_ISOLATED = 2,   /**< one candidate, or the best leads clearly after the averaging window */
  HSTMON_MATCH_AMBIGUOUS = 3,  /**< several candidates after the window, none clearly best */
  HSTMON_MATCH_UNEXPLAINED = 4 /**< every single-fault hypothesis of the table contradicted */
} hstmon_match;

/** Kind of a matcher event (hstmon::MatchEventKind). */
typedef enum hstmon_event_kind {
  HSTMON_EVENT_DETECTED = 0,    /**< an episode started */
  HSTMON_EVENT_ISOLATED = 1,    /**< status became HSTMON_MATCH_ISOLATED */
  HSTMON_EVENT_AMBIGUOUS = 2,   /**< status became HSTMON_MATCH_AMBIGUOUS */
  HSTMON_EVENT_UNEXPLAINED = 3, /**< status became HSTMON_MATCH_UNEXPLAINED */
  HSTMON_EVENT_CLEARED = 4      /**< the episode ended (back to nominal) */
} hstmon_event_kind;

/** Candidates an event carries (the best); hstmon_candidates() / hstmon_circuit_candidates() give all of them. */
#define HSTMON_EVENT_CANDIDATES 1

/** A ranked fault hypothesis. */
typedef struct hstmon_candidate {
  const char* name; /**< "kp-", "Dp+", "sensor_p_pp", … (static storage: the table in flash) */
  float score;      /**< ranking score in [-1, 1], higher is better (cosine of the deviation) [-] */
} hstmon_candidate;

/** A matcher event. */
typedef struct hstmon_event {
  float t_s;                                           /**< t_s of the sample whose tick raised it [s] */
  uint8_t kind;                                        /**< hstmon_event_kind */
  uint8_t consistent;                                  /**< consistent hypotheses in total then (0 for CLEARED) */
  uint8_t count;                                       /**< entries used in candidate[] (≤ HSTMON_EVENT_CANDIDATES) */
  hstmon_candidate candidate[HSTMON_EVENT_CANDIDATES]; /**< best first; empty for CLEARED */
} hstmon_event;

/** Alignment specifier usable in C11 and C++ headers. */
#if defined(__cplusplus)
#define HSTMON_ALIGNAS(n) alignas(n)
#else
#define HSTMON_ALIGNAS(n) _Alignas(n) /* C11 */
#endif

/** Lower-case name of a status or event kind ("nominal", "isolated", "cleared", …); "?"
 *  for any other value. They take an int (an hstmon_match / hstmon_event_kind converts to
 *  it), so a value outside the enumeration — an uninitialised variable, a corrupted
 *  message — is range-checked as a number and never loaded as the enum type. */
const char* hstmon_match_name(int s);
const char* hstmon_event_name(int k);

#ifdef __cplusplus
}
#endif

#endif /* HSTMON_C_TYPES_H */
