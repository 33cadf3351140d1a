// Free memory as Linux reports it in /proc/meminfo.
#include "isurface/base/available_memory.h"

#include <fmt/format.h>

#include <fstream>
#include <sstream>

#include "isurface/base/diagnostic.h"

namespace isurface {

std::optional<std::uint64_t> availableMemoryIn(const std::string& meminfo) {
  std::istringstream in(meminfo);
  std::string key, unit;
  std::uint64_t value = 0, total = 0;
  bool found = false;
  // Lines read "MemAvailable:   12345678 kB".
  while (in >> key >> value) {
    std::getline(in, unit);
    if (key == "MemAvailable:" || key == "SwapFree:") {
      total += value * (unit.find("kB") != std::string::npos ? 1024 : 1);
      found = true;
    }
  }
  return found ? std::optional<std::uint64_t>(total) : std::nullopt;
}

std::optional<std::uint64_t> availableMemory() {
  std::ifstream in("/proc/meminfo");
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  return availableMemoryIn(text.str());
}

void requireMemory(const std::string& file, const std::string& what, std::uint64_t bytes,
                   std::optional<std::uint64_t> available) {
  if (!available || bytes <= *available) return;
  constexpr double kGB = 1e9;
  throw InputError(Diagnostic{file, 0, 0,
                              fmt::format("{} need {:.1f} GB of memory and this machine has {:.1f} GB free "
                                          "(memory and swap): open it on a larger machine, or cut the run into parts",
                                          what, double(bytes) / kGB, double(*available) / kGB)});
}

}  // namespace isurface
