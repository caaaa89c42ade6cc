/// @file plots.cpp
/// gnuplot x–y plots (through hstmon_plot/gnuplot.hpp).
#include "hstmon_ident/plots.hpp"

#include "hstmon_plot/gnuplot.hpp"

#include <fmt/format.h>
#include <fmt/os.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace hstmon::ident {

namespace {
std::string quote(std::string s) {
  for (auto& c : s) {
    if (c == '\'') c = '"';
  }
  return s;
}
}  // namespace

std::string plot_xy(const std::string& path, const std::string& title, const std::string& xlabel,
                    const std::string& ylabel, const std::vector<PlotSeries>& series) {
  std::string terminal;
  if (std::string err = sim::gnuplot_terminal(path, 1000, 650, terminal); !err.empty()) return err;
  if (series.empty()) return "nothing to plot";
  namespace fs = std::filesystem;
  const fs::path data =
      fs::temp_directory_path() / fmt::format("hstmon-ident-{}-{}.dat", static_cast<long>(::getpid()), fs::path(path).stem().string());
  {
    auto out = fmt::output_file(data.string());
    for (const auto& s : series) {
      for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) out.print("{:.9g} {:.9g}\n", s.x[i], s.y[i]);
      out.print("\n\n");
    }
  }
  std::string script = fmt::format("set terminal {}\nset output '{}'\nset grid\nset key bottom right opaque\n", terminal, path);
  script += fmt::format("set title '{}'\nset xlabel '{}'\nset ylabel '{}'\nplot ", quote(title), quote(xlabel), quote(ylabel));
  for (std::size_t k = 0; k < series.size(); ++k) {
    script += fmt::format("{}'{}' index {} using 1:2 with {} title '{}'", k ? ", " : "", data.string(), k,
                          series[k].points ? "points pt 7 ps 0.6" : "lines lw 1.8", quote(series[k].label));
  }
  script += "\n";
  const std::string err = sim::run_gnuplot(script);
  std::error_code ec;
  fs::remove(data, ec);
  return err.empty() ? err : err + " on " + path;
}

}  // namespace hstmon::ident
