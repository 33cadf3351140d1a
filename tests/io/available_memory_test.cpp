// A dump too large for the machine is refused with a message, not killed halfway by the kernel.
#include "isurface/base/available_memory.h"

#include <gtest/gtest.h>

#include "isurface/base/diagnostic.h"

namespace isurface {
namespace {

TEST(availableMemory, MemoryAndSwapFreeAreAddedUp) {
  const std::string meminfo =
      "MemTotal:       24000000 kB\n"
      "MemFree:         1000000 kB\n"
      "MemAvailable:   12000000 kB\n"
      "Buffers:           20000 kB\n"
      "SwapTotal:       2000000 kB\n"
      "SwapFree:        1500000 kB\n"
      "HugePages_Total:       0\n";
  EXPECT_EQ(availableMemoryIn(meminfo), std::optional<std::uint64_t>((12000000ull + 1500000ull) * 1024));
  EXPECT_EQ(availableMemoryIn("MemTotal: 5 kB\n"), std::nullopt);
  EXPECT_EQ(availableMemoryIn("SwapFree: 0 kB\n"), std::nullopt);  // swap alone says nothing of the memory
  EXPECT_EQ(availableMemoryIn(""), std::nullopt);
  // This machine's own figure is there and is not nothing.
  const std::optional<std::uint64_t> here = availableMemory();
  ASSERT_TRUE(here.has_value());
  EXPECT_GT(*here, 0u);
}

TEST(availableMemory, AContainersLimitBinds) {
  EXPECT_EQ(cgroupRoomIn("8589934592\n", "1073741824\n"), std::optional<std::uint64_t>(7516192768ull));
  EXPECT_EQ(cgroupRoomIn("1000\n", "2000\n"), std::optional<std::uint64_t>(0));
  EXPECT_EQ(cgroupRoomIn("max\n", "1073741824\n"), std::nullopt);
  EXPECT_EQ(cgroupRoomIn("", ""), std::nullopt);
  // Page cache the kernel would give back is room: 8 GB limit, 5 GB used of which 3 GB files.
  EXPECT_EQ(cgroupRoomIn("8000000000\n", "5000000000\n",
                         "inactive_file 1\nactive_file 1\ntotal_inactive_file 1000000000\ntotal_active_file 2000000000\n"),
            std::optional<std::uint64_t>(6'000'000'000ull));
  EXPECT_EQ(cgroupRoomIn("8000000000\n", "5000000000\n", "anon 1\ninactive_file 1000000000\nactive_file 2000000000\n"),
            std::optional<std::uint64_t>(6'000'000'000ull));
  EXPECT_EQ(cgroupRoomIn("8000000000\n", "1000\n", "inactive_file 3000000000\n"),
            std::optional<std::uint64_t>(8'000'000'000ull));
}

TEST(availableMemory, TheProcesssOwnGroupsLimitIsFoundInV1AndV2) {
  // cgroup v1, as on a machine whose controllers are mounted apart.
  const std::vector<CgroupMemoryFiles> v1 =
      cgroupMemoryFiles("9:name=systemd:/\n4:memory:/process_api/a32\n3:cpuset:/\n0::/\n");
  ASSERT_EQ(v1.size(), 4u);
  EXPECT_EQ(v1[0].limit, "/sys/fs/cgroup/memory/process_api/a32/memory.limit_in_bytes");
  EXPECT_EQ(v1[0].usage, "/sys/fs/cgroup/memory/process_api/a32/memory.usage_in_bytes");
  EXPECT_EQ(v1[0].stat, "/sys/fs/cgroup/memory/process_api/a32/memory.stat");
  EXPECT_EQ(v1[1].limit, "/sys/fs/cgroup/memory.max");  // the v2 line's group is the root
  EXPECT_EQ(v1[2].limit, "/sys/fs/cgroup/memory.max");
  EXPECT_EQ(v1[3].limit, "/sys/fs/cgroup/memory/memory.limit_in_bytes");  // a container's own v1 root
  // cgroup v2 alone, and a v1 line naming several controllers.
  const std::vector<CgroupMemoryFiles> v2 = cgroupMemoryFiles("0::/user.slice/app.scope\n");
  ASSERT_EQ(v2.size(), 3u);
  EXPECT_EQ(v2[0].limit, "/sys/fs/cgroup/user.slice/app.scope/memory.max");
  EXPECT_EQ(v2[0].usage, "/sys/fs/cgroup/user.slice/app.scope/memory.current");
  EXPECT_EQ(cgroupMemoryFiles("5:cpu,memory:/box\n")[0].limit, "/sys/fs/cgroup/memory/box/memory.limit_in_bytes");
  EXPECT_EQ(cgroupMemoryFiles("5:memoryless:/box\n").size(), 2u) << "not the memory controller";
  EXPECT_EQ(cgroupMemoryFiles("garbage").size(), 2u);
  // v1's "no limit" is a huge number: the machine's memory binds.
  EXPECT_GT(*cgroupRoomIn("9223372036854771712\n", "1618874368\n"), 1ull << 62);
}

TEST(availableMemory, TooLittleIsRefusedNamingTheFileAndTheSizes) {
  EXPECT_NO_THROW(requireMemory("run.biip", "its 10 samples", 360, 1000));
  EXPECT_NO_THROW(requireMemory("run.biip", "its 10 samples", 360, std::nullopt));
  try {
    requireMemory("huge.biip", "its 940000000 samples", 33'840'000'000ull, 20'500'000'000ull);
    FAIL() << "not refused";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("huge.biip"), std::string::npos) << message;
    EXPECT_NE(message.find("its 940000000 samples need 33.8 GB"), std::string::npos) << message;
    EXPECT_NE(message.find("20.5 GB free"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace isurface
