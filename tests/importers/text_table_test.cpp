// Delimited-text helpers: line splitting (LF, CRLF, missing final newline,
// numbering kept across empty lines), field splitting with quotes and 1-based
// columns, delimiter detection, and strict finite-number parsing with errors
// that point at file:line:column and name the column.
#include "importers/text_table.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "src/core/error.hpp"

namespace hydrocoef {
namespace {

std::vector<std::string> texts(const std::vector<TextLine>& lines) {
  std::vector<std::string> out;
  for (const auto& line : lines) out.emplace_back(line.text);
  return out;
}

std::vector<std::size_t> numbers(const std::vector<TextLine>& lines) {
  std::vector<std::size_t> out;
  for (const auto& line : lines) out.push_back(line.number);
  return out;
}

using Strings = std::vector<std::string>;
using Sizes = std::vector<std::size_t>;

TEST(SplitLines, Lf) {
  const auto lines = split_lines("a,b\n1,2\n");
  EXPECT_EQ(texts(lines), (Strings{"a,b", "1,2"}));
  EXPECT_EQ(numbers(lines), (Sizes{1, 2}));
}

TEST(SplitLines, Crlf) {
  const auto lines = split_lines("a,b\r\n1,2\r\n");
  EXPECT_EQ(texts(lines), (Strings{"a,b", "1,2"}));
  EXPECT_EQ(numbers(lines), (Sizes{1, 2}));
}

TEST(SplitLines, NoFinalNewline) {
  EXPECT_EQ(texts(split_lines("a\nb")), (Strings{"a", "b"}));
  EXPECT_EQ(texts(split_lines("a\r\nb")), (Strings{"a", "b"}));
  EXPECT_EQ(texts(split_lines("only")), (Strings{"only"}));
}

TEST(SplitLines, EmptyLinesKeepNumbering) {
  const auto lines = split_lines("\nh\n\n\r\nx\n");
  EXPECT_EQ(texts(lines), (Strings{"", "h", "", "", "x"}));
  EXPECT_EQ(numbers(lines), (Sizes{1, 2, 3, 4, 5}));
}

TEST(SplitLines, EmptyBufferHasNoLines) { EXPECT_TRUE(split_lines("").empty()); }

TEST(SplitLines, OnlyTheFinalCarriageReturnIsStripped) {
  // A lone CR inside a line is content, not a line break.
  EXPECT_EQ(texts(split_lines("a\rb\r\n")), (Strings{"a\rb"}));
}

TextLine line_of(std::string_view text, std::size_t number = 1) { return TextLine{text, number}; }

TEST(SplitFields, PlainFieldsAndColumns) {
  const auto fields = split_fields(line_of("u,X,N"), ',', "t.csv");
  ASSERT_EQ(fields.size(), 3u);
  EXPECT_EQ(fields[0].text, "u");
  EXPECT_EQ(fields[1].text, "X");
  EXPECT_EQ(fields[2].text, "N");
  EXPECT_EQ(fields[0].column, 1u);
  EXPECT_EQ(fields[1].column, 3u);
  EXPECT_EQ(fields[2].column, 5u);
}

TEST(SplitFields, BlanksAreTrimmedAndColumnsPointAtTheText) {
  // CFX writes ", " between fields.
  const auto fields = split_fields(line_of("X [ m ], Y [ m ],  1.5  "), ',', "t.csv");
  ASSERT_EQ(fields.size(), 3u);
  EXPECT_EQ(fields[0].text, "X [ m ]");
  EXPECT_EQ(fields[1].text, "Y [ m ]");
  EXPECT_EQ(fields[2].text, "1.5");
  EXPECT_EQ(fields[0].column, 1u);
  EXPECT_EQ(fields[1].column, 10u);  // "X [ m ], " is 9 characters
  EXPECT_EQ(fields[2].column, 20u);  // "X [ m ], Y [ m ],  " is 19 characters
}

TEST(SplitFields, QuotedFieldHoldsTheDelimiter) {
  const auto fields = split_fields(line_of("a,\"b,c\",d"), ',', "t.csv");
  ASSERT_EQ(fields.size(), 3u);
  EXPECT_EQ(fields[0].text, "a");
  EXPECT_EQ(fields[1].text, "b,c");
  EXPECT_EQ(fields[2].text, "d");
  EXPECT_EQ(fields[1].column, 3u);  // the opening quote
  EXPECT_EQ(fields[2].column, 9u);
}

TEST(SplitFields, DoubledQuotes) {
  // The cfx5mondata point-monitor style.
  const auto fields =
      split_fields(line_of(R"("USER POINT,T1,D1,""x= 4.65E-02,y= 4.16E-01"",Temperature",2)"), ',', "m.csv");
  ASSERT_EQ(fields.size(), 2u);
  EXPECT_EQ(fields[0].text, R"(USER POINT,T1,D1,"x= 4.65E-02,y= 4.16E-01",Temperature)");
  EXPECT_EQ(fields[1].text, "2");
  const auto only_quote = split_fields(line_of(R"("""")"), ',', "m.csv");
  ASSERT_EQ(only_quote.size(), 1u);
  EXPECT_EQ(only_quote[0].text, "\"");
}

TEST(SplitFields, BlanksAroundAQuotedField) {
  const auto fields = split_fields(line_of(R"(1,  "a" ,3)"), ',', "t.csv");
  ASSERT_EQ(fields.size(), 3u);
  EXPECT_EQ(fields[1].text, "a");
  EXPECT_EQ(fields[1].column, 5u);
  EXPECT_EQ(fields[2].text, "3");
}

TEST(SplitFields, EmptyFields) {
  const auto fields = split_fields(line_of("a,,c,"), ',', "t.csv");
  ASSERT_EQ(fields.size(), 4u);
  EXPECT_EQ(fields[1].text, "");
  EXPECT_EQ(fields[1].column, 3u);
  EXPECT_EQ(fields[3].text, "");
  EXPECT_EQ(fields[2].column, 4u);
  EXPECT_EQ(fields[3].column, 6u);  // just past the trailing delimiter at column 5
  const auto empty_line = split_fields(line_of(""), ',', "t.csv");
  ASSERT_EQ(empty_line.size(), 1u);
  EXPECT_EQ(empty_line[0].text, "");
}

TEST(SplitFields, TabAndSemicolon) {
  const auto tabs = split_fields(line_of("u [m s^-1]\tX [N]\t\t"), '\t', "t.tsv");
  ASSERT_EQ(tabs.size(), 4u);
  EXPECT_EQ(tabs[0].text, "u [m s^-1]");
  EXPECT_EQ(tabs[1].text, "X [N]");
  EXPECT_EQ(tabs[1].column, 12u);
  EXPECT_EQ(tabs[2].text, "");
  const auto semis = split_fields(line_of("0,1; 2,5 ;3"), ';', "t.csv");
  ASSERT_EQ(semis.size(), 3u);
  EXPECT_EQ(semis[0].text, "0,1");
  EXPECT_EQ(semis[1].text, "2,5");
  EXPECT_EQ(semis[1].column, 6u);
  EXPECT_EQ(semis[2].text, "3");
}

TEST(SplitFields, UnterminatedQuoteIsAnErrorAtLineAndColumn) {
  try {
    (void)split_fields(line_of("1.0,\"abc,2", 7), ',', "table.csv");
    FAIL() << "an unterminated quote was accepted";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_EQ(message.rfind("table.csv:7:5: ", 0), 0u) << message;
    EXPECT_NE(message.find("unterminated"), std::string::npos) << message;
    EXPECT_EQ(error.where().line, 7u);
    EXPECT_EQ(error.where().column, 5u);
  }
}

TEST(SplitFields, TextAfterAClosingQuoteIsAnError) {
  try {
    (void)split_fields(line_of("\"a\"b,c", 3), ',', "t.csv");
    FAIL() << "text after a closing quote was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()).rfind("t.csv:3:4: ", 0), 0u) << error.what();
  }
}

TEST(SplitFields, AFieldIsBoundedBeforeItIsCopied) {
  // A line of one 2 GB field cost three times its size before it was
  // refused; the bound, as the count of fields, refuses it at its column.
  EXPECT_EQ(kMaxTextFieldBytes, 65536u);
  const std::string long_field(65537, '1');
  const std::string line_text = "1," + long_field + ",3";
  try {
    (void)split_fields(TextLine{line_text, 7}, ',', "t.csv");
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "t.csv:7:3: a field of more than 65536 bytes; expected at most 65536 bytes per field");
  }
  EXPECT_EQ(split_fields(TextLine{"1," + std::string(65536, '2') + ",3", 7}, ',', "t.csv")[1].text.size(), 65536u);
  // A smaller bound, quoted fields (doubled quotes counted as one byte) and blanks around.
  const std::string quoted = R"(a,"1234""6789",  0123456789  )";
  const auto fields = split_fields(TextLine{quoted, 2}, ',', "t.csv", kMaxTextFields, 10);
  EXPECT_EQ(fields[1].text, "1234\"6789");
  EXPECT_EQ(fields[2].text, "0123456789");
  for (const std::string text : {R"(a,"1234""678901")", "a,01234567890", "\"12345678901\""}) {
    try {
      (void)split_fields(TextLine{text, 2}, ',', "t.csv", kMaxTextFields, 10);
      ADD_FAILURE() << "accepted " << text;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("t.csv:2:"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("a field of more than 10 bytes"), std::string::npos) << e.what();
    }
  }
}

TEST(DetectDelimiter, PrefersCommaThenTabThenSemicolon) {
  EXPECT_EQ(detect_delimiter("u [m s^-1],X [N]"), ',');
  EXPECT_EQ(detect_delimiter("u [m s^-1]\tX [N]"), '\t');
  EXPECT_EQ(detect_delimiter("u [m s^-1];X [N]"), ';');
  EXPECT_EQ(detect_delimiter("a\tb,c;d"), ',');
  EXPECT_EQ(detect_delimiter("a;b\tc"), '\t');
  EXPECT_EQ(detect_delimiter("u [m s^-1]"), ',');  // a single column
  EXPECT_EQ(detect_delimiter(""), ',');
}

TextField field_of(const std::string& text, std::size_t column = 1) { return TextField{text, column}; }

TEST(ParseNumber, Values) {
  EXPECT_DOUBLE_EQ(parse_number(field_of("2.02633496e+03"), "f", 1, "c"), 2026.33496);
  EXPECT_DOUBLE_EQ(parse_number(field_of("+1.5"), "f", 1, "c"), 1.5);
  EXPECT_DOUBLE_EQ(parse_number(field_of("-5.05357236e-02"), "f", 1, "c"), -0.0505357236);
  EXPECT_DOUBLE_EQ(parse_number(field_of("0.00000000e+00"), "f", 1, "c"), 0.0);
  EXPECT_DOUBLE_EQ(parse_number(field_of("42"), "f", 1, "c"), 42.0);
  EXPECT_DOUBLE_EQ(parse_number(field_of("1E3"), "f", 1, "c"), 1000.0);
  EXPECT_EQ(parse_number(field_of("0.1"), "f", 1, "c"), 0.1);  // correctly rounded
}

TEST(ParseNumber, NegativeZeroKeepsItsSign) {
  const double value = parse_number(field_of("-0"), "f", 1, "c");
  EXPECT_EQ(value, 0.0);
  EXPECT_TRUE(std::signbit(value));
}

// The message of the InputError for parsing `text` at t.csv:12:9 in column 'X [N]'.
std::string number_error(const std::string& text) {
  try {
    const double value = parse_number(field_of(text, 9), "t.csv", 12, "X [N]");
    ADD_FAILURE() << "'" << text << "' was accepted as " << value;
  } catch (const InputError& error) {
    EXPECT_EQ(error.where().file, "t.csv");
    EXPECT_EQ(error.where().line, 12u);
    EXPECT_EQ(error.where().column, 9u);
    return error.what();
  }
  return {};
}

TEST(ParseNumber, ErrorsNameLocationColumnAndText) {
  for (const std::string text :
       {"abc", "1.5x", "nan", "NaN", "inf", "-inf", "Infinity", "1e999", "null", "1,5", "0x10", "1.5 2", "--1", "+"}) {
    const std::string message = number_error(text);
    EXPECT_EQ(message.rfind("t.csv:12:9: ", 0), 0u) << text << ": " << message;
    EXPECT_NE(message.find("'X [N]'"), std::string::npos) << text << ": " << message;
    EXPECT_NE(message.find("'" + text + "'"), std::string::npos) << text << ": " << message;
  }
}

TEST(ParseNumber, ErrorsSayWhatWasExpected) {
  EXPECT_NE(number_error("abc").find("expected a number"), std::string::npos);
  EXPECT_NE(number_error("nan").find("expected a finite number"), std::string::npos);
  EXPECT_NE(number_error("inf").find("expected a finite number"), std::string::npos);
  EXPECT_NE(number_error("1e999").find("expected a finite number"), std::string::npos);
}

TEST(ParseNumber, EmptyField) {
  const std::string message = number_error("");
  EXPECT_EQ(message.rfind("t.csv:12:9: ", 0), 0u) << message;
  EXPECT_NE(message.find("'X [N]'"), std::string::npos) << message;
  EXPECT_NE(message.find("empty"), std::string::npos) << message;
}

TEST(ParseNumber, DoubleSignIsRefused) {
  // Regression test: this input once slipped through (see the commit that fixed it).
  const std::string message = number_error("+-1.5");
  EXPECT_NE(message.find("'+-1.5'"), std::string::npos) << message;
}

}  // namespace
}  // namespace hydrocoef

namespace hydrocoef {
namespace {

TEST(SplitLines, DropsAUtf8ByteOrderMark) {
  const auto lines = split_lines("\xEF\xBB\xBFu [m s^-1],X [N]\n0.1,1\n");
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0].text, "u [m s^-1],X [N]");
}

TEST(DetectDelimiter, IgnoresDelimitersInsideQuotes) {
  EXPECT_EQ(detect_delimiter("\"u [m s^-1]\";\"X, total [N]\""), ';');
  EXPECT_EQ(detect_delimiter("\"a;b\",c"), ',');
}

TEST(ParseNumber, UnderflowIsZeroOverflowIsAnError) {
  const TextField tiny{"1e-400", 3};
  EXPECT_EQ(parse_number(tiny, "t.csv", 2, "X [N]"), 0.0);
  const TextField huge{"-1e400", 3};
  EXPECT_THROW(parse_number(huge, "t.csv", 2, "X [N]"), InputError);
}

}  // namespace
}  // namespace hydrocoef
