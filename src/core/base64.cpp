#include "src/core/base64.hpp"

#include <array>
#include <cstdint>
#include <cstring>

namespace hydrocoef {
namespace {

constexpr std::int8_t kInvalid = -1;
constexpr std::int8_t kPad = -2;

constexpr std::array<std::int8_t, 256> make_table() {
  std::array<std::int8_t, 256> table{};
  for (auto& entry : table) entry = kInvalid;
  const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  for (int i = 0; i < 64; ++i) table[static_cast<unsigned char>(alphabet[i])] = static_cast<std::int8_t>(i);
  table[static_cast<unsigned char>('=')] = kPad;
  return table;
}
constexpr std::array<std::int8_t, 256> kTable = make_table();

inline std::int32_t sextet(char c) { return kTable[static_cast<unsigned char>(c)]; }

}  // namespace

Base64Decoded decode_base64(std::string_view text, unsigned char* out) {
  Base64Decoded result;
  const std::size_t groups = text.size() / 4;
  const char* in = text.data();
  unsigned char* const start = out;
  for (std::size_t g = 0; g < groups; ++g, in += 4) {
    const std::int32_t a = sextet(in[0]), b = sextet(in[1]), c = sextet(in[2]), d = sextet(in[3]);
    if ((a | b | c | d) >= 0) {  // all four in the alphabet: the common case
      const auto bits = static_cast<std::uint32_t>((a << 18) | (b << 12) | (c << 6) | d);
      out[0] = static_cast<unsigned char>(bits >> 16);
      out[1] = static_cast<unsigned char>(bits >> 8);
      out[2] = static_cast<unsigned char>(bits);
      out += 3;
      continue;
    }
    // Padding is allowed at the end of the last group: "xx==" or "xxx=".
    const std::size_t offset = 4 * g;
    const bool last = g + 1 == groups;
    if (a < 0 || b < 0) {
      result.bad_offset = offset + (a < 0 ? 0 : 1);
      break;
    }
    if (c == kPad && d == kPad && last) {
      out[0] = static_cast<unsigned char>((a << 2) | (b >> 4));
      out += 1;
      break;
    }
    if (c >= 0 && d == kPad && last) {
      const auto bits = static_cast<std::uint32_t>((a << 18) | (b << 12) | (c << 6));
      out[0] = static_cast<unsigned char>(bits >> 16);
      out[1] = static_cast<unsigned char>(bits >> 8);
      out += 2;
      break;
    }
    result.bad_offset = offset + (c < 0 ? 2 : 3);
    break;
  }
  if (result.ok() && text.size() % 4 != 0) result.bad_offset = 4 * groups;
  result.bytes = static_cast<std::size_t>(out - start);
  return result;
}

bool decode_base64_range(std::string_view text, std::size_t first, std::size_t last, unsigned char* out) {
  if (last <= first) return last == first;
  const std::size_t first_group = first / 3, end_group = (last + 2) / 3;
  if (4 * end_group > text.size()) return false;
  unsigned char edge[3];
  std::size_t group = first_group;
  std::size_t skip = first - 3 * first_group;  // bytes of the first group before `first`
  // A group cut by `first` or by `last` goes through a small buffer.
  auto partial_group = [&](std::size_t g, std::size_t from, std::size_t to) {
    const Base64Decoded decoded = decode_base64(text.substr(4 * g, 4), edge);
    if (!decoded.ok() || decoded.bytes < to) return false;
    std::memcpy(out, edge + from, to - from);
    out += to - from;
    return true;
  };
  if (skip > 0 || 3 * (group + 1) > last) {
    const std::size_t to = std::min<std::size_t>(3, last - 3 * group);
    if (!partial_group(group, skip, to)) return false;
    ++group;
    skip = 0;
  }
  if (group >= end_group) return true;
  const std::size_t whole_end = last / 3;  // groups wholly inside [first, last)
  if (whole_end > group) {
    const Base64Decoded decoded = decode_base64(text.substr(4 * group, 4 * (whole_end - group)), out);
    if (!decoded.ok() || decoded.bytes != 3 * (whole_end - group)) return false;
    out += decoded.bytes;
    group = whole_end;
  }
  if (group < end_group) return partial_group(group, 0, last - 3 * group);
  return true;
}

}  // namespace hydrocoef
