// Base64 decoding (RFC 4648, standard alphabet), for the binary arrays of VTK
// XML files: inline "binary" data and base64-encoded appended data. Written
// for speed on arrays of tens of megabytes, and for random access: any run of
// whole 4-character groups decodes on its own, so a long stream can be
// decoded in pieces on several threads.
#pragma once

#include <cstddef>
#include <string_view>

namespace hydrocoef {

struct Base64Decoded {
  static constexpr std::size_t npos = static_cast<std::size_t>(-1);
  std::size_t bytes = 0;          ///< bytes written
  std::size_t bad_offset = npos;  ///< offset in the text of the first character that is not base64, or npos
  bool ok() const { return bad_offset == npos; }
};

/// Decodes `text`, a whole number of 4-character groups, into `out`, which
/// has room for 3 bytes a group. '=' padding may end the last group only
/// ("xx==" gives one byte, "xxx=" two). No whitespace is skipped: a character
/// outside the alphabet stops decoding and is reported.
Base64Decoded decode_base64(std::string_view text, unsigned char* out);

/// Bytes [first, last) of the stream that `text` (whole groups) encodes,
/// decoded into `out` (last - first bytes), without decoding the rest: byte b
/// lies in group b / 3. False when `text` is too short for `last` or a group
/// in that range is not valid base64.
bool decode_base64_range(std::string_view text, std::size_t first, std::size_t last, unsigned char* out);

}  // namespace hydrocoef
