// The report folder of `identify --circuit` and `gap --circuit` (circuit_report.hpp).
#include "hstmon_plot/circuit_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <system_error>

#include "hstmon_plot/gnuplot.hpp"

namespace hstmon::sim {

namespace {

std::string cell(const std::string& s) {
  std::string out;
  for (char ch : s) out += ch == '|' ? std::string("\\|") : std::string(1, ch);
  return out;
}

std::string markdown(const CircuitReport& r, bool figure) {
  std::string md = "# " + r.title + "\n\n**Verdict:** " + r.verdict + "\n\n";
  for (const ReportTable& t : r.tables) {
    md += "## " + t.title + "\n\n|";
    for (const auto& h : t.header) md += " " + cell(h) + " |";
    md += "\n|";
    for (std::size_t i = 0; i < t.header.size(); ++i) md += "---|";
    md += "\n";
    for (const auto& row : t.rows) {
      md += "|";
      for (std::size_t i = 0; i < t.header.size(); ++i) md += " " + cell(i < row.size() ? row[i] : "") + " |";
      md += "\n";
    }
    md += "\n";
  }
  for (const auto& n : r.notes) md += "note: " + n + "\n\n";
  if (figure) md += "![" + r.figure_caption + "](figure.svg)\n\n*" + r.figure_caption + "*\n\n";
  md += "## Full text report\n\n```\n" + r.text + "```\n";
  return md;
}

// The panels' data, one block per panel (x then each series; "nan" where none), separated
// by two blank lines so gnuplot's `index` picks a panel.
std::string figure_data(const CircuitReport& r) {
  std::string d;
  for (const ReportPanel& p : r.panels) {
    d += "# " + p.title + "\n";
    for (std::size_t i = 0; i < p.x.size(); ++i) {
      d += fmt::format("{}", p.x[i]);
      for (const ReportSeries& s : p.series) d += fmt::format(" {}", i < s.y.size() ? s.y[i] : std::nan(""));
      d += "\n";
    }
    d += "\n\n";
  }
  return d;
}

// The script, with file names relative to the report folder: it reruns from there.
std::string figure_script(const CircuitReport& r) {
  const int height = 60 + 230 * static_cast<int>(r.panels.size());
  std::string terminal;
  (void)sim::gnuplot_terminal("figure.svg", 900, height, terminal);
  std::string s = fmt::format("set terminal {}\nset output 'figure.svg'\nset datafile missing 'nan'\n", terminal);
  s += fmt::format("set multiplot layout {},1 title {}\n", r.panels.size(), sim::gnuplot_quote(r.figure_caption));
  s += "set grid\nset key outside right top vertical samplen 2\n";
  for (std::size_t k = 0; k < r.panels.size(); ++k) {
    const ReportPanel& p = r.panels[k];
    s += fmt::format("set title {}\nset xlabel {}\nset ylabel {}\n", sim::gnuplot_quote(p.title),
                     sim::gnuplot_quote(p.xlabel), sim::gnuplot_quote(p.ylabel));
    s += "set offsets 0.3, 0.3, 0, 0\n";
    // Operating points and candidates are counted: ticks on whole numbers only.
    const bool counted = !p.x.empty() &&
                         std::all_of(p.x.begin(), p.x.end(), [](double x) { return x == std::round(x); });
    s += counted && p.x.size() <= 40 ? "set xtics 1\n" : "set xtics autofreq\n";
    s += p.from_zero ? "set yrange [0:*]\n" : "set autoscale y\n";
    std::string plot = "plot ";
    for (std::size_t j = 0; j < p.series.size(); ++j) {
      plot += fmt::format("{}'figure.dat' index {} using 1:{} with {} title {}", j == 0 ? "" : ", ", k, j + 2,
                          p.series[j].style, sim::gnuplot_quote(p.series[j].key));
    }
    s += plot + "\n";
  }
  return s + "unset multiplot\n";
}

}  // namespace

std::string write_circuit_report(const std::string& dir, const CircuitReport& r, std::string& plot_warning) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) return dir + ": cannot create the report folder: " + ec.message();
  const std::filesystem::path d(dir);
  bool figure = false;
  plot_warning.clear();
  if (!r.panels.empty()) {
    std::ofstream(d / "figure.dat") << figure_data(r);
    const std::string script = figure_script(r);
    std::ofstream(d / "plots.gp") << script;
    // gnuplot runs here, not in the folder: it changes into it first, as a user would.
    plot_warning = sim::run_gnuplot("cd " + sim::gnuplot_quote(d.string()) + "\n" + script);
    figure = plot_warning.empty();
  }
  std::ofstream md(d / "report.md");
  md << markdown(r, figure);
  if (!md) return (d / "report.md").string() + ": cannot write";
  sim::HtmlReport page(r.title);
  page.verdict(r.verdict, r.tone);
  for (const ReportTable& t : r.tables) {
    page.heading(t.title);
    page.table(t.header, t.rows);
  }
  for (const auto& n : r.notes) page.paragraph("note: " + n);
  if (figure) {
    page.heading("Figure");
    (void)page.image((d / "figure.svg").string(), r.figure_caption);
  }
  page.heading("Full text report");
  page.preformatted(r.text);
  return page.write((d / "report.html").string());
}

}  // namespace hstmon::sim
