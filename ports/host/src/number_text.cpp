#include "hstmon_host/number_text.hpp"

#include <cmath>
#include <cstdio>

namespace hstmon::host {

std::string number_text(double v, int digits) {
  char b[48];  // "-" + 17 digits + "." + "e-308" with room to spare
  std::snprintf(b, sizeof b, "%.*g", digits, v);
  return b;
}

std::string duration_text(double t) {
  return std::fabs(t) < 1.0 ? number_text(t * 1e3, 3) + " ms" : number_text(t, 3) + " s";
}

}  // namespace hstmon::host
