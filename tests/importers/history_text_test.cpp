// The row reader under both history importers (importers/history_text): its
// number parser gives from_chars' double bit for bit; rows split over chunks
// and threads, with comment lines between them, land in order with their
// lines; skipped and quoted fields; files streamed in small blocks give the
// same rows, lines and SHA-256 as the whole text, and errors in later blocks
// name the right line.
#include "importers/history_text.hpp"

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "src/core/error.hpp"
#include "src/core/source_file.hpp"
#include "tests/support/expect_input_error.hpp"
#include "tests/support/file_bytes.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef::history_text {
namespace {

TEST(HistoryText, NumbersAreReadAsFromCharsReadsThem) {
  std::mt19937_64 random(42);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const char* formats[] = {"%.10e", "%.17g", "%.6g", "%.3f", "%.0f", "%.19e", "%.1e", "%g", "%.15E", "%.12f"};
  std::size_t checked = 0;
  for (int i = 0; i < 200000; ++i) {
    const double magnitude = std::pow(10.0, static_cast<double>(static_cast<int>(random() % 60) - 30));
    const double value = unit(random) * magnitude;
    char text[64];
    std::snprintf(text, sizeof text, formats[i % 10], value);
    double expected = 0.0, got = 0.0;
    const auto [end, ec] = std::from_chars(text, text + std::strlen(text), expected);
    ASSERT_EQ(ec, std::errc{}) << text;
    const char* stop = read_finite_number(text, text + std::strlen(text), got);
    ASSERT_EQ(stop, end) << text;
    ASSERT_EQ(std::memcmp(&got, &expected, sizeof got), 0) << text << ": " << got << " vs " << expected;
    ++checked;
  }
  for (const char* text : {"0",
                           "-0",
                           "0.0",
                           "1.",
                           ".5",
                           "-.5",
                           "00012.5000",
                           "123456789012345678901234",
                           "9007199254740993",
                           "1e22",
                           "1e23",
                           "1.7976931348623157e308",
                           "4.9e-324",
                           "1e-400",
                           "12345678901234567890e-10",
                           "0.000000000000000000000001",
                           "1e+5",
                           "1E5",
                           "+3.5",
                           "1e"}) {
    double got = 0.0, expected = 0.0;
    const char* end = text + std::strlen(text);
    const char* stop = read_finite_number(text, end, got);
    const char* from = *text == '+' ? text + 1 : text;
    const auto [expected_end, ec] = std::from_chars(from, end, expected);
    ASSERT_NE(stop, nullptr) << text;
    EXPECT_EQ(stop, expected_end) << text;
    if (ec == std::errc{}) {
      EXPECT_EQ(std::memcmp(&got, &expected, sizeof got), 0) << text;
    }
  }
  double v = 0.0;
  for (const char* text : {"nan", "inf", "-inf", "1e999", "abc", "-", ".", ""})
    EXPECT_EQ(read_finite_number(text, text + std::strlen(text), v), nullptr) << text;
  EXPECT_EQ(checked, 200000u);
}

std::string numbered_rows(std::size_t rows, bool comments) {
  std::string text;
  char line[128];
  for (std::size_t i = 0; i < rows; ++i) {
    if (comments && i % 1000 == 0) text += "# a comment between rows\n\n";
    std::snprintf(line, sizeof line, "%zu (%.10e %.10e)\n", i, 0.5 * double(i), -double(i));
    text += line;
  }
  return text;
}

TEST(HistoryText, ChunksOnThreadsKeepTheOrderAndTheLines) {
  const std::string text = numbered_rows(400000, true);  // about 15 MB, comments every 1000 rows
  RowSyntax syntax;
  syntax.columns = 3;
  syntax.parentheses = true;
  for (const unsigned threads : {1u, 2u, 4u}) {
    std::vector<double> t, a, b;
    std::vector<std::uint32_t> lines;
    RowSink sink{{&t, &a, nullptr}, &lines};
    RowOptions options;
    options.threads = threads;
    const ParsedRows rows = parse_rows(text, 10, syntax, "x.dat", sink, options);
    ASSERT_EQ(rows.rows, 400000u);
    ASSERT_EQ(t.size(), 400000u);
    EXPECT_TRUE(b.empty());
    for (std::size_t i = 0; i < t.size(); i += 997) {
      ASSERT_EQ(t[i], double(i));
      ASSERT_EQ(a[i], 0.5 * double(i));
      // Two comment/blank lines before every thousandth row.
      ASSERT_EQ(lines[i], 10 + i + 2 * (i / 1000 + 1));
    }
  }
}

TEST(HistoryText, DelimitedSkippedAndQuotedFields) {
  RowSyntax syntax;
  syntax.columns = 4;
  syntax.delimiter = ',';
  syntax.skip = {false, true, false, false};
  syntax.names = {"t", "note", "x", "y"};
  std::vector<double> t, x, y;
  std::vector<std::uint32_t> lines;
  const RowSink sink{{&t, &x, &y}, &lines};
  const std::string text = "1, \"a, b\", 2, \"3\"\n2,,+4,5,\n3, note , 6 ,7";
  const ParsedRows rows = parse_rows(text, 1, syntax, "t.csv", sink);
  EXPECT_EQ(rows.rows, 3u);
  EXPECT_EQ(x, (std::vector<double>{2, 4, 6}));
  EXPECT_EQ(y, (std::vector<double>{3, 5, 7}));
  EXPECT_EQ(lines, (std::vector<std::uint32_t>{1, 2, 3}));
  test::expect_input_error([&] { parse_rows("1, \"open, 2, 3\n", 1, syntax, "t.csv", sink); },
                           {"t.csv:1:4", "column 2 'note'", "quoted field is not closed"});
  test::expect_input_error([&] { parse_rows("1, a, 2 3, 3\n", 1, syntax, "t.csv", sink); },
                           {"t.csv:1:9", "column 3 'x'", "found '3' after the number", "expected ','"});
  test::expect_input_error([&] { parse_rows("1, a, \"2, 3\n", 1, syntax, "t.csv", sink); },
                           {"t.csv:1:7", "column 3 'x'", "closed quotes"});
}

// A file streamed in blocks far smaller than its rows' total: the same as the
// whole text, whatever the block size.
TEST(HistoryText, StreamedFilesGiveTheSameRowsLinesAndDigest) {
  const std::string header = "# Time a b\n";
  const std::string text = header + numbered_rows(5000, true);
  test::TempDir dir;
  test::write_bytes(dir / "s.dat", text);
  RowSyntax syntax;
  syntax.columns = 3;
  syntax.parentheses = true;
  syntax.require_line_end = true;

  std::vector<double> t0, a0;
  std::vector<std::uint32_t> lines0;
  parse_rows(std::string_view(text).substr(header.size()), 2, syntax, "s.dat", RowSink{{&t0, &a0, nullptr}, &lines0});

  for (const std::size_t block : {std::size_t{64}, std::size_t{1000}, std::size_t{65536}, std::size_t{32} << 20}) {
    SCOPED_TRACE(block);
    std::vector<double> t, a;
    std::vector<std::uint32_t> lines;
    RowOptions options;
    options.block_bytes = block;
    std::string head_seen;
    const StreamedRows streamed = parse_file_rows(
        dir / "s.dat",
        [&](std::string_view head) {
          head_seen = std::string(head.substr(0, 6));
          FileLayout layout;
          layout.data_offset = header.size();
          layout.first_line = 2;
          layout.syntax = syntax;
          layout.sink = RowSink{{&t, &a, nullptr}, &lines};
          return layout;
        },
        options, true);
    EXPECT_EQ(head_seen, "# Time");
    EXPECT_EQ(streamed.rows.rows, 5000u);
    EXPECT_EQ(streamed.size_bytes, text.size());
    EXPECT_EQ(streamed.sha256, sha256_hex(text));
    EXPECT_EQ(t, t0);
    EXPECT_EQ(a, a0);
    EXPECT_EQ(lines, lines0);
  }

  // An error in a late block names its line; a cut last row is refused or dropped.
  std::string bad = text;
  bad.replace(bad.find("\n4321 (") + 7, 3, "x.y");
  std::string cut = text.substr(0, text.size() - 5);
  test::write_bytes(dir / "bad.dat", bad);
  test::write_bytes(dir / "cut.dat", cut);
  const auto layout_of = [&](std::vector<double>& t) {
    return [&, header](std::string_view) {
      FileLayout layout;
      layout.data_offset = header.size();
      layout.first_line = 2;
      layout.syntax = syntax;
      layout.sink = RowSink{{&t, nullptr, nullptr}, nullptr};
      return layout;
    };
  };
  RowOptions small;
  small.block_bytes = 1000;
  std::vector<double> t;
  const std::size_t bad_line = 2 + 4321 + 2 * 5;  // comment and blank lines before rows 0, 1000, ..., 4000
  test::expect_input_error([&] { parse_file_rows(dir / "bad.dat", layout_of(t), small); },
                           {"bad.dat:" + std::to_string(bad_line) + ":", "found 'x.y"});
  test::expect_input_error([&] { parse_file_rows(dir / "cut.dat", layout_of(t), small); },
                           {"cut.dat:", "stopped while writing"});
  small.drop_incomplete_last_row = true;
  const StreamedRows dropped = parse_file_rows(dir / "cut.dat", layout_of(t), small);
  EXPECT_TRUE(dropped.rows.dropped_last_row);
  EXPECT_EQ(dropped.rows.rows, 4999u);
  EXPECT_TRUE(dropped.sha256.empty());

  test::expect_input_error([&] { parse_file_rows(dir / "none.dat", layout_of(t), small); },
                           {"none.dat", "no such file"});
  test::expect_input_error([&] { parse_file_rows(dir.path(), layout_of(t), small); }, {"is a directory"});
  RowOptions tiny;
  tiny.block_bytes = 5;  // smaller than the header
  test::expect_input_error([&] { parse_file_rows(dir / "s.dat", layout_of(t), tiny); },
                           {"s.dat", "header runs past the first 5 bytes"});
}

TEST(HistoryText, ALineIsBoundedWhileItIsRead) {
  // A file of one endless line cost the line twice over (carried and
  // re-read at every block) before anything refused it; now a line still
  // without its end past max_line_bytes is refused as soon as it is seen.
  EXPECT_EQ(kMaxLineBytes, std::size_t{1} << 20);
  EXPECT_EQ(RowOptions{}.max_line_bytes, kMaxLineBytes);
  const std::string header = "# Time a\n";
  const std::string rows = "0 1\n1 2\n2 3\n";
  test::TempDir dir;
  RowSyntax syntax;
  syntax.columns = 2;
  std::vector<double> t, a;
  const auto layout = [&](std::string_view) {
    FileLayout out;
    out.data_offset = header.size();
    out.first_line = 2;
    out.syntax = syntax;
    out.sink = RowSink{{&t, &a}, nullptr};
    return out;
  };
  // The default bound, with blocks of 64 kB: a line of 1.2 MB of digits.
  test::write_bytes(dir / "long.dat", header + rows + std::string(1200000, '7') + " 1\n");
  RowOptions options;
  options.block_bytes = 65536;
  test::expect_input_error(
      [&] { parse_file_rows(dir / "long.dat", layout, options); },
      {"long.dat:5:", "a line of more than 1048576 bytes; expected rows of at most 1048576 bytes"});
  // A smaller bound, and a long line that ends within it is read.
  options.block_bytes = 1000;
  options.max_line_bytes = 2000;
  test::write_bytes(dir / "field.dat", header + rows + std::string(5000, '1') + " 1\n");
  test::expect_input_error([&] { parse_file_rows(dir / "field.dat", layout, options); },
                           {"field.dat:5:", "a line of more than 2000 bytes"});
  test::write_bytes(dir / "fits.dat", header + rows + std::string(1500, '0') + "3 4\n");  // 3, written long
  const StreamedRows fits = parse_file_rows(dir / "fits.dat", layout, options);
  EXPECT_EQ(fits.rows.rows, 4u);
  EXPECT_EQ(a.back(), 4.0);
}

}  // namespace
}  // namespace hydrocoef::history_text
