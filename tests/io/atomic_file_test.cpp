// AtomicOutputFile: whole output or none, with clear errors.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <functional>
#include <thread>
#include <fstream>
#include <string>
#include <vector>

#include "isurface/io/atomic_file.h"
#include "isurface/base/diagnostic.h"
#include "test_support.h"

namespace isurface {
namespace {

namespace fs = std::filesystem;
using test::readFile;
using test::scratchDir;

fs::path freshDir(const std::string& name) {
  const fs::path dir = scratchDir() / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::size_t entries(const fs::path& dir) {
  return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(atomicFile, CommitRenamesIntoPlace) {
  const fs::path dir = freshDir("commit");
  const std::string target = (dir / "out.txt").string();
  AtomicOutputFile out(target);
  EXPECT_EQ(out.temporaryPath().rfind(target + ".tmp", 0), 0u) << out.temporaryPath();
  EXPECT_EQ(out.temporaryPath().size(), target.size() + 10);
  out.write("hello ");
  out.write(std::string_view("world"));
  EXPECT_EQ(out.size(), 11u);
  EXPECT_FALSE(fs::exists(target));
  out.commit();
  EXPECT_TRUE(out.committed());
  EXPECT_EQ(readFile(target), "hello world");
  EXPECT_EQ(entries(dir), 1u);
}

TEST(atomicFile, LargeWritesAndPatchesSurviveBuffering) {
  const fs::path dir = freshDir("large");
  const std::string target = (dir / "big.bin").string();
  std::string expected;
  {
    AtomicOutputFile out(target, 4096);
    std::string chunk;
    for (int i = 0; i < 3000; ++i) {
      chunk = std::to_string(i) + (i % 17 == 0 ? std::string(5000, 'x') : std::string(",")) ;
      out.write(chunk);
      expected += chunk;
    }
    out.writeAt(0, "AB", 2);
    out.write("tail");
    expected += "tail";
    expected.replace(0, 2, "AB");
    EXPECT_EQ(out.size(), expected.size());
    out.commit();
  }
  EXPECT_EQ(readFile(target), expected);
}

TEST(atomicFile, DestructorRemovesAnUncommittedTemporary) {
  const fs::path dir = freshDir("abandon");
  const std::string target = (dir / "out.txt").string();
  std::string temp;
  {
    AtomicOutputFile out(target);
    temp = out.temporaryPath();
    out.write(std::string(3 << 20, 'z'));  // spills past the buffer onto disk
    EXPECT_TRUE(fs::exists(temp));
  }
  EXPECT_FALSE(fs::exists(temp));
  EXPECT_FALSE(fs::exists(target));
  EXPECT_EQ(entries(dir), 0u);
}

TEST(atomicFile, ReplacesAnExistingFileOnlyOnCommit) {
  const fs::path dir = freshDir("replace");
  const std::string target = (dir / "out.txt").string();
  { std::ofstream(target) << "old"; }
  ::chmod(target.c_str(), 0640);
  AtomicOutputFile out(target);
  out.write("new");
  EXPECT_EQ(readFile(target), "old");
  out.commit();
  EXPECT_EQ(readFile(target), "new");
  struct stat st {};
  ASSERT_EQ(::stat(target.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0640u);  // permissions of the file it replaced
}

TEST(atomicFile, NewFilesGetTheUsualPermissions) {
  const fs::path dir = freshDir("mode");
  const std::string target = (dir / "out.txt").string();
  writeFileAtomically(target, "x");
  struct stat st {};
  ASSERT_EQ(::stat(target.c_str(), &st), 0);
  const mode_t mask = ::umask(022);
  ::umask(mask);
  EXPECT_EQ(st.st_mode & 0777, 0666u & ~mask);
}

TEST(atomicFile, WritesThroughASymlink) {
  const fs::path dir = freshDir("symlink");
  { std::ofstream(dir / "real.txt") << "old"; }
  fs::create_symlink(dir / "real.txt", dir / "link.txt");
  writeFileAtomically((dir / "link.txt").string(), "new");
  EXPECT_TRUE(fs::is_symlink(dir / "link.txt"));
  EXPECT_EQ(readFile((dir / "real.txt").string()), "new");
}

TEST(atomicFile, WriteFileAtomicallyHandlesEmptyAndLargeContent) {
  const fs::path dir = freshDir("helper");
  writeFileAtomically((dir / "empty").string(), "");
  EXPECT_TRUE(fs::exists(dir / "empty"));
  EXPECT_EQ(fs::file_size(dir / "empty"), 0u);
  const std::string big(5 << 20, 'q');
  writeFileAtomically((dir / "big").string(), big);
  EXPECT_EQ(readFile((dir / "big").string()), big);
  EXPECT_EQ(entries(dir), 2u);
}

// Past a few megabytes the file is synced in the background while it is written (and the cache
// of the file it replaces dropped): the content and the all-or-nothing replacement are the same.
TEST(atomicFile, LargeFilesReplaceTheOldOneOnlyOnCommit) {
  const fs::path dir = freshDir("large");
  const std::string target = (dir / "out.canon").string();
  const std::string old(12 << 20, 'o');
  writeFileAtomically(target, old);
  std::string written;
  {
    AtomicOutputFile out(target);
    for (int i = 0; i < 40; ++i) {
      const std::string chunk((1 << 20) + i, static_cast<char>('a' + i % 26));
      out.write(chunk);
      written += chunk;
    }
    EXPECT_TRUE(readFile(target) == old);
    EXPECT_EQ(entries(dir), 2u);
    out.commit();
  }
  EXPECT_TRUE(readFile(target) == written);
  EXPECT_EQ(entries(dir), 1u);

  // Destroyed without commit after the background sync began: the temporary file goes, the
  // target stays as it was.
  {
    AtomicOutputFile out(target);
    for (int i = 0; i < 30; ++i) out.write(std::string(1 << 20, 'x'));
  }
  EXPECT_TRUE(readFile(target) == written);
  EXPECT_EQ(entries(dir), 1u);
}

TEST(atomicFile, MissingFolderIsReported) {
  const std::string target = (scratchDir() / "missing_dir" / "out.json").string();
  const std::string what = errorOf([&] { writeFileAtomically(target, "{}"); });
  EXPECT_EQ(what.rfind(target + ": cannot write: No such file or directory", 0), 0u) << what;
  EXPECT_NE(what.find("temporary file"), std::string::npos) << what;
}

TEST(atomicFile, FolderAsTargetIsReported) {
  const fs::path dir = freshDir("is_dir");
  const std::string what = errorOf([&] { writeFileAtomically(dir.string(), "{}"); });
  EXPECT_EQ(what, dir.string() + ": cannot write: Is a directory");
}

TEST(atomicFile, UnwritableFolderIsReported) {
  if (::geteuid() == 0) GTEST_SKIP() << "root may write anywhere";
  const fs::path dir = freshDir("readonly");
  ::chmod(dir.c_str(), 0555);
  const std::string target = (dir / "out.txt").string();
  const std::string what = errorOf([&] { writeFileAtomically(target, "{}"); });
  ::chmod(dir.c_str(), 0755);
  EXPECT_EQ(what.rfind(target + ": cannot write: Permission denied", 0), 0u) << what;
}

TEST(atomicFile, FullDiskIsReported) {
  // /dev/full is a device: it is written in place (never replaced), and every write fails
  // with ENOSPC, as on a full disk.
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  const std::string what = errorOf([] { writeFileAtomically("/dev/full", "some content"); });
  EXPECT_EQ(what, "/dev/full: cannot write: No space left on device");
  EXPECT_TRUE(fs::is_character_file("/dev/full"));

  // Large writes fail at the first flush, not only at commit.
  const std::string early = errorOf([] {
    AtomicOutputFile out("/dev/full", 4096);
    out.write(std::string(10000, 'a'));
    ADD_FAILURE() << "write did not fail";
  });
  EXPECT_EQ(early, "/dev/full: cannot write: No space left on device");
}

TEST(atomicFile, DevNullAcceptsOutput) {
  if (!fs::exists("/dev/null")) GTEST_SKIP();
  writeFileAtomically("/dev/null", "discarded");
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
}

TEST(atomicFile, PipesAreWrittenInPlace) {
  const fs::path dir = freshDir("fifo");
  const std::string fifo = (dir / "pipe").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string received;
  std::thread reader([&] { received = readFile(fifo); });
  {
    AtomicOutputFile out(fifo);
    EXPECT_FALSE(out.seekable());
    out.write("through the pipe");
    out.commit();
  }
  reader.join();
  EXPECT_EQ(received, "through the pipe");
}

TEST(atomicFile, EmptyNameIsReported) {
  EXPECT_THROW(writeFileAtomically("", "x"), InputError);
}

}  // namespace
}  // namespace isurface
