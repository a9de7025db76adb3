// The per-language escapes (src/core/escape.hpp) on every name of the
// hostile corpus: each output keeps the properties its language needs (one
// line, no early end of a comment or string, only characters the format can
// hold), and text without special characters passes unchanged. The escapes
// are also run through the real consumers in tests/export/hostile_exports_test.cpp
// and tests/plot/hostile_titles_test.cpp.
#include "src/core/escape.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "src/core/utf8.hpp"
#include "tests/support/csv_record.hpp"
#include "tests/support/hostile_names.hpp"

namespace hydrocoef {
namespace {

// True when `text` is valid UTF-8 without control or formatting characters.
bool clean_line(const std::string& text) {
  for (std::size_t i = 0; i < text.size();) {
    const auto decoded = decode_utf8(text, i);
    if (!decoded || is_format_or_control(decoded->value)) return false;
    i += decoded->length;
  }
  return true;
}

TEST(Escape, CorpusHasEveryKindOfHostileName) {
  const auto names = test::hostile_names();
  EXPECT_GE(names.size(), 40u);
  auto has = [&](std::string_view piece) {
    for (const auto& name : names)
      if (name.find(piece) != std::string::npos) return true;
    return false;
  };
  const std::vector<std::string_view> pieces = {
      "`", "$(", "\n",           "\r",  std::string_view("\0", 1), "\x01", "*/", "/*", "]]>", "<script>", "'", "\"",
      "%", ";",  "\xE2\x80\xAE", "\xff"};
  for (const std::string_view piece : pieces)
    EXPECT_TRUE(has(piece)) << "no name holds " << testing::PrintToString(std::string(piece));
}

TEST(Escape, OneLineIsCleanAndKeepsPlainText) {
  for (const auto& name : test::hostile_names()) {
    const std::string out = escape::one_line(name);
    EXPECT_TRUE(clean_line(out)) << testing::PrintToString(name);
  }
  EXPECT_EQ(escape::one_line("caf\xC3\xA9 u|u| [m/s]"), "caf\xC3\xA9 u|u| [m/s]");
  EXPECT_EQ(escape::one_line("a\nb"),
            "a\xEF\xBF\xBD"
            "b");
  EXPECT_EQ(escape::one_line("a\xff"), "a\xEF\xBF\xBD");
}

TEST(Escape, GnuplotStringsCannotEndEarlyOrExpand) {
  for (const auto& name : test::hostile_names()) {
    const std::string out = escape::gnuplot_string(name);
    ASSERT_GE(out.size(), 2u);
    EXPECT_EQ(out.front(), '\'');
    EXPECT_EQ(out.back(), '\'');
    // Single-quoted pieces joined by ."'". : outside the pieces there is
    // nothing but those joins.
    std::string outside;
    bool in_piece = false;
    for (std::size_t i = 0; i < out.size(); ++i) {
      // In a piece, a quote always ends it (quotes in the text are never raw);
      // outside, a quote is either the "'" of a join or opens a piece.
      const bool joined_quote = !in_piece && i > 0 && out[i - 1] == '"' && i + 1 < out.size() && out[i + 1] == '"';
      if (out[i] == '\'' && !joined_quote) {
        in_piece = !in_piece;
        continue;
      }
      if (!in_piece) outside += out[i];
    }
    EXPECT_FALSE(in_piece) << out;
    for (std::size_t at = outside.find(".\"'\"."); at != std::string::npos; at = outside.find(".\"'\"."))
      outside.erase(at, 5);
    EXPECT_TRUE(outside.empty()) << out << " leaves " << outside;
    EXPECT_TRUE(clean_line(out)) << out;
    EXPECT_EQ(out.find("]]>"), std::string::npos) << out;
    const std::string comment = escape::gnuplot_comment(name);
    EXPECT_TRUE(clean_line(comment));
    EXPECT_TRUE(comment.empty() || comment.back() != '\\') << comment;
  }
  EXPECT_EQ(escape::gnuplot_string("it's"), "'it'.\"'\".'s'");
}

TEST(Escape, MatlabTextStaysOnItsLine) {
  for (const auto& name : test::hostile_names()) {
    EXPECT_TRUE(clean_line(escape::matlab_comment(name)));
    const std::string literal = escape::matlab_string(name);
    EXPECT_TRUE(clean_line(literal));
    const std::string inside = literal.substr(1, literal.size() - 2);
    for (std::size_t i = 0; i < inside.size(); ++i)
      if (inside[i] == '\'') {
        ASSERT_EQ(inside[++i], '\'') << literal;
      }
  }
  EXPECT_EQ(escape::matlab_string("a'b"), "'a''b'");
}

TEST(Escape, CCommentsArePrintableAsciiThatCannotCloseOrOpenAComment) {
  for (const auto& name : test::hostile_names()) {
    const std::string out = escape::c_comment(name);
    for (const char c : out) EXPECT_TRUE(c >= 0x20 && c < 0x7F) << testing::PrintToString(out);
    EXPECT_EQ(out.find("*/"), std::string::npos) << out;
    EXPECT_EQ(out.find("/*"), std::string::npos) << out;
    EXPECT_EQ(out.find("??"), std::string::npos) << out;
    EXPECT_TRUE(out.empty() || out.back() != '\\') << out;
  }
  EXPECT_EQ(escape::c_comment("u|u| [m/s]"), "u|u| [m/s]");
}

TEST(Escape, CStringsAreOneLiteralOfTheSameBytes) {
  for (const auto& name : test::hostile_names()) {
    const std::string out = escape::c_string(name);
    ASSERT_GE(out.size(), 2u);
    EXPECT_EQ(out.front(), '"');
    EXPECT_EQ(out.back(), '"');
    // Decode the octal escapes back: the same bytes.
    std::string decoded;
    for (std::size_t i = 1; i + 1 < out.size(); ++i) {
      ASSERT_NE(out[i], '"');
      if (out[i] == '\\') {
        decoded += static_cast<char>(std::stoi(out.substr(i + 1, 3), nullptr, 8));
        i += 3;
      } else {
        decoded += out[i];
      }
    }
    EXPECT_EQ(decoded, name);
  }
}

TEST(Escape, CsvFieldsAreOneFieldOnOneLine) {
  for (const auto& name : test::hostile_names()) {
    const std::string field = escape::csv_text(name);
    EXPECT_TRUE(clean_line(field));
    const auto record = test::csv_record(field + ",next");
    ASSERT_TRUE(record) << field;
    ASSERT_EQ(record->size(), 2u) << field;
    EXPECT_FALSE(test::formula_cell((*record)[0])) << field;
    EXPECT_EQ(escape::csv_text_value((*record)[0]), escape::one_line(name));
    EXPECT_TRUE(clean_line(escape::csv_comment(name)));
  }
}

// A text a spreadsheet would evaluate gets one quote before it (OWASP); a
// text that already starts with quotes before such a character one more, so
// that csv_text_value gives every text back; other texts are unchanged.
TEST(Escape, CsvTextThatLooksLikeAFormulaIsQuotedAsText) {
  EXPECT_EQ(escape::csv_text("=HYPERLINK(\"http://x\")"), "\"'=HYPERLINK(\"\"http://x\"\")\"");
  EXPECT_EQ(escape::csv_text("+1+1"), "\"'+1+1\"");
  EXPECT_EQ(escape::csv_text("-2+3"), "\"'-2+3\"");
  EXPECT_EQ(escape::csv_text("-0.5"), "\"'-0.5\"");  // a text, not a number: numbers never come here
  EXPECT_EQ(escape::csv_text("@SUM(A1)"), "\"'@SUM(A1)\"");
  EXPECT_EQ(escape::csv_text("'=1"), "\"''=1\"");
  EXPECT_EQ(escape::csv_text("'a"), "'a");
  EXPECT_EQ(escape::csv_text("a=1"), "a=1");
  EXPECT_EQ(escape::csv_text_value("'=1"), "=1");
  EXPECT_EQ(escape::csv_text_value("''=1"), "'=1");
  EXPECT_EQ(escape::csv_text_value("'a"), "'a");
  EXPECT_EQ(escape::csv_text_value("=1"), "=1");
}

TEST(Escape, XmlTextHoldsNoMarkupAndOnlyXmlCharacters) {
  for (const auto& name : test::hostile_names()) {
    for (const bool keep : {false, true}) {
      const std::string out = escape::xml_text(name, keep);
      EXPECT_EQ(out.find_first_of("<>\"'"), std::string::npos) << out;
      for (std::size_t at = out.find('&'); at != std::string::npos; at = out.find('&', at + 1)) {
        const std::size_t end = out.find(';', at);
        ASSERT_NE(end, std::string::npos) << out;
        const std::string entity = out.substr(at, end - at + 1);
        EXPECT_TRUE(entity == "&amp;" || entity == "&lt;" || entity == "&gt;" || entity == "&quot;" ||
                    entity == "&apos;")
            << entity;
      }
      for (const char c : out) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte < 0x20) {
          EXPECT_TRUE(keep && (c == '\n' || c == '\t')) << testing::PrintToString(out);
        }
      }
    }
    const std::string comment = escape::xml_comment(name);
    EXPECT_TRUE(clean_line(comment)) << comment;
    EXPECT_EQ(comment.find("--"), std::string::npos) << comment;
    EXPECT_TRUE(comment.empty() || comment.back() != '-') << comment;
  }
}

TEST(Escape, JsonTextParsesBackToTheNameOrItsReplacement) {
  for (const auto& name : test::hostile_names()) {
    const std::string text = escape::json_text(nlohmann::json{{"name", name}});
    const auto parsed = nlohmann::json::parse(text);
    const std::string back = parsed.at("name").get<std::string>();
    // Valid UTF-8 comes back exactly (controls included, as \u escapes);
    // an invalid byte comes back as U+FFFD.
    bool valid = true;
    for (std::size_t i = 0; i < name.size() && valid;) {
      const auto decoded = decode_utf8(name, i);
      valid = decoded.has_value();
      if (decoded) i += decoded->length;
    }
    if (valid)
      EXPECT_EQ(back, name);
    else
      EXPECT_NE(back.find("\xEF\xBF\xBD"), std::string::npos);
  }
}

}  // namespace
}  // namespace hydrocoef
