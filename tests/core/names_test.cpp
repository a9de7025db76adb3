// The name rule: what each kind of name accepts and refuses, and that a
// refusal is one InputError line naming where the name came from.
#include "src/core/names.hpp"

#include <gtest/gtest.h>

#include <string>

#include "src/core/error.hpp"

namespace hydrocoef {
namespace {

TEST(Names, PrintableNamesPass) {
  for (const char* name : {"asr-v", "ASR V hull", "sphere:surge", "µ-body", "a`b", "$(x)", "%s", "*/", "]]>",
                           "<script>", "it's", "\"q\"", "x;y", "fit@current_v=0.05", "日本語"}) {
    EXPECT_EQ(name_problem(NameKind::Body, name), std::nullopt) << name;
    EXPECT_EQ(name_problem(NameKind::Fit, name), std::nullopt) << name;
  }
}

TEST(Names, ControlAndFormattingCharactersAreRefused) {
  const std::string refused[] = {
      std::string("a\nb"),
      std::string("a\rb"),
      std::string("a\0b", 3),
      std::string("a\x01"),
      std::string("tab\t"),
      std::string("del\x7f"),
      std::string("c1 \xc2\x85"),           // U+0085 NEXT LINE
      std::string("rtl \xe2\x80\xae"),      // U+202E RIGHT-TO-LEFT OVERRIDE
      std::string("isolate \xe2\x81\xa6"),  // U+2066
      std::string("ls \xe2\x80\xa8"),       // U+2028 LINE SEPARATOR
      std::string("bom \xef\xbb\xbf"),      // U+FEFF
  };
  for (const auto& name : refused) {
    const auto problem = name_problem(NameKind::Surface, name);
    ASSERT_TRUE(problem.has_value()) << printable_text(name);
    EXPECT_NE(problem->find("control or formatting character"), std::string::npos) << *problem;
  }
}

TEST(Names, InvalidUtf8IsRefused) {
  for (const std::string& name :
       {std::string("a\xff"), std::string("\xc0\xaf"), std::string("\xed\xa0\x80"), std::string("cut \xe2\x82")}) {
    const auto problem = name_problem(NameKind::Body, name);
    ASSERT_TRUE(problem.has_value()) << printable_text(name);
    EXPECT_NE(problem->find("not valid UTF-8"), std::string::npos) << *problem;
  }
}

TEST(Names, LengthIsCountedInCharacters) {
  EXPECT_EQ(name_problem(NameKind::Body, std::string(128, 'a')), std::nullopt);
  EXPECT_TRUE(name_problem(NameKind::Body, std::string(129, 'a')).has_value());
  std::string micro;
  for (int i = 0; i < 128; ++i) micro += "\xc2\xb5";  // 128 characters, 256 bytes
  EXPECT_EQ(name_problem(NameKind::Body, micro), std::nullopt);
  EXPECT_EQ(name_problem(NameKind::Fit, std::string(160, 'f')), std::nullopt);
  EXPECT_TRUE(name_problem(NameKind::Fit, std::string(161, 'f')).has_value());
  EXPECT_TRUE(name_problem(NameKind::Field, std::string(257, 'x')).has_value());
}

TEST(Names, EmptyAndPaddedNamesAreRefused) {
  EXPECT_EQ(name_problem(NameKind::Body, ""), "is empty");
  EXPECT_TRUE(name_problem(NameKind::Body, " a").has_value());
  EXPECT_TRUE(name_problem(NameKind::Body, "a ").has_value());
}

TEST(Names, ParametersAreIdentifiers) {
  for (const char* name : {"current_v", "_x", "a1", "U"})
    EXPECT_EQ(name_problem(NameKind::Parameter, name), std::nullopt);
  for (const char* name : {"a=1;b", "a;b", "a=b", "1a", "a b", "a-b", "a.b", "µ", ""})
    EXPECT_TRUE(name_problem(NameKind::Parameter, name).has_value()) << name;
  EXPECT_TRUE(name_problem(NameKind::Parameter, std::string(65, 'p')).has_value());
}

TEST(Names, CheckNameThrowsOneLineNamingTheOrigin) {
  try {
    check_name(NameKind::Body, "evil\nsystem(\"touch x\")", SourceLocation{"run.json", 3, 11}, "key 'body'");
    FAIL() << "no exception";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos);
    EXPECT_EQ(message.rfind("run.json:3:11: body name from key 'body' 'evil\\x0asystem(", 0), 0u) << message;
    EXPECT_NE(message.find("U+000A"), std::string::npos) << message;
    EXPECT_NE(message.find("expected printable UTF-8"), std::string::npos) << message;
  }
  EXPECT_EQ(check_name(NameKind::Parameter, "current_v", {}), "current_v");
}

TEST(PrintableText, EscapesBidirectionalControls) {
  EXPECT_EQ(printable_text("a\xe2\x80\xae"
                           "b"),
            "a\\xe2\\x80\\xaeb");
  EXPECT_EQ(printable_text("\xc2\xb5N"), "\xc2\xb5N");
}

TEST(InputErrorMessage, IsCutAtTheBackstopLength) {
  const InputError error(std::string(100000, 'x'));
  EXPECT_LE(std::string(error.what()).size(), kMaxMessageCharacters + 3);
}

}  // namespace
}  // namespace hydrocoef
