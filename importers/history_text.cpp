#include "importers/history_text.hpp"

#include <fcntl.h>
#include <openssl/evp.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <exception>
#include <functional>
#include <limits>
#include <optional>
#include <stdexcept>
#include <system_error>
#include <thread>

#include "src/core/error.hpp"
#include "src/core/huge_pages.hpp"
#include "src/core/parallel.hpp"

namespace hydrocoef::history_text {
namespace {

constexpr std::size_t kNoError = std::numeric_limits<std::size_t>::max();

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

// Where the line starting at `p` ends (its '\n', or `end`).
const char* line_end(const char* p, const char* end) {
  const void* newline = std::memchr(p, '\n', static_cast<std::size_t>(end - p));
  return newline != nullptr ? static_cast<const char*>(newline) : end;
}

// Clinger's fast path (W. D. Clinger, "How to read floating point numbers
// accurately", PLDI 1990): a decimal of at most 19 digits whose integer
// mantissa m is at most 2^53, scaled by 10^k with |k| <= 22, is m * 10^k or
// m / 10^-k, one correctly rounded operation on two exact doubles, so the
// result is the correctly rounded value from_chars gives too. What solvers
// write ("-1.0238908340e-04") takes this path; anything else goes to
// from_chars.
constexpr double kPowersOfTen[23] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                     1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

inline bool is_digit(char c) { return static_cast<unsigned char>(c - '0') < 10; }

// Eight ASCII digits at once (SWAR, as in D. Lemire's fast_float): whether
// the 8 bytes are all digits, and their value. The first character must be
// the lowest byte of the word.
static_assert(std::endian::native == std::endian::little, "the eight-digit parsing assumes little-endian words");
inline bool eight_digits(std::uint64_t v) {
  return (((v + 0x4646464646464646ULL) | (v - 0x3030303030303030ULL)) & 0x8080808080808080ULL) == 0;
}
inline std::uint32_t eight_digit_value(std::uint64_t v) {
  constexpr std::uint64_t mask = 0x000000FF000000FFULL;
  constexpr std::uint64_t mul1 = 0x000F424000000064ULL;  // 100 + (1000000 << 32)
  constexpr std::uint64_t mul2 = 0x0000271000000001ULL;  // 1 + (10000 << 32)
  v -= 0x3030303030303030ULL;
  v = (v * 10) + (v >> 8);
  v = (((v & mask) * mul1) + (((v >> 16) & mask) * mul2)) >> 32;
  return static_cast<std::uint32_t>(v);
}

const char* fast_number(const char* p, const char* end, double& value) {
  const char* q = p;
  bool negative = false;
  if (q < end && *q == '-') {
    negative = true;
    ++q;
  }
  std::uint64_t mantissa = 0;
  int digits = 0;  // digits taken into the mantissa, leading zeros included
  int scale = 0;   // power of ten of the mantissa's last digit
  const char* const integer = q;
  while (q < end && is_digit(*q)) {
    mantissa = mantissa * 10 + static_cast<std::uint64_t>(*q - '0');
    ++q;
    if (++digits > 19) return nullptr;
  }
  bool any = q > integer;
  if (q < end && *q == '.') {
    ++q;
    const char* const fraction = q;
    if (digits <= 11) {
      while (end - q >= 8) {
        std::uint64_t block;
        std::memcpy(&block, q, 8);
        if (!eight_digits(block)) break;
        mantissa = mantissa * 100000000 + eight_digit_value(block);
        q += 8;
        scale -= 8;
        digits += 8;
        if (digits > 11) break;
      }
    }
    while (q < end && is_digit(*q)) {
      mantissa = mantissa * 10 + static_cast<std::uint64_t>(*q - '0');
      --scale;
      ++q;
      if (++digits > 19) return nullptr;
    }
    any = any || q > fraction;
  }
  if (!any) return nullptr;
  if (q < end && (*q == 'e' || *q == 'E')) {
    const char* e = q + 1;
    bool negative_exponent = false;
    if (e < end && (*e == '+' || *e == '-')) {
      negative_exponent = *e == '-';
      ++e;
    }
    if (e == end || !is_digit(*e)) return nullptr;  // from_chars decides what "1e" means
    int exponent = 0;
    while (e < end && is_digit(*e)) {
      if (exponent > 10000) return nullptr;
      exponent = exponent * 10 + (*e - '0');
      ++e;
    }
    scale += negative_exponent ? -exponent : exponent;
    q = e;
  }
  if (mantissa > (std::uint64_t{1} << 53) || scale < -22 || scale > 22) return nullptr;
  double v = static_cast<double>(mantissa);
  v = scale < 0 ? v / kPowersOfTen[-scale] : v * kPowersOfTen[scale];
  value = negative ? -v : v;
  return q;
}

// A finite number from [p, end): the fast path above, else from_chars (plus
// a leading '+'). Returns the end of the number, or nullptr when there is none
// or it is not finite.
const char* read_number(const char* p, const char* end, double& value) {
  if (const char* stop = fast_number(p, end, value)) return stop;
  if (p < end && *p == '+' && p + 1 < end && (std::isdigit(static_cast<unsigned char>(p[1])) || p[1] == '.')) ++p;
  const auto [stop, ec] = std::from_chars(p, end, value);
  if (ec == std::errc::result_out_of_range && stop != p) {
    // Below the smallest double: zero. Above the largest: refused below.
    const std::string digits(p, stop);
    value = std::strtod(digits.c_str(), nullptr);
    return std::isfinite(value) ? stop : nullptr;
  }
  if (ec != std::errc{} || !std::isfinite(value)) return nullptr;
  return stop;
}

// The fast path: parses one row starting at p (at a non-blank, non-comment
// character). Returns the position after the row's '\n' (or `end` for a last
// row without one, when that is allowed), or nullptr for anything wrong.
const char* parse_whitespace_row(const char* p, const char* end, const RowSyntax& syntax, bool require_line_end,
                                 double* out) {
  const bool parens = syntax.parentheses;
  const bool has_skip = !syntax.skip.empty();
  int depth = 0;
  for (std::size_t column = 0; column < syntax.columns; ++column) {
    for (;;) {
      if (p == end) return nullptr;
      const char c = *p;
      if (c == ' ' || c == '\t') {
        ++p;
      } else if (parens && c == '(') {
        ++depth;
        ++p;
      } else if (parens && c == ')') {
        if (--depth < 0) return nullptr;
        ++p;
      } else {
        break;
      }
    }
    if (*p == '\n' || *p == '\r') return nullptr;
    if (has_skip && syntax.skip[column]) {
      while (p < end && !is_blank(*p) && *p != '\n' && !(parens && (*p == '(' || *p == ')'))) ++p;
      continue;
    }
    double value;
    const char* stop = read_number(p, end, value);
    if (stop == nullptr) return nullptr;
    if (stop < end) {
      const char c = *stop;
      if (!(c == ' ' || c == '\t' || c == '\n' || c == '\r' || (parens && (c == '(' || c == ')')))) return nullptr;
    }
    *out++ = value;
    p = stop;
  }
  for (;;) {
    if (p == end) return require_line_end || depth != 0 ? nullptr : p;
    const char c = *p;
    if (is_blank(c)) {
      ++p;
    } else if (parens && c == ')') {
      if (--depth < 0) return nullptr;
      ++p;
    } else {
      break;
    }
  }
  if (*p != '\n' || depth != 0) return nullptr;
  return p + 1;
}

// Skips one delimited field's text from p; nullptr for an unterminated quote.
const char* skip_field(const char* p, const char* end, char delimiter) {
  if (p < end && *p == '"') {
    ++p;
    for (;;) {
      if (p == end || *p == '\n') return nullptr;
      if (*p == '"') {
        if (p + 1 < end && p[1] == '"') {
          p += 2;
          continue;
        }
        return p + 1;
      }
      ++p;
    }
  }
  while (p < end && *p != delimiter && *p != '\n') ++p;
  return p;
}

const char* parse_delimited_row(const char* p, const char* end, const RowSyntax& syntax, bool require_line_end,
                                double* out) {
  const char delimiter = syntax.delimiter;
  const bool has_skip = !syntax.skip.empty();
  const auto blank = [delimiter](char c) { return c == ' ' || c == '\r' || (c == '\t' && delimiter != '\t'); };
  for (std::size_t column = 0; column < syntax.columns; ++column) {
    while (p < end && blank(*p)) ++p;
    if (has_skip && syntax.skip[column]) {
      p = skip_field(p, end, delimiter);
      if (p == nullptr) return nullptr;
      while (p < end && blank(*p)) ++p;
    } else {
      const bool quoted = p < end && *p == '"';
      if (quoted) ++p;
      double value;
      const char* stop = read_number(p, end, value);
      if (stop == nullptr) return nullptr;
      p = stop;
      if (quoted) {
        if (p == end || *p != '"') return nullptr;
        ++p;
      }
      while (p < end && blank(*p)) ++p;
      *out++ = value;
    }
    if (column + 1 < syntax.columns) {
      if (p == end || *p != delimiter) return nullptr;
      ++p;
    }
  }
  // A delimiter after the last field is harmless when nothing follows it.
  if (p < end && *p == delimiter) {
    ++p;
    while (p < end && blank(*p)) ++p;
  }
  if (p == end) return require_line_end ? nullptr : p;
  if (*p != '\n') return nullptr;
  return p + 1;
}

struct Chunk {
  const char* begin = nullptr;
  const char* end = nullptr;
  std::size_t newlines = 0;             // line ends in [begin, end)
  std::size_t capacity = 0;             // rows it can hold: its lines, a last one without a line end included
  std::size_t base = 0;                 // its first row in the output
  std::size_t first_line = 0;           // the file line of `begin`
  std::size_t rows = 0;                 // rows parsed
  std::size_t error_offset = kNoError;  // start of the first bad line, from `begin`
  std::size_t error_line = 0;
  bool error_is_last_line = false;  // the bad line has no line end after it
};

// Line ends in [begin, end): byte counters in 64 lanes, which the compiler
// turns into vector compares (about 2.5x std::count here), emptied before
// they can wrap.
std::size_t count_newlines(const char* begin, const char* end) {
  const auto* p = reinterpret_cast<const unsigned char*>(begin);
  const std::size_t n = static_cast<std::size_t>(end - begin);
  std::size_t total = 0;
  std::size_t i = 0;
  while (i + 64 <= n) {
    const std::size_t stop = std::min(n - n % 64, i + 255 * 64);
    unsigned char lanes[64] = {};
    for (; i < stop; i += 64)
      for (std::size_t k = 0; k < 64; ++k) lanes[k] = static_cast<unsigned char>(lanes[k] + (p[i + k] == '\n'));
    for (const unsigned char lane : lanes) total += lane;
  }
  for (; i < n; ++i) total += p[i] == '\n';
  return total;
}

void count_lines(Chunk& chunk) {
  chunk.newlines = count_newlines(chunk.begin, chunk.end);
  chunk.capacity = chunk.newlines + (chunk.begin < chunk.end && chunk.end[-1] != '\n' ? 1 : 0);
}

// Parses the chunk's rows into columns[k][base + r] (columns[k] may be null)
// and lines[base + r].
void parse_chunk(Chunk& chunk, const RowSyntax& syntax, std::size_t numbers, double* const* columns,
                 std::uint32_t* lines) {
  const char* p = chunk.begin;
  const char* const end = chunk.end;
  std::size_t line = chunk.first_line;
  const bool delimited = syntax.delimiter != 0;
  const bool require_line_end = syntax.require_line_end;
  double row[64];
  std::vector<double> long_row(numbers > 64 ? numbers : 0);
  double* const values = numbers > 64 ? long_row.data() : row;
  std::size_t r = chunk.base;
  while (p < end) {
    const char* q = p;
    while (q < end && is_blank(*q)) ++q;
    if (q == end || *q == '\n' || *q == '#') {
      const char* eol = line_end(q, end);
      if (eol == end) break;
      p = eol + 1;
      ++line;
      continue;
    }
    const char* next = delimited ? parse_delimited_row(q, end, syntax, require_line_end, values)
                                 : parse_whitespace_row(q, end, syntax, require_line_end, values);
    if (next == nullptr) {
      chunk.error_offset = static_cast<std::size_t>(p - chunk.begin);
      chunk.error_line = line;
      chunk.error_is_last_line = line_end(q, end) == end;
      break;
    }
    for (std::size_t k = 0; k < numbers; ++k)
      if (columns[k] != nullptr) columns[k][r] = values[k];
    if (lines != nullptr) lines[r] = static_cast<std::uint32_t>(line);
    ++r;
    ++line;
    p = next;
  }
  chunk.rows = r - chunk.base;
}

std::string column_label(const RowSyntax& syntax, std::size_t column) {
  std::string label = "column " + std::to_string(column + 1);
  if (column < syntax.names.size() && !syntax.names[column].empty())
    label += " " + history_text::quoted_text(syntax.names[column]);
  return label;
}

// The slow path: says what is wrong with a row the fast path refused. Throws.
[[noreturn]] void diagnose_row(std::string_view line_text, std::size_t line, const RowSyntax& syntax,
                               const std::string& file, bool last_line_cut) {
  const char* const begin = line_text.data();
  const char* const end = begin + line_text.size();
  const auto at = [&](const char* p) { return SourceLocation{file, line, static_cast<std::size_t>(p - begin) + 1}; };
  const auto token_at = [&](const char* p) {
    const char* q = p;
    if (syntax.delimiter != 0) {
      while (q < end && *q != syntax.delimiter && *q != '\n') ++q;
    } else {
      while (q < end && !is_blank(*q) && *q != '\n' && *q != '(' && *q != ')') ++q;
    }
    std::string_view token(p, static_cast<std::size_t>(q - p));
    while (!token.empty() && is_blank(token.back())) token.remove_suffix(1);
    return token;
  };
  const std::string cut_note = last_line_cut ? " (the file ends inside this row: a run stopped while writing?)" : "";
  const char* p = begin;
  int depth = 0;
  const bool parens = syntax.parentheses && syntax.delimiter == 0;
  std::size_t found = 0;
  for (std::size_t column = 0; column < syntax.columns; ++column) {
    if (syntax.delimiter == 0) {
      while (p < end && (is_blank(*p) || (parens && (*p == '(' || *p == ')')))) {
        if (*p == '(') ++depth;
        if (*p == ')' && --depth < 0) throw InputError(at(p), "')' without a matching '('");
        ++p;
      }
    } else {
      while (p < end && (*p == ' ' || *p == '\r' || (*p == '\t' && syntax.delimiter != '\t'))) ++p;
    }
    if (p == end || *p == '\n') {
      if (syntax.delimiter != 0 && column > 0)  // after a delimiter: the field is there, and empty
        throw InputError(at(p), column_label(syntax, column) + ": found an empty field, expected a number" + cut_note);
      throw InputError(
          at(p), "found " + std::to_string(found) + " fields, expected " + std::to_string(syntax.columns) + cut_note);
    }
    if (!syntax.skip.empty() && syntax.skip[column]) {
      const char* q = syntax.delimiter != 0 ? skip_field(p, end, syntax.delimiter) : p + token_at(p).size();
      if (q == nullptr)
        throw InputError(at(p), column_label(syntax, column) + ": a quoted field is not closed" + cut_note);
      p = q;
    } else {
      const bool quote = syntax.delimiter != 0 && *p == '"';
      const char* number = quote ? p + 1 : p;
      double value;
      const char* stop = read_number(number, end, value);
      const std::string_view token = token_at(p);
      if (stop == nullptr) {
        double any;
        const auto [q, ec] = std::from_chars(number, end, any);
        if (q != number && (ec == std::errc{} || ec == std::errc::result_out_of_range))
          throw InputError(at(p), column_label(syntax, column) + ": found " + history_text::quoted_text(token) +
                                      ", expected a finite number" + cut_note);
        throw InputError(at(p), column_label(syntax, column) + ": found " +
                                    (token.empty() ? std::string("an empty field") : history_text::quoted_text(token)) +
                                    ", expected a number" + cut_note);
      }
      if (quote) {
        if (stop == end || *stop != '"')
          throw InputError(at(p), column_label(syntax, column) + ": found " + history_text::quoted_text(token) +
                                      ", expected a number in closed quotes" + cut_note);
        ++stop;
      }
      const bool separated =
          stop == end || is_blank(*stop) || *stop == '\n' ||
          (syntax.delimiter != 0 ? *stop == syntax.delimiter : parens && (*stop == '(' || *stop == ')'));
      if (!separated)
        throw InputError(at(p), column_label(syntax, column) + ": found " + history_text::quoted_text(token) +
                                    ", expected a number" + cut_note);
      p = stop;
    }
    ++found;
    if (syntax.delimiter != 0) {
      while (p < end && (*p == ' ' || *p == '\r' || (*p == '\t' && syntax.delimiter != '\t'))) ++p;
      if (column + 1 < syntax.columns) {
        if (p == end || *p == '\n')
          throw InputError(at(p), "found " + std::to_string(found) + " fields, expected " +
                                      std::to_string(syntax.columns) + cut_note);
        if (*p != syntax.delimiter)
          throw InputError(at(p), column_label(syntax, column) + ": found " + history_text::quoted_text(token_at(p)) +
                                      " after the number, expected " +
                                      (syntax.delimiter == '\t' ? std::string("a tab")
                                                                : "'" + std::string(1, syntax.delimiter) + "'"));
        ++p;
      }
    }
  }
  // Past the last field.
  if (syntax.delimiter == 0) {
    while (p < end && (is_blank(*p) || (parens && *p == ')'))) {
      if (*p == ')' && --depth < 0) throw InputError(at(p), "')' without a matching '('");
      ++p;
    }
  } else {
    if (p < end && *p == syntax.delimiter) ++p;
    while (p < end && is_blank(*p)) ++p;
  }
  if (p < end && *p != '\n')
    throw InputError(at(p), "found more than " + std::to_string(syntax.columns) + " fields ('" +
                                std::string(token_at(p).substr(0, 40)) + "' after the last), expected " +
                                std::to_string(syntax.columns));
  if (depth != 0) throw InputError(at(p), "'(' without a matching ')'" + cut_note);
  if (last_line_cut)
    throw InputError(SourceLocation{file, line, 0},
                     "the last row has no line end: the file ends inside it (a run stopped while writing?); "
                     "expected every row to end with a line end");
  throw InputError(SourceLocation{file, line, 0},
                   "cannot read this row; expected " + std::to_string(syntax.columns) + " numbers");
}

}  // namespace

const char* read_finite_number(const char* begin, const char* end, double& value) {
  return read_number(begin, end, value);
}

std::string quoted_text(std::string_view text) { return "'" + printable_text(text, 40) + "'"; }

namespace {

struct Appended {
  std::size_t rows = 0;      // rows appended
  std::size_t newlines = 0;  // line ends in the data
  bool dropped_last_row = false;
};

// Appends the rows of `data` (whole lines, the last one possibly without its
// line end when `final` is set) to the sink, whose vectors hold `before` rows.
// Two passes, both on every core: the line ends of each chunk are counted
// (which places its rows), then each chunk parses straight into place.
Appended append_rows(std::string_view data, std::size_t first_line, std::size_t before, const RowSyntax& syntax,
                     std::size_t numbers, const std::string& file, const RowSink& sink, const RowOptions& options) {
  // Chunks of at least 4 MB, split after a line end, one per core.
  const std::size_t by_size = std::max<std::size_t>(1, data.size() / (std::size_t{4} << 20));
  const unsigned count = parallel_threads(by_size, options.threads);
  std::vector<Chunk> chunks(count);
  const char* const begin = data.data();
  const char* const end = begin + data.size();
  const char* cursor = begin;
  for (std::size_t c = 0; c < count; ++c) {
    chunks[c].begin = cursor;
    const char* target = c + 1 == count ? end : begin + data.size() * (c + 1) / count;
    if (target < cursor) target = cursor;
    const char* stop = target == end ? end : line_end(target, end);
    if (stop < end) ++stop;
    chunks[c].end = stop;
    cursor = stop;
  }

  parallel_for(count, count, [&](std::size_t c) { count_lines(chunks[c]); });
  std::size_t capacity = before;
  std::size_t line = first_line;
  for (Chunk& chunk : chunks) {
    chunk.base = capacity;
    chunk.first_line = line;
    capacity += chunk.capacity;
    line += chunk.newlines;
  }
  if (line > std::numeric_limits<std::uint32_t>::max())
    throw InputError(SourceLocation{file}, "more than 4294967295 lines; expected a smaller file");
  for (std::vector<double>* column : sink.columns)
    if (column != nullptr) column->resize(capacity);
  if (sink.lines != nullptr) sink.lines->resize(capacity);

  std::vector<double*> columns(numbers, nullptr);
  for (std::size_t k = 0; k < numbers; ++k)
    if (sink.columns[k] != nullptr) columns[k] = sink.columns[k]->data();
  std::uint32_t* const lines = sink.lines != nullptr ? sink.lines->data() : nullptr;
  parallel_for(count, count, [&](std::size_t c) { parse_chunk(chunks[c], syntax, numbers, columns.data(), lines); });

  Appended result;
  result.newlines = line - first_line;
  std::size_t used = count;
  for (std::size_t c = 0; c < count; ++c) {
    const Chunk& chunk = chunks[c];
    if (chunk.error_offset == kNoError) continue;
    if (chunk.error_is_last_line && options.drop_incomplete_last_row) {
      result.dropped_last_row = true;
    } else {
      const char* const row = chunk.begin + chunk.error_offset;
      const std::string_view text(row, static_cast<std::size_t>(line_end(row, end) - row));
      diagnose_row(text, chunk.error_line, syntax, file, chunk.error_is_last_line);
    }
    used = c + 1;
    break;
  }

  // Close the gaps that skipped lines left between chunks.
  std::size_t rows = before;
  for (std::size_t c = 0; c < used; ++c) {
    const Chunk& chunk = chunks[c];
    if (chunk.base != rows) {
      for (std::size_t k = 0; k < numbers; ++k)
        if (columns[k] != nullptr)
          std::memmove(columns[k] + rows, columns[k] + chunk.base, chunk.rows * sizeof(double));
      if (lines != nullptr) std::memmove(lines + rows, lines + chunk.base, chunk.rows * sizeof(std::uint32_t));
    }
    rows += chunk.rows;
  }
  for (std::vector<double>* column : sink.columns)
    if (column != nullptr) column->resize(rows);
  if (sink.lines != nullptr) sink.lines->resize(rows);
  result.rows = rows - before;
  return result;
}

std::size_t parsed_fields(const RowSyntax& syntax, const RowSink& sink) {
  if (syntax.columns == 0) throw std::invalid_argument("history rows need at least one column");
  if (!syntax.skip.empty() && syntax.skip.size() != syntax.columns)
    throw std::invalid_argument("history rows: skip mask of the wrong size");
  std::size_t numbers = syntax.columns;
  if (!syntax.skip.empty())
    numbers = static_cast<std::size_t>(std::count(syntax.skip.begin(), syntax.skip.end(), false));
  if (sink.columns.size() != numbers) throw std::invalid_argument("history rows: one sink column per parsed field");
  return numbers;
}

void clear_sink(const RowSink& sink) {
  for (std::vector<double>* column : sink.columns)
    if (column != nullptr) column->clear();
  if (sink.lines != nullptr) sink.lines->clear();
}

void reserve_sink(const RowSink& sink, std::size_t rows) {
  for (std::vector<double>* column : sink.columns)
    if (column != nullptr) reserve_with_huge_pages(*column, rows);
  if (sink.lines != nullptr) reserve_with_huge_pages(*sink.lines, rows);
}

// A file descriptor closed on every path.
struct Descriptor {
  int fd = -1;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

// Reads up to `size` bytes at the end of `buffer` (which grows by what is
// read); returns the count, 0 at the end of the file.
std::size_t read_some(int fd, std::vector<char>& buffer, std::size_t size, const std::string& file) {
  const std::size_t old = buffer.size();
  buffer.resize(old + size);
  std::size_t got = 0;
  while (got < size) {
    const ssize_t n = ::read(fd, buffer.data() + old + got, size - got);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw InputError(SourceLocation{file}, std::string("read error: ") + std::strerror(errno));
    if (n == 0) break;
    got += static_cast<std::size_t>(n);
  }
  buffer.resize(old + got);
  return got;
}

class Sha256 {
 public:
  Sha256() : context_(EVP_MD_CTX_new()) {
    if (context_ == nullptr || EVP_DigestInit_ex(context_, EVP_sha256(), nullptr) != 1)
      throw std::runtime_error("SHA-256 unavailable");
  }
  ~Sha256() { EVP_MD_CTX_free(context_); }
  Sha256(const Sha256&) = delete;
  Sha256& operator=(const Sha256&) = delete;
  void update(const char* data, std::size_t size) {
    if (size > 0 && EVP_DigestUpdate(context_, data, size) != 1) throw std::runtime_error("SHA-256 update failed");
  }
  std::string hex() {
    unsigned char digest[EVP_MAX_MD_SIZE];
    unsigned int length = 0;
    if (EVP_DigestFinal_ex(context_, digest, &length) != 1) throw std::runtime_error("SHA-256 final failed");
    static constexpr char kHex[] = "0123456789abcdef";
    std::string text;
    for (unsigned int i = 0; i < length; ++i) {
      text += kHex[digest[i] >> 4];
      text += kHex[digest[i] & 15];
    }
    return text;
  }

 private:
  EVP_MD_CTX* context_;
};

}  // namespace

ParsedRows parse_rows(std::string_view data, std::size_t first_line, const RowSyntax& syntax, const std::string& file,
                      const RowSink& sink, const RowOptions& options) {
  const std::size_t numbers = parsed_fields(syntax, sink);
  clear_sink(sink);
  const Appended appended = append_rows(data, first_line, 0, syntax, numbers, file, sink, options);
  return {appended.rows, appended.dropped_last_row};
}

StreamedRows parse_file_rows(const std::filesystem::path& path,
                             const std::function<FileLayout(std::string_view)>& layout, const RowOptions& options,
                             bool compute_sha256) {
  const std::string file = path.string();
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError(SourceLocation{file}, "no such file");
  if (std::filesystem::is_directory(path, ec))
    throw InputError(SourceLocation{file}, "is a directory, expected a file");
  Descriptor descriptor{::open(path.c_str(), O_RDONLY | O_CLOEXEC)};
  if (descriptor.fd < 0) throw InputError(SourceLocation{file}, std::string("cannot open: ") + std::strerror(errno));
  struct stat info {};
  const std::uint64_t expected_size =
      ::fstat(descriptor.fd, &info) == 0 && S_ISREG(info.st_mode) ? static_cast<std::uint64_t>(info.st_size) : 0;

  // A file smaller than a block is read in one block of its own size: a
  // 32 MB buffer for a 200 kB force.dat made the kernel zero 32 MB per file
  // (a sweep of 1,000 cases spent most of its time there). One byte more
  // than the size tells the end of the file on the first read.
  std::size_t block_bytes = std::max<std::size_t>(options.block_bytes, 1);
  if (expected_size > 0 && expected_size < block_bytes)
    block_bytes = std::max<std::size_t>(static_cast<std::size_t>(expected_size) + 1, std::size_t{1} << 16);
  std::vector<char> buffer;
  buffer.reserve(block_bytes + std::min<std::size_t>(block_bytes, std::size_t{1} << 20));
  std::optional<Sha256> digest;
  if (compute_sha256) digest.emplace();
  StreamedRows result;

  // The head: the first block, which must hold the header.
  read_some(descriptor.fd, buffer, block_bytes, file);
  bool at_end = buffer.size() < block_bytes;
  const FileLayout rows_layout = layout(std::string_view(buffer.data(), buffer.size()));
  if (rows_layout.data_offset > buffer.size() || (!at_end && rows_layout.data_offset == buffer.size()))
    throw InputError(SourceLocation{file}, "the header runs past the first " + std::to_string(block_bytes) +
                                               " bytes; expected a header followed by rows");
  const std::size_t numbers = parsed_fields(rows_layout.syntax, rows_layout.sink);
  clear_sink(rows_layout.sink);
  if (digest) digest->update(buffer.data(), rows_layout.data_offset);
  std::size_t start = rows_layout.data_offset;  // of the unparsed bytes in the buffer
  std::size_t line = rows_layout.first_line;
  std::size_t rows = 0;
  bool reserved = false;
  result.size_bytes = 0;
  std::uint64_t consumed = rows_layout.data_offset;

  // The next block is read on another thread while this one is parsed
  // (double buffering): reading and parsing no longer take turns.
  std::vector<char> next;
  std::size_t next_got = 0;
  std::exception_ptr read_error;
  std::thread reader;
  struct JoinOnExit {
    std::thread& thread;
    ~JoinOnExit() {
      if (thread.joinable()) thread.join();
    }
  } join_reader{reader};

  for (;;) {
    if (!at_end)
      reader = std::thread([&] {
        try {
          next.clear();
          next_got = read_some(descriptor.fd, next, block_bytes, file);
        } catch (...) {
          read_error = std::current_exception();
        }
      });
    // Whole lines of the buffer, or everything at the end of the file.
    std::size_t stop = buffer.size();
    if (!at_end) {
      const void* last = nullptr;
      for (std::size_t back = buffer.size(); back > start && last == nullptr;) {
        const std::size_t from = back > start + 65536 ? back - 65536 : start;
        last = ::memrchr(buffer.data() + from, '\n', back - from);
        back = from;
      }
      stop = last != nullptr ? static_cast<std::size_t>(static_cast<const char*>(last) - buffer.data()) + 1 : start;
    }
    if (stop > start) {
      const std::string_view block(buffer.data() + start, stop - start);
      std::thread hasher;
      if (digest) hasher = std::thread([&] { digest->update(block.data(), block.size()); });
      Appended appended;
      try {
        appended = append_rows(block, line, rows, rows_layout.syntax, numbers, file, rows_layout.sink, options);
      } catch (...) {
        if (hasher.joinable()) hasher.join();
        throw;
      }
      if (hasher.joinable()) hasher.join();
      rows += appended.rows;
      line += appended.newlines;
      result.rows.dropped_last_row = result.rows.dropped_last_row || appended.dropped_last_row;
      consumed += block.size();
      if (!reserved && !at_end && expected_size > consumed && appended.rows > 0) {
        // Room for the rest at this block's bytes per row, and a little more.
        const double per_row = static_cast<double>(block.size()) / static_cast<double>(appended.rows);
        const auto estimate =
            static_cast<std::size_t>(static_cast<double>(expected_size - consumed) / per_row * 1.02) + 1024;
        reserve_sink(rows_layout.sink, rows + estimate);
        reserved = true;
      }
    }
    if (at_end) break;
    // The partial last line goes in front of the block read meanwhile,
    // unless it is already longer than a line may be.
    if (buffer.size() - stop > options.max_line_bytes)
      throw InputError(SourceLocation{file, line, 0}, "a line of more than " + std::to_string(options.max_line_bytes) +
                                                          " bytes; expected rows of at most " +
                                                          std::to_string(options.max_line_bytes) + " bytes");
    reader.join();
    if (read_error) std::rethrow_exception(read_error);
    next.insert(next.begin(), buffer.begin() + static_cast<std::ptrdiff_t>(stop), buffer.end());
    buffer.swap(next);
    start = 0;
    at_end = next_got < block_bytes;
  }
  result.size_bytes = consumed;
  result.rows.rows = rows;
  if (digest) result.sha256 = digest->hex();
  return result;
}

}  // namespace hydrocoef::history_text
