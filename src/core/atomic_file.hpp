// Files written whole or not at all. Every file hydrocoef writes
// (exports, trajectories, plots, reports, batch-query answers) goes to a
// temporary file beside its destination and is renamed onto it only once
// everything was written and closed without error; a failure (a full disk,
// a vanished directory, an exception in the producer) removes the temporary
// and leaves the destination as it was. Renaming replaces a symbolic link at
// the destination instead of writing through it.
#pragma once

#include <sys/types.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <string_view>

namespace hydrocoef {

/// A file being written. The temporary is created by the constructor and
/// removed by the destructor unless commit() succeeded.
class AtomicFile {
 public:
  /// Creates ".NAME.tmp-PID-N" (O_EXCL, O_NOFOLLOW, mode 0600 until commit)
  /// beside `path`, skipping names already taken. Throws InputError naming `path`
  /// when its directory is missing, `path` is a directory, or the temporary
  /// cannot be created.
  explicit AtomicFile(std::filesystem::path path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  /// Appends bytes; throws InputError naming `path` on a write error
  /// ("disk full" when the device has no space left).
  void write(std::string_view bytes);
  /// The open stream, for producers that write through stdio themselves;
  /// errors are then reported by commit().
  std::FILE* stream() { return file_; }
  /// Flushes, syncs and closes the temporary without renaming it: every
  /// write error is known before a companion file is committed.
  void finish();
  /// finish() if not yet done, then renames the temporary onto `path`.
  void commit();

  const std::filesystem::path& path() const { return path_; }
  const std::filesystem::path& temporary() const { return temporary_; }

 private:
  void fail(int error);
  std::filesystem::path path_;
  std::filesystem::path temporary_;
  std::FILE* file_ = nullptr;
  bool finished_ = false;
  bool committed_ = false;
};

/// Writes bytes to `path` through an AtomicFile.
void write_file_atomically(const std::filesystem::path& path, std::string_view bytes);

/// A file written by someone else (matio, gnuplot) under a temporary name
/// beside its destination. The constructor creates the temporary itself,
/// exclusively and never through a symbolic link, so the other writer only
/// truncates and fills a file hydrocoef made; the destructor removes it
/// unless commit() renamed it onto the destination.
class TemporaryFile {
 public:
  /// Creates ".NAME.tmp-PID-N" (mode 0600) beside `path`, skipping names
  /// already taken. Throws InputError as AtomicFile does.
  explicit TemporaryFile(std::filesystem::path path);
  ~TemporaryFile();
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;

  /// Checks that the temporary is still the regular file created here and
  /// not empty, syncs it (reporting "disk full" and the like), gives it the
  /// mode a new file gets (0666 less the umask) and renames it onto `path`.
  /// Throws InputError naming `path` and removes the temporary otherwise.
  void commit();

  const std::filesystem::path& path() const { return path_; }
  const std::filesystem::path& temporary() const { return temporary_; }

 private:
  void discard();
  [[noreturn]] void fail(const std::string& what);
  std::filesystem::path path_;
  std::filesystem::path temporary_;
  int fd_ = -1;
  dev_t device_ = 0;
  ino_t inode_ = 0;
  bool committed_ = false;
};

/// A temporary name beside `path`: ".NAME.tmp-PID-N" in the same directory.
/// Only names; AtomicFile and TemporaryFile create the file.
/// Throws InputError when the directory does not exist or `path` names a
/// directory.
std::filesystem::path temporary_beside(const std::filesystem::path& path);

/// Renames a finished temporary onto `path`; removes the temporary and
/// throws InputError naming `path` if that fails.
void commit_temporary(const std::filesystem::path& temporary, const std::filesystem::path& path);

/// An errno value in words for a message about writing a file: ENOSPC is
/// "disk full (no space left on device)", EDQUOT "disk quota exceeded",
/// EROFS "read-only file system", others strerror's text.
std::string write_error_text(int error);

}  // namespace hydrocoef
