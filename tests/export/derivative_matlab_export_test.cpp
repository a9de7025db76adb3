// The MATLAB function of derivative sets in the form of Fossen's MSS vessel
// models (src/export/derivative_matlab_export.hpp). No MATLAB or Octave runs
// here, so the text is checked: the signature, the size checks, the mass
// matrix, each term's expression reading x(k) and ui(k) with its on-body
// coefficient (re-evaluated from the text by a small reader of the forms the
// export writes, and compared with the sets' own forces), and hostile names:
// a function name that is not an identifier is refused, set names stay in
// one comment line, input names never become MATLAB variables.
#include "src/export/derivative_matlab_export.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <regex>
#include <sstream>
#include <string>

#include "tests/support/derivative_sets.hpp"
#include "tests/support/expect_input_error.hpp"

namespace hydrocoef {
namespace {

using test::derivative_set;
using test::expect_input_error;

Matrix6 mass() {
  Matrix6 m = Matrix6::Identity() * 10.0;
  m(1, 5) = m(5, 1) = 0.5;
  return m;
}

// The value of one factor expression as the export writes them: x(k),
// ui(k), abs(.), ^n, products joined by " * " or "*".
double factor_value(const std::string& text, const std::vector<double>& x, const std::vector<double>& ui) {
  const std::regex read(R"((x|ui)\((\d+)\))");
  double product = 1.0;
  std::string rest = text;
  // Split at '*' that are not inside parentheses.
  std::vector<std::string> parts;
  int depth = 0;
  std::string part;
  for (const char c : rest) {
    if (c == '(') ++depth;
    if (c == ')') --depth;
    if (c == '*' && depth == 0) {
      parts.push_back(part);
      part.clear();
    } else if (c != ' ') {
      part += c;
    }
  }
  parts.push_back(part);
  for (const std::string& p : parts) {
    std::smatch m;
    EXPECT_TRUE(std::regex_search(p, m, read)) << p;
    const auto index = static_cast<std::size_t>(std::stoi(m[2]) - 1);
    const double value = m[1] == "x" ? x.at(index) : ui.at(index);
    double factor = p.starts_with("abs(") ? std::abs(value) : value;
    if (const auto caret = p.find('^'); caret != std::string::npos)
      factor = std::pow(factor, std::stoi(p.substr(caret + 1)));
    product *= factor;
  }
  return product;
}

TEST(DerivativeMatlab, MssFormWithEveryTermReadingItsStateOrInput) {
  const std::vector<DerivativeSet> sets = {
      derivative_set("Y", "v, r, v*|v|, u*v, v^2*r, u^2*delta, 1", {-2.0, 0.4, -11.0, -3.0, 5.0, 1.5, 0.01}),
      derivative_set("N", "r, r*|r|, current, v^3, v^2*|v|", {-0.8, -1.1, 0.2, 0.3, -0.4})};
  const std::string text = derivative_matlab("auv_model", sets, mass());
  EXPECT_TRUE(text.starts_with("function [xdot, U] = auv_model(x, ui)\n")) << text;
  EXPECT_NE(text.find("if numel(x) ~= 6, error('x must have 6 elements: [u v w p q r]'''); end"), std::string::npos);
  EXPECT_NE(text.find("if numel(ui) ~= 2, error('ui must have 2 elements'); end"), std::string::npos);
  EXPECT_NE(text.find("%   ui(1) = current\n"), std::string::npos);  // inputs sorted by name
  EXPECT_NE(text.find("%   ui(2) = delta\n"), std::string::npos);
  EXPECT_NE(text.find("M = [10 0 0 0 0 0;\n     0 10 0 0 0 0.5;"), std::string::npos) << text;
  EXPECT_NE(text.find("xdot = M \\ tau;\nU = sqrt(x(1)^2 + x(2)^2 + x(3)^2);\nend\n"), std::string::npos);

  // Re-evaluate tau from the text at a state and compare with the sets.
  const std::vector<double> x = {1.2, -0.35, 0.1, 0.05, -0.02, 0.21}, ui = {0.3, -0.15};
  std::map<std::string, double> point = {{"u", 1.2},   {"v", -0.35}, {"w", 0.1},       {"p", 0.05},
                                         {"q", -0.02}, {"r", 0.21},  {"current", 0.3}, {"delta", -0.15}};
  std::map<int, double> tau;
  std::istringstream in(text);
  std::string line;
  int dof = 0;
  const std::regex start(R"(^tau\((\d)\) = \.\.\.$)");
  const std::regex term(R"(^    [+ ] \(([^)]*)\)(?: \* (.*?))?(?: \.\.\.|;)  % (.*)$)");
  std::size_t terms_read = 0;
  while (std::getline(in, line)) {
    std::smatch m;
    if (std::regex_match(line, m, start)) {
      dof = std::stoi(m[1]);
      continue;
    }
    if (std::regex_match(line, m, term)) {
      const double c = std::stod(m[1]);
      tau[dof] += c * (m[2].length() ? factor_value(m[2], x, ui) : 1.0);
      ++terms_read;
    }
  }
  EXPECT_EQ(terms_read, 12u);
  for (const auto& set : sets) {
    const int i = static_cast<int>(std::string("XYZKMN").find(set.output)) + 1;
    double own = 0.0;
    for (std::size_t k = 0; k < set.terms.size(); ++k) own += set.coefficients[k] * set.terms[k].evaluate(point);
    EXPECT_NEAR(tau[i], own, 1e-14) << set.output;
  }
  // "opposing" numbers are negated to the force on the body.
  DerivativeSet opposing = derivative_set("Y", "v", {2.0});
  opposing.sign = SignConvention::OpposingMotion;
  EXPECT_NE(derivative_matlab("m", {opposing}, mass()).find("      (-2) * x(2);"), std::string::npos);
}

TEST(DerivativeMatlab, HostileNamesStayData) {
  for (const std::string& bad :
       std::vector<std::string>{"", "1model", "a b", "end", "x;system('rm -rf /')", std::string(64, 'a'), "_x"})
    expect_input_error([&] { derivative_matlab(bad, {derivative_set("Y", "v", {1.0})}, mass()); },
                       {"MATLAB function name"});
  EXPECT_NO_THROW(derivative_matlab(std::string(63, 'a'), {derivative_set("Y", "v", {1.0})}, mass()));
  DerivativeSet set = derivative_set("Y", "v, x, ui, xdot, end_", {1.0, 2.0, 3.0, 4.0, 5.0});
  set.name = "evil\nsystem('rm -rf /')\n%{";
  const std::string text = derivative_matlab("m", {set}, mass());
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    // Outside comment lines the set's name never appears, and no line opens a block comment.
    EXPECT_FALSE(line.starts_with("system(")) << line;
    EXPECT_NE(line, "%{");
  }
  // Disturbances named like the function's own variables are read from ui, never by name.
  // ui = [end_ ui x xdot]
  EXPECT_NE(text.find("(2) * ui(3)"), std::string::npos) << text;  // x
  EXPECT_NE(text.find("(3) * ui(2)"), std::string::npos) << text;  // ui
  EXPECT_NE(text.find("(4) * ui(4)"), std::string::npos) << text;  // xdot
  EXPECT_NE(text.find("(5) * ui(1)"), std::string::npos) << text;  // end_
}

TEST(DerivativeMatlab, BadInputsAreRefused) {
  Matrix6 m = mass();
  m(0, 0) = -1.0;
  expect_input_error([&] { derivative_matlab("m", {derivative_set("Y", "v", {1.0})}, m); }, {"not positive definite"});
  m = mass();
  m(0, 1) = 3.0;
  expect_input_error([&] { derivative_matlab("m", {derivative_set("Y", "v", {1.0})}, m); }, {"symmetric", "(1,2)"});
  expect_input_error(
      [&] {
        derivative_matlab("m", {derivative_set("Y", "v, beta", {1.0, 2.0})}, mass());
      },
      {"fit-Y", "'beta'"});
  expect_input_error([&] { derivative_matlab("m", {derivative_set("Q", "v", {1.0})}, mass()); }, {"'Q'"});
  expect_input_error(
      [&] {
        derivative_matlab("m", {derivative_set("Y", "v", {1.0}), derivative_set("Y", "r", {1.0})}, mass());
      },
      {"second set of output Y"});
  expect_input_error([&] { derivative_matlab("m", {}, mass()); }, {"no derivative sets"});
}

}  // namespace
}  // namespace hydrocoef
