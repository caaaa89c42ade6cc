#include "hstmon_host/signals.hpp"

#include <array>

#include "text_util.hpp"

namespace hstmon::host {

namespace {

constexpr std::array<SignalInfo, kSignalCount> kSignals{{
    {Signal::kT, "t", Quantity::kTime, false, "time"},
    {Signal::kPSup, "p_sup", Quantity::kPressure, true, "supply pressure upstream of the DCV (Psupl)"},
    {Signal::kPS, "p_s", Quantity::kPressure, true, "DCV return / tank pressure (thesis Ps)"},
    {Signal::kPBp, "p_bp", Quantity::kPressure, true, "booster pressure downstream of the PRV (Pbp)"},
    {Signal::kKp, "kp", Quantity::kKp, true, "PRV orifice coefficient"},
    {Signal::kPMi, "p_mi", Quantity::kPressure, false, "motor inlet pressure (Pmi)"},
    {Signal::kPMo, "p_mo", Quantity::kPressure, false, "motor outlet pressure (Pmo)"},
    {Signal::kPPp, "p_pp", Quantity::kPressure, false, "loading-pump outlet pressure (Ppp)"},
    {Signal::kWm, "w_m", Quantity::kSpeed, false, "motor speed (wm)"},
    {Signal::kPPump, "p_pump", Quantity::kPressure, false, "paper rig pump-B pressure (paper Ps)"},
    {Signal::kADcv, "a_dcv", Quantity::kArea, true, "paper rig DCV port area"},
    {Signal::kAPrv, "a_prv", Quantity::kArea, true, "paper rig PRV port area"},
}};

constexpr bool table_in_order() {
  for (std::size_t i = 0; i < kSignalCount; ++i) {
    if (index(kSignals[i].signal) != i) return false;
  }
  return true;
}
static_assert(table_in_order(), "kSignals must be in Signal order");

}  // namespace

const SignalInfo& signal_info(Signal s) noexcept { return kSignals[index(s)]; }

std::string_view signal_name(Signal s) noexcept { return kSignals[index(s)].name; }

std::optional<Signal> signal_from_name(std::string_view name) noexcept {
  for (const SignalInfo& info : kSignals) {
    if (detail::iequals(info.name, name)) return info.signal;
  }
  return std::nullopt;
}

}  // namespace hstmon::host
