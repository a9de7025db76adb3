#include "importers/history_text.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <system_error>
#include <thread>

#include "src/core/error.hpp"

namespace hydrocoef::history_text {
namespace {

constexpr std::size_t kNoError = std::numeric_limits<std::size_t>::max();

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

// Where the line starting at `p` ends (its '\n', or `end`).
const char* line_end(const char* p, const char* end) {
  const void* newline = std::memchr(p, '\n', static_cast<std::size_t>(end - p));
  return newline != nullptr ? static_cast<const char*>(newline) : end;
}

// A finite number from [p, end): from_chars plus a leading '+'. Returns the
// end of the number, or nullptr when there is none or it is not finite.
const char* read_number(const char* p, const char* end, double& value) {
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
  std::vector<double> values;
  std::vector<std::uint32_t> local_lines;  // 0-based line index within the chunk
  std::size_t newlines = 0;
  std::size_t error_offset = kNoError;  // start of the first bad line, from `begin`
  bool error_is_last_line = false;      // the bad line has no line end after it
};

void parse_chunk(Chunk& chunk, const RowSyntax& syntax, std::size_t numbers, bool require_line_end) {
  const char* p = chunk.begin;
  const char* const end = chunk.end;
  std::size_t line = 0;
  const bool delimited = syntax.delimiter != 0;
  // A rough reservation: rows are at least a few bytes per number.
  chunk.values.reserve(static_cast<std::size_t>(end - p) / 8);
  std::vector<double> row(numbers);
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
    const char* next = delimited ? parse_delimited_row(q, end, syntax, require_line_end, row.data())
                                 : parse_whitespace_row(q, end, syntax, require_line_end, row.data());
    if (next == nullptr) {
      chunk.error_offset = static_cast<std::size_t>(p - chunk.begin);
      chunk.error_is_last_line = line_end(q, end) == end;
      chunk.newlines = line;
      return;
    }
    chunk.values.insert(chunk.values.end(), row.begin(), row.end());
    chunk.local_lines.push_back(static_cast<std::uint32_t>(line));
    ++line;
    p = next;
  }
  chunk.newlines = static_cast<std::size_t>(std::count(chunk.begin, chunk.end, '\n'));
}

std::string column_label(const RowSyntax& syntax, std::size_t column) {
  std::string label = "column " + std::to_string(column + 1);
  if (column < syntax.names.size() && !syntax.names[column].empty()) label += " " + quoted(syntax.names[column]);
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
      throw InputError(at(p), "found " + std::to_string(found) + " fields, expected " + std::to_string(syntax.columns) +
                                  cut_note);
    }
    if (!syntax.skip.empty() && syntax.skip[column]) {
      const char* q = syntax.delimiter != 0 ? skip_field(p, end, syntax.delimiter) : p + token_at(p).size();
      if (q == nullptr) throw InputError(at(p), column_label(syntax, column) + ": a quoted field is not closed" + cut_note);
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
          throw InputError(at(p), column_label(syntax, column) + ": found " + quoted(token) +
                                      ", expected a finite number" + cut_note);
        throw InputError(at(p), column_label(syntax, column) + ": found " +
                                    (token.empty() ? std::string("an empty field") : quoted(token)) +
                                    ", expected a number" + cut_note);
      }
      if (quote) {
        if (stop == end || *stop != '"')
          throw InputError(at(p), column_label(syntax, column) + ": found " + quoted(token) +
                                      ", expected a number in closed quotes" + cut_note);
        ++stop;
      }
      const bool separated = stop == end || is_blank(*stop) || *stop == '\n' ||
                             (syntax.delimiter != 0 ? *stop == syntax.delimiter : parens && (*stop == '(' || *stop == ')'));
      if (!separated)
        throw InputError(at(p), column_label(syntax, column) + ": found " + quoted(token) + ", expected a number" +
                                    cut_note);
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
          throw InputError(at(p), column_label(syntax, column) + ": found " + quoted(token_at(p)) +
                                      " after the number, expected " +
                                      (syntax.delimiter == '\t' ? std::string("a tab") : "'" + std::string(1, syntax.delimiter) + "'"));
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
  throw InputError(SourceLocation{file, line, 0}, "cannot read this row; expected " + std::to_string(syntax.columns) +
                                                      " numbers");
}

}  // namespace

std::string quoted(std::string_view text) {
  return "'" + printable_text(text, 40) + "'";
}

ParsedRows parse_rows(std::string_view data, std::size_t first_line, const RowSyntax& syntax, const std::string& file,
                      const RowOptions& options) {
  if (syntax.columns == 0) throw std::invalid_argument("history rows need at least one column");
  if (!syntax.skip.empty() && syntax.skip.size() != syntax.columns)
    throw std::invalid_argument("history rows: skip mask of the wrong size");
  std::size_t numbers = syntax.columns;
  if (!syntax.skip.empty()) numbers = static_cast<std::size_t>(std::count(syntax.skip.begin(), syntax.skip.end(), false));

  // Chunks of at least 4 MB, split after a line end, one per core.
  const unsigned cores = options.threads != 0 ? options.threads : std::max(1u, std::thread::hardware_concurrency());
  const std::size_t by_size = std::max<std::size_t>(1, data.size() / (std::size_t{4} << 20));
  const std::size_t count = std::min<std::size_t>(cores, by_size);
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
  const bool require_line_end = syntax.require_line_end;
  if (count == 1) {
    parse_chunk(chunks[0], syntax, numbers, require_line_end);
  } else {
    std::vector<std::thread> helpers;
    helpers.reserve(count - 1);
    for (std::size_t c = 1; c < count; ++c)
      helpers.emplace_back([&, c] { parse_chunk(chunks[c], syntax, numbers, require_line_end); });
    parse_chunk(chunks[0], syntax, numbers, require_line_end);
    for (auto& helper : helpers) helper.join();
  }

  ParsedRows rows;
  rows.columns = numbers;
  std::size_t line = first_line;
  std::size_t total = 0;
  for (std::size_t c = 0; c < count; ++c) {
    Chunk& chunk = chunks[c];
    if (chunk.error_offset != kNoError) {
      const char* const row = chunk.begin + chunk.error_offset;
      const std::size_t row_line = line + chunk.newlines;
      const std::string_view text(row, static_cast<std::size_t>(line_end(row, end) - row));
      if (chunk.error_is_last_line && options.drop_incomplete_last_row) {
        rows.dropped_last_row = true;
        // Keep what came before; later chunks are empty (this was the last line).
      } else {
        diagnose_row(text, row_line, syntax, file, chunk.error_is_last_line);
      }
    }
    total += chunk.local_lines.size();
    line += chunk.newlines;
    if (chunk.error_offset != kNoError) break;
  }
  if (line > std::numeric_limits<std::uint32_t>::max())
    throw InputError(SourceLocation{file}, "more than 4294967295 lines; expected a smaller file");

  rows.values.reserve(total * numbers);
  rows.lines.reserve(total);
  line = first_line;
  for (std::size_t c = 0; c < count; ++c) {
    const Chunk& chunk = chunks[c];
    rows.values.insert(rows.values.end(), chunk.values.begin(), chunk.values.end());
    for (const std::uint32_t local : chunk.local_lines) rows.lines.push_back(static_cast<std::uint32_t>(line + local));
    line += chunk.newlines;
    if (chunk.error_offset != kNoError) break;
  }
  return rows;
}

}  // namespace hydrocoef::history_text
