// zip_stored (zip_writer.hpp): local file headers, the central directory and
// its end record of a ZIP archive of stored entries; CRC-32 by libdeflate.
#include "src/export/zip_writer.hpp"

#include <libdeflate.h>

#include <cstdint>
#include <limits>

#include "src/core/error.hpp"

namespace hydrocoef {
namespace {

void put16(std::string& out, std::uint32_t value) {
  out.push_back(static_cast<char>(value & 0xffu));
  out.push_back(static_cast<char>((value >> 8) & 0xffu));
}

void put32(std::string& out, std::uint32_t value) {
  put16(out, value & 0xffffu);
  put16(out, value >> 16);
}

constexpr std::uint32_t kDosDate = (0u << 9) | (1u << 5) | 1u;  // 1980-01-01
constexpr std::uint32_t kDosTime = 0;
constexpr std::uint32_t kLimit = std::numeric_limits<std::uint32_t>::max();

void check_name(const std::string& name) {
  bool bad = name.empty() || name.front() == '/' || name.find('\\') != std::string::npos ||
             name.find('\0') != std::string::npos || name.size() > 0xffffu;
  for (std::size_t at = 0; !bad && at <= name.size();) {
    const auto slash = name.find('/', at);
    const std::string part = name.substr(at, slash == std::string::npos ? std::string::npos : slash - at);
    bad = part.empty() || part == "..";
    at = slash == std::string::npos ? name.size() + 1 : slash + 1;
  }
  if (bad)
    throw InputError("zip entry name '" + name +
                     "' is not a relative path of non-empty parts without '..', '\\' or NUL; expected one");
}

}  // namespace

std::string zip_stored(const std::vector<ZipEntry>& entries) {
  if (entries.size() > 0xffffu) throw InputError("a zip archive holds at most 65535 entries; expected fewer");
  std::string out, directory;
  for (const ZipEntry& entry : entries) {
    check_name(entry.name);
    if (entry.bytes.size() >= kLimit || out.size() >= kLimit - 30 - entry.name.size() - entry.bytes.size())
      throw InputError("zip entry '" + entry.name + "' would pass the 4 GiB limit of a zip archive without ZIP64");
    const auto offset = static_cast<std::uint32_t>(out.size());
    const auto crc = static_cast<std::uint32_t>(libdeflate_crc32(0, entry.bytes.data(), entry.bytes.size()));
    const auto size = static_cast<std::uint32_t>(entry.bytes.size());
    const auto name_length = static_cast<std::uint32_t>(entry.name.size());
    // Local file header.
    put32(out, 0x04034b50u);
    put16(out, 20);      // version needed: 2.0
    put16(out, 0x0800);  // flags: UTF-8 names
    put16(out, 0);       // method: stored
    put16(out, kDosTime);
    put16(out, kDosDate);
    put32(out, crc);
    put32(out, size);
    put32(out, size);
    put16(out, name_length);
    put16(out, 0);
    out += entry.name;
    out.append(entry.bytes.data(), entry.bytes.size());
    // Central directory entry.
    put32(directory, 0x02014b50u);
    put16(directory, (3u << 8) | 20u);  // made by: Unix, 2.0 (the mode in the external attributes)
    put16(directory, 20);
    put16(directory, 0x0800);
    put16(directory, 0);
    put16(directory, kDosTime);
    put16(directory, kDosDate);
    put32(directory, crc);
    put32(directory, size);
    put32(directory, size);
    put16(directory, name_length);
    put16(directory, 0);  // extra
    put16(directory, 0);  // comment
    put16(directory, 0);  // disk
    put16(directory, 0);  // internal attributes
    put32(directory, (entry.executable ? 0100755u : 0100644u) << 16);
    put32(directory, offset);
    directory += entry.name;
  }
  if (out.size() + directory.size() + 22 >= kLimit)
    throw InputError("the zip archive would pass the 4 GiB limit of a zip archive without ZIP64");
  const auto directory_offset = static_cast<std::uint32_t>(out.size());
  out += directory;
  put32(out, 0x06054b50u);
  put16(out, 0);
  put16(out, 0);
  put16(out, static_cast<std::uint32_t>(entries.size()));
  put16(out, static_cast<std::uint32_t>(entries.size()));
  put32(out, static_cast<std::uint32_t>(directory.size()));
  put32(out, directory_offset);
  put16(out, 0);
  return out;
}

}  // namespace hydrocoef
