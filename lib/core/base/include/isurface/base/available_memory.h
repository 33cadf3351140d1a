#pragma once
// How much memory this machine can still give a process: checked before a dump's samples are
// copied, so that a dump too large for the machine is refused with a message instead of the
// process being killed by the kernel halfway through.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace isurface {

// MemAvailable plus SwapFree of a /proc/meminfo text, bytes; nullopt without MemAvailable.
std::optional<std::uint64_t> availableMemoryIn(const std::string& meminfo);

// Room left under a cgroup's limit, bytes, from its limit and usage (v2 memory.max and
// memory.current, v1 memory.limit_in_bytes and memory.usage_in_bytes), the page cache of files
// its memory.stat names (active and inactive: the kernel reclaims both before it refuses
// memory, as MemAvailable counts them) counted as room; nullopt when there is no limit ("max")
// or a text is not a number.
std::optional<std::uint64_t> cgroupRoomIn(const std::string& limit, const std::string& usage,
                                          const std::string& stat = "");

// A memory limit's file and the usage's file of a cgroup.
struct CgroupMemoryFiles {
  std::string limit, usage, stat;
};

// Where the limits on this process's memory are, from the text of /proc/self/cgroup: its own
// group's (v2 memory.max, or v1 memory.limit_in_bytes), then the mount's root (v2, then v1).
// Limits of the groups above its own are not read.
std::vector<CgroupMemoryFiles> cgroupMemoryFiles(const std::string& procSelfCgroup);

// The same for this process now, the smallest of them all; nullopt when none can be read.
std::optional<std::uint64_t> availableMemory();

// Throws InputError naming `file` when `bytes` (what `what` needs in memory) exceed `available`.
void requireMemory(const std::string& file, const std::string& what, std::uint64_t bytes,
                   std::optional<std::uint64_t> available);

}  // namespace isurface
