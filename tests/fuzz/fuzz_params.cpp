// libFuzzer target: the JSON parameter-file reader (parse_params_json).
// Invariants: never crash; on error, line ≥ 1 and column ≥ 1 (or no position) and
// neither params nor inputs set; on success both set, every value finite and accepted
// by the model (the reader's own validation), and the formatted file reads back to the
// same values (round trip).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "hstmon/thesis_reduced.hpp"
#include "hstmon_host/params_file.hpp"

namespace {
[[noreturn]] void fail(const char* what, const hstmon::host::ParamsFileResult& r) {
  std::fprintf(stderr, "fuzz_params invariant violated: %s\n", what);
  if (r.error) std::fprintf(stderr, "  error: %s\n", r.error->to_string().c_str());
  std::abort();
}
bool finite_params(const hstmon::ThesisParams<double>& p) {
  const double v[] = {p.Dm, p.Dp, p.Rlkg, p.Ripl, p.Rf, p.Rbl, p.kf, p.J, p.K, p.dp_t_dcv, p.dp_t_prv};
  for (double x : v) {
    if (!std::isfinite(x)) return false;
  }
  return true;
}
bool finite_inputs(const hstmon::ThesisInputs<double>& u) {
  return std::isfinite(u.Psupl) && std::isfinite(u.Ps) && std::isfinite(u.Pbp) && std::isfinite(u.kp);
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace hstmon::host;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const ParamsFileResult r = parse_params_json(text, "fuzz.json");
  if (r.error) {
    const auto& e = *r.error;
    const bool no_pos = e.line == 0 && e.column == 0;
    if (!no_pos && (e.line < 1 || e.column < 1)) fail("error position has line or column 0", r);
    if (r.params || r.inputs) fail("error but params/inputs set", r);
    return 0;
  }
  if (!r.params || !r.inputs) fail("ok but params or inputs missing", r);
  if (!finite_params(*r.params)) fail("accepted a non-finite parameter", r);
  if (!finite_inputs(*r.inputs)) fail("accepted a non-finite input", r);
  if (!hstmon::ThesisReducedModel<double>::params_valid(*r.params)) fail("accepted parameters the model refuses", r);
  if (!hstmon::ThesisReducedModel<double>::inputs_valid(*r.inputs)) fail("accepted inputs the model refuses", r);
  const std::string again = format_params_json(*r.params, *r.inputs, r.description);
  const ParamsFileResult r2 = parse_params_json(again, "roundtrip.json");
  if (!r2.ok()) fail("formatted parameters do not read back", r2);
  if (!(r2.params->Dm == r.params->Dm && r2.params->K == r.params->K && r2.inputs->kp == r.inputs->kp &&
        r2.inputs->Psupl == r.inputs->Psupl))
    fail("round trip changed a value", r2);
  return 0;
}
