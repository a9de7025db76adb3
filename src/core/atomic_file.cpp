#include "src/core/atomic_file.hpp"

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>

#include "src/core/error.hpp"

namespace hydrocoef {
namespace {

std::filesystem::path directory_of(const std::filesystem::path& path) {
  return path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
}

}  // namespace

std::string write_error_text(int error) {
  switch (error) {
    case ENOSPC: return "disk full (no space left on device)";
#ifdef EDQUOT
    case EDQUOT: return "disk quota exceeded";
#endif
    case EROFS: return "read-only file system";
    case EACCES: return "permission denied";
    default: return std::strerror(error);
  }
}

std::filesystem::path temporary_beside(const std::filesystem::path& path) {
  static std::atomic<unsigned> counter{0};
  const std::filesystem::path directory = directory_of(path);
  std::error_code ec;
  if (path.filename().empty())
    throw InputError("cannot write '" + path.string() + "': it names a directory; expected a file name");
  if (!std::filesystem::is_directory(directory, ec)) {
    const bool exists = std::filesystem::exists(directory, ec);
    throw InputError("cannot write '" + path.string() + "': '" + directory.string() + "' " +
                     (exists ? "is not a directory" : "does not exist") + "; expected an existing directory");
  }
  if (std::filesystem::is_directory(path, ec))
    throw InputError("cannot write '" + path.string() + "': it is a directory; expected a file name");
  return directory / ("." + path.filename().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                      std::to_string(counter.fetch_add(1)));
}

void commit_temporary(const std::filesystem::path& temporary, const std::filesystem::path& path) {
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  if (ec) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw InputError("cannot write '" + path.string() + "': " + write_error_text(ec.value()));
  }
}

TemporaryFile::TemporaryFile(std::filesystem::path path)
    : path_(std::move(path)), temporary_(temporary_beside(path_)) {}

TemporaryFile::~TemporaryFile() {
  if (committed_) return;
  std::error_code ignored;
  std::filesystem::remove(temporary_, ignored);
}

void TemporaryFile::commit() {
  commit_temporary(temporary_, path_);
  committed_ = true;
}

AtomicFile::AtomicFile(std::filesystem::path path) : path_(std::move(path)), temporary_(temporary_beside(path_)) {
  file_ = std::fopen(temporary_.c_str(), "wbx");
  if (!file_)
    throw InputError("cannot write '" + path_.string() + "': " + write_error_text(errno) +
                     "; expected a writable directory");
}

AtomicFile::~AtomicFile() {
  if (committed_) return;
  if (file_) std::fclose(file_);
  std::error_code ec;
  std::filesystem::remove(temporary_, ec);
}

void AtomicFile::fail(int error) {
  if (file_) std::fclose(file_);
  file_ = nullptr;
  std::error_code ec;
  std::filesystem::remove(temporary_, ec);
  throw InputError("cannot write '" + path_.string() + "': " + write_error_text(error));
}

void AtomicFile::write(std::string_view bytes) {
  if (!file_) throw std::logic_error("AtomicFile::write after commit");
  if (bytes.empty()) return;
  if (std::fwrite(bytes.data(), 1, bytes.size(), file_) != bytes.size()) fail(errno ? errno : EIO);
}

void AtomicFile::commit() {
  if (!file_) throw std::logic_error("AtomicFile::commit twice");
  errno = 0;
  if (std::ferror(file_) || std::fflush(file_) != 0) fail(errno ? errno : EIO);
  // The bytes reach the disk before the name does: after a crash the
  // destination is the old file or the new one, never an empty one.
  if (::fsync(::fileno(file_)) != 0 && errno != EINVAL) fail(errno);
  const int closed = std::fclose(file_);
  file_ = nullptr;
  if (closed != 0) fail(errno ? errno : EIO);
  commit_temporary(temporary_, path_);
  committed_ = true;
}

void write_file_atomically(const std::filesystem::path& path, std::string_view bytes) {
  AtomicFile file(path);
  file.write(bytes);
  file.commit();
}

}  // namespace hydrocoef
