#pragma once
/// @file gnuplot.hpp
/// The one place the host tools talk to gnuplot: terminal choice by file extension and
/// running a script through a pipe. Callers write their own data files and scripts.

#include <string>

namespace hstmon::sim {

/// gnuplot terminal for an output file: "svg …" for .svg, "pngcairo …" for .png.
/// @param path      output file
/// @param width     image width [px]
/// @param height    image height [px]
/// @param terminal  out: the `set terminal` argument
/// @return          empty on success, else why (unknown extension)
std::string gnuplot_terminal(const std::string& path, int width, int height, std::string& terminal);

/// Runs `script` with gnuplot (script's own `set output` decides the file).
/// @return empty on success, else why (gnuplot missing, could not start, failed)
std::string run_gnuplot(const std::string& script);

}  // namespace hstmon::sim
