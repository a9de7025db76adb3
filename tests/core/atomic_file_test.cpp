// Files written whole or not at all: a committed file has every byte, an
// abandoned one leaves the destination as it was and no temporary behind, a
// symbolic link at the destination is replaced rather than written through,
// and a full device is called "disk full".
#include "src/core/atomic_file.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
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

// Links at the temporary names of `path` in this process, counters 0 to
// count-1 in steps of `step`, all pointing at `victim`.
void plant_links(const fs::path& path, const fs::path& victim, int count, int step) {
  for (int n = 0; n < count; n += step)
    fs::create_symlink(victim, path.parent_path() / ("." + path.filename().string() + ".tmp-" +
                                                     std::to_string(::getpid()) + "-" + std::to_string(n)));
}

// A link planted at a temporary's name is skipped, never written through: the
// writer (here a library reopening the name with O_TRUNC) fills a file
// hydrocoef created, and the victim keeps its bytes.
TEST(TemporaryFile, ALinkPlantedAtItsNameIsSkippedNotFollowed) {
  test::TempDir dir;
  write_file_atomically(dir / "victim", "precious");
  plant_links(dir / "out.vtr", dir / "victim", 4000, 2);
  for (int i = 0; i < 3; ++i) {
    TemporaryFile file(dir / "out.vtr");
    EXPECT_FALSE(fs::is_symlink(file.temporary())) << file.temporary();
    struct stat created {};
    ASSERT_EQ(::lstat(file.temporary().c_str(), &created), 0);
    EXPECT_EQ(created.st_mode & 0777, 0600u);
    std::ofstream(file.temporary(), std::ios::trunc) << "new " << i;
    file.commit();
  }
  for (int i = 0; i < 3; ++i) {
    AtomicFile file(dir / "out.vtr");
    EXPECT_FALSE(fs::is_symlink(file.temporary()));
    file.write("atomic");
    file.commit();
  }
  EXPECT_EQ(read_all(dir / "victim"), "precious");
  EXPECT_EQ(read_all(dir / "out.vtr"), "atomic");
  EXPECT_FALSE(fs::is_symlink(dir / "out.vtr"));
}

TEST(TemporaryFile, EveryNameTakenIsOneInputErrorAndTheVictimIsKept) {
  test::TempDir dir;
  write_file_atomically(dir / "victim", "precious");
  plant_links(dir / "out.mat", dir / "victim", 4000, 1);
  try {
    TemporaryFile file(dir / "out.mat");
    ADD_FAILURE() << "created " << file.temporary() << " where every name was a link";
  } catch (const InputError& error) {
    const std::string what = error.what();
    EXPECT_NE(what.find("cannot write '" + (dir / "out.mat").string() + "'"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
  EXPECT_THROW(write_file_atomically(dir / "out.mat", "x"), InputError);
  EXPECT_EQ(read_all(dir / "victim"), "precious");
  EXPECT_FALSE(fs::exists(dir / "out.mat"));
}

// The temporary is private while written and gets a new file's mode (0666
// less the umask) when committed.
TEST(TemporaryFile, CommittedFileHasTheModeOfANewFile) {
  test::TempDir dir;
  const mode_t mask = ::umask(022);
  ::umask(mask);
  TemporaryFile file(dir / "out.mat");
  std::ofstream(file.temporary(), std::ios::trunc) << "bytes";
  file.commit();
  struct stat committed {};
  ASSERT_EQ(::stat((dir / "out.mat").c_str(), &committed), 0);
  EXPECT_EQ(committed.st_mode & 0777, 0666u & ~mask);
}

// A temporary replaced behind hydrocoef's back (here by a link) is not
// renamed onto the destination.
TEST(TemporaryFile, AReplacedTemporaryIsNotCommitted) {
  test::TempDir dir;
  write_file_atomically(dir / "victim", "precious");
  TemporaryFile file(dir / "out.vtr");
  fs::remove(file.temporary());
  fs::create_symlink(dir / "victim", file.temporary());
  EXPECT_THROW(file.commit(), InputError);
  EXPECT_FALSE(fs::exists(dir / "out.vtr"));
  EXPECT_EQ(read_all(dir / "victim"), "precious");
}

}  // namespace
}  // namespace hydrocoef
