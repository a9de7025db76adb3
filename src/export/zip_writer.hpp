// A ZIP archive of stored (uncompressed) entries, each with its CRC-32
// (APPNOTE 6.3: local headers, the central directory, its end record; no
// ZIP64, no data descriptors): what an FMU is. Deterministic: every entry's
// time is 1980-01-01 00:00 (the format's earliest), so the same entries give
// the same bytes.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace hydrocoef {

struct ZipEntry {
  std::string name;         ///< path inside the archive, '/'-separated
  std::string_view bytes;   ///< the content (not owned)
  bool executable = false;  ///< Unix mode 0755 instead of 0644
};

/// The archive's bytes. InputError when an entry's name is empty, absolute,
/// holds "..", a backslash or a NUL, or an entry or the archive would pass
/// the format's 4 GiB / 65,535-entry limits.
std::string zip_stored(const std::vector<ZipEntry>& entries);

}  // namespace hydrocoef
