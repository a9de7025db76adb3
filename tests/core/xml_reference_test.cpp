// src/core/xml_reference: the XML references the project's XML readers decode,
// and the ones XML 1.0 does not allow, which they refuse.
#include "src/core/xml_reference.hpp"

#include <gtest/gtest.h>

#include <string>

namespace hydrocoef {
namespace {

std::string decoded(std::string_view name) {
  std::string out = "x";
  const char* wrong = append_xml_reference(name, out);
  EXPECT_EQ(wrong, nullptr) << name;
  return out;
}

std::string refusal(std::string_view name) {
  std::string out = "x";
  const char* wrong = append_xml_reference(name, out);
  EXPECT_EQ(out, "x") << name << ": nothing is appended when refused";
  return wrong == nullptr ? "(accepted)" : wrong;
}

TEST(XmlReference, PredefinedEntitiesAndCharacterReferencesAppendTheirCharacter) {
  EXPECT_EQ(decoded("lt"), "x<");
  EXPECT_EQ(decoded("gt"), "x>");
  EXPECT_EQ(decoded("amp"), "x&");
  EXPECT_EQ(decoded("quot"), "x\"");
  EXPECT_EQ(decoded("apos"), "x'");
  EXPECT_EQ(decoded("#65"), "xA");
  EXPECT_EQ(decoded("#x41"), "xA");
  EXPECT_EQ(decoded("#xe9"), "x\xc3\xa9");             // U+00E9
  EXPECT_EQ(decoded("#8364"), "x\xe2\x82\xac");        // U+20AC
  EXPECT_EQ(decoded("#x1F600"), "x\xf0\x9f\x98\x80");  // beyond the BMP
  EXPECT_EQ(decoded("#9"), "x\t");
  EXPECT_EQ(decoded("#x10FFFF"), "x\xf4\x8f\xbf\xbf");
}

TEST(XmlReference, WhatXmlDoesNotAllowIsRefusedWithWhatIsWrong) {
  for (const char* name : {"", "LT", "nbsp", "#", "x41"}) EXPECT_EQ(refusal(name), "an unknown entity") << name;
  for (const char* name : {"#x", "#-65", "#+65", "#6a", "#x4G", "# 65", "#99999999999999999999"})
    EXPECT_EQ(refusal(name), "a malformed character reference") << name;
  // NUL, the C0 controls but tab, line feed and carriage return, surrogates,
  // beyond U+10FFFF.
  for (const char* name : {"#0", "#1", "#x1f", "#xD800", "#xdfff", "#x110000"})
    EXPECT_EQ(refusal(name), "a character reference to a character XML 1.0 cannot hold") << name;
}

}  // namespace
}  // namespace hydrocoef
