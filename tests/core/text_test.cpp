// The shared text helpers (src/core/text.hpp): trimming with the caller's
// blanks, views that stay inside the caller's text, splitting that keeps
// empty fields, ASCII lower case without a locale.
#include "src/core/text.hpp"

#include <gtest/gtest.h>

#include <string>
#include <string_view>
#include <vector>

namespace hydrocoef {
namespace {

using namespace std::string_view_literals;

TEST(Trim, RemovesBlanksAtBothEndsOnly) {
  EXPECT_EQ(trim("  a b \t"), "a b");
  EXPECT_EQ(trim("\r\n\v\f x \f\v\n\r"), "x");
  EXPECT_EQ(trim("x"), "x");
  EXPECT_EQ(trim(""), "");
  EXPECT_EQ(trim(" \t\r\n"), "");
  EXPECT_EQ(trim_left("  a  "), "a  ");
  EXPECT_EQ(trim_right("  a  "), "  a");
}

TEST(Trim, OnlyTheGivenBlanks) {
  // A CSV cell trims spaces and tabs: a \r or \f is content.
  EXPECT_EQ(trim(" \t1.5\r\t ", kSpaceTab), "1.5\r");
  EXPECT_EQ(trim("\f1.5 ", kSpaceTab), "\f1.5");
  EXPECT_EQ(trim(" 1.5\r ", " \t\r"), "1.5");
  EXPECT_EQ(trim("--x--", "-"), "x");
  EXPECT_EQ(trim("x\0 "sv, kSpaceTab), "x\0"sv);  // NUL is not a blank
}

TEST(Trim, ResultIsAViewIntoTheText) {
  const std::string line = "   value  ";
  const std::string_view view(line);
  const std::string_view trimmed = trim(view);
  EXPECT_EQ(trimmed.data() - view.data(), 3);
  EXPECT_EQ(trimmed.size(), 5u);
  // Only blanks: an empty view, still within the text (positions stay valid).
  const std::string blanks = "    ";
  const std::string_view none = trim(std::string_view(blanks));
  EXPECT_TRUE(none.empty());
  EXPECT_GE(none.data(), blanks.data());
  EXPECT_LE(none.data(), blanks.data() + blanks.size());
}

TEST(WithoutBlanks, LeavesOutBlanksEverywhere) {
  EXPECT_EQ(without_blanks(" u | u |\t"), "u|u|");
  EXPECT_EQ(without_blanks("huber : 0.01", " "), "huber:0.01");
  EXPECT_EQ(without_blanks("a\fb", " \t\r\n"), "a\fb");
  EXPECT_EQ(without_blanks(" \t "), "");
}

TEST(Lower, AsciiLettersOnly) {
  EXPECT_EQ(lower("Force.DAT"), "force.dat");
  EXPECT_EQ(lower("ABCXYZ abcxyz 09@[`{"), "abcxyz abcxyz 09@[`{");  // the bytes around A-Z and a-z stay
  EXPECT_EQ(lower("\xC3\x89T\xC9"), "\xC3\x89t\xC9");                // UTF-8 and Latin-1 bytes as they are
  EXPECT_EQ(lower(""), "");
  EXPECT_EQ(lower('Q'), 'q');
  EXPECT_EQ(lower('q'), 'q');
  EXPECT_EQ(lower('\xC9'), '\xC9');
}

TEST(Split, KeepsEmptyFields) {
  EXPECT_EQ(split("a,b,c", ','), (std::vector<std::string_view>{"a", "b", "c"}));
  EXPECT_EQ(split("a,,b", ','), (std::vector<std::string_view>{"a", "", "b"}));
  EXPECT_EQ(split("a,", ','), (std::vector<std::string_view>{"a", ""}));
  EXPECT_EQ(split(",a", ','), (std::vector<std::string_view>{"", "a"}));
  EXPECT_EQ(split("", ','), (std::vector<std::string_view>{""}));
  EXPECT_EQ(split("a b", ','), (std::vector<std::string_view>{"a b"}));
  EXPECT_EQ(split(" a ; b ", ';'), (std::vector<std::string_view>{" a ", " b "}));
}

}  // namespace
}  // namespace hydrocoef
