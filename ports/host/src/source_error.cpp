#include "hstmon_host/source_error.hpp"

namespace hstmon::host {

std::string SourceError::to_string() const {
  std::string s = file;
  if (line != 0) {
    s += ':';
    s += std::to_string(line);
    s += ':';
    s += std::to_string(column);
  }
  s += ": error: ";
  s += message;
  return s;
}

}  // namespace hstmon::host
