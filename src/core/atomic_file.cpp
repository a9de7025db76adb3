#include "src/core/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
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

// Read before main, while there is one thread: umask can only be read by
// setting it.
const mode_t kUmask = [] {
  const mode_t mask = ::umask(022);
  ::umask(mask);
  return mask;
}();

// How many taken names (another file, a planted link) are skipped before
// giving up.
constexpr int kNameAttempts = 64;

// Creates a new temporary beside `path` that nobody else can have prepared:
// O_EXCL refuses an existing name, O_NOFOLLOW a symbolic link, and mode 0600
// keeps the half-written file private until commit gives it the final mode.
int create_temporary(const std::filesystem::path& path, std::filesystem::path& temporary) {
  int error = EEXIST;
  for (int attempt = 0; attempt < kNameAttempts && error == EEXIST; ++attempt) {
    temporary = temporary_beside(path);
    const int fd = ::open(temporary.c_str(), O_RDWR | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
    if (fd >= 0) return fd;
    error = errno;
  }
  temporary.clear();
  throw InputError("cannot write '" + path.string() + "': " + write_error_text(error) +
                   (error == EEXIST ? " (every temporary name beside it is taken)" : "") +
                   "; expected a writable directory");
}

// The mode a file created by fopen would have had: 0666 less the umask.
int give_final_mode(int fd) { return ::fchmod(fd, 0666 & ~kUmask); }

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

TemporaryFile::TemporaryFile(std::filesystem::path path) : path_(std::move(path)) {
  fd_ = create_temporary(path_, temporary_);
  struct stat created {};
  if (::fstat(fd_, &created) != 0) {
    const int error = errno;
    discard();
    throw InputError("cannot write '" + path_.string() + "': " + write_error_text(error));
  }
  device_ = created.st_dev;
  inode_ = created.st_ino;
}

TemporaryFile::~TemporaryFile() {
  if (!committed_) discard();
}

void TemporaryFile::discard() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  std::error_code ignored;
  if (!temporary_.empty()) std::filesystem::remove(temporary_, ignored);
}

void TemporaryFile::fail(const std::string& what) {
  discard();
  throw InputError("cannot write '" + path_.string() + "': " + what);
}

void TemporaryFile::commit() {
  if (committed_ || fd_ < 0) throw std::logic_error("TemporaryFile::commit twice");
  // The name must still be the regular file created here, owned by us: the
  // writer truncated and filled it, it did not replace it.
  struct stat named {};
  if (::lstat(temporary_.c_str(), &named) != 0) fail(write_error_text(errno) + " (its temporary vanished)");
  if (!S_ISREG(named.st_mode) || named.st_dev != device_ || named.st_ino != inode_ || named.st_uid != ::geteuid())
    fail("its temporary '" + temporary_.string() + "' was replaced while being written");
  if (named.st_size == 0) fail("the writer left it empty");
  // Errors the writer never saw (delayed allocation on a full disk) show here.
  if (::fsync(fd_) != 0 && errno != EINVAL) fail(write_error_text(errno));
  if (give_final_mode(fd_) != 0) fail(write_error_text(errno));
  const int closed = ::close(fd_);
  fd_ = -1;
  if (closed != 0) fail(write_error_text(errno));
  commit_temporary(temporary_, path_);
  committed_ = true;
}

AtomicFile::AtomicFile(std::filesystem::path path) : path_(std::move(path)) {
  const int fd = create_temporary(path_, temporary_);
  file_ = ::fdopen(fd, "wb");
  if (!file_) {
    const int error = errno;
    ::close(fd);
    std::error_code ignored;
    std::filesystem::remove(temporary_, ignored);
    throw InputError("cannot write '" + path_.string() + "': " + write_error_text(error));
  }
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

void AtomicFile::finish() {
  if (!file_) throw std::logic_error("AtomicFile::finish after commit");
  errno = 0;
  if (std::ferror(file_) || std::fflush(file_) != 0) fail(errno ? errno : EIO);
  // The bytes reach the disk before the name does: after a crash the
  // destination is the old file or the new one, never an empty one.
  if (::fsync(::fileno(file_)) != 0 && errno != EINVAL) fail(errno);
  if (give_final_mode(::fileno(file_)) != 0) fail(errno);
  const int closed = std::fclose(file_);
  file_ = nullptr;
  if (closed != 0) fail(errno ? errno : EIO);
  finished_ = true;
}

void AtomicFile::commit() {
  if (committed_) throw std::logic_error("AtomicFile::commit twice");
  if (!finished_) finish();
  commit_temporary(temporary_, path_);
  committed_ = true;
}

void write_file_atomically(const std::filesystem::path& path, std::string_view bytes) {
  AtomicFile file(path);
  file.write(bytes);
  file.commit();
}

}  // namespace hydrocoef
