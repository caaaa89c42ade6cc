// hstmon._core.identify and .gap: the circuit identify (circuit_fit.hpp) and sim-to-real
// gap (circuit_gap.hpp) of `hstmon identify --circuit` and `hstmon gap --circuit`. Each
// returns an outcome that keeps the C++ result, so its text and its report folder are the
// CLI's own (circuit_identify_report.hpp, circuit_gap_report.hpp).
#include <pybind11/stl.h>

#include "binding.hpp"
#include "hstmon_gap/circuit_gap.hpp"
#include "hstmon_gap/circuit_gap_report.hpp"
#include "hstmon_host/circuit_units.hpp"
#include "hstmon_ident/circuit_fit.hpp"
#include "hstmon_ident/circuit_identify_report.hpp"
#include "hstmon_plot/circuit_report.hpp"

namespace hstmon::python {

namespace {

// One identify run: the circuit, the fit, and how its logs are named.
struct IdentifyOutcome {
  std::shared_ptr<Circuit> circuit;
  ident::CircuitFitResult result;
  ident::CircuitIdentifyRun run;
  std::string values;  // the fitted parameter file
  py::dict as_dict() const;
  std::string text() const { return ident::circuit_identify_text(run, circuit->loaded(), result); }
  sim::CircuitReport report() const { return ident::circuit_identify_report(run, circuit->loaded(), result, text()); }
};

// One gap run.
struct GapOutcome {
  std::shared_ptr<Circuit> circuit;
  gap::CircuitGapResult result;
  gap::CircuitGapRun run;
  py::dict as_dict() const;
  std::string text() const { return gap::circuit_gap_text(run, circuit->loaded(), result); }
  sim::CircuitReport report() const { return gap::circuit_gap_report(run, circuit->loaded(), result, text()); }
};

// Writes the outcome's report folder; returns why the figure is missing ("" when drawn).
template <class Outcome>
std::string write_report(const Outcome& o, const std::string& folder) {
  std::string warning;
  const std::string err = sim::write_circuit_report(folder, o.report(), warning);
  if (!err.empty()) throw py::value_error(err);
  return warning;
}

constexpr const char* kReportDoc = "writes the CLI's report folder; returns why the figure is missing ('' when drawn)";

std::shared_ptr<IdentifyOutcome> identify(const std::shared_ptr<Circuit>& c, const std::vector<std::shared_ptr<Log>>& logs,
                                          const std::vector<std::string>& fit, double min_duration,
                                          const std::vector<std::string>& labels) {
  if (logs.empty()) throw py::value_error("identify needs logs");
  if (!(min_duration > 0.0)) throw py::value_error("min_duration must be > 0 s");
  std::vector<circuit_tools::CircuitLog> data;
  for (const auto& l : logs) data.push_back(l->data);
  ident::CircuitFitOptions o;
  o.fit = fit;
  o.min_duration = min_duration;
  ident::CircuitFitResult r;
  std::string values;
  {
    py::gil_scoped_release release;
    r = ident::fit_circuit(c->loaded(), data, o);
    if (!r.error) values = ident::fitted_values_json(c->loaded(), r);
  }
  if (r.error) throw py::value_error("identify, " + c->path() + ": " + *r.error);
  auto out = std::make_shared<IdentifyOutcome>();
  out->circuit = c;
  out->result = std::move(r);
  out->run.circuit = c->path();
  out->run.logs = labels;
  out->values = std::move(values);
  return out;
}

py::dict IdentifyOutcome::as_dict() const {
  const ident::CircuitFitResult& r = result;
  const std::shared_ptr<Circuit>& c = circuit;
  py::list params;
  for (std::size_t j = 0; j < r.names.size(); ++j) {
    const int k = c->loaded().file.param_index(r.names[j]);
    py::dict p;
    p["name"] = r.names[j];
    p["start"] = r.start[j];
    p["value"] = r.value[j];
    p["rel_se"] = r.rel_se[j];
    p["unit"] = host::circuit_si_unit(c->loaded().file.params[static_cast<std::size_t>(k)].quantity);
    params.append(p);
  }
  using P = ident::CircuitOperatingPoint;
  py::list points;
  for (const P& pt : r.points) {
    points.append(dict_of(pt, "log", &P::log, "t0", &P::t0, "t1", &P::t1, "rows", &P::n, "inputs", &P::inputs, "mean",
                          &P::mean, "before", &P::before, "after", &P::after));
  }
  using R = ident::CircuitFitResult;
  py::dict d;
  py::list held;
  for (const auto& h : r.held) {
    py::dict e;
    e["name"] = h.name;
    e["value"] = h.value;
    e["why"] = h.why;
    held.append(e);
  }
  d["parameters"] = params;
  d["held"] = held;
  d["points"] = points;
  put_fields(d, r, "rms_before", &R::rms_before, "rms_after", &R::rms_after, "status", &R::status, "notes", &R::notes);
  d["values_json"] = values;
  return d;
}

std::shared_ptr<GapOutcome> gap_of(const std::shared_ptr<Circuit>& c, const std::shared_ptr<Log>& fit,
                                   const std::shared_ptr<Log>& check, const std::string& fit_label,
                                   const std::string& check_label) {
  auto out = std::make_shared<GapOutcome>();
  {
    py::gil_scoped_release release;
    out->result = gap::circuit_gap(c->loaded(), fit->data, check->data);
  }
  if (out->result.error) throw py::value_error("gap --circuit " + c->path() + ": " + *out->result.error);
  out->circuit = c;
  out->run = {c->path(), fit_label, check_label};
  return out;
}

py::dict GapOutcome::as_dict() const {
  const gap::CircuitGapResult& r = result;
  const std::shared_ptr<Circuit>& c = circuit;
  py::list ranked;
  for (const auto& e : r.ranked) {
    py::dict d;
    d["effect"] = e.effect.name;
    d["magnitude"] = e.magnitude;
    d["unit"] = gap::effect_unit(c->loaded(), e.effect);
    d["rms_fit"] = e.rms_fit;
    d["rms_check"] = e.rms_check;
    d["z_check"] = e.z_check;
    ranked.append(d);
  }
  using R = gap::CircuitGapResult;
  py::dict d = dict_of(r, "fit_points", &R::fit_points, "check_points", &R::check_points, "rms_fit", &R::rms_fit,
                       "rms_check", &R::rms_check, "channels", &R::channels, "mean_fit", &R::mean_fit, "noise_fit",
                       &R::noise_fit, "noise_check", &R::noise_check, "z_fit", &R::z_fit, "z_check", &R::z_check,
                       "evidence_missing", &R::evidence_missing);
  d["ranked"] = ranked;
  put_fields(d, r, "verdict", &R::verdict, "notes", &R::notes);
  return d;
}

}  // namespace

void bind_identify_gap(py::module_& m) {
  py::class_<IdentifyOutcome, std::shared_ptr<IdentifyOutcome>>(m, "IdentifyOutcome")
      .def("as_dict", &IdentifyOutcome::as_dict, "the result as a dict (SI units, residuals in sensor sigma)")
      .def_property_readonly("text", &IdentifyOutcome::text, "what `hstmon identify --circuit` prints")
      .def("report", &write_report<IdentifyOutcome>, py::arg("folder"), kReportDoc);
  py::class_<GapOutcome, std::shared_ptr<GapOutcome>>(m, "GapOutcome")
      .def("as_dict", &GapOutcome::as_dict, "the result as a dict (SI units, residuals in sigma)")
      .def_property_readonly("text", &GapOutcome::text, "what `hstmon gap --circuit` prints")
      .def_property_readonly(
          "verdict_text", [](const GapOutcome& o) { return gap::circuit_gap_verdict(o.result); },
          "the verdict in words")
      .def("report", &write_report<GapOutcome>, py::arg("folder"), kReportDoc);
  m.def("identify", &identify, py::arg("circuit"), py::arg("logs"), py::arg("fit"), py::arg("min_duration") = 0.2,
        py::arg("labels") = std::vector<std::string>{},
        "Fits named parameters to the logs' steady operating points; labels name the logs in the text and report");
  m.def("gap", &gap_of, py::arg("circuit"), py::arg("fit"), py::arg("check"), py::arg("fit_label") = "fit",
        py::arg("check_label") = "check", "Fits each candidate effect on one log and judges it on the other");
}

}  // namespace hstmon::python
