#include "importers/vtk_xml_polydata.hpp"

#include <libdeflate.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <exception>
#include <functional>
#include <iterator>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <string_view>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

#include "src/core/base64.hpp"
#include "src/core/error.hpp"
#include "src/core/file_bytes.hpp"
#include "src/core/huge_pages.hpp"
#include "src/core/parallel.hpp"
#include "src/core/xml_reference.hpp"
#include "src/mesh/duplicate_faces.hpp"

namespace hydrocoef {
namespace {

constexpr auto npos = std::string_view::npos;

// --- the XML up to the appended data ------------------------------------------

struct XmlElement {
  std::string name;
  std::vector<std::pair<std::string, std::string>> attributes;
  std::vector<XmlElement> children;
  std::string_view text;  ///< the first run of non-blank character data directly inside

  const std::string* attribute(std::string_view key) const {
    for (const auto& [k, v] : attributes)
      if (k == key) return &v;
    return nullptr;
  }
  std::vector<const XmlElement*> children_named(std::string_view child) const {
    std::vector<const XmlElement*> out;
    for (const auto& c : children)
      if (c.name == child) out.push_back(&c);
    return out;
  }
};

/// The XML of a VTK file up to its appended data, which are raw bytes no XML
/// parser may look at. Reads the XML that VTK's writers and foamToVTK write
/// (elements, attributes in either quote, comments, processing instructions,
/// the five predefined entities and character references in attributes);
/// anything else makes it give up, and VTK's expat-based reader has the
/// final word on the file.
class XmlHeader {
 public:
  explicit XmlHeader(std::string_view bytes) : in_(bytes) { ok_ = parse(); }

  bool ok() const { return ok_; }
  const XmlElement& root() const { return root_; }
  bool has_appended() const { return has_appended_; }
  /// The bytes after the '_' that starts the appended data.
  std::string_view appended() const { return appended_; }
  const std::string* appended_encoding() const { return appended_encoding_.empty() ? nullptr : &appended_encoding_; }

 private:
  static constexpr int kMaxDepth = 32;
  static constexpr std::size_t kMaxAttributes = 64;

  static bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
  static bool is_name_char(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == ':' || c == '-' || c == '.';
  }
  bool at(std::string_view text) const { return in_.substr(pos_, text.size()) == text; }
  void skip_blanks() {
    while (pos_ < in_.size() && is_blank(in_[pos_])) ++pos_;
  }
  bool skip_past(std::string_view end) {
    const auto found = in_.find(end, pos_);
    if (found == npos) return false;
    pos_ = found + end.size();
    return true;
  }
  /// Comments and processing instructions, and the blanks around them.
  bool skip_misc() {
    for (;;) {
      skip_blanks();
      if (at("<?")) {
        if (!skip_past("?>")) return false;
      } else if (at("<!--")) {
        if (!skip_past("-->")) return false;
      } else {
        return true;
      }
    }
  }
  bool parse_name(std::string& name) {
    const std::size_t start = pos_;
    while (pos_ < in_.size() && is_name_char(in_[pos_])) ++pos_;
    if (pos_ == start) return false;
    name.assign(in_.substr(start, pos_ - start));
    return true;
  }

  static bool decode_attribute(std::string_view raw, std::string& out) {
    out.clear();
    for (std::size_t i = 0; i < raw.size(); ++i) {
      const char c = raw[i];
      if (c == '<') return false;
      if (c != '&') {
        out += c;
        continue;
      }
      const auto end = raw.find(';', i);
      if (end == npos) return false;
      if (append_xml_reference(raw.substr(i + 1, end - i - 1), out) != nullptr) return false;
      i = end;
    }
    return true;
  }

  bool parse_element(XmlElement& element, int depth) {
    if (depth > kMaxDepth || !at("<")) return false;
    ++pos_;
    if (!parse_name(element.name)) return false;
    for (;;) {
      const std::size_t before = pos_;
      skip_blanks();
      if (pos_ >= in_.size()) return false;
      if (at("/>")) {
        pos_ += 2;
        return true;
      }
      if (in_[pos_] == '>') {
        ++pos_;
        break;
      }
      if (pos_ == before) return false;  // attributes are separated by blanks
      std::string key;
      if (!parse_name(key)) return false;
      skip_blanks();
      if (!at("=")) return false;
      ++pos_;
      skip_blanks();
      if (pos_ >= in_.size() || (in_[pos_] != '"' && in_[pos_] != '\'')) return false;
      const char quote = in_[pos_++];
      const auto end = in_.find(quote, pos_);
      if (end == npos) return false;
      std::string value;
      if (!decode_attribute(in_.substr(pos_, end - pos_), value)) return false;
      pos_ = end + 1;
      // A repeated attribute is not XML; VTK's elements have a handful (the
      // limit keeps the repeat check cheap on hostile input).
      if (element.attributes.size() >= kMaxAttributes || element.attribute(key) != nullptr) return false;
      element.attributes.emplace_back(std::move(key), std::move(value));
    }
    if (element.name == "AppendedData") {
      // The data start after the '_' that follows the start tag; from there
      // on the file is bytes, not XML.
      if (const std::string* encoding = element.attribute("encoding")) appended_encoding_ = *encoding;
      skip_blanks();
      if (!at("_")) return false;
      appended_ = in_.substr(pos_ + 1);
      has_appended_ = true;
      return true;
    }
    for (;;) {
      const auto next = in_.find('<', pos_);
      if (next == npos) return false;
      if (element.text.empty()) {
        std::string_view run = in_.substr(pos_, next - pos_);
        while (!run.empty() && is_blank(run.front())) run.remove_prefix(1);
        while (!run.empty() && is_blank(run.back())) run.remove_suffix(1);
        element.text = run;
      }
      pos_ = next;
      if (at("</")) {
        pos_ += 2;
        std::string name;
        if (!parse_name(name) || name != element.name) return false;
        skip_blanks();
        if (!at(">")) return false;
        ++pos_;
        return true;
      }
      if (at("<!--")) {
        if (!skip_past("-->")) return false;
        continue;
      }
      if (at("<?")) {
        if (!skip_past("?>")) return false;
        continue;
      }
      if (at("<!")) return false;  // CDATA, DOCTYPE: left to expat
      element.children.emplace_back();
      if (!parse_element(element.children.back(), depth + 1)) return false;
      if (has_appended_) return true;
    }
  }

  bool parse() {
    if (!skip_misc()) return false;
    return parse_element(root_, 0);
  }

  std::string_view in_;
  std::size_t pos_ = 0;
  bool ok_ = false;
  bool has_appended_ = false;
  XmlElement root_;
  std::string_view appended_;
  std::string appended_encoding_;
};

// --- what the file declares --------------------------------------------------------

enum class WordType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Int64, UInt64, Float32, Float64 };

std::optional<WordType> parse_word_type(std::string_view name) {
  static constexpr std::pair<std::string_view, WordType> kTypes[] = {
      {"Int8", WordType::Int8},      {"UInt8", WordType::UInt8},   {"Int16", WordType::Int16},
      {"UInt16", WordType::UInt16},  {"Int32", WordType::Int32},   {"UInt32", WordType::UInt32},
      {"Int64", WordType::Int64},    {"UInt64", WordType::UInt64}, {"Float32", WordType::Float32},
      {"Float64", WordType::Float64}};
  for (const auto& [text, type] : kTypes)
    if (text == name) return type;
  return std::nullopt;
}

std::size_t word_size(WordType type) {
  switch (type) {
    case WordType::Int8:
    case WordType::UInt8: return 1;
    case WordType::Int16:
    case WordType::UInt16: return 2;
    case WordType::Int32:
    case WordType::UInt32:
    case WordType::Float32: return 4;
    default: return 8;
  }
}

/// A count attribute: a non-negative decimal integer; `fallback` when absent.
std::optional<std::uint64_t> count_attribute(const XmlElement& element, std::string_view key, std::uint64_t fallback) {
  const std::string* text = element.attribute(key);
  if (text == nullptr) return fallback;
  std::uint64_t value = 0;
  const auto [ptr, ec] = std::from_chars(text->data(), text->data() + text->size(), value);
  if (ec != std::errc() || ptr != text->data() + text->size() || text->empty()) return std::nullopt;
  return value;
}

/// A header word (UInt32 or UInt64) of the file's byte order.
std::uint64_t header_word(const unsigned char* p, std::size_t size, bool swap) {
  if (size == 4) {
    std::uint32_t v;
    std::memcpy(&v, p, 4);
    return swap ? __builtin_bswap32(v) : v;
  }
  std::uint64_t v;
  std::memcpy(&v, p, 8);
  return swap ? __builtin_bswap64(v) : v;
}

// --- decoding plans -------------------------------------------------------------------

/// What an array's values become.
enum class Target {
  Real,   ///< double
  Index,  ///< uint32 point index, checked to be below the point count
  Offset  ///< uint32 offset, checked to fit
};

/// One array: where its encoded bytes are and how to decode them into where
/// they go. Uncompressed data are one stream (the byte count, then the
/// values); zlib data are a header stream (block count, block size, size of
/// a partial last block, compressed size of each block) and a stream of the
/// compressed blocks one after the other. In base64 the two streams are
/// encoded separately (the header's last group may be padded).
struct ArrayJob {
  std::string what;  ///< for messages: "point data array 'p'"
  WordType type = WordType::Float64;
  std::size_t word = 8;
  bool swap = false;
  std::string_view source;  ///< raw bytes or base64 text, from the array's start on
  bool base64 = false;
  std::optional<std::uint64_t> appended_offset;  ///< where it starts in the appended data, if there
  std::uint64_t extent = 0;                      ///< bytes (or base64 characters) of `source` it uses
  std::size_t data_origin = 0;                   ///< where the value (or block) stream starts in `source`
  std::size_t header_bytes = 0;                  ///< uncompressed: bytes of the count before the values in that stream
  std::uint64_t block_size = 0, last_block_size = 0;    ///< uncompressed; 0 = the last block is whole
  std::vector<std::uint64_t> block_start, block_bytes;  ///< compressed blocks in the block stream
  std::uint64_t stored_words = 0;                       ///< values the array holds
  std::uint64_t words = 0;                              ///< values to decode
  Target target = Target::Real;
  void* out = nullptr;
  std::uint64_t index_limit = 0;

  // The first value out of range, found by any thread.
  std::mutex bad_mutex;
  std::uint64_t bad_position = std::numeric_limits<std::uint64_t>::max();
  std::string bad_value;

  std::uint64_t block_words(std::size_t block) const {
    const std::uint64_t begin = block * block_size / word;
    const std::uint64_t end = std::min<std::uint64_t>(words, begin + block_size / word);
    return end > begin ? end - begin : 0;
  }
  std::uint64_t block_uncompressed_bytes(std::size_t block) const {
    return block + 1 == block_bytes.size() && last_block_size != 0 ? last_block_size : block_size;
  }

  void record_bad(std::uint64_t position, std::string value) {
    const std::lock_guard<std::mutex> lock(bad_mutex);
    if (position < bad_position) {
      bad_position = position;
      bad_value = std::move(value);
    }
  }
};

/// The reader's state for one file: its name, byte order and header word,
/// and the appended data.
struct FileFormat {
  std::string file;
  bool swap = false;
  std::size_t header_word = 4;
  bool compressed = false;
  bool has_appended = false;
  std::string_view appended;
  bool appended_base64 = false;
};

[[noreturn]] void fail(const FileFormat& format, const std::string& message) {
  throw InputError(SourceLocation{format.file}, message);
}

std::size_t base64_chars(std::uint64_t bytes) { return static_cast<std::size_t>((bytes + 2) / 3 * 4); }

/// Reads bytes [first, last) of the stream at `origin` of an array's source.
bool read_stream(const ArrayJob& job, std::size_t origin, std::uint64_t first, std::uint64_t last, unsigned char* out) {
  if (origin > job.source.size()) return false;
  const std::string_view stream = job.source.substr(origin);
  if (!job.base64) {
    if (last > stream.size()) return false;
    std::memcpy(out, stream.data() + first, static_cast<std::size_t>(last - first));
    return true;
  }
  return decode_base64_range(stream, static_cast<std::size_t>(first), static_cast<std::size_t>(last), out);
}

/// The InputError for base64 text that did not decode in bytes [first,
/// last) of the stream at `origin`: the character at fault, and where.
[[noreturn]] void fail_base64(const FileFormat& format, const ArrayJob& job, std::size_t origin, std::uint64_t first,
                              std::uint64_t last) {
  const std::string_view stream = job.source.substr(std::min(origin, job.source.size()));
  const std::size_t begin = std::min<std::size_t>(first / 3 * 4, stream.size());
  const std::size_t end = std::min<std::size_t>((last + 2) / 3 * 4, stream.size());
  std::vector<unsigned char> scratch(3 * (end - begin) / 4 + 3);
  const Base64Decoded decoded = decode_base64(stream.substr(begin, end - begin), scratch.data());
  if (decoded.ok())
    fail(format, job.what + ": the base64 text ends after " + std::to_string(stream.size()) +
                     " characters, inside the array; the file is cut short");
  const std::size_t at = std::min(origin, job.source.size()) + begin + decoded.bad_offset;
  const char c = job.source[at];
  fail(format, job.what + ": character " + std::to_string(at) + " of the array's base64 text is " +
                   (c == '=' ? std::string("'=' before its end") : "'" + std::string(1, c) + "'") +
                   "; expected only A-Z a-z 0-9 + / and '=' padding at the end");
}

bool plan_array_unchecked(const XmlElement& array, const FileFormat& format, std::string what,
                          std::optional<std::uint64_t> needed, ArrayJob& job);

/// Decides how to decode `array`, reading its header. `needed` is the number
/// of values the piece calls for, or nothing to take all the array holds.
/// Returns false to leave the file to VTK's reader; throws InputError for
/// data that cannot be right.
bool plan_array(const XmlElement& array, const FileFormat& format, std::string what,
                std::optional<std::uint64_t> needed, ArrayJob& job) {
  try {
    return plan_array_unchecked(array, format, std::move(what), needed, job);
  } catch (const InputError&) {
    // Inline base64 broken by whitespace does not decode here; VTK's reader
    // has the last word on it.
    const std::string* data_format = array.attribute("format");
    if (data_format != nullptr && *data_format == "binary" &&
        array.text.find_first_of(" \t\r\n") != std::string_view::npos)
      return false;
    throw;
  }
}

bool plan_array_unchecked(const XmlElement& array, const FileFormat& format, std::string what,
                          std::optional<std::uint64_t> needed, ArrayJob& job) {
  const std::string* type_name = array.attribute("type");
  const std::string* data_format = array.attribute("format");
  if (type_name == nullptr || data_format == nullptr) return false;
  const auto type = parse_word_type(*type_name);
  if (!type) return false;
  job.what = std::move(what);
  job.type = *type;
  job.word = word_size(*type);
  job.swap = format.swap;
  if (*data_format == "binary") {
    job.source = array.text;
    job.base64 = true;
  } else if (*data_format == "appended") {
    const auto offset = count_attribute(array, "offset", std::numeric_limits<std::uint64_t>::max());
    if (!offset || !format.has_appended || *offset == std::numeric_limits<std::uint64_t>::max()) return false;
    if (*offset > format.appended.size())
      fail(format, job.what + ": starts at byte " + std::to_string(*offset) + " of the appended data, which hold " +
                       std::to_string(format.appended.size()) + " bytes; the file is cut short");
    job.source = format.appended.substr(static_cast<std::size_t>(*offset));
    job.base64 = format.appended_base64;
    job.appended_offset = *offset;
  } else {
    return false;  // ascii: VTK's reader
  }

  const std::size_t h = format.header_word;
  unsigned char head[24];
  const std::string cut_short =
      job.what + (job.base64 ? ": the base64 text is cut short or holds a character outside the base64 alphabet"
                             : ": the data are cut short (the file ends inside the array)");
  std::uint64_t stated_bytes = 0;
  const std::uint64_t room = job.base64 ? job.source.size() / 4 * 3 : job.source.size();
  if (!format.compressed) {
    if (!read_stream(job, 0, 0, h, head)) fail(format, cut_short);
    stated_bytes = header_word(head, h, format.swap);
    // What the source can hold bounds what is believed of the count.
    job.stored_words = std::min(stated_bytes, room > h ? room - h : 0) / job.word;
    job.header_bytes = h;
  } else {
    if (!read_stream(job, 0, 0, 3 * h, head)) fail(format, cut_short);
    const std::uint64_t blocks = header_word(head, h, format.swap);
    job.block_size = header_word(head + h, h, format.swap);
    job.last_block_size = header_word(head + 2 * h, h, format.swap);
    const std::uint64_t max_blocks = job.source.size() / h;  // each block needs a header word
    if (blocks > max_blocks)
      fail(format, job.what + ": the compression header gives " + std::to_string(blocks) +
                       " blocks; the array's data hold room for the sizes of " + std::to_string(max_blocks) +
                       " at most (a damaged header, or the file is cut short)");
    if (blocks > 0 && (job.block_size == 0 || job.last_block_size > job.block_size))
      fail(format, job.what + ": the compression header gives blocks of " + std::to_string(job.block_size) +
                       " bytes and a last block of " + std::to_string(job.last_block_size) +
                       "; expected a last block no larger than the others");
    if (job.block_size % job.word != 0) return false;  // values across blocks: VTK's reader
    const auto header_bytes = static_cast<std::size_t>((3 + blocks) * h);
    std::vector<unsigned char> header(header_bytes);
    if (!read_stream(job, 0, 0, header_bytes, header.data())) fail(format, cut_short);
    job.data_origin = job.base64 ? base64_chars(header_bytes) : header_bytes;
    std::uint64_t start = 0;
    job.block_start.resize(static_cast<std::size_t>(blocks));
    job.block_bytes.resize(static_cast<std::size_t>(blocks));
    for (std::size_t b = 0; b < blocks; ++b) {
      job.block_start[b] = start;
      job.block_bytes[b] = header_word(header.data() + (3 + b) * h, h, format.swap);
      if (job.block_bytes[b] > job.source.size() - start) fail(format, cut_short);
      start += job.block_bytes[b];
    }
    // Deflate expands at most about 1032:1: a header claiming more is
    // corrupt, and must not make the reader allocate (or compute) what it claims.
    for (std::size_t b = 0; b < blocks; ++b)
      if (job.block_uncompressed_bytes(b) > 1032 * job.block_bytes[b] + 64)
        fail(format, job.what + ": the compression header gives zlib block " + std::to_string(b + 1) + " " +
                         std::to_string(job.block_uncompressed_bytes(b)) + " bytes from " +
                         std::to_string(job.block_bytes[b]) +
                         " compressed bytes; expected at most 1032 bytes from each compressed byte");
    const std::uint64_t total =
        blocks == 0 ? 0 : (blocks - 1) * job.block_size + job.block_uncompressed_bytes(blocks - 1);
    const std::size_t stream_size = job.base64 ? base64_chars(start) : static_cast<std::size_t>(start);
    if (job.data_origin + stream_size > job.source.size()) fail(format, cut_short);
    job.stored_words = total / job.word;
  }
  job.words = needed ? *needed : job.stored_words;
  if (job.words > job.stored_words) {
    if (!format.compressed && stated_bytes / job.word >= job.words) fail(format, cut_short);
    fail(format,
         job.what + ": holds " + std::to_string(job.stored_words) + " values; expected " + std::to_string(job.words));
  }
  if (!format.compressed) {
    const std::uint64_t stream_bytes = h + job.words * job.word;
    if (job.base64) {
      // Inline text must be exactly the stream (whitespace inside it, which
      // VTK skips, leaves the file to VTK); appended text runs on to the end.
      if (*data_format == "binary" && (stated_bytes > room || job.source.size() != base64_chars(h + stated_bytes)))
        return false;
      if (base64_chars(stream_bytes) > job.source.size()) fail(format, cut_short);
    } else if (stream_bytes > job.source.size()) {
      fail(format, cut_short);
    }
  }
  if (!format.compressed) {
    const std::uint64_t bytes = h + job.stored_words * job.word;
    job.extent = job.base64 ? base64_chars(bytes) : bytes;
  } else {
    const std::uint64_t compressed = job.block_bytes.empty() ? 0 : job.block_start.back() + job.block_bytes.back();
    job.extent = job.data_origin + (job.base64 ? base64_chars(compressed) : compressed);
    if (*data_format == "binary" && job.source.size() != job.extent) return false;
  }
  return true;
}

// --- decoding ------------------------------------------------------------------------

template <typename T, bool Swap>
inline T load(const unsigned char* p) {
  if constexpr (sizeof(T) == 1) {
    return static_cast<T>(*p);
  } else {
    using Bits = std::conditional_t<sizeof(T) == 2, std::uint16_t,
                                    std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>>;
    Bits bits;
    std::memcpy(&bits, p, sizeof(T));
    if constexpr (Swap) {
      if constexpr (sizeof(T) == 2)
        bits = __builtin_bswap16(bits);
      else if constexpr (sizeof(T) == 4)
        bits = __builtin_bswap32(bits);
      else
        bits = __builtin_bswap64(bits);
    }
    T value;
    std::memcpy(&value, &bits, sizeof(T));
    return value;
  }
}

template <typename T>
std::string value_text(T value) {
  if constexpr (std::is_floating_point_v<T>)
    return std::to_string(value);
  else
    return std::to_string(+value);
}

/// Converts `count` values starting at value `first` of the array.
template <typename T, bool Swap>
void convert_values(ArrayJob& job, const unsigned char* in, std::uint64_t first, std::uint64_t count) {
  if (job.target == Target::Real) {
    double* out = static_cast<double*>(job.out) + first;
    for (std::uint64_t i = 0; i < count; ++i) out[i] = static_cast<double>(load<T, Swap>(in + i * sizeof(T)));
    return;
  }
  if constexpr (std::is_floating_point_v<T>) {
    job.record_bad(first, "a floating-point value");  // not planned: index arrays of reals go to VTK
  } else {
    std::uint32_t* out = static_cast<std::uint32_t*>(job.out) + first;
    const std::uint64_t limit = job.index_limit;
    for (std::uint64_t i = 0; i < count; ++i) {
      const T value = load<T, Swap>(in + i * sizeof(T));
      bool good;
      if constexpr (std::is_signed_v<T>)
        good = value >= 0 && static_cast<std::uint64_t>(value) < limit;
      else
        good = static_cast<std::uint64_t>(value) < limit;
      if (!good) {
        job.record_bad(first + i, value_text(value));
        out[i] = 0;
        continue;
      }
      out[i] = static_cast<std::uint32_t>(value);
    }
  }
}

template <bool Swap>
void convert_swapped(ArrayJob& job, const unsigned char* in, std::uint64_t first, std::uint64_t count) {
  switch (job.type) {
    case WordType::Int8: return convert_values<std::int8_t, Swap>(job, in, first, count);
    case WordType::UInt8: return convert_values<std::uint8_t, Swap>(job, in, first, count);
    case WordType::Int16: return convert_values<std::int16_t, Swap>(job, in, first, count);
    case WordType::UInt16: return convert_values<std::uint16_t, Swap>(job, in, first, count);
    case WordType::Int32: return convert_values<std::int32_t, Swap>(job, in, first, count);
    case WordType::UInt32: return convert_values<std::uint32_t, Swap>(job, in, first, count);
    case WordType::Int64: return convert_values<std::int64_t, Swap>(job, in, first, count);
    case WordType::UInt64: return convert_values<std::uint64_t, Swap>(job, in, first, count);
    case WordType::Float32: return convert_values<float, Swap>(job, in, first, count);
    case WordType::Float64: return convert_values<double, Swap>(job, in, first, count);
  }
}

void convert(ArrayJob& job, const unsigned char* in, std::uint64_t first, std::uint64_t count) {
  if (job.swap)
    convert_swapped<true>(job, in, first, count);
  else
    convert_swapped<false>(job, in, first, count);
}

/// Per-thread buffers and zlib state.
struct Scratch {
  std::vector<unsigned char> encoded, decoded;
  std::unique_ptr<libdeflate_decompressor, void (*)(libdeflate_decompressor*)> inflater{nullptr,
                                                                                        &libdeflate_free_decompressor};
  libdeflate_decompressor* zlib() {
    if (!inflater) inflater.reset(libdeflate_alloc_decompressor());
    if (!inflater) throw std::bad_alloc();
    return inflater.get();
  }
};

/// One piece of work: `count` values from value `first` of a job; for
/// compressed data, block `block`.
struct Task {
  ArrayJob* job;
  std::uint64_t first, count;
  std::size_t block;
};

constexpr std::uint64_t kChunkBytes = std::uint64_t{1} << 18;

void add_tasks(ArrayJob& job, const FileFormat& format, std::vector<Task>& tasks) {
  if (job.words == 0) return;
  if (format.compressed) {
    for (std::size_t b = 0; b < job.block_bytes.size(); ++b) {
      const std::uint64_t count = job.block_words(b);
      if (count == 0) break;
      tasks.push_back({&job, b * job.block_size / job.word, count, b});
    }
    return;
  }
  const std::uint64_t chunk = std::max<std::uint64_t>(1, kChunkBytes / job.word);
  for (std::uint64_t first = 0; first < job.words; first += chunk)
    tasks.push_back({&job, first, std::min(chunk, job.words - first), 0});
}

void run_task(const Task& task, const FileFormat& format, Scratch& scratch) {
  ArrayJob& job = *task.job;
  const std::uint64_t bytes = task.count * job.word;
  if (!format.compressed) {
    const std::uint64_t first_byte = job.header_bytes + task.first * job.word;
    if (!job.base64) {
      convert(job, reinterpret_cast<const unsigned char*>(job.source.data()) + first_byte, task.first, task.count);
      return;
    }
    scratch.decoded.resize(static_cast<std::size_t>(bytes));
    if (!read_stream(job, 0, first_byte, first_byte + bytes, scratch.decoded.data()))
      fail_base64(format, job, 0, first_byte, first_byte + bytes);
    convert(job, scratch.decoded.data(), task.first, task.count);
    return;
  }
  const std::size_t b = task.block;
  const auto compressed_bytes = static_cast<std::size_t>(job.block_bytes[b]);
  const unsigned char* compressed;
  if (job.base64) {
    scratch.encoded.resize(compressed_bytes);
    if (!read_stream(job, job.data_origin, job.block_start[b], job.block_start[b] + compressed_bytes,
                     scratch.encoded.data()))
      fail_base64(format, job, job.data_origin, job.block_start[b], job.block_start[b] + compressed_bytes);
    compressed = scratch.encoded.data();
  } else {
    compressed = reinterpret_cast<const unsigned char*>(job.source.data()) + job.data_origin + job.block_start[b];
  }
  const auto expected = static_cast<std::size_t>(job.block_uncompressed_bytes(b));
  scratch.decoded.resize(expected);
  std::size_t actual = 0;
  const libdeflate_result result = libdeflate_zlib_decompress(scratch.zlib(), compressed, compressed_bytes,
                                                              scratch.decoded.data(), expected, &actual);
  const std::string block = "zlib block " + std::to_string(b + 1) + " of " + std::to_string(job.block_bytes.size());
  if (result == LIBDEFLATE_INSUFFICIENT_SPACE)
    fail(format, job.what + ": " + block + " decompresses to more than the " + std::to_string(expected) +
                     " bytes its header gives");
  if (result != LIBDEFLATE_SUCCESS) fail(format, job.what + ": " + block + " is not valid zlib data");
  if (actual != expected)
    fail(format, job.what + ": " + block + " decompresses to " + std::to_string(actual) + " bytes; its header gives " +
                     std::to_string(expected));
  convert(job, scratch.decoded.data(), task.first, task.count);
}

/// Runs body(i, scratch) for i in [0, count) on up to 8 cores, with one
/// Scratch per thread; the error of the first failing task (in task order,
/// so the message does not depend on timing) is rethrown.
template <typename Body>
void run_parallel(std::size_t count, Body body) {
  const unsigned threads = parallel_threads(count, std::min(8u, std::max(1u, std::thread::hardware_concurrency())));
  std::vector<Scratch> scratch(threads);
  parallel_for(count, threads, [&](std::size_t i, unsigned worker) { body(i, scratch[worker]); });
}

// --- the piece ---------------------------------------------------------------------------

/// The arrays of PointData or CellData that become fields: named, 1 or 3
/// components, numeric, not VTK's ghost array. False leaves the file to VTK
/// (a type this reader does not decode, a name used twice).
bool field_arrays(const XmlElement* attributes, std::vector<const XmlElement*>& out) {
  if (attributes == nullptr) return true;
  std::set<std::string> names;
  for (const auto& array : attributes->children) {
    const std::string* name = array.attribute("Name");
    const std::string* type = array.attribute("type");
    if (type == nullptr) return false;
    // String arrays are written as <Array type="String">: never a field.
    if (array.name == "Array" && *type == "String") continue;
    if (array.name != "DataArray") return false;
    if (name != nullptr) {
      if (!names.insert(*name).second) return false;
    }
    if (!parse_word_type(*type)) return false;
    const auto components = count_attribute(array, "NumberOfComponents", 1);
    if (!components || *components == 0) return false;
    if (name == nullptr || name->empty() || *name == "vtkGhostType") continue;
    if (*components == 1 || *components == 3) out.push_back(&array);
  }
  return true;
}

const XmlElement* only_child(const XmlElement& parent, std::string_view name, bool& several) {
  const auto found = parent.children_named(name);
  several = several || found.size() > 1;
  return found.empty() ? nullptr : found.front();
}

const XmlElement* array_named(const XmlElement& cells, std::string_view name) {
  for (const auto& child : cells.children)
    if (child.name == "DataArray")
      if (const std::string* n = child.attribute("Name"); n != nullptr && *n == name) return &child;
  return nullptr;
}

std::string in_quotes(const std::string& name) { return "'" + name + "'"; }

/// The appended bytes the arrays planned so far use, as [begin, end) by
/// begin. VTK's writers never let two arrays share bytes; a file that does
/// is left to VTK's reader, so that a few bytes cannot stand for many arrays
/// (and many times the memory).
class AppendedRanges {
 public:
  /// False when the job's bytes overlap an earlier array's.
  bool add(const ArrayJob& job) {
    if (!job.appended_offset) return true;
    const std::uint64_t begin = *job.appended_offset, end = begin + std::max<std::uint64_t>(job.extent, 1);
    const auto next = ranges_.lower_bound(begin);
    if (next != ranges_.end() && next->first < end) return false;
    if (next != ranges_.begin() && std::prev(next)->second > begin) return false;
    ranges_.emplace(begin, end);
    return true;
  }

 private:
  std::map<std::uint64_t, std::uint64_t> ranges_;
};

}  // namespace

std::optional<SurfaceMesh> read_vtp_surface(const std::filesystem::path& file) {
  std::optional<FileBytes> bytes;
  try {
    bytes.emplace(file);
  } catch (const InputError&) {
    return std::nullopt;  // VTK's reader says why, as for every other VTK format
  }
  return parse_vtp_surface(bytes->view(), file.string(), file.stem().string());
}

std::optional<SurfaceMesh> parse_vtp_surface(std::string_view bytes, const std::string& file_name,
                                             const std::string& location) {
  const XmlHeader xml(bytes);
  if (!xml.ok()) return std::nullopt;

  // The file: VTKFile of type PolyData, a byte order, a header word, zlib or no compression.
  const XmlElement& root = xml.root();
  FileFormat format;
  format.file = file_name;
  const std::string* type = root.attribute("type");
  const std::string* byte_order = root.attribute("byte_order");
  const std::string* header_type = root.attribute("header_type");
  const std::string* compressor = root.attribute("compressor");
  const std::string* version = root.attribute("version");
  if (root.name != "VTKFile" || type == nullptr || *type != "PolyData" || byte_order == nullptr) return std::nullopt;
  if (version == nullptr || (*version != "0.1" && *version != "1.0" && version->rfind("2.", 0) != 0))
    return std::nullopt;
  if (*byte_order != "LittleEndian" && *byte_order != "BigEndian") return std::nullopt;
  format.swap = (*byte_order == "BigEndian") != (std::endian::native == std::endian::big);
  if (header_type != nullptr && *header_type != "UInt32" && *header_type != "UInt64") return std::nullopt;
  format.header_word = header_type != nullptr && *header_type == "UInt64" ? 8 : 4;
  if (compressor != nullptr && !compressor->empty() && *compressor != "vtkZLibDataCompressor") return std::nullopt;
  format.compressed = compressor != nullptr && !compressor->empty();
  format.has_appended = xml.has_appended();
  format.appended = xml.appended();
  if (format.has_appended) {
    const std::string* encoding = xml.appended_encoding();
    if (encoding == nullptr || (*encoding != "raw" && *encoding != "base64")) return std::nullopt;
    format.appended_base64 = *encoding == "base64";
  }

  // One piece of polygons.
  bool several = false;
  const XmlElement* poly_data = only_child(root, "PolyData", several);
  if (poly_data == nullptr || several) return std::nullopt;
  const XmlElement* piece = only_child(*poly_data, "Piece", several);
  if (piece == nullptr || several) return std::nullopt;
  const auto point_count = count_attribute(*piece, "NumberOfPoints", 0);
  const auto polygon_count = count_attribute(*piece, "NumberOfPolys", 0);
  for (const char* other : {"NumberOfVerts", "NumberOfLines", "NumberOfStrips"}) {
    const auto count = count_attribute(*piece, other, 0);
    if (!count || *count != 0) return std::nullopt;
  }
  if (!point_count || !polygon_count) return std::nullopt;
  const XmlElement* points = only_child(*piece, "Points", several);
  const XmlElement* polys = only_child(*piece, "Polys", several);
  const XmlElement* point_data = only_child(*piece, "PointData", several);
  const XmlElement* cell_data = only_child(*piece, "CellData", several);
  if (several) return std::nullopt;
  if (*polygon_count == 0) fail(format, "no faces (triangles, quads, polygons or triangle strips) in the file");
  if (points == nullptr || polys == nullptr || points->children.size() != 1 || points->children[0].name != "DataArray")
    return std::nullopt;
  const XmlElement& point_array = points->children[0];
  if (count_attribute(point_array, "NumberOfComponents", 1) != std::uint64_t{3}) return std::nullopt;
  const XmlElement* offsets_array = array_named(*polys, "offsets");
  const XmlElement* connectivity_array = array_named(*polys, "connectivity");
  if (offsets_array == nullptr || connectivity_array == nullptr) return std::nullopt;
  std::vector<const XmlElement*> cell_fields, point_fields;
  if (!field_arrays(cell_data, cell_fields) || !field_arrays(point_data, point_fields)) return std::nullopt;

  // Plans, all before any decoding, so that leaving the file to VTK costs nothing.
  constexpr std::uint64_t kMax32 = std::numeric_limits<std::uint32_t>::max();
  if (*point_count > kMax32)
    fail(format, "NumberOfPoints is " + std::to_string(*point_count) + "; at most " + std::to_string(kMax32) +
                     " points are supported");
  if (*polygon_count >= kMax32)
    fail(format, "NumberOfPolys is " + std::to_string(*polygon_count) + "; fewer than " + std::to_string(kMax32) +
                     " polygons are supported");
  const std::size_t points_n = static_cast<std::size_t>(*point_count);
  const std::size_t polygons_n = static_cast<std::size_t>(*polygon_count);
  std::vector<std::unique_ptr<ArrayJob>> jobs;
  AppendedRanges appended_ranges;
  auto plan = [&](const XmlElement& array, std::string what, std::optional<std::uint64_t> needed) -> ArrayJob* {
    jobs.push_back(std::make_unique<ArrayJob>());
    ArrayJob& job = *jobs.back();
    const bool planned = plan_array(array, format, std::move(what), needed, job) && appended_ranges.add(job);
    return planned ? &job : nullptr;
  };
  ArrayJob* point_job = plan(point_array, "the points array", 3 * *point_count);
  ArrayJob* offsets_job = plan(*offsets_array, "the Polys offsets array", *polygon_count);
  ArrayJob* connectivity_job = plan(*connectivity_array, "the Polys connectivity array", std::nullopt);
  if (point_job == nullptr || offsets_job == nullptr || connectivity_job == nullptr) return std::nullopt;
  for (const ArrayJob* job : {offsets_job, connectivity_job})
    if (job->type == WordType::Float32 || job->type == WordType::Float64) return std::nullopt;
  if (connectivity_job->words > kMax32)
    fail(format, "the Polys connectivity array holds " + std::to_string(connectivity_job->words) +
                     " point indices; at most " + std::to_string(kMax32) + " are supported");

  SurfaceMesh mesh;
  mesh.location_names = {location};
  struct FieldPlan {
    FieldArray* field;
    ArrayJob* job;
  };
  std::vector<FieldPlan> field_plans;
  mesh.fields.reserve(cell_fields.size() + point_fields.size());
  for (const auto& [arrays, association] :
       {std::pair{&cell_fields, FieldAssociation::Face}, std::pair{&point_fields, FieldAssociation::Point}}) {
    for (const XmlElement* array : *arrays) {
      FieldArray field;
      field.name = *array->attribute("Name");
      field.association = association;
      field.components = static_cast<int>(*count_attribute(*array, "NumberOfComponents", 1));
      const std::uint64_t tuples = association == FieldAssociation::Point ? *point_count : *polygon_count;
      const std::string what = std::string(association == FieldAssociation::Point ? "point" : "cell") + " data array " +
                               in_quotes(field.name);
      ArrayJob* job = plan(*array, what, tuples * static_cast<std::uint64_t>(field.components));
      if (job == nullptr) return std::nullopt;
      mesh.fields.push_back(std::move(field));
      field_plans.push_back({&mesh.fields.back(), job});
    }
  }

  // The arrays are allocated on every core too: first writes to fresh
  // memory are page faults, which cost more than decoding on virtual machines.
  std::vector<std::pair<std::size_t, std::function<void()>>> allocations;
  auto allocate = [&allocations](auto& values, std::size_t size) {
    allocations.emplace_back(size * sizeof(values[0]), [&values, size] {
      reserve_with_huge_pages(values, size);
      values.resize(size);
    });
  };
  allocate(mesh.points_xyz, 3 * points_n);
  allocate(mesh.face_offsets, polygons_n + 1);
  allocate(mesh.face_indices, static_cast<std::size_t>(connectivity_job->words));
  allocate(mesh.face_location, polygons_n);
  for (const auto& plan_entry : field_plans)
    allocate(plan_entry.field->values, static_cast<std::size_t>(plan_entry.job->words));
  std::stable_sort(allocations.begin(), allocations.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  try {
    run_parallel(allocations.size(), [&allocations](std::size_t i, Scratch&) { allocations[i].second(); });
  } catch (const std::bad_alloc&) {
    std::size_t total = 0;
    for (const auto& allocation : allocations) total += allocation.first;
    fail(format,
         "the arrays the file declares need " + std::to_string(total >> 20) + " MiB, more memory than there is");
  }

  point_job->out = mesh.points_xyz.data();
  offsets_job->out = mesh.face_offsets.data() + 1;
  offsets_job->target = Target::Offset;
  offsets_job->index_limit = kMax32 + 1;
  connectivity_job->out = mesh.face_indices.data();
  connectivity_job->target = Target::Index;
  connectivity_job->index_limit = *point_count;
  for (const auto& plan_entry : field_plans) plan_entry.job->out = plan_entry.field->values.data();
  std::vector<Task> tasks;
  for (const auto& job : jobs) add_tasks(*job, format, tasks);
  run_parallel(tasks.size(),
               [&tasks, &format](std::size_t i, Scratch& scratch) { run_task(tasks[i], format, scratch); });

  // Offsets: from 0, never back, at least 3 points a polygon, within the connectivity.
  const std::string block = "block " + in_quotes(location) + ": ";
  if (offsets_job->bad_position != std::numeric_limits<std::uint64_t>::max())
    fail(format, block + "the Polys offsets array holds " + offsets_job->bad_value + " at cell " +
                     std::to_string(offsets_job->bad_position) + "; expected an offset from 0 to " +
                     std::to_string(kMax32));
  const std::uint32_t* offsets = mesh.face_offsets.data();
  for (std::size_t cell = 0; cell < polygons_n; ++cell) {
    if (offsets[cell + 1] >= std::uint64_t{offsets[cell]} + 3) continue;
    if (offsets[cell + 1] < offsets[cell])
      fail(format, block + "the Polys offsets array goes back at cell " + std::to_string(cell) + " (" +
                       std::to_string(offsets[cell + 1]) + " after " + std::to_string(offsets[cell]) +
                       "); expected offsets that never decrease");
    fail(format, block + "cell " + std::to_string(cell) + " is a polygon with " +
                     std::to_string(offsets[cell + 1] - offsets[cell]) + " points; expected at least 3");
  }
  const std::uint32_t index_count = offsets[polygons_n];
  if (index_count > connectivity_job->words)
    fail(format, block + "the Polys connectivity array holds " + std::to_string(connectivity_job->words) +
                     " point indices; the offsets call for " + std::to_string(index_count));
  if (connectivity_job->bad_position < index_count) {
    const auto cell =
        static_cast<std::size_t>(std::upper_bound(offsets, offsets + polygons_n + 1,
                                                  static_cast<std::uint32_t>(connectivity_job->bad_position)) -
                                 offsets - 1);
    fail(format, block + "cell " + std::to_string(cell) + " refers to point " + connectivity_job->bad_value +
                     (*point_count == 0 ? std::string("; the block has no points")
                                        : "; expected 0.." + std::to_string(*point_count - 1) + " (the block has " +
                                              std::to_string(*point_count) + " points)"));
  }
  mesh.face_indices.resize(index_count);
  if (const auto twice = find_duplicate_face(mesh))
    fail(format, block + "cell " + std::to_string(twice->second) + ": the points of cell " +
                     std::to_string(twice->first) +
                     " again, in the same or another order; expected each face once (a face listed twice counts twice "
                     "in the forces)");
  return mesh;
}

}  // namespace hydrocoef
