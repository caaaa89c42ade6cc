// Plots an engineer can trust (issue 16, item 4), one test per problem found:
// file names with '_' print as written, a flat signal (one load, no noise) gets a readable
// axis, gnuplot's warnings never reach the user and a failed plot is one line, the figure
// has one key (not one per panel), an unmeasured channel is drawn as model only with no
// residual, the model's start-up transient does not set a residual's scale, a circuit's
// replay draws its own sensors, a lenient replay's report says where reading stopped; and
// the helpers behind them (ranges, quoting, HTML escaping, base64).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include "hstmon_plot/gnuplot.hpp"
#include "hstmon_plot/html_report.hpp"

#include "../support/cli_run.hpp"

namespace {

namespace fs = std::filesystem;

struct CliRun {
  int exit_code = -1;
  std::string out;  // stdout
  std::string err;  // stderr
};

fs::path dir() {
  const fs::path d = fs::temp_directory_path() / ("hstmon_plots_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}

CliRun run(const std::string& args) {
  const fs::path err = dir() / "stderr.txt";
  const hstmon_test::CliRun c =
      hstmon_test::run_command(std::string("'") + HSTMON_CLI + "' " + args + " 2>'" + err.string() + "'");
  CliRun r;
  r.exit_code = c.exit_code;
  r.out = c.out;
  std::ifstream in(err);
  r.err.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return r;
}

/// `hstmon replay --circuit` of an example circuit (examples/circuits/NAME.json) on one of
/// the logs beside it (LOG.csv), with more options.
CliRun replay_circuit(const std::string& name, const std::string& log, const std::string& options) {
  const std::string examples = std::string(HSTMON_SOURCE_DIR) + "/examples/circuits/";
  return run("replay --circuit '" + examples + name + ".json' '" + examples + log + ".csv' " + options);
}

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

// One load, no noise: every channel exactly flat (the steady state of Table 2.2 at kp0),
// in a file whose name has underscores. `with_speed` false drops the w_m column.
fs::path flat_log(const std::string& name, bool with_speed) {
  const fs::path p = dir() / name;
  std::ofstream f(p);
  f << "t[s],p_sup[bar],kp,p_mi[bar],p_mo[bar],p_pp[bar]" << (with_speed ? ",w_m[rpm]" : "") << "\n";
  for (int k = 0; k < 300; ++k) {
    f << 0.01 * k << ",35,4.41e-8,33.12079052,1.879209336,171.0822092" << (with_speed ? ",1677.684372" : "") << "\n";
  }
  return p;
}

// The logs and plots of this process go when its tests are done.
struct RemoveTempDir : ::testing::Environment {
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir(), ec);
  }
};
[[maybe_unused]] ::testing::Environment* const kRemoveTempDir = ::testing::AddGlobalTestEnvironment(new RemoveTempDir);

bool have_gnuplot() { return std::system("command -v gnuplot >/dev/null 2>&1") == 0; }

TEST(Plots, FlatSingleLoadLogGivesReadableAxesAndNoGnuplotWarnings) {
  if (!have_gnuplot()) GTEST_SKIP() << "gnuplot not installed";
  const fs::path log = flat_log("single_load_no_noise.csv", true);
  const fs::path svg = dir() / "flat.svg";
  const CliRun r = run("replay '" + log.string() + "' --no-diagnosis --plot '" + svg.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_EQ(r.err, "") << "gnuplot's warnings (e.g. empty y range) must not reach the user";
  const std::string s = read(svg);
  // Every tick label is a short plain number: no 1e-9 scale, no ×10⁻⁹ from a degenerate range.
  const std::regex tick("<text> ?(-?[0-9][^<]*)</text>");
  int ticks = 0;
  for (auto it = std::sregex_iterator(s.begin(), s.end(), tick); it != std::sregex_iterator(); ++it) {
    const std::string label = (*it)[1];
    ++ticks;
    EXPECT_EQ(label.find_first_of("ex"), std::string::npos) << "unreadable tick label " << label;
    EXPECT_LE(label.size(), 6u) << "tick label " << label;
  }
  EXPECT_GT(ticks, 40) << "the plot should have labelled axes";
}

TEST(Plots, FileNamesWithUnderscoresPrintAsWritten) {
  if (!have_gnuplot()) GTEST_SKIP() << "gnuplot not installed";
  const fs::path log = flat_log("m_bias_p_mi.csv", true);
  const fs::path svg = dir() / "names.svg";
  ASSERT_EQ(run("replay '" + log.string() + "' --no-diagnosis --plot '" + svg.string() + "'").exit_code, 0);
  // Enhanced text would split "m_bias_p_mi" into subscript <tspan>s.
  EXPECT_NE(read(svg).find("m_bias_p_mi.csv</text>"), std::string::npos);
}

TEST(Plots, OneKeyForTheFigureNotOnePerPanel) {
  if (!have_gnuplot()) GTEST_SKIP() << "gnuplot not installed";
  const fs::path svg = dir() / "key.svg";
  ASSERT_EQ(run("replay '" + flat_log("key_log.csv", true).string() + "' --no-diagnosis --plot '" + svg.string() + "'").exit_code, 0);
  const std::string s = read(svg);
  EXPECT_EQ(count(s, "<text>measured</text>"), 1u);
  EXPECT_EQ(count(s, "<text>model</text>"), 1u);
  EXPECT_EQ(count(s, "<text>residual</text>"), 1u);
}

TEST(Plots, UnmeasuredChannelIsModelOnlyAndHasNoResidual) {
  if (!have_gnuplot()) GTEST_SKIP() << "gnuplot not installed";
  const fs::path svg = dir() / "no_speed.svg";
  const CliRun r = run("replay '" + flat_log("no_speed.csv", false).string() + "' --no-diagnosis --plot '" + svg.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_EQ(r.err, "");
  const std::string s = read(svg);
  EXPECT_NE(s.find("<text>w_m model (not in the log)</text>"), std::string::npos) << s.substr(0, 3000);
  EXPECT_NE(s.find("<text>w_m is not in the log: no residual</text>"), std::string::npos);
  EXPECT_EQ(s.find("w_m residual"), std::string::npos) << "no residual panel for a channel the log lacks";
  EXPECT_NE(s.find("<text>p_pp residual (measured − model)</text>"), std::string::npos);
}

TEST(Plots, StartUpTransientDoesNotSetTheResidualScale) {
  if (!have_gnuplot()) GTEST_SKIP() << "gnuplot not installed";
  // The logger's first row reads the machine at rest; the model starts there and needs its
  // start-up hold-off to reach the steady state the later rows show.
  const fs::path log = dir() / "from_rest.csv";
  {
    std::ofstream f(log);
    f << "t[s],p_sup[bar],kp,p_mi[bar],p_mo[bar],p_pp[bar],w_m[rpm]\n0,35,4.41e-8,0,0,0,0\n";
    for (int k = 1; k < 2000; ++k) f << 0.001 * k << ",35,4.41e-8,33.12079052,1.879209336,171.0822092,1677.684372\n";
  }
  const fs::path svg = dir() / "from_rest.svg";
  const CliRun r = run("replay '" + log.string() + "' --no-diagnosis --plot '" + svg.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(read(svg).find("residual (measured − model), start-up transient off scale</text>"), std::string::npos);
}

TEST(Plots, FailedPlotIsOneLineNamingTheFile) {
  if (!have_gnuplot()) GTEST_SKIP() << "gnuplot not installed";
  const CliRun r = run("replay '" + flat_log("fail_log.csv", true).string() + "' --no-diagnosis --plot /nonexistent_dir/out.svg");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_EQ(count(r.err, "\n"), 1u) << r.err;
  EXPECT_EQ(r.err.rfind("hstmon replay: error: plot: gnuplot failed", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("/nonexistent_dir/out.svg"), std::string::npos) << r.err;
}

// A circuit's replay draws one row per sensor of the circuit, titled with the sensor's
// name and in the unit its file gives — not the thesis rig's four channels.
TEST(Plots, CircuitReplayDrawsTheCircuitsSensorsInTheirUnits) {
  if (!have_gnuplot()) GTEST_SKIP() << "gnuplot not installed";
  const fs::path svg = dir() / "test_stand.svg";
  const CliRun r = replay_circuit("test_stand", "test_stand", "--no-diagnosis --plot '" + svg.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const std::string text = read(svg);
  EXPECT_EQ(count(text, "p_line measured and model"), 1u);
  EXPECT_EQ(count(text, "q residual (measured"), 1u);
  EXPECT_EQ(count(text, "L/min"), 2u);  // the flow sensor's unit, on its two panels
  EXPECT_EQ(count(text, "Pmi"), 0u);
  EXPECT_EQ(count(text, "'model'") + count(text, ">model<"), 1u);  // one key
}

// --report with --circuit writes the report beside its figure, verdict first, naming the circuit.
TEST(Plots, CircuitReplayReportNamesTheCircuitAndItsVerdict) {
  if (!have_gnuplot()) GTEST_SKIP() << "gnuplot not installed";
  const fs::path out = dir() / "circuit_report";
  const CliRun r = replay_circuit("paper", "paper_dm_fault", "--report '" + out.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string md = read(out / "report.md");
  // A step at held inputs is detected at 4.110 s; the fit of the first steady window after
  // it isolates and sizes the fault (the log's truth: Dm 10 % low).
  EXPECT_NE(md.find("**Verdict:** isolated at the end of the log (since t = 5.815 s): Dm- (1.000; Dm 3.8 cc/rev, "
                    "-10 % (-11 … -10 %))"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("circuit paper ("), std::string::npos);
  EXPECT_NE(md.find("| w_m [rpm] |"), std::string::npos);
  EXPECT_TRUE(fs::exists(out / "report.html"));
  EXPECT_NE(read(out / "residuals.svg").find("p_pp residual"), std::string::npos);
}

// A lenient replay that stopped at a bad row says so in its report's verdict, for the
// thesis rig's logs and a circuit's alike, and still exits 2.
TEST(Plots, LenientReplayReportSaysWhereReadingStopped) {
  if (!have_gnuplot()) GTEST_SKIP() << "gnuplot not installed";
  const fs::path thesis_log = flat_log("stops.csv", true);
  {
    std::ofstream f(thesis_log, std::ios::app);
    f << "3.0,35,4.41e-8,33.1,oops,171.1,1677\n";
  }
  const fs::path out = dir() / "lenient_report";
  CliRun r = run("replay '" + thesis_log.string() + "' --lenient --report '" + out.string() + "'");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  std::string md = read(out / "report.md");
  EXPECT_NE(md.find("only the 300 rows before a bad row were replayed (" + thesis_log.string() + ":302:"),
            std::string::npos)
      << md;

  const std::string src = HSTMON_SOURCE_DIR;
  const fs::path circuit_log = dir() / "stand_stops.csv";
  {
    std::ifstream in(src + "/examples/circuits/test_stand.csv");
    std::ofstream f(circuit_log);
    std::string line;
    for (int k = 0; k < 200 && std::getline(in, line); ++k) f << line << "\n";
    f << "9.9,x,1,150,60\n";
  }
  const fs::path out2 = dir() / "lenient_circuit_report";
  r = run("replay --circuit '" + src + "/examples/circuits/test_stand.json' '" + circuit_log.string() +
          "' --lenient --report '" + out2.string() + "'");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  md = read(out2 / "report.md");
  EXPECT_NE(md.find("rows before a bad row were replayed (" + circuit_log.string() + ":201:"), std::string::npos) << md;
}

TEST(PlotHelpers, ReadableRangeWidensFlatDataAndKeepsEveryValue) {
  const hstmon::sim::AxisRange flat = hstmon::sim::readable_range({171.08, 171.08, 171.08}, 0.1);
  EXPECT_NEAR(flat.hi - flat.lo, 0.1, 1e-12);
  EXPECT_NEAR(0.5 * (flat.lo + flat.hi), 171.08, 1e-9);
  const hstmon::sim::AxisRange tiny = hstmon::sim::readable_range({1.5e-9, 1.5e-9 + 1e-15}, 0.1);
  EXPECT_NEAR(tiny.hi - tiny.lo, 0.1, 1e-12);
  const hstmon::sim::AxisRange wide = hstmon::sim::readable_range({-3.0, NAN, 7.0, INFINITY}, 0.1);
  EXPECT_LT(wide.lo, -3.0);
  EXPECT_GT(wide.hi, 7.0);
  EXPECT_NEAR(wide.hi - wide.lo, 11.0, 1e-12);  // 5 % margin each side
  const hstmon::sim::AxisRange none = hstmon::sim::readable_range({NAN}, 2.0);
  EXPECT_EQ(none.lo, -1.0);
  EXPECT_EQ(none.hi, 1.0);
}

TEST(PlotHelpers, QuotingAndEscaping) {
  EXPECT_EQ(hstmon::sim::gnuplot_quote("it's m_b.csv"), "'it''s m_b.csv'");
  EXPECT_EQ(hstmon::sim::html_escape("<a href=\"x\">'&'</a>"), "&lt;a href=&quot;x&quot;&gt;&#39;&amp;&#39;&lt;/a&gt;");
  EXPECT_EQ(hstmon::sim::base64(""), "");
  EXPECT_EQ(hstmon::sim::base64("f"), "Zg==");
  EXPECT_EQ(hstmon::sim::base64("fo"), "Zm8=");
  EXPECT_EQ(hstmon::sim::base64("foo"), "Zm9v");
  EXPECT_EQ(hstmon::sim::base64(std::string("\xff\x00\x80", 3)), "/wCA");
}

TEST(PlotHelpers, HtmlPutsTheVerdictFirstAndEscapesText) {
  hstmon::sim::HtmlReport page("report <1>");
  page.heading("tables");
  page.table({"a", "b"}, {{"x<y", "1"}});
  const std::string missing = page.image((dir() / "absent.png").string(), "absent plot");
  page.verdict("explained & done", hstmon::sim::VerdictTone::kGood);
  const std::string html = page.html();
  EXPECT_FALSE(missing.empty());
  EXPECT_NE(html.find("<title>report &lt;1&gt;</title>"), std::string::npos);
  EXPECT_LT(html.find("explained &amp; done"), html.find("<h2>tables</h2>")) << "the verdict comes first";
  EXPECT_NE(html.find("<td class=\"text\">x&lt;y</td>"), std::string::npos);
  EXPECT_NE(html.find("class=\"missing\""), std::string::npos) << "a missing plot is said, not silently left out";
}

}  // namespace
