// A file's bytes in memory, for the importers that parse large exports
// themselves (CFD-Post exports, .vtp files). A regular file is read with
// pread(2) by two threads, each into its half of an anonymous mapping that may
// use huge pages (see huge_pages.hpp): the copy and the first touch of fresh
// memory, which virtual machines make costly, are shared by two cores. The
// bytes are copied rather than mapped from the file, so that a file truncated
// while it is parsed cannot raise SIGBUS.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

namespace hydrocoef {

class FileBytes {
 public:
  /// Reads the whole file. Throws InputError naming it when it does not
  /// exist, is a directory, cannot be opened or cannot be read. A file that
  /// shrinks while it is read gives the bytes read up to the first gap;
  /// pipes and special files are read in chunks.
  explicit FileBytes(const std::filesystem::path& path);
  ~FileBytes();
  FileBytes(const FileBytes&) = delete;
  FileBytes& operator=(const FileBytes&) = delete;

  std::string_view view() const { return map_ != nullptr ? std::string_view(map_, size_) : fallback_; }

 private:
  char* map_ = nullptr;
  std::size_t mapped_ = 0;
  std::size_t size_ = 0;
  std::string fallback_;
};

}  // namespace hydrocoef
