#include "hstmon_host/number_text.hpp"

#include <cstdio>

namespace hstmon::host {

std::string number_text(double v, int digits) {
  char b[48];  // "-" + 17 digits + "." + "e-308" with room to spare
  std::snprintf(b, sizeof b, "%.*g", digits, v);
  return b;
}

}  // namespace hstmon::host
