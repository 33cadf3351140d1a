#pragma once
// How much memory this machine can still give a process: checked before a dump's samples are
// copied, so that a dump too large for the machine is refused with a message instead of the
// process being killed by the kernel halfway through.
#include <cstdint>
#include <optional>
#include <string>

namespace isurface {

// MemAvailable plus SwapFree of a /proc/meminfo text, bytes; nullopt without MemAvailable.
std::optional<std::uint64_t> availableMemoryIn(const std::string& meminfo);

// Room left under a cgroup v2 limit, bytes, from memory.max and memory.current; nullopt when
// there is no limit ("max") or a text is not a number.
std::optional<std::uint64_t> cgroupRoomIn(const std::string& limit, const std::string& usage);

// The same for this process now, the smaller of the two; nullopt when neither can be read.
std::optional<std::uint64_t> availableMemory();

// Throws InputError naming `file` when `bytes` (what `what` needs in memory) exceed `available`.
void requireMemory(const std::string& file, const std::string& what, std::uint64_t bytes,
                   std::optional<std::uint64_t> available);

}  // namespace isurface
