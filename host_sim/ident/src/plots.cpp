/// @file plots.cpp
/// gnuplot x–y plots via popen.
#include "hstmon_ident/plots.hpp"

#include <fmt/format.h>
#include <fmt/os.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace hstmon::ident {

namespace {
bool ends_with(const std::string& s, const std::string& x) {
  return s.size() >= x.size() && s.compare(s.size() - x.size(), x.size(), x) == 0;
}
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
  if (ends_with(path, ".svg")) {
    terminal = "svg size 1000,650 dynamic font 'sans,11'";
  } else if (ends_with(path, ".png")) {
    terminal = "pngcairo size 1000,650 font 'sans,10'";
  } else {
    return "plot file must end in .svg or .png: " + path;
  }
  if (series.empty()) return "nothing to plot";
  if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) return "gnuplot not found (apt-get install gnuplot-nox)";
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
  FILE* gp = popen("gnuplot", "w");
  if (gp == nullptr) return "could not start gnuplot";
  std::fputs(script.c_str(), gp);
  const int rc = pclose(gp);
  std::error_code ec;
  fs::remove(data, ec);
  if (rc != 0) return "gnuplot failed on " + path;
  return {};
}

}  // namespace hstmon::ident
