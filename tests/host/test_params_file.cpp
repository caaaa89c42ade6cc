// Parameter files: good files (numbers, units, defaults), every refusal with its
// line:column, and write → read round trips.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "../support/params_errors.hpp"
#include "hstmon_host/params_file.hpp"

namespace hh = hstmon::host;

namespace {

using hstmon_test::parse;

// A misspelt key on a line of its own: the error points at it.
const char* const kMisspeltParam = R"({
  "model": "thesis",
  "params": {
    "Dm": 7.96e-6,
    "Dmm": 1
  }
})";

}  // namespace

TEST(ParamsFile, GoodFileWithUnitsAndDefaults) {
  const auto r = parse(R"json({
  "model": "thesis",
  "description": "Table 2.2, kp halved",
  "params": {"Dm": 7.96e-6, "K": 1e14, "dp_t_prv": "1 bar", "kf": "3.226e-6 m3/(s*Pa^0.5)"},
  "inputs": {"Psupl": "35 bar", "Ps": 0, "Pbp": "10 bar", "kp": 2.205e-8}
})json");
  ASSERT_TRUE(r.ok()) << r.error->to_string();
  const hstmon::ThesisParams<double> defaults;
  EXPECT_EQ(r.params->Dm, 7.96e-6);
  EXPECT_EQ(r.params->K, 1e14);
  EXPECT_EQ(r.params->dp_t_prv, 1e5);
  EXPECT_EQ(r.params->kf, 3.226e-6);
  EXPECT_EQ(r.params->J, defaults.J);
  EXPECT_EQ(r.params->Rlkg, defaults.Rlkg);
  EXPECT_EQ(r.inputs->Psupl, 3.5e6);
  EXPECT_EQ(r.inputs->Ps, 0.0);
  EXPECT_EQ(r.inputs->Pbp, 1e6);
  EXPECT_EQ(r.inputs->kp, 2.205e-8);
  EXPECT_EQ(r.description, "Table 2.2, kp halved");
}

TEST(ParamsFile, MinimalFileIsAllDefaults) {
  const auto r = parse("\xEF\xBB\xBF{\"model\": \"thesis\"}");
  ASSERT_TRUE(r.ok()) << r.error->to_string();
  const hstmon::ThesisParams<double> p;
  const hstmon::ThesisInputs<double> u;
  EXPECT_EQ(r.params->Ripl, p.Ripl);
  EXPECT_EQ(r.params->dp_t_dcv, p.dp_t_dcv);
  EXPECT_EQ(r.inputs->kp, u.kp);
  EXPECT_EQ(r.inputs->Psupl, u.Psupl);
}

TEST(ParamsFile, IntegersAndZeroFriction) {
  const auto r = parse(R"({"model":"thesis","params":{"Rlkg":64779000000000000,"Rf":0},"inputs":{"kp":0}})");
  ASSERT_TRUE(r.ok()) << r.error->to_string();
  EXPECT_EQ(r.params->Rlkg, 6.4779e16);
  EXPECT_EQ(r.params->Rf, 0.0);
  EXPECT_EQ(r.inputs->kp, 0.0);
}

// Each refused file of the table: one error at its line:column, and nothing kept.
class ParamsRefusal : public testing::TestWithParam<hstmon_test::ErrorCase> {};

TEST_P(ParamsRefusal, PointsAtTheMistake) { hstmon_test::expect_params_refused(GetParam()); }

// One case a line.
// clang-format off
const hstmon_test::ErrorCase kRefused[] = {
    {"UnknownKeys", kMisspeltParam, 5, 5, "unknown key 'Dmm' in 'params' (known: Dm, Dp, Rlkg, Ripl, Rf, Rbl, kf, J, K, dp_t_dcv, dp_t_prv)"},
    {"UnknownKeys", "{\"model\": \"thesis\", \"inputs\": {\"Psup\": 1}}", 1, 32, "unknown key 'Psup' in 'inputs' (known: Psupl, Ps, Pbp, kp)"},
    {"UnknownKeys", "{\"model\": \"thesis\",\n \"param\": {}}", 2, 2, "unknown key 'param' (known: model, description, params, inputs)"},
    // Keys are case-sensitive, as in the C++ structs.
    {"UnknownKeys", "{\"model\": \"thesis\", \"params\": {\"dm\": 1}}", 1, 32, "unknown key 'dm'"},
    {"WrongTypes", "{\"model\": \"thesis\", \"params\": {\"Dm\": \"7.96e-6\"}}", 1, 38, "params.Dm must be a number [m3/rad], got string"},
    {"WrongTypes", "{\"model\": \"thesis\", \"params\": {\"J\": true}}", 1, 37, "params.J must be a number [kg*m2], got boolean"},
    {"WrongTypes", "{\"model\": \"thesis\", \"params\": {\"J\": null}}", 1, 37, "got null"},
    {"WrongTypes", "{\"model\": \"thesis\", \"inputs\": {\"Psupl\": [35]}}", 1, 41, "inputs.Psupl must be a number [Pa] or a string with a unit, got array"},
    {"WrongTypes", "{\"model\": \"thesis\", \"params\": [1, 2]}", 1, 31, "'params' must be an object"},
    {"WrongTypes", "{\"model\": \"thesis\", \"description\": 3}", 1, 36, "'description' must be a string"},
    {"WrongTypes", "[1, 2]", 1, 1, "the top level must be an object"},
    {"WrongTypes", "  \"thesis\"", 1, 3, "the top level must be an object"},
    {"UnitsInStrings", "{\"model\": \"thesis\", \"inputs\": {\"Psupl\": \"35 bars\"}}", 1, 41, "inputs.Psupl: unknown pressure unit 'bars'"},
    {"UnitsInStrings", "{\"model\": \"thesis\", \"inputs\": {\"Pbp\": \"10 mpa\"}}", 1, 39, "ambiguous pressure unit"},
    {"UnitsInStrings", "{\"model\": \"thesis\", \"inputs\": {\"kp\": \"4e-8 l/min\"}}", 1, 38, "unknown orifice coefficient unit"},
    {"UnitsInStrings", "{\"model\": \"thesis\", \"inputs\": {\"Ps\": \"bar\"}}", 1, 38, "expected a number"},
    {"InvalidValues", "{\"model\": \"thesis\",\n \"params\": {\"Dm\": -7.96e-6}}", 2, 19, "params.Dm must be finite and > 0 [m3/rad], got -7.96e-06"},
    {"InvalidValues", "{\"model\": \"thesis\", \"params\": {\"J\": 0}}", 1, 37, "params.J must be finite and > 0"},
    {"InvalidValues", "{\"model\": \"thesis\", \"params\": {\"Rf\": -0.1}}", 1, 38, "params.Rf must be finite and >= 0"},
    {"InvalidValues", "{\"model\": \"thesis\", \"params\": {\"dp_t_dcv\": \"0 bar\"}}", 1, 44, "params.dp_t_dcv must be finite and > 0 [Pa], got 0"},
    {"InvalidValues", "{\"model\": \"thesis\", \"inputs\": {\"kp\": -1e-8}}", 1, 38, "inputs.kp must be finite and >= 0"},
    {"InvalidValues", "{\"model\": \"thesis\", \"params\": {\"Rf\": 0, \"Rbl\": 0}}", 1, 31, "Rf + Rbl must be > 0"},
    {"InvalidValues", "{\"model\": \"thesis\", \"params\": {\"K\": 1e400}}", 1, 37, "number overflow"},
    {"InvalidValues", "{\"model\": \"thesis\", \"inputs\": {\"Psupl\": \"1e308 bar\"}}", 1, 41, "not finite"},
    {"ModelKey", "{\"params\": {}}", 1, 1, "missing key 'model'"},
    {"ModelKey", "{\"model\": \"paper\"}", 1, 11, "'model' must be \"thesis\""},
    {"ModelKey", "{\"model\": 1}", 1, 11, "'model' must be \"thesis\""},
    {"DuplicateKeys", "{\"model\": \"thesis\", \"params\": {\"Dm\": 1e-6,\n \"Dm\": 2e-6}}", 2, 2, "duplicate key 'Dm' in 'params'"},
    {"DuplicateKeys", "{\"model\": \"thesis\", \"model\": \"thesis\"}", 1, 21, "duplicate key 'model' in the top level"},
    {"SyntaxErrors", "{\n  \"model\": \"thesis\",\n  \"params\" {}\n}", 3, 12, "JSON: syntax error while parsing object separator"},
    {"SyntaxErrors", "{\"model\": \"thesis\",}", 1, 20, "JSON: syntax error"},
    {"SyntaxErrors", "", 1, 1, "unexpected end of input"},
    {"SyntaxErrors", "{\"model\": \"the\xffsis\"}", 1, 15, "ill-formed UTF-8"},
    {"SyntaxErrors", "{\"model\": \"thesis\"} x", 1, 21, "JSON: syntax error"},
    {"SyntaxErrors", std::string("{\"model\": \"thesis\"\0}", 20), 1, 19, "JSON: syntax error"},
};
// clang-format on

INSTANTIATE_TEST_SUITE_P(ParamsFile, ParamsRefusal, testing::ValuesIn(kRefused), hstmon_test::error_case_name);

TEST(ParamsFile, SyntaxErrors) {
  std::string deep(100000, '[');
  const auto r = parse(deep);  // must not overflow the stack
  EXPECT_FALSE(r.ok());
}

TEST(ParamsFile, WriteThenReadIsExact) {
  hstmon::ThesisParams<double> p;
  p.Dm = 7.9612345678901234e-6;
  p.K = 1.2345e14;
  p.Rf = 0.0;
  hstmon::ThesisInputs<double> u;
  u.kp = 1.0 / 3.0 * 1e-7;
  u.Ps = -1234.5;
  const std::string text = hh::format_params_json(p, u, "identified 2024");
  const auto r = parse(text);
  ASSERT_TRUE(r.ok()) << r.error->to_string() << "\n" << text;
  EXPECT_EQ(r.params->Dm, p.Dm);
  EXPECT_EQ(r.params->K, p.K);
  EXPECT_EQ(r.params->Rf, 0.0);
  EXPECT_EQ(r.params->Rbl, p.Rbl);
  EXPECT_EQ(r.params->dp_t_prv, p.dp_t_prv);
  EXPECT_EQ(r.inputs->kp, u.kp);
  EXPECT_EQ(r.inputs->Ps, u.Ps);
  EXPECT_EQ(r.description, "identified 2024");
  EXPECT_EQ(text.rfind("{\n  \"model\": \"thesis\",\n  \"description\": \"identified 2024\",\n  \"params\": {\n    \"Dm\": ", 0), 0u) << text;

  const std::string path = ::testing::TempDir() + "hstmon_host_params.json";
  ASSERT_FALSE(hh::write_params_file(path, p, u, "x"));
  const auto f = hh::read_params_file(path);
  ASSERT_TRUE(f.ok()) << f.error->to_string();
  EXPECT_EQ(f.params->Dm, p.Dm);
  EXPECT_EQ(f.inputs->kp, u.kp);
  std::remove(path.c_str());
}

TEST(ParamsFile, WriteRefusesInvalidValuesAndBadPaths) {
  hstmon::ThesisParams<double> p;
  p.J = -1.0;
  EXPECT_TRUE(hh::write_params_file(::testing::TempDir() + "never.json", p, {}));
  EXPECT_TRUE(hh::write_params_file("/nonexistent/dir/p.json", {}, {}));
  const auto r = hh::read_params_file("/nonexistent/dir/p.json");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error->line, 0u);
  EXPECT_EQ(r.error->to_string(), "/nonexistent/dir/p.json: error: cannot open: No such file or directory");
}
