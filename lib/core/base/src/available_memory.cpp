// Free memory as Linux reports it in /proc/meminfo.
#include "isurface/base/available_memory.h"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "isurface/base/diagnostic.h"

namespace isurface {

std::optional<std::uint64_t> availableMemoryIn(const std::string& meminfo) {
  std::istringstream in(meminfo);
  std::string key, unit;
  std::uint64_t value = 0, total = 0;
  bool memory = false;
  // Lines read "MemAvailable:   12345678 kB".
  while (in >> key >> value) {
    std::getline(in, unit);
    if (key == "MemAvailable:" || key == "SwapFree:") {
      total += value * (unit.find("kB") != std::string::npos ? 1024 : 1);
      memory = memory || key == "MemAvailable:";
    }
  }
  // Free swap alone (a kernel that does not report MemAvailable) says nothing of the memory.
  return memory ? std::optional<std::uint64_t>(total) : std::nullopt;
}

std::optional<std::uint64_t> cgroupRoomIn(const std::string& limit, const std::string& usage) {
  std::uint64_t max = 0, current = 0;
  if (!(std::istringstream(limit) >> max) || !(std::istringstream(usage) >> current)) return std::nullopt;  // "max": none
  return max > current ? max - current : 0;
}

namespace {

std::optional<std::string> readText(const char* path) {
  std::ifstream in(path);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

std::optional<std::uint64_t> availableMemory() {
  const std::optional<std::string> meminfo = readText("/proc/meminfo");
  std::optional<std::uint64_t> available = meminfo ? availableMemoryIn(*meminfo) : std::nullopt;
  // A container's limit (cgroup v2) binds before the machine's memory does.
  const std::optional<std::string> limit = readText("/sys/fs/cgroup/memory.max");
  const std::optional<std::string> usage = readText("/sys/fs/cgroup/memory.current");
  if (limit && usage)
    if (const std::optional<std::uint64_t> room = cgroupRoomIn(*limit, *usage))
      available = available ? std::min(*available, *room) : *room;
  return available;
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
