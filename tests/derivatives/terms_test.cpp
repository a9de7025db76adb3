// Terms of derivative models (src/derivatives/terms.hpp): the issue's
// examples parsed to their canonical text, spellings of one term made one,
// the canonical order of names, values with the sign rules of |x|, unit
// powers, and every refusal naming the term, its place and column.
#include "src/derivatives/terms.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "src/core/error.hpp"
#include "tests/support/expect_input_error.hpp"

namespace hydrocoef {
namespace {

using test::expect_input_error;

std::vector<std::string> texts(const std::vector<Term>& terms) {
  std::vector<std::string> out;
  for (const auto& t : terms) out.push_back(t.text());
  return out;
}

TEST(DerivativeTerms, ParsesTheIssuesExamples) {
  const auto terms = parse_terms("v, u*v, v*|v|, v^2*r, u^2*delta, v*|r|, 1");
  const std::vector<std::string> expected = {"v", "u*v", "v*|v|", "v^2*r", "u^2*delta", "v*|r|", "1"};
  EXPECT_EQ(texts(terms), expected);
  EXPECT_TRUE(terms.back().is_constant());
  EXPECT_FALSE(terms.front().is_constant());
  EXPECT_EQ(format_terms(terms), "v, u*v, v*|v|, v^2*r, u^2*delta, v*|r|, 1");
  EXPECT_EQ(texts(parse_terms(format_terms(terms))), expected);
}

TEST(DerivativeTerms, SpellingsOfOneTermShareTheirCanonicalText) {
  EXPECT_EQ(parse_term("|v|*v").text(), "v*|v|");
  EXPECT_EQ(parse_term("v*v").text(), "v^2");
  EXPECT_EQ(parse_term("|v|*|v|").text(), "v^2");
  EXPECT_EQ(parse_term("v*|v|*|v|").text(), "v^3");
  EXPECT_EQ(parse_term("|v|*v^2").text(), "v^2*|v|");
  EXPECT_EQ(parse_term("v^2*v*|v|").text(), "v^3*|v|");
  EXPECT_EQ(parse_term("v^2*v^2").text(), "v^4");
  EXPECT_EQ(parse_term("|v|").text(), "|v|");
  EXPECT_EQ(parse_term(" v ^ 2 * r ").text(), "v^2*r");
  EXPECT_EQ(parse_term("| v |*v").text(), "v*|v|");
  EXPECT_EQ(parse_term(" 1 ").text(), "1");
  EXPECT_EQ(parse_term("|r|*v").text(), "v*|r|");
}

TEST(DerivativeTerms, OrdersNamesVelocitiesAnglesRatesThenOthers) {
  EXPECT_EQ(parse_term("delta*u^2").text(), "u^2*delta");
  EXPECT_EQ(parse_term("r*v").text(), "v*r");
  EXPECT_EQ(parse_term("r*beta^2").text(), "beta^2*r");
  EXPECT_EQ(parse_term("delta*du").text(), "du*delta");
  EXPECT_EQ(parse_term("delta_s*u^2").text(), "u^2*delta_s");
  EXPECT_EQ(parse_term("zeta*r*q*p*beta*alpha*w*v*du*u").text(), "u*du*v*w*alpha*beta*p*q*r*zeta");
  // Other names in byte order: upper case before lower case, '_' between.
  EXPECT_EQ(parse_term("b*a*B*_x").text(), "B*_x*a*b");
}

TEST(DerivativeTerms, ValuesFollowTheSignOfEachFactor) {
  const std::map<std::string, double> at = {{"u", 2.0}, {"v", -2.0}, {"r", 0.5}, {"delta", -0.25}};
  EXPECT_EQ(parse_term("v").evaluate(at), -2.0);
  EXPECT_EQ(parse_term("|v|").evaluate(at), 2.0);
  EXPECT_EQ(parse_term("v*|v|").evaluate(at), -4.0);
  EXPECT_EQ(parse_term("v^2").evaluate(at), 4.0);
  EXPECT_EQ(parse_term("v^3").evaluate(at), -8.0);
  EXPECT_EQ(parse_term("v^2*|v|").evaluate(at), 8.0);
  EXPECT_EQ(parse_term("v^3*|v|").evaluate(at), -16.0);
  EXPECT_EQ(parse_term("v^4").evaluate(at), 16.0);
  EXPECT_EQ(parse_term("u^2*delta").evaluate(at), -1.0);
  EXPECT_EQ(parse_term("v^2*r").evaluate(at), 2.0);
  EXPECT_EQ(parse_term("v*|r|").evaluate(at), -1.0);
  EXPECT_EQ(parse_term("1").evaluate({}), 1.0);
  // The same term at +v: odd factors turn sign, even ones do not.
  const std::map<std::string, double> mirrored = {{"v", 2.0}};
  EXPECT_EQ(parse_term("v*|v|").evaluate(mirrored), 4.0);
  EXPECT_EQ(parse_term("v^2*|v|").evaluate(mirrored), 8.0);
  expect_input_error([] { parse_term("u*v").evaluate({{"v", 1.0}}); }, {"\"u*v\"", "needs a value of u"});
}

TEST(DerivativeTerms, UnitPowersCountAbsoluteValuesAsFirstPowers) {
  EXPECT_EQ(parse_term("v*|v|").powers(), (std::map<std::string, int>{{"v", 2}}));
  EXPECT_EQ(parse_term("u^2*delta").powers(), (std::map<std::string, int>{{"u", 2}, {"delta", 1}}));
  EXPECT_EQ(parse_term("v*|r|").powers(), (std::map<std::string, int>{{"v", 1}, {"r", 1}}));
  EXPECT_EQ(parse_term("|v|").powers(), (std::map<std::string, int>{{"v", 1}}));
  EXPECT_TRUE(parse_term("1").powers().empty());
  EXPECT_EQ(parse_term("v^2*r").variables(), (std::vector<std::string>{"v", "r"}));
  EXPECT_EQ(term_variables(parse_terms("r, u^2*delta, v*r, 1")), (std::vector<std::string>{"u", "v", "r", "delta"}));
}

TEST(DerivativeTerms, TermsBuiltInCodeAreCanonicalAndChecked) {
  EXPECT_EQ(Term({{"v", 1, true}, {"u", 1, true}}).text(), "u*v");
  EXPECT_EQ(Term({{"v", 2, true}}).text(), "v*|v|");
  EXPECT_EQ(Term({{"v", 1, false}}).text(), "|v|");
  EXPECT_EQ(Term().text(), "1");
  EXPECT_EQ(Term({{"v", 2, true}}), parse_term("|v|*v"));
  EXPECT_THROW(Term({{"v", 1, true}, {"v", 2, false}}), std::invalid_argument);
  EXPECT_THROW(Term({{"v", 5, true}}), std::invalid_argument);
  EXPECT_THROW(Term({{"2v", 1, true}}), std::invalid_argument);
  EXPECT_TRUE(is_term_variable_name("delta_r2"));
  EXPECT_TRUE(is_term_variable_name("_x"));
  EXPECT_FALSE(is_term_variable_name("2x"));
  EXPECT_FALSE(is_term_variable_name(""));
  EXPECT_FALSE(is_term_variable_name("v'"));
}

TEST(DerivativeTerms, RefusesUnknownCharactersNamingTermAndColumn) {
  expect_input_error([] { parse_terms("v, r+v"); },
                     {"term \"r+v\"", "term 2 of the list \"v, r+v\"", "column 5", "the character '+'"});
  expect_input_error([] { parse_terms("v/r"); }, {"\"v/r\"", "column 2", "the character '/'", "expected '*'"});
  expect_input_error([] { parse_terms("v r"); }, {"\"v r\"", "column 3", "the character 'r' after v"});
  expect_input_error([] { parse_terms("v*(r)"); }, {"column 3", "the character '('"});
  expect_input_error([] { parse_terms("v*\xCE\xB4"); }, {"column 3", "the character '\\xce'"});
  expect_input_error([] { parse_term("v'"); }, {"term \"v'\" (column 2)", "the character '''"});
}

TEST(DerivativeTerms, RefusesEmptyTermsAndFactors) {
  expect_input_error([] { parse_terms("v,,r"); }, {"term 2 of the list \"v,,r\"", "column 3", "an empty term"});
  expect_input_error([] { parse_terms("v, r,"); }, {"term 3", "column 6", "an empty term"});
  expect_input_error([] { parse_terms(""); }, {"an empty term"});
  expect_input_error([] { parse_terms("v**r"); }, {"\"v**r\"", "column 3", "an empty factor before '*'"});
  expect_input_error([] { parse_terms("r, v*"); }, {"\"v*\"", "column 6", "an empty factor at the end"});
  expect_input_error([] { parse_terms("*v"); }, {"column 1", "an empty factor"});
  expect_input_error([] { parse_terms("||"); }, {"column 2", "an empty |...|"});
  expect_input_error([] { parse_terms("|v"); }, {"an unclosed |v"});
  expect_input_error([] { parse_terms("v*|v r|"); }, {"an unclosed |v"});
}

TEST(DerivativeTerms, RefusesPowersOtherThanTwoToFour) {
  expect_input_error([] { parse_terms("v, v^5"); },
                     {"term \"v^5\"", "term 2", "column 6", "the power 5 of v", "expected 2, 3 or 4"});
  expect_input_error([] { parse_terms("v^1"); }, {"the power 1 of v", "expected 2, 3 or 4"});
  expect_input_error([] { parse_terms("v^0.5"); }, {"the power 0 of v"});
  expect_input_error([] { parse_terms("v^"); }, {"column 3", "no power after '^'"});
  expect_input_error([] { parse_terms("v^-2"); }, {"no power after '^'"});
  expect_input_error([] { parse_terms("|v|^2"); }, {"column 4", "a power of |v|"});
  expect_input_error([] { parse_terms("v^3*r*v^2"); }, {"\"v^3*r*v^2\"", "column 1", "v to the power 5", "at most 4"});
  expect_input_error([] { parse_terms("v*|v|*v^3"); }, {"v to the power 5"});
}

TEST(DerivativeTerms, RefusesNumbersOtherThanTheConstantAlone) {
  expect_input_error([] { parse_terms("2*v"); }, {"\"2*v\"", "column 1", "a number"});
  expect_input_error([] { parse_terms("1*v"); }, {"\"1*v\"", "a number", "the constant term is 1, alone"});
  expect_input_error([] { parse_terms("v, 2"); }, {"column 4", "a number"});
}

TEST(DerivativeTerms, RefusesTheSameTermTwiceNamingBothSpellings) {
  expect_input_error([] { parse_terms("v*|v|, r, |v|*v"); },
                     {"term \"|v|*v\"", "term 3", "column 11", "the same term as \"v*|v|\"", "(term 1, column 1)",
                      "both v*|v|", "expected each term once"});
  expect_input_error([] { parse_terms("delta*u^2, v,  u*u*delta"); },
                     {"\"u*u*delta\"", "the same term as \"delta*u^2\"", "both u^2*delta"});
  expect_input_error([] { parse_terms("1, v, 1"); }, {"term 3", "the same term as \"1\""});
}

}  // namespace
}  // namespace hydrocoef
