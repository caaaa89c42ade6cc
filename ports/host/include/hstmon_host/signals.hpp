#pragma once
/// @file signals.hpp
/// The signals a log may carry, with their canonical column names and quantities.
/// Inputs are operator settings (the caller falls back to parameter defaults when a
/// log lacks them); the rest are measurements. Pressures are gauge.

#include <cstddef>
#include <optional>
#include <string_view>

#include "hstmon_host/units.hpp"

namespace hstmon::host {

/// Known log signals. The underlying value indexes LogData's per-signal arrays.
enum class Signal : std::size_t {
  kT = 0,    ///< "t": time [s]; required in every log
  kPSup,     ///< "p_sup": supply pressure upstream of the DCV, thesis Psupl [Pa] (input)
  kPS,       ///< "p_s": DCV return (tank) pressure, thesis Ps [Pa] (input)
  kPBp,      ///< "p_bp": booster pressure downstream of the PRV, thesis Pbp [Pa] (input)
  kKp,       ///< "kp": PRV orifice coefficient [m³/(s·√Pa)] (input)
  kPMi,      ///< "p_mi": motor inlet pressure Pmi [Pa] (measured)
  kPMo,      ///< "p_mo": motor outlet pressure Pmo [Pa] (measured)
  kPPp,      ///< "p_pp": loading-pump outlet pressure Ppp [Pa] (measured)
  kWm,       ///< "w_m": motor speed ωm [rad/s] (measured)
  kPPump,    ///< "p_pump": paper rig pump-B pressure, the paper's Ps [Pa] (measured)
  kADcv,     ///< "a_dcv": paper rig DCV port area [m²] (input)
  kAPrv,     ///< "a_prv": paper rig PRV port area [m²] (input)
};

/// Number of Signal values.
inline constexpr std::size_t kSignalCount = 12;

/// Array index of a signal.
constexpr std::size_t index(Signal s) noexcept { return static_cast<std::size_t>(s); }

/// Static description of a signal.
struct SignalInfo {
  Signal signal;                 ///< the signal
  std::string_view name;         ///< canonical column name, lower case ("p_mi")
  Quantity quantity;             ///< physical quantity (decides accepted units)
  bool input;                    ///< true for operator inputs, false for measurements/time
  std::string_view description;  ///< one line for messages and help
};

/// Description of signal s.
const SignalInfo& signal_info(Signal s) noexcept;

/// Canonical column name of s ("t", "p_sup", ...).
std::string_view signal_name(Signal s) noexcept;

/// The signal whose canonical name equals `name` ignoring ASCII case, if any.
std::optional<Signal> signal_from_name(std::string_view name) noexcept;

}  // namespace hstmon::host
