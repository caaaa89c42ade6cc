/// @file gnuplot.cpp
#include "hstmon_plot/gnuplot.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace hstmon::sim {

namespace {
bool ends_with(const std::string& s, const std::string& x) {
  return s.size() >= x.size() && s.compare(s.size() - x.size(), x.size(), x) == 0;
}

// The line of gnuplot's stderr that says what went wrong: the last one that is neither
// blank nor the echo of the offending script line (gnuplot prints the line, a caret
// line, then `"file" line N: message`).
std::string failure_line(const std::string& err) {
  std::string best;
  std::size_t start = 0;
  while (start < err.size()) {
    std::size_t end = err.find('\n', start);
    if (end == std::string::npos) end = err.size();
    std::string line = err.substr(start, end - start);
    start = end + 1;
    const auto first = line.find_first_not_of(" \t^");
    if (first == std::string::npos) continue;
    line = line.substr(first);
    if (line.rfind("Warning", 0) == 0) continue;
    best = line;
  }
  return best.size() > 200 ? best.substr(0, 200) + "…" : best;
}
}  // namespace

std::string gnuplot_terminal(const std::string& path, int width, int height, std::string& terminal) {
  const std::string size = " size " + std::to_string(width) + "," + std::to_string(height);
  if (ends_with(path, ".svg")) {
    terminal = "svg" + size + " fixed noenhanced font 'sans,11'";
  } else if (ends_with(path, ".png")) {
    terminal = "pngcairo" + size + " noenhanced font 'sans,10'";
  } else {
    return "plot file must end in .svg or .png: " + path;
  }
  return {};
}

std::string gnuplot_quote(const std::string& text) {
  std::string q = "'";
  for (char c : text) {
    if (c == '\n') {
      q += ' ';
      continue;
    }
    q += c;
    if (c == '\'') q += '\'';  // gnuplot's escape inside single quotes
  }
  return q + "'";
}

AxisRange readable_range(const std::vector<double>& values, double min_span) {
  double lo = INFINITY, hi = -INFINITY;
  for (double v : values) {
    if (!std::isfinite(v)) continue;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  if (!(lo <= hi)) return {-0.5 * min_span, 0.5 * min_span};
  const double margin = 0.05 * (hi - lo);
  lo -= margin;
  hi += margin;
  if (hi - lo < min_span) {
    const double mid = 0.5 * (lo + hi);
    lo = mid - 0.5 * min_span;
    hi = mid + 0.5 * min_span;
  }
  return {lo, hi};
}

std::string gnuplot_temp_file(const std::string& stem, const std::string& ext) {
  static std::atomic<unsigned> counter{0};
  return (std::filesystem::temp_directory_path() /
          fmt::format("hstmon-{}-{}-{}.{}", stem, static_cast<long>(::getpid()), ++counter, ext))
      .string();
}

std::string run_gnuplot(const std::string& script) {
  if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) return "gnuplot not found (apt-get install gnuplot-nox)";
  namespace fs = std::filesystem;
  const fs::path err_file = gnuplot_temp_file("gnuplot", "err");
  const std::string cmd = "gnuplot 2>'" + err_file.string() + "'";
  FILE* gp = popen(cmd.c_str(), "w");
  if (gp == nullptr) return "could not start gnuplot";
  std::fputs(script.c_str(), gp);
  const int status = pclose(gp);
  std::string err;
  {
    // Through a stringstream: GCC 12's -Wnull-dereference misfires on istreambuf_iterator.
    std::ifstream in(err_file);
    std::ostringstream text;
    text << in.rdbuf();
    err = text.str();
  }
  std::error_code ec;
  fs::remove(err_file, ec);
  if (status == 0) return {};
  const std::string why = failure_line(err);
  return why.empty() ? "gnuplot failed" : "gnuplot failed: " + why;
}

}  // namespace hstmon::sim
