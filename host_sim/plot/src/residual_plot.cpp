#include "hstmon_plot/residual_plot.hpp"

#include "hstmon_plot/gnuplot.hpp"

#include <fmt/format.h>
#include <fmt/os.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include <unistd.h>

namespace hstmon::cli {

namespace {

struct Panel {
  const char* name;
  const char* unit;
  double scale;  // SI → display
};
const Panel kPanels[4] = {{"Pmi", "bar", 1e-5}, {"Pmo", "bar", 1e-5}, {"Ppp", "bar", 1e-5}, {"ωm", "rpm", 60.0 / (2.0 * M_PI)}};

}  // namespace

std::string plot_trace(const host::ReplayResult& result, const std::string& title, const std::string& path) {
  std::string terminal;
  if (std::string err = sim::gnuplot_terminal(path, 1400, 1100, terminal); !err.empty()) return err;
  if (result.trace.empty()) return "nothing to plot";

  namespace fs = std::filesystem;
  const fs::path data = fs::temp_directory_path() / fmt::format("hstmon-plot-{}.dat", static_cast<long>(::getpid()));
  {
    auto out = fmt::output_file(data.string());
    // Thin very long traces to ~20 000 points: the plot cannot show more.
    const std::size_t stride = std::max<std::size_t>(1, result.trace.size() / 20000);
    for (std::size_t i = 0; i < result.trace.size(); i += stride) {
      const auto& r = result.trace[i];
      out.print("{:.9g}", r.t);
      for (int c = 0; c < 4; ++c) {
        const double s = kPanels[c].scale;
        out.print(" {:.9g} {:.9g} {:.9g}", r.y[c] * s, r.y_hat[c] * s, r.r[c] * s);
      }
      out.print("\n");
    }
  }
  std::string script = fmt::format("set terminal {}\nset output '{}'\nset datafile missing 'nan'\n", terminal, path);
  script += fmt::format("set multiplot layout 4,2 title '{}'\nset grid\nset key top right opaque\n", title);
  for (int c = 0; c < 4; ++c) {
    const int col = 2 + 3 * c;
    if (!result.measured[static_cast<std::size_t>(c)]) {
      script += fmt::format("set title '{} (not measured)'\nset xlabel 't [s]'\nset ylabel '{}'\n", kPanels[c].name, kPanels[c].unit);
      script += fmt::format("plot '{}' using 1:{} with lines lw 1.5 title 'model'\n", data.string(), col + 1);
      script += "set title ''\nunset key\nplot 0 notitle\nset key top right\n";
      continue;
    }
    script += fmt::format("set title '{} measured and model'\nset xlabel 't [s]'\nset ylabel '{}'\n", kPanels[c].name, kPanels[c].unit);
    script += fmt::format("plot '{0}' using 1:{1} with lines lc rgb '#888888' title 'measured', '{0}' using 1:{2} with lines lw 1.5 lc rgb '#1f77b4' title 'model'\n",
                          data.string(), col, col + 1);
    script += fmt::format("set title '{} residual (measured − model)'\nset ylabel '{}'\n", kPanels[c].name, kPanels[c].unit);
    script += fmt::format("plot '{}' using 1:{} with lines lc rgb '#d62728' title 'residual'\n", data.string(), col + 2);
  }
  script += "unset multiplot\n";

  const std::string err = sim::run_gnuplot(script);
  std::error_code ec;
  fs::remove(data, ec);
  return err.empty() ? err : err + " writing " + path;
}

}  // namespace hstmon::cli
