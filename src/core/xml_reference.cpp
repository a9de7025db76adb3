#include "src/core/xml_reference.hpp"

#include <charconv>
#include <cstdint>
#include <system_error>

#include "src/core/utf8.hpp"

namespace hydrocoef {

const char* append_xml_reference(std::string_view name, std::string& out) {
  if (name == "lt") {
    out += '<';
  } else if (name == "gt") {
    out += '>';
  } else if (name == "amp") {
    out += '&';
  } else if (name == "quot") {
    out += '"';
  } else if (name == "apos") {
    out += '\'';
  } else if (name.size() > 1 && name[0] == '#') {
    const bool hex = name[1] == 'x';
    const std::string_view digits = name.substr(hex ? 2 : 1);
    std::uint32_t code = 0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), code, hex ? 16 : 10);
    // from_chars takes no sign and no 0x, so digits alone get this far.
    if (digits.empty() || error != std::errc() || end != digits.data() + digits.size())
      return "a malformed character reference";
    const bool control = code < 0x20 && code != 0x9 && code != 0xa && code != 0xd;
    if (control || !append_utf8(code, out)) return "a character reference to a character XML 1.0 cannot hold";
  } else {
    return "an unknown entity";
  }
  return nullptr;
}

}  // namespace hydrocoef
