#include "isurface/base/time_format.h"

#include <cmath>
#include <cstdio>

namespace isurface {

std::string formatDuration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) seconds = 0;
  const long long ms = std::llround(seconds * 1000.0);
  char text[64];
  if (ms < 3600000)
    std::snprintf(text, sizeof text, "%lld:%02lld.%03lld", ms / 60000, (ms / 1000) % 60, ms % 1000);
  else
    std::snprintf(text, sizeof text, "%lld:%02lld:%02lld.%03lld", ms / 3600000, (ms / 60000) % 60, (ms / 1000) % 60,
                  ms % 1000);
  return text;
}

}  // namespace isurface
