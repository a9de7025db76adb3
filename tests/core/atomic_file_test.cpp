// Files written whole or not at all: a committed file has every byte, an
// abandoned one leaves the destination as it was and no temporary behind, a
// symbolic link at the destination is replaced rather than written through,
// and a full device is called "disk full".
#include "src/core/atomic_file.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

#include "src/core/error.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

namespace fs = std::filesystem;

std::string read_all(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

std::size_t entries(const fs::path& directory) {
  return static_cast<std::size_t>(std::distance(fs::directory_iterator(directory), fs::directory_iterator()));
}

TEST(AtomicFile, CommittedFileHasEveryByte) {
  test::TempDir dir;
  const std::string bytes(3 << 20, 'z');
  write_file_atomically(dir / "out.txt", bytes);
  EXPECT_EQ(read_all(dir / "out.txt"), bytes);
  EXPECT_EQ(entries(dir.path()), 1u);
}

TEST(AtomicFile, AbandonedFileLeavesTheOldOneAndNoTemporary) {
  test::TempDir dir;
  write_file_atomically(dir / "out.txt", "old");
  try {
    AtomicFile file(dir / "out.txt");
    file.write("new, half");
    throw std::runtime_error("producer failed");
  } catch (const std::runtime_error&) {}
  EXPECT_EQ(read_all(dir / "out.txt"), "old");
  EXPECT_EQ(entries(dir.path()), 1u);
}

TEST(TemporaryFile, AnotherWritersFileIsRenamedOnCommitAndRemovedOtherwise) {
  test::TempDir dir;
  write_file_atomically(dir / "out.vtr", "old");
  {
    // A writer (VTK, matio) that fails after creating its file.
    TemporaryFile file(dir / "out.vtr");
    EXPECT_EQ(file.temporary().parent_path(), dir.path());
    EXPECT_NE(file.temporary(), dir / "out.vtr");
    std::ofstream(file.temporary()) << "half";
    EXPECT_EQ(entries(dir.path()), 2u);
  }
  EXPECT_EQ(read_all(dir / "out.vtr"), "old");
  EXPECT_EQ(entries(dir.path()), 1u);
  {
    TemporaryFile file(dir / "out.vtr");
    std::ofstream(file.temporary()) << "new";
    file.commit();
  }
  EXPECT_EQ(read_all(dir / "out.vtr"), "new");
  EXPECT_EQ(entries(dir.path()), 1u);
  // A writer that never created its file: committing it is an InputError naming the destination.
  TemporaryFile nothing(dir / "none.vtr");
  try {
    nothing.commit();
    ADD_FAILURE() << "committing a file nobody wrote succeeded";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("none.vtr"), std::string::npos) << error.what();
  }
  EXPECT_FALSE(fs::exists(dir / "none.vtr"));
}

TEST(AtomicFile, ReplacesASymbolicLinkInsteadOfItsTarget) {
  test::TempDir dir;
  write_file_atomically(dir / "target.txt", "precious");
  fs::create_symlink(dir / "target.txt", dir / "plot.dat");
  write_file_atomically(dir / "plot.dat", "plot data");
  EXPECT_EQ(read_all(dir / "target.txt"), "precious");
  EXPECT_FALSE(fs::is_symlink(dir / "plot.dat"));
  EXPECT_EQ(read_all(dir / "plot.dat"), "plot data");
}

TEST(AtomicFile, MissingDirectoryIsAnInputError) {
  test::TempDir dir;
  EXPECT_THROW(write_file_atomically(dir / "no" / "such.txt", "x"), InputError);
  EXPECT_THROW(write_file_atomically(dir.path(), "x"), InputError);
}

TEST(AtomicFile, FullDeviceIsCalledDiskFull) {
  // /dev/full answers every write with ENOSPC: the errno a full disk gives.
  EXPECT_EQ(write_error_text(ENOSPC), "disk full (no space left on device)");
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full on this machine";
  const int fd = ::open("/dev/full", O_WRONLY);
  ASSERT_GE(fd, 0);
  const char byte = 'x';
  errno = 0;
  const auto written = ::write(fd, &byte, 1);
  const int error = errno;
  ::close(fd);
  ASSERT_EQ(written, -1);
  EXPECT_EQ(write_error_text(error), "disk full (no space left on device)");
}

TEST(AtomicFile, DirectoryRemovedBeforeCommitLeavesNothing) {
  test::TempDir dir;
  const fs::path sub = dir / "sub";
  fs::create_directory(sub);
  AtomicFile file(sub / "out.txt");
  file.write("data");
  fs::remove(file.temporary());
  fs::remove(sub);
  EXPECT_THROW(file.commit(), InputError);
  EXPECT_FALSE(fs::exists(sub));
}

}  // namespace
}  // namespace hydrocoef
