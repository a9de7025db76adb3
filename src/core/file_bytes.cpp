#include "src/core/file_bytes.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <optional>
#include <system_error>

#include "src/core/error.hpp"
#include "src/core/huge_pages.hpp"
#include "src/core/parallel.hpp"

namespace hydrocoef {
namespace {

/// Bytes [offset, offset + size) of the file, fewer only where it ends; the
/// error number of a failed read.
struct ReadResult {
  std::size_t bytes = 0;
  int error = 0;
};

ReadResult read_range(int fd, char* out, std::size_t offset, std::size_t size) {
  ReadResult result;
  while (result.bytes < size) {
    const ssize_t got = ::pread(fd, out + result.bytes, size - result.bytes, static_cast<off_t>(offset + result.bytes));
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) {
      result.error = errno;
      break;
    }
    if (got == 0) break;
    result.bytes += static_cast<std::size_t>(got);
  }
  return result;
}

}  // namespace

FileBytes::FileBytes(const std::filesystem::path& path) {
  const std::string name = path.string();
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError(SourceLocation{name}, "no such file");
  if (std::filesystem::is_directory(path, ec))
    throw InputError(SourceLocation{name}, "is a directory, expected a file");
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw InputError(SourceLocation{name}, std::string("cannot open: ") + std::strerror(errno));
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  auto read_error = [&name](int error) {
    return InputError(SourceLocation{name}, std::string("read error: ") + std::strerror(error));
  };

  struct stat info {};
  if (::fstat(fd, &info) == 0 && S_ISREG(info.st_mode) && info.st_size > 0) {
    const auto size = static_cast<std::size_t>(info.st_size);
    void* map = ::mmap(nullptr, size, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (map != MAP_FAILED) {
      map_ = static_cast<char*>(map);
      mapped_ = size;
      prefer_huge_pages(map, size);
      const bool split = size >= (std::size_t{1} << 21);
      const std::size_t half = split ? size / 2 : size;
      ReadResult first, second;
      parallel_for(split ? 2 : 1, 2, [&](std::size_t part) {
        if (part == 0)
          first = read_range(fd, map_, 0, half);
        else
          second = read_range(fd, map_ + half, half, size - half);
      });
      if (first.error != 0 || second.error != 0) {
        ::munmap(map_, mapped_);
        map_ = nullptr;
        throw read_error(first.error != 0 ? first.error : second.error);
      }
      size_ = first.bytes < half ? first.bytes : half + second.bytes;
      return;
    }
  }
  // Pipes and special files have no size to trust: read in chunks.
  std::array<char, 1 << 16> chunk{};
  for (;;) {
    const ssize_t got = ::read(fd, chunk.data(), chunk.size());
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) throw read_error(errno);
    if (got == 0) break;
    fallback_.append(chunk.data(), static_cast<std::size_t>(got));
  }
}

FileBytes::~FileBytes() {
  if (map_ != nullptr) ::munmap(map_, mapped_);
}

}  // namespace hydrocoef
