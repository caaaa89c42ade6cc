/// @file fault_catalogue.cpp
#include "hstmon_fdi/fault_catalogue.hpp"

#include <stdexcept>

#include "hstmon_fdi/backward.hpp"

namespace hstmon::fdi {

const std::vector<FaultParameter>& fault_parameters() {
  // The usual parameter: a 10 % cross-check step, and a fault either way (the defaults).
  // Leakage resistances only fall (wear); an increase is not a fault of a real motor.
  static const std::vector<FaultParameter> kAll = {
      {"kp", "PRV orifice coefficient (blockage: kp-)", 0.5},
      {"kf", "DCV orifice coefficient, inlet and outlet"},
      {"Psupl", "supply pressure"},
      {"Pbp", "booster-pump pressure"},
      {"Rbl", "fluid friction of the flow-control valves, Rbl1 + Rbl2"},
      {"Rf", "shaft friction"},
      {"Dp", "loading-pump displacement"},
      {"Dm", "motor displacement"},
      {"Rlkg", "motor port leakage resistance, Rlkg1 = Rlkg2", 0.1, false},
      {"Ripl", "motor cross-port leakage resistance", 0.1, false},
      {"J", "inertia of motor + loading pump"},
      {"K", "bulk stiffness of every volume, Kpmi = Kpmo = Kpp"},
  };
  return kAll;
}

const FaultParameter* find_fault_parameter(std::string_view name) {
  for (const FaultParameter& f : fault_parameters()) {
    if (f.name == name) return &f;
  }
  return nullptr;
}

void scale_parameter(std::string_view name, double factor, ThesisParams<double>& p, ThesisInputs<double>& u) {
  if (name == "kp")
    u.kp *= factor;
  else if (name == "kf")
    p.kf *= factor;
  else if (name == "Psupl")
    u.Psupl *= factor;
  else if (name == "Pbp")
    u.Pbp *= factor;
  else if (name == "Rbl")
    p.Rbl *= factor;
  else if (name == "Rf")
    p.Rf *= factor;
  else if (name == "Dp")
    p.Dp *= factor;
  else if (name == "Dm")
    p.Dm *= factor;
  else if (name == "Rlkg")
    p.Rlkg *= factor;
  else if (name == "Ripl")
    p.Ripl *= factor;
  else if (name == "J")
    p.J *= factor;
  else if (name == "K")
    p.K *= factor;
  else
    throw std::invalid_argument("unknown fault parameter " + std::string(name));
}

std::vector<ParamStep> graph_parameters(std::string_view name, ValveModel valves) {
  const bool lin = valves == ValveModel::kLinearised;
  if (name == "kp") return {lin ? ParamStep{"Rpl", -1} : ParamStep{"kp", 1}};
  if (name == "kf")
    return lin ? std::vector<ParamStep>{{"Rin", -1}, {"Rout", -1}} : std::vector<ParamStep>{{"kfi", 1}, {"kfo", 1}};
  if (name == "Psupl" || name == "Pbp" || name == "Rf" || name == "Dp" || name == "Dm" || name == "Ripl") {
    return {ParamStep{std::string(name), 1}};
  }
  if (name == "Rbl") return {{"Rbl1", 1}, {"Rbl2", 1}};
  if (name == "Rlkg") return {{"Rlkg1", 1}, {"Rlkg2", 1}};
  if (name == "J") return {{"J1", 1}};
  if (name == "K") return {{"Kpmi", 1}, {"Kpmo", 1}, {"Kpp", 1}};
  throw std::invalid_argument("unknown fault parameter " + std::string(name));
}

std::string fault_name(std::string_view param, int sign) { return std::string(param) + (sign > 0 ? "+" : "-"); }

void parse_fault(const std::string& text, std::string& param, int& sign) { parse_observation(text, param, sign); }

std::vector<ParamStep> fault_steps(const std::string& param, int sign, ValveModel valves) {
  if (find_fault_parameter(param) == nullptr) return {ParamStep{param, sign}};
  std::vector<ParamStep> steps = graph_parameters(param, valves);
  for (ParamStep& s : steps) s.sign *= sign;
  return steps;
}

}  // namespace hstmon::fdi
