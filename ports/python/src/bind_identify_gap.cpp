// hstmon._core.identify and .gap: the circuit identify (circuit_fit.hpp) and sim-to-real
// gap (circuit_gap.hpp) of `hstmon identify --circuit` and `hstmon gap --circuit`.
#include <pybind11/stl.h>

#include "binding.hpp"
#include "hstmon_gap/circuit_gap.hpp"
#include "hstmon_host/circuit_units.hpp"
#include "hstmon_ident/circuit_fit.hpp"

namespace hstmon::python {

namespace {

py::dict identify(const std::shared_ptr<Circuit>& c, const std::vector<std::shared_ptr<Log>>& logs,
                  const std::vector<std::string>& fit, double min_duration) {
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

py::dict gap_of(const std::shared_ptr<Circuit>& c, const std::shared_ptr<Log>& fit, const std::shared_ptr<Log>& check) {
  gap::CircuitGapResult r;
  {
    py::gil_scoped_release release;
    r = gap::circuit_gap(c->loaded(), fit->data, check->data);
  }
  if (r.error) throw py::value_error("gap --circuit " + c->path() + ": " + *r.error);
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
  m.def("identify", &identify, py::arg("circuit"), py::arg("logs"), py::arg("fit"), py::arg("min_duration") = 0.2,
        "Fits named parameters to the logs' steady operating points; a dict (SI units, residuals in sensor sigma)");
  m.def("gap", &gap_of, py::arg("circuit"), py::arg("fit"), py::arg("check"),
        "Fits each candidate effect on one log and judges it on the other; a dict (SI units, residuals in sigma)");
}

}  // namespace hstmon::python
