#pragma once
/// @file paper_studies.hpp
/// The paper's parameter studies (seed 001 §5.1–5.3, Figs. 7–9) with the paper model
/// (hstmon::PaperModel integrated by host_sim's stiff PaperReference, no measurements):
///  - Fig. 7: motor speed ωm(t) from rest for several bulk stiffnesses K (all three volumes);
///  - Fig. 9: pump-B pressure Ps(t) for the same K values;
///  - Fig. 8: motor speed for several DCV port areas.
/// Each curve reports its final value, peak and the settling time into a ±2 % band.

#include <string>
#include <vector>

#include "hstmon/paper_model.hpp"

namespace hstmon::ident {

/// One simulated response.
struct StudyCurve {
  std::string label;          ///< legend text, e.g. "K = 1e+11 Pa/m³"
  double value = 0.0;         ///< the varied parameter's value [its SI unit]
  std::vector<double> t;      ///< sample times [s]
  std::vector<double> y;      ///< response [SI: rad/s or Pa]
  double final_value = 0.0;   ///< y at the last sample [SI]
  double peak = 0.0;          ///< max y [SI]
  double t_peak = 0.0;        ///< time of the peak [s]
  double settling_time = 0.0; ///< last time |y − final| > 2 %·|final| [s]
  double rise_time = 0.0;     ///< first time y reaches 90 % of final [s]
};

/// A parameter study: several responses of one output.
struct ParameterStudy {
  std::string name;           ///< file stem, e.g. "fig7_speed_vs_K"
  std::string title;          ///< plot title
  std::string output;         ///< "w_m" or "p_pump"
  std::string unit;           ///< display unit, "rpm" or "bar"
  double scale = 1.0;         ///< SI → display factor
  std::vector<StudyCurve> curves;  ///< one per value
};

/// Fig. 7: ωm from rest for each bulk stiffness K [Pa/m³] (Kpmp = Kpm = Kpp = K).
/// @param duration  simulated time [s]; @param dt  sample period [s]
ParameterStudy study_speed_vs_bulk_stiffness(const std::vector<double>& K, double duration = 5.0, double dt = 2e-3,
                                             const PaperParams<double>& base = {});

/// Fig. 9: pump-B pressure from rest for each bulk stiffness K [Pa/m³].
ParameterStudy study_pump_pressure_vs_bulk_stiffness(const std::vector<double>& K, double duration = 1.0,
                                                     double dt = 5e-4, const PaperParams<double>& base = {});

/// Fig. 8: ωm from rest for each DCV port area [m²].
ParameterStudy study_speed_vs_dcv_area(const std::vector<double>& areas, double duration = 5.0, double dt = 2e-3,
                                       const PaperParams<double>& base = {});

}  // namespace hstmon::ident
