/// @file signature_table.cpp
#include "hstmon_fdi/signature_table.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "hstmon/circuit/thesis_circuit_model.hpp"
#include "hstmon_fdi/fault_catalogue.hpp"
#include "hstmon_fdi/operating_point.hpp"
#include "hstmon_fdi/qual.hpp"
#include "hstmon_fdi/thesis_tcg.hpp"

namespace hstmon::fdi {

namespace {

constexpr double kRpmPerRadS = 60.0 / (2.0 * 3.14159265358979323846);

/// Steady-state change (Pmi, Pmo, Ppp [Pa], ωm [rad/s]) for parameter `name` scaled by
/// factor, at the load given by kp × kp_scale (1 = Table 2.2).
std::array<double, 4> steady_change(const std::string& name, double factor, double kp_scale = 1.0) {
  ThesisParams<double> p{};
  ThesisInputs<double> u{};
  u.kp *= kp_scale;
  double y0[4];
  if (!steady_outputs(p, u, y0)) throw std::runtime_error("signature table: no nominal steady state");
  scale_parameter(name, factor, p, u);
  double y[4];
  if (!steady_outputs(p, u, y)) throw std::runtime_error("signature table: no steady state for " + name);
  return {y[0] - y0[0], y[1] - y0[1], y[2] - y0[2], y[3] - y0[3]};
}

/// The loads of the cross-check besides nominal: light (kp × 1.6) and heavy (kp × 0.65).
constexpr double kOtherLoads[] = {1.6, 0.65};

const char* qual_enumerator(std::int8_t q) {
  switch (q) {
    case kQualPlus:
      return "kQualPlus";
    case kQualMinus:
      return "kQualMinus";
    case kQualZero:
      return "kQualZero";
    default:
      return "kQualAny";
  }
}

std::string format_float(float v) {
  if (std::fabs(v) < 5e-7f) v = 0.0f;  // no "-0.000000"
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6ff", static_cast<double>(v));
  return buf;
}

}  // namespace

std::vector<SignatureRow> build_signature_rows(const SignatureOptions& opt) {
  if (!(opt.sigma_pressure > 0.0 && opt.sigma_speed_rpm > 0.0 && opt.direction_step > 0.0 && opt.max_order >= 0)) {
    throw std::invalid_argument("signature table: noise levels and step must be positive");
  }
  const OperatingPoint op = operating_point();
  const CausalGraph g = thesis_tcg(ValveModel::kNonlinear, op);
  const double y0[4] = {op.x.Pmi, op.x.Pmo, op.x.Ppp, op.x.w_m};  // nominal, for the zero tolerance
  const double sigma[4] = {opt.sigma_pressure, opt.sigma_pressure, opt.sigma_pressure,
                           opt.sigma_speed_rpm / kRpmPerRadS};
  std::vector<SignatureRow> rows;
  for (const FaultParameter& fp : fault_parameters()) {
    for (int dir : {-1, 1}) {
      if ((dir < 0 && !fp.down_in_table) || (dir > 0 && !fp.up_in_table)) continue;
      SignatureRow row{};
      row.name = fault_name(fp.name, dir);
      row.sig.sensor = false;
      const std::array<double, 4> ss = steady_change(fp.name, 1.0 + dir * fp.crosscheck_step);
      const std::array<double, 4> small = steady_change(fp.name, 1.0 + dir * opt.direction_step);
      std::array<std::array<double, 4>, 2> other{};
      for (std::size_t l = 0; l < 2; ++l)
        other[l] = steady_change(fp.name, 1.0 + dir * fp.crosscheck_step, kOtherLoads[l]);
      const std::vector<ParamStep> steps = fault_steps(fp.name, dir, ValveModel::kNonlinear);
      const ForwardResult tcg = forward_qualitative(g, steps, opt.max_order);
      const ForwardResult weighted = forward_weighted(g, steps, opt.max_order);
      double norm = 0.0;
      for (std::size_t c = 0; c < 4; ++c) norm += (small[c] / sigma[c]) * (small[c] / sigma[c]);
      norm = std::sqrt(norm);
      std::string disagree;
      for (std::size_t c = 0; c < 4; ++c) {
        ChannelSignature& ch = row.sig.channel[c];
        const QualSign mag = qual_from_value(ss[c], 1e-12 * std::fabs(y0[c]));
        const QualSign mag_small = qual_from_value(small[c], 1e-12 * std::fabs(y0[c]));
        const ChannelPrediction& pr = tcg.channel[c];
        // Near an extremum (Ppp against Dp) the sign depends on the fault size or on the
        // load (the table must hold over the operating range): promise nothing there.
        bool same_over_loads = true;
        for (const auto& o : other) same_over_loads &= qual_from_value(o[c], 1e-12 * std::fabs(y0[c])) == mag;
        ch.magnitude = (mag == mag_small && same_over_loads) ? mag : kQualAny;
        // Opposite paths meeting: the operating-point gains decide (they match the nonlinear 0+ slope).
        ch.slope = pr.order < 0 ? kQualZero : (pr.slope == kQualAny ? weighted.channel[c].slope : pr.slope);
        ch.order = static_cast<std::uint8_t>(pr.order < 0 ? 0 : pr.order);
        // Direction only where the fault moves the steady state above rounding.
        row.sig.direction[c] = norm > 0.0 && mag != kQualZero ? static_cast<float>(small[c] / sigma[c] / norm) : 0.0f;
        if (pr.magnitude != kQualAny && pr.magnitude != mag) {
          disagree += std::string(disagree.empty() ? "" : ", ") + kMeasurementNodes[c] + " TCG " +
                      qual_symbol(pr.magnitude) + " vs steady " + qual_symbol(mag);
        }
        if (pr.magnitude == kQualAny) {
          disagree += std::string(disagree.empty() ? "" : ", ") + kMeasurementNodes[c] +
                      " TCG ambiguous (slope from gains)";
        }
        if (mag != mag_small) {
          disagree += std::string(disagree.empty() ? "" : ", ") + kMeasurementNodes[c] + " steady sign depends on size";
        } else if (!same_over_loads) {
          disagree += std::string(disagree.empty() ? "" : ", ") + kMeasurementNodes[c] + " steady sign depends on load";
        }
      }
      row.note = disagree;
      rows.push_back(row);
    }
  }
  for (int c = 0; c < 4; ++c) {
    SignatureRow row{};
    row.name = std::string("sensor_") + kMeasurementNodes[c];
    row.sig.sensor = true;
    for (int k = 0; k < 4; ++k) {
      const bool own = k == c;
      row.sig.channel[k] = ChannelSignature{own ? std::int8_t{kQualAny} : std::int8_t{kQualZero},
                                            own ? std::int8_t{kQualAny} : std::int8_t{kQualZero}, 0};
      row.sig.direction[k] = 0.0f;
    }
    rows.push_back(row);
  }
  for (SignatureRow& r : rows) r.sig.name = r.name.c_str();
  return rows;
}

std::string render_signature_header(const std::vector<SignatureRow>& rows, const SignatureOptions& opt) {
  char opts[256];
  std::snprintf(opts, sizeof opts,
                "sigma_pressure = %g Pa, sigma_speed = %g rpm, direction step = %g %%, TCG order <= %d",
                opt.sigma_pressure, opt.sigma_speed_rpm, 100.0 * opt.direction_step, opt.max_order);
  std::string s;
  s += "#pragma once\n";
  s += "/// @file thesis_signatures.hpp\n";
  s += "/// Fault-signature table of the thesis rig (seed 000) for the matcher.\n";
  s += "/// Generated by the test oracle (tests/fdi/thesis): do not edit. Regenerate with\n";
  s += "///   thesis_signature_header lib/include/hstmon/generated/thesis_signatures.hpp (built with the tests)\n";
  s += std::string("/// Options: ") + opts + ".\n";
  s += "/// Per channel (Pmi, Pmo, Ppp, wm) {magnitude, slope, order}: magnitude = sign of the nonlinear\n";
  s += "/// steady-state change at Table 2.2 (step 10 %, kp 50 %), kQualAny where that sign changes with\n";
  s += "/// the fault size or between light (kp x 1.6) and heavy (kp x 0.65) load; slope and order = the temporal "
       "causal\n";
  s += "/// graph of Fig. 2.3 (docs/fdi.md). direction = unit vector of the noise-scaled steady-state\n";
  s += "/// residual of a small fault; zero where the fault does not move the steady state.\n\n";
  s += "#include \"hstmon/fault_signature.hpp\"\n\n";
  s += "namespace hstmon {\n\n";
  s += "// clang-format off\n";
  s += "inline constexpr FaultSignature kThesisSignatures[] = {\n";
  for (const SignatureRow& r : rows) {
    if (!r.note.empty()) s += "    // " + r.name + ": " + r.note + "\n";
    s += "    {\"" + r.name + "\", " + (r.sig.sensor ? "true" : "false") + ", {";
    for (int c = 0; c < 4; ++c) {
      const ChannelSignature& ch = r.sig.channel[c];
      s += std::string(c ? ", " : "") + "{" + qual_enumerator(ch.magnitude) + ", " + qual_enumerator(ch.slope) + ", " +
           std::to_string(ch.order) + "}";
    }
    s += "}, {";
    for (int c = 0; c < 4; ++c) s += std::string(c ? ", " : "") + format_float(r.sig.direction[c]);
    s += "}},\n";
  }
  s += "};\n";
  s += "// clang-format on\n\n";
  s += "/// Number of rows of kThesisSignatures.\n";
  s += "inline constexpr int kThesisSignatureCount = " + std::to_string(rows.size()) + ";\n\n";
  s += "}  // namespace hstmon\n";
  return s;
}

}  // namespace hstmon::fdi
