// Unit strings → SI factors, and the refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "hstmon_host/circuit_units.hpp"
#include "hstmon_host/number_text.hpp"
#include "hstmon_host/signals.hpp"
#include "hstmon_host/units.hpp"

namespace hh = hstmon::host;
using hh::Quantity;

namespace {

struct Case {
  Quantity q;
  const char* unit;
  double factor;
};

constexpr double kRpm = 2.0 * 3.14159265358979323846 / 60.0;

const Case kGood[] = {
    {Quantity::kPressure, "", 1.0},
    {Quantity::kPressure, "Pa", 1.0},
    {Quantity::kPressure, "pa", 1.0},
    {Quantity::kPressure, "kPa", 1e3},
    {Quantity::kPressure, "KPA", 1e3},
    {Quantity::kPressure, "hPa", 1e2},
    {Quantity::kPressure, "bar", 1e5},
    {Quantity::kPressure, "Bar", 1e5},
    {Quantity::kPressure, " bar ", 1e5},
    {Quantity::kPressure, "mbar", 1e2},
    {Quantity::kPressure, "MPa", 1e6},
    {Quantity::kPressure, "psi", 6894.757293168},
    {Quantity::kPressure, "PSI", 6894.757293168},
    {Quantity::kPressure, "N/m2", 1.0},
    {Quantity::kPressure, "N/m^2", 1.0},
    {Quantity::kPressure, "N/m\xC2\xB2", 1.0},
    {Quantity::kSpeed, "rad/s", 1.0},
    {Quantity::kSpeed, "rad / s", 1.0},
    {Quantity::kSpeed, "rpm", kRpm},
    {Quantity::kSpeed, "RPM", kRpm},
    {Quantity::kSpeed, "1/min", kRpm},
    {Quantity::kSpeed, "U/min", kRpm},
    {Quantity::kSpeed, "u/min", kRpm},
    {Quantity::kSpeed, "min-1", kRpm},
    {Quantity::kSpeed, "min^-1", kRpm},
    {Quantity::kTime, "s", 1.0},
    {Quantity::kTime, "S", 1.0},
    {Quantity::kTime, "ms", 1e-3},
    {Quantity::kTime, "min", 60.0},
    {Quantity::kTime, "h", 3600.0},
    {Quantity::kKp, "", 1.0},
    {Quantity::kKp, "m3/(s*Pa^0.5)", 1.0},
    {Quantity::kKp, "m^3/(s*Pa^0.5)", 1.0},
    {Quantity::kKp, "m3/(s*sqrt(Pa))", 1.0},
    {Quantity::kArea, "", 1.0},
    {Quantity::kArea, "m2", 1.0},
    {Quantity::kArea, "m^2", 1.0},
    {Quantity::kArea, "mm2", 1e-6},
    {Quantity::kArea, "mm^2", 1e-6},
    {Quantity::kNone, "", 1.0},
    {Quantity::kNone, "-", 1.0},
};

struct BadCase {
  Quantity q;
  const char* unit;
  const char* message_part;
};

const BadCase kBad[] = {
    {Quantity::kPressure, "mpa", "ambiguous pressure unit 'mpa'"},
    {Quantity::kPressure, "mPa", "ambiguous pressure unit 'mPa'"},
    {Quantity::kPressure, "MPA", "ambiguous pressure unit 'MPA'"},
    {Quantity::kPressure, "Mbar", "ambiguous pressure unit 'Mbar'"},
    {Quantity::kPressure, "MBAR", "ambiguous"},
    {Quantity::kPressure, "bars", "unknown pressure unit 'bars'"},
    {Quantity::kPressure, "rpm", "unknown pressure unit"},
    {Quantity::kPressure, "-", "unknown pressure unit"},
    {Quantity::kSpeed, "bar", "unknown speed unit 'bar'"},
    {Quantity::kSpeed, "Hz", "unknown speed unit"},
    {Quantity::kTime, "MS", "ambiguous time unit 'MS'"},
    {Quantity::kTime, "us", "unknown time unit"},
    {Quantity::kKp, "m3/s", "unknown orifice coefficient unit"},
    {Quantity::kKp, "l/min", "unknown orifice coefficient unit"},
    {Quantity::kArea, "cm2", "unknown area unit"},
    {Quantity::kArea, "M2", "ambiguous area unit"},
    {Quantity::kNone, "bar", "unknown dimensionless unit"},
};

}  // namespace

TEST(Units, AcceptedSpellingsGiveTheirFactor) {
  for (const Case& c : kGood) {
    const hh::UnitResult r = hh::parse_unit(c.q, c.unit);
    ASSERT_TRUE(r.ok()) << "'" << c.unit << "': " << r.error;
    EXPECT_DOUBLE_EQ(r.conversion.factor, c.factor) << "'" << c.unit << "'";
    EXPECT_EQ(r.conversion.offset, 0.0);
  }
}

TEST(Units, RefusedSpellingsSayWhy) {
  for (const BadCase& c : kBad) {
    const hh::UnitResult r = hh::parse_unit(c.q, c.unit);
    ASSERT_FALSE(r.ok()) << "'" << c.unit << "' was accepted";
    EXPECT_NE(r.error.find(c.message_part), std::string::npos) << r.error;
  }
}

TEST(Units, ConversionRoundTrips) {
  const hh::UnitConversion bar = hh::parse_unit(Quantity::kPressure, "bar").conversion;
  EXPECT_EQ(bar.to_si(35.0), 3.5e6);
  EXPECT_EQ(bar.from_si(3.5e6), 35.0);
  const hh::UnitConversion psi = hh::parse_unit(Quantity::kPressure, "psi").conversion;
  EXPECT_NEAR(psi.from_si(psi.to_si(123.456)), 123.456, 1e-12);
}

TEST(Units, ValueWithUnit) {
  auto v = hh::parse_value_with_unit(Quantity::kPressure, "35 bar");
  ASSERT_TRUE(v.ok()) << v.error;
  EXPECT_EQ(v.value, 3.5e6);
  v = hh::parse_value_with_unit(Quantity::kPressure, " 3.5e6 ");
  ASSERT_TRUE(v.ok()) << v.error;
  EXPECT_EQ(v.value, 3.5e6);
  v = hh::parse_value_with_unit(Quantity::kSpeed, "+60rpm");
  ASSERT_TRUE(v.ok()) << v.error;
  EXPECT_NEAR(v.value, 2.0 * 3.14159265358979323846, 1e-12);
  v = hh::parse_value_with_unit(Quantity::kPressure, "-0.5 MPa");
  ASSERT_TRUE(v.ok()) << v.error;
  EXPECT_EQ(v.value, -5e5);

  EXPECT_FALSE(hh::parse_value_with_unit(Quantity::kPressure, "bar").ok());
  EXPECT_FALSE(hh::parse_value_with_unit(Quantity::kPressure, "").ok());
  EXPECT_FALSE(hh::parse_value_with_unit(Quantity::kPressure, "35 bars").ok());
  EXPECT_FALSE(hh::parse_value_with_unit(Quantity::kPressure, "nan").ok());
  EXPECT_FALSE(hh::parse_value_with_unit(Quantity::kPressure, "inf bar").ok());
  EXPECT_FALSE(hh::parse_value_with_unit(Quantity::kPressure, "1e308 bar").ok());
  EXPECT_FALSE(hh::parse_value_with_unit(Quantity::kPressure, "1e999").ok());
  EXPECT_FALSE(hh::parse_value_with_unit(Quantity::kPressure, "3,5 bar").ok());
}

TEST(Units, SiUnitsParseAsSi) {
  for (Quantity q : {Quantity::kPressure, Quantity::kSpeed, Quantity::kTime, Quantity::kKp, Quantity::kArea,
                     Quantity::kNone}) {
    const hh::UnitResult r = hh::parse_unit(q, hh::si_unit(q));
    ASSERT_TRUE(r.ok()) << hh::quantity_name(q) << ": " << r.error;
    EXPECT_EQ(r.conversion.factor, 1.0);
  }
}

TEST(Units, SignalTable) {
  EXPECT_EQ(hh::signal_name(hh::Signal::kT), "t");
  EXPECT_EQ(hh::signal_name(hh::Signal::kPSup), "p_sup");
  EXPECT_EQ(hh::signal_name(hh::Signal::kAPrv), "a_prv");
  EXPECT_EQ(hh::signal_from_name("P_MI"), hh::Signal::kPMi);
  EXPECT_EQ(hh::signal_from_name("W_m"), hh::Signal::kWm);
  EXPECT_EQ(hh::signal_from_name("p_pump"), hh::Signal::kPPump);
  EXPECT_FALSE(hh::signal_from_name("p_mii").has_value());
  EXPECT_EQ(hh::signal_info(hh::Signal::kKp).quantity, Quantity::kKp);
  EXPECT_EQ(hh::signal_info(hh::Signal::kADcv).quantity, Quantity::kArea);
  EXPECT_TRUE(hh::signal_info(hh::Signal::kPBp).input);
  EXPECT_FALSE(hh::signal_info(hh::Signal::kPPp).input);
  for (std::size_t k = 0; k < hh::kSignalCount; ++k) {
    const auto s = static_cast<hh::Signal>(k);
    EXPECT_EQ(hh::signal_from_name(hh::signal_name(s)), s);
  }
}

// Tables, notes and plots show what an engineer reads: the unit the circuit file states for
// a sensor, else bar, rpm, L/min, cc/rev, (L/min)/bar ...; never SI e-notation.
TEST(Units, DisplayUnits) {
  using Q = hh::CircuitQuantity;
  EXPECT_EQ(hh::display_unit(Q::kPressure).text(2.031e5, 3, true), "+2.03 bar");
  EXPECT_EQ(hh::display_unit(Q::kPressure, "psi").unit, "psi");
  EXPECT_EQ(hh::display_unit(Q::kPressure, "furlong").unit, "bar");  // unknown: the engineering unit
  EXPECT_EQ(hh::display_unit(Q::kSpeed).text(2.0 * M_PI * 1000.0 / 60.0, 4), "1000 rpm");
  EXPECT_EQ(hh::display_unit(Q::kDisplacement).text(6.04e-7), "3.8 cc/rev");
  EXPECT_EQ(hh::display_unit(Q::kArea).text(3.17e-6), "3.17 mm2");
  EXPECT_EQ(hh::display_unit(Q::kConductance).text(9.357e-13), "0.00561 (L/min)/bar");
  EXPECT_EQ(hh::display_unit(Q::kResistance).text(6e9), "1 bar/(L/min)");
  EXPECT_EQ(hh::engineering_text(Q::kFlow, 1e-3 / 60.0), "1 L/min");
  const hh::ValueResult leak = hh::parse_circuit_value(Q::kConductance, "0.006 (L/min)/bar");
  ASSERT_TRUE(leak.ok()) << leak.error;
  EXPECT_NEAR(leak.value, 1e-12, 1e-24);
}

TEST(Units, DurationText) {
  EXPECT_EQ(hh::duration_text(0.00304), "3.04 ms");
  EXPECT_EQ(hh::duration_text(2.0), "2 s");  // not "2e+03 ms"
  EXPECT_EQ(hh::duration_text(0.0), "0 ms");
}
