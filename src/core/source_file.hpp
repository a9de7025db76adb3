// A source file read once into memory with its SHA-256, so that the bytes an
// importer parses are exactly the bytes the provenance record hashes.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace hydrocoef {

struct SourceFile {
  std::filesystem::path path;
  std::string bytes;
  std::string sha256;  ///< lower-case hex of SHA-256(bytes)
};

/// Reads the whole file. Throws InputError naming the path when it does not
/// exist, is a directory or cannot be read.
SourceFile load_source_file(const std::filesystem::path& path);

/// The SHA-256 and size of a file read in blocks, for files another library
/// parses itself (VTK): the bytes are hashed, never held in memory. Throws
/// InputError as load_source_file does.
struct FileDigest {
  std::string sha256;
  std::uint64_t size_bytes = 0;
};
FileDigest digest_file(const std::filesystem::path& path);

/// SHA-256 of a byte string as 64 lower-case hex digits.
std::string sha256_hex(std::string_view bytes);

}  // namespace hydrocoef
