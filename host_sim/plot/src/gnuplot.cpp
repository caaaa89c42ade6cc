/// @file gnuplot.cpp
#include "hstmon_plot/gnuplot.hpp"

#include <cstdio>
#include <cstdlib>

namespace hstmon::sim {

namespace {
bool ends_with(const std::string& s, const std::string& x) {
  return s.size() >= x.size() && s.compare(s.size() - x.size(), x.size(), x) == 0;
}
}  // namespace

std::string gnuplot_terminal(const std::string& path, int width, int height, std::string& terminal) {
  const std::string size = " size " + std::to_string(width) + "," + std::to_string(height);
  if (ends_with(path, ".svg")) {
    terminal = "svg" + size + " dynamic font 'sans,11'";
  } else if (ends_with(path, ".png")) {
    terminal = "pngcairo" + size + " font 'sans,10'";
  } else {
    return "plot file must end in .svg or .png: " + path;
  }
  return {};
}

std::string run_gnuplot(const std::string& script) {
  if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) return "gnuplot not found (apt-get install gnuplot-nox)";
  FILE* gp = popen("gnuplot", "w");
  if (gp == nullptr) return "could not start gnuplot";
  std::fputs(script.c_str(), gp);
  if (pclose(gp) != 0) return "gnuplot failed";
  return {};
}

}  // namespace hstmon::sim
