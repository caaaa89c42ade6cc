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
};

// One gap run.
struct GapOutcome {
  std::shared_ptr<Circuit> circuit;
  gap::CircuitGapResult result;
  gap::CircuitGapRun run;
  py::dict as_dict() const;
};

// Writes a report folder; returns why the figure is missing ("" when drawn).
std::string write_report(const std::string& folder, const sim::CircuitReport& report) {
  std::string warning;
  const std::string err = sim::write_circuit_report(folder, report, warning);
  if (!err.empty()) throw py::value_error(err);
  return warning;
}

std::shared_ptr<IdentifyOutcome> identify(const std::shared_ptr<Circuit>& c, const std::vector<std::shared_ptr<Log>>& logs,
                                          const std::vector<std::string>& fit, double min_duration,
                                          const std::vector<std::string>& labels) {
  if (logs.empty() || fit.empty()) throw py::value_error("identify needs logs and the parameters to fit");
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
  if (r.error) throw py::value_error("identify --circuit " + c->path() + ": " + *r.error);
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
  py::list points;
  for (const auto& pt : r.points) {
    py::dict p;
    p["log"] = pt.log;
    p["t0"] = pt.t0;
    p["t1"] = pt.t1;
    p["rows"] = pt.n;
    p["inputs"] = pt.inputs;
    p["mean"] = pt.mean;
    p["before"] = pt.before;
    p["after"] = pt.after;
    points.append(p);
  }
  py::dict d;
  d["parameters"] = params;
  d["points"] = points;
  d["rms_before"] = r.rms_before;
  d["rms_after"] = r.rms_after;
  d["status"] = r.status;
  d["notes"] = r.notes;
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
  py::dict d;
  d["fit_points"] = r.fit_points;
  d["check_points"] = r.check_points;
  d["rms_fit"] = r.rms_fit;
  d["rms_check"] = r.rms_check;
  d["channels"] = r.channels;
  d["mean_fit"] = r.mean_fit;
  d["noise_fit"] = r.noise_fit;
  d["noise_check"] = r.noise_check;
  d["z_fit"] = r.z_fit;
  d["z_check"] = r.z_check;
  d["evidence_missing"] = r.evidence_missing;
  d["ranked"] = ranked;
  d["verdict"] = r.verdict;
  d["notes"] = r.notes;
  return d;
}

}  // namespace

void bind_identify_gap(py::module_& m) {
  py::class_<IdentifyOutcome, std::shared_ptr<IdentifyOutcome>>(m, "IdentifyOutcome")
      .def("as_dict", &IdentifyOutcome::as_dict, "the result as a dict (SI units, residuals in sensor sigma)")
      .def_property_readonly(
          "text", [](const IdentifyOutcome& o) { return ident::circuit_identify_text(o.run, o.circuit->loaded(), o.result); },
          "what `hstmon identify --circuit` prints")
      .def(
          "report",
          [](const IdentifyOutcome& o, const std::string& folder) {
            const std::string text = ident::circuit_identify_text(o.run, o.circuit->loaded(), o.result);
            return write_report(folder, ident::circuit_identify_report(o.run, o.circuit->loaded(), o.result, text));
          },
          py::arg("folder"), "writes the CLI's report folder; returns why the figure is missing ('' when drawn)");
  py::class_<GapOutcome, std::shared_ptr<GapOutcome>>(m, "GapOutcome")
      .def("as_dict", &GapOutcome::as_dict, "the result as a dict (SI units, residuals in sigma)")
      .def_property_readonly(
          "text", [](const GapOutcome& o) { return gap::circuit_gap_text(o.run, o.circuit->loaded(), o.result); },
          "what `hstmon gap --circuit` prints")
      .def_property_readonly(
          "verdict_text", [](const GapOutcome& o) { return gap::circuit_gap_verdict(o.result); }, "the verdict in words")
      .def(
          "report",
          [](const GapOutcome& o, const std::string& folder) {
            const std::string text = gap::circuit_gap_text(o.run, o.circuit->loaded(), o.result);
            return write_report(folder, gap::circuit_gap_report(o.run, o.circuit->loaded(), o.result, text));
          },
          py::arg("folder"), "writes the CLI's report folder; returns why the figure is missing ('' when drawn)");
  m.def("identify", &identify, py::arg("circuit"), py::arg("logs"), py::arg("fit"), py::arg("min_duration") = 0.2,
        py::arg("labels") = std::vector<std::string>{},
        "Fits named parameters to the logs' steady operating points; labels name the logs in the text and report");
  m.def("gap", &gap_of, py::arg("circuit"), py::arg("fit"), py::arg("check"), py::arg("fit_label") = "fit",
        py::arg("check_label") = "check", "Fits each candidate effect on one log and judges it on the other");
}

}  // namespace hstmon::python
