// The simulator's log layouts (written through the host port's CsvWriter).
#include <gtest/gtest.h>

#include <limits>
#include <sstream>

#include "hstmon_sim/log_layout.hpp"

namespace hstmon::sim {
namespace {

TEST(LogLayout, ThesisColumnsAndUnitConversion) {
  Measurement<ThesisInputs<double>> m;
  m.t = 4.0;
  m.y = {3.312079e6, 1.879209e5, 1.710822e7, 1678.0 * kRadPerSecPerRpm};
  std::ostringstream bar_rpm, pa_rad;
  write_log(bar_rpm, ThesisMeasurements{m}, LogUnits{PressureUnit::kBar, SpeedUnit::kRpm});
  write_log(pa_rad, ThesisMeasurements{m}, LogUnits{PressureUnit::kPa, SpeedUnit::kRadPerSec});
  EXPECT_EQ(bar_rpm.str(),
            "t[s],p_sup[bar],p_s[bar],p_bp[bar],kp[m^3/(s*Pa^0.5)],p_mi[bar],p_mo[bar],p_pp[bar],w_m[rpm]\n"
            "4,35,0,10,4.41e-08,33.12079,1.879209,171.0822,1678\n");
  EXPECT_EQ(pa_rad.str(),
            "t[s],p_sup[Pa],p_s[Pa],p_bp[Pa],kp[m^3/(s*Pa^0.5)],p_mi[Pa],p_mo[Pa],p_pp[Pa],w_m[rad/s]\n"
            "4,3500000,0,1000000,4.41e-08,3312079,187920.9,17108220,175.7197491\n");
}

TEST(LogLayout, PaperColumns) {
  Measurement<PaperInputs<double>> m;
  m.y = {79.4e5, 65.9e5, 18.7e5, 2249.0 * kRadPerSecPerRpm};
  std::ostringstream os;
  write_log(os, PaperMeasurements{m}, LogUnits{PressureUnit::kBar, SpeedUnit::kRpm});
  EXPECT_EQ(os.str(),
            "t[s],a_dcv[m^2],a_prv[m^2],p_pump[bar],p_mi[bar],p_pp[bar],w_m[rpm]\n"
            "0,5e-06,3.525e-06,79.4,65.9,18.7,2249\n");
}

}  // namespace
}  // namespace hstmon::sim
