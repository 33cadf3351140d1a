// Free memory as Linux reports it in /proc/meminfo, and a container's limit.
#include "isurface/base/available_memory.h"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <vector>

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

std::optional<std::uint64_t> cgroupRoomIn(const std::string& limit, const std::string& usage, const std::string& stat) {
  std::uint64_t max = 0, current = 0;
  if (!(std::istringstream(limit) >> max) || !(std::istringstream(usage) >> current)) return std::nullopt;  // "max": none
  // The usage counts the page cache of files read (a dump read before), which the kernel gives
  // back before it refuses memory, as MemAvailable counts it free: (in)active_file in
  // memory.stat; v1's usage is its subtree's, as its total_ figures are.
  std::istringstream in(stat);
  std::string key;
  std::uint64_t value = 0, own = 0, subtree = 0;
  bool hierarchical = false;
  while (in >> key >> value) {
    if (key == "inactive_file" || key == "active_file") own += value;
    if (key == "total_inactive_file" || key == "total_active_file") subtree += value, hierarchical = true;
  }
  current -= std::min(current, hierarchical ? subtree : own);
  return max > current ? max - current : 0;
}

std::vector<CgroupMemoryFiles> cgroupMemoryFiles(const std::string& procSelfCgroup) {
  std::vector<CgroupMemoryFiles> files;
  std::istringstream in(procSelfCgroup);
  std::string line;
  // Lines read "0::/path" (v2) or "4:memory:/path" (v1, the memory controller).
  while (std::getline(in, line)) {
    const std::size_t first = line.find(':'), second = first == std::string::npos ? first : line.find(':', first + 1);
    if (second == std::string::npos) continue;
    const std::string controllers = line.substr(first + 1, second - first - 1);
    std::string path = line.substr(second + 1);
    if (path == "/") path.clear();
    if (controllers.empty() && line.compare(0, first, "0") == 0) {
      const std::string dir = "/sys/fs/cgroup" + path;
      files.push_back({dir + "/memory.max", dir + "/memory.current", dir + "/memory.stat"});
    } else if (("," + controllers + ",").find(",memory,") != std::string::npos) {
      const std::string dir = "/sys/fs/cgroup/memory" + path;
      files.push_back({dir + "/memory.limit_in_bytes", dir + "/memory.usage_in_bytes", dir + "/memory.stat"});
    }
  }
  // Inside a container the process's own group may be the mount's root (v2, then v1).
  files.push_back({"/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory.current", "/sys/fs/cgroup/memory.stat"});
  files.push_back({"/sys/fs/cgroup/memory/memory.limit_in_bytes", "/sys/fs/cgroup/memory/memory.usage_in_bytes",
                   "/sys/fs/cgroup/memory/memory.stat"});
  return files;
}

namespace {

std::optional<std::string> readText(const std::string& path) {
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
  // A container's limit (its cgroup's, v1 or v2) binds before the machine's memory does.
  const std::optional<std::string> self = readText("/proc/self/cgroup");
  for (const CgroupMemoryFiles& group : cgroupMemoryFiles(self ? *self : std::string())) {
    const std::optional<std::string> limit = readText(group.limit), usage = readText(group.usage);
    const std::optional<std::string> stat = readText(group.stat);
    if (limit && usage)
      if (const std::optional<std::uint64_t> room = cgroupRoomIn(*limit, *usage, stat ? *stat : std::string()))
        available = available ? std::min(*available, *room) : *room;
  }
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
