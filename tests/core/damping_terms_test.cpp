// Damping laws as data (src/core/damping_terms.hpp): every term form parsed,
// named and written back, bad lists refused naming the term, a spec built in
// code checked the same way, and the law's value summed in term order.
#include "src/core/damping_terms.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "src/core/error.hpp"
#include "tests/support/expect_input_error.hpp"

namespace hydrocoef {
namespace {

using test::expect_input_error;

TEST(DampingLawTerms, ParsesEveryForm) {
  const DampingLawSpec spec = parse_damping_terms("1,v,v|v|,v^2,v^3,|v|");
  EXPECT_EQ(spec.variable, "v");
  const std::vector<DampingTerm> expected = {DampingTerm::Constant,  DampingTerm::Linear, DampingTerm::SignedQuadratic,
                                             DampingTerm::Quadratic, DampingTerm::Cubic,  DampingTerm::AbsLinear};
  EXPECT_EQ(spec.terms, expected);
  EXPECT_EQ(format_damping_terms(spec), "1,v,v|v|,v^2,v^3,|v|");
}

TEST(DampingLawTerms, ToleratesWhitespaceAndKeepsOrder) {
  const DampingLawSpec spec = parse_damping_terms("  r , r | r | ,\tr^3 ");
  EXPECT_EQ(spec.variable, "r");
  const std::vector<DampingTerm> expected = {DampingTerm::Linear, DampingTerm::SignedQuadratic, DampingTerm::Cubic};
  EXPECT_EQ(spec.terms, expected);
  EXPECT_EQ(format_damping_terms(spec), "r,r|r|,r^3");
}

TEST(DampingLawTerms, AcceptsEveryVelocityComponent) {
  for (const char* name : {"u", "v", "w", "p", "q", "r"}) {
    const std::string x(name);
    const DampingLawSpec spec = parse_damping_terms(x + "|" + x + "|,1");
    EXPECT_EQ(spec.variable, x);
    EXPECT_EQ(format_damping_terms(spec), x + "|" + x + "|,1");
  }
}

TEST(DampingLawTerms, NamesAndBasisValues) {
  EXPECT_EQ(term_name(DampingTerm::Constant, "u"), "1");
  EXPECT_EQ(term_name(DampingTerm::Linear, "q"), "q");
  EXPECT_EQ(term_name(DampingTerm::SignedQuadratic, "u"), "u|u|");
  EXPECT_EQ(term_name(DampingTerm::Quadratic, "v"), "v^2");
  EXPECT_EQ(term_name(DampingTerm::Cubic, "r"), "r^3");
  EXPECT_EQ(term_name(DampingTerm::AbsLinear, "w"), "|w|");

  EXPECT_EQ(basis_value(DampingTerm::Constant, -3.0), 1.0);
  EXPECT_EQ(basis_value(DampingTerm::Linear, -3.0), -3.0);
  EXPECT_EQ(basis_value(DampingTerm::SignedQuadratic, -3.0), -9.0);
  EXPECT_EQ(basis_value(DampingTerm::SignedQuadratic, 3.0), 9.0);
  EXPECT_EQ(basis_value(DampingTerm::Quadratic, -3.0), 9.0);
  EXPECT_EQ(basis_value(DampingTerm::Cubic, -3.0), -27.0);
  EXPECT_EQ(basis_value(DampingTerm::AbsLinear, -3.0), 3.0);
  // A value outside the enumeration (memory gone wrong) is an error, never a read past the basis.
  const auto unknown = static_cast<DampingTerm>(6);
  EXPECT_THROW(basis_value(unknown, 1.0), std::invalid_argument);
  const std::array<DampingTerm, 2> terms = {DampingTerm::Linear, unknown};
  const std::array<double, 2> c = {1.0, 2.0};
  EXPECT_THROW(damping_law_value(terms, c, 1.0), std::invalid_argument);
}

TEST(DampingLawTerms, RejectsBadLists) {
  expect_input_error([] { parse_damping_terms("1,u,u|u"); }, {"'u|u'", "accepted terms"});
  expect_input_error([] { parse_damping_terms("u^4"); }, {"'u^4'", "accepted terms"});
  expect_input_error([] { parse_damping_terms("u|r|"); }, {"'u|r|'"});
  expect_input_error([] { parse_damping_terms("u,r|r|"); }, {"'r|r|'", "one velocity component"});
  expect_input_error([] { parse_damping_terms("u,u|u|,u"); }, {"'u'", "twice"});
  expect_input_error([] { parse_damping_terms(""); }, {"empty"});
  expect_input_error([] { parse_damping_terms("   "); }, {"empty"});
  expect_input_error([] { parse_damping_terms("1,,u"); }, {"empty", "'1,,u'"});
  expect_input_error([] { parse_damping_terms("u,"); }, {"empty"});
  expect_input_error([] { parse_damping_terms("x,x|x|"); }, {"'x'", "u, v, w, p, q, r"});
  expect_input_error([] { parse_damping_terms("1,speed"); }, {"'speed'", "not a velocity component"});
  expect_input_error([] { parse_damping_terms("1"); }, {"'1'", "no term in a velocity component"});
}

TEST(DampingLawSpecCheck, RefusesWhatTheParserRefuses) {
  check_damping_law_spec(parse_damping_terms("1,u,u|u|"));
  expect_input_error([] { check_damping_law_spec({"u", {}}); }, {"no terms"});
  expect_input_error([] { check_damping_law_spec({"u", {DampingTerm::Constant}}); }, {"no term in a velocity"});
  expect_input_error([] { check_damping_law_spec({"x", {DampingTerm::Linear}}); }, {"'x'", "u, v, w, p, q, r"});
  expect_input_error(
      [] {
        check_damping_law_spec({"r", {DampingTerm::Linear, DampingTerm::Linear}});
      },
      {"'r'", "twice"});
}

TEST(DampingLawValue, SumsTheTermsInOrder) {
  // The ASR-V surge law on the body: X(u) = -0.0155 u - 11.0365 u|u|.
  const DampingLawSpec spec = parse_damping_terms("u,u|u|");
  const std::vector<double> coefficients = {-0.0155, -11.0365};
  for (const double u : {-0.3, 0.0, 0.1, 0.25}) {
    EXPECT_EQ(damping_law_value(spec.terms, coefficients, u), -0.0155 * u + -11.0365 * (u * std::abs(u))) << u;
  }
  EXPECT_LT(damping_law_value(spec.terms, coefficients, 0.2), 0.0);  // damping opposes motion
  EXPECT_GT(damping_law_value(spec.terms, coefficients, -0.2), 0.0);
  // Every term, and a law with fewer coefficients than terms (the rest count 0).
  const DampingLawSpec all = parse_damping_terms("1,v,v|v|,v^2,v^3,|v|");
  const std::array<double, 6> c = {0.5, 1.0, 2.0, 3.0, 4.0, 5.0};
  EXPECT_EQ(damping_law_value(all.terms, c, -2.0), 0.5 - 2.0 - 8.0 + 12.0 - 32.0 + 10.0);
  EXPECT_EQ(damping_law_value(all.terms, std::span(c.data(), 2), -2.0), 0.5 - 2.0);
  EXPECT_EQ(damping_law_value({}, c, 3.0), 0.0);
}

}  // namespace
}  // namespace hydrocoef
