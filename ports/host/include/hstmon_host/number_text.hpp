#pragma once
/// @file number_text.hpp
/// Numbers as text for messages, comments and files: printf's %g at a chosen number of
/// significant digits, so each caller states the precision it needs and all agree on the form.

#include <string>

namespace hstmon::host {

/// v as printf "%.<digits>g": `digits` significant digits (6, %g's own, by default; 9
/// round-trips a float, 17 a double), e.g. 2.5e-06 or 3000.
std::string number_text(double v, int digits = 6);

/// A duration t [s] as an engineer reads it, 3 significant digits: "3.04 ms" below 1 s,
/// "2 s" from there (never "2e+03 ms").
std::string duration_text(double t);

}  // namespace hstmon::host
