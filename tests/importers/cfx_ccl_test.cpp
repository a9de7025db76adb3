// CFX Command Language (importers/cfx_ccl): objects, labels and parameters
// with their lines, comments, continuation lines, CRLF, merged singletons,
// the refusals of malformed text; the CCL block of a solver output file; and
// the constant CEL evaluator: units in SI (atm, km h^-1), operators,
// expression chains, and the refusal of functions, variables, cycles and
// wrong dimensions with the file and line.
#include "importers/cfx_ccl.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "src/core/error.hpp"
#include "tests/support/expect_input_error.hpp"
#include "tests/support/run_cli.hpp"

namespace hydrocoef {
namespace {

namespace fs = std::filesystem;

const fs::path kData = fs::path(HYDROCOEF_SOURCE_DIR) / "tests" / "data" / "cfx";

std::string read_file(const fs::path& path) { return test::read_text(path); }

/// The 1-based number of the first line of `text` that contains `needle`.
std::size_t line_of(const std::string& text, const std::string& needle) {
  std::istringstream in(text);
  std::string line;
  for (std::size_t number = 1; std::getline(in, line); ++number)
    if (line.find(needle) != std::string::npos) return number;
  ADD_FAILURE() << "no line contains '" << needle << "'";
  return 0;
}

std::string with_crlf(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '\n') out += '\r';
    out += c;
  }
  return out;
}

constexpr const char* kSmall =
    "# a comment line\n"                        // 1
    "\n"                                        // 2
    "FLOW: Flow Analysis 1\n"                   // 3
    "  DOMAIN:   Default   Domain  # a note\n"  // 4
    "    BOUNDARY: inlet\n"                     // 5
    "      Boundary Type = INLET\n"             // 6
    "      Location = A,B,\\\n"                 // 7
    "        C\n"                               // 8
    "    END\n"                                 // 9
    "    boundary: wall 1\n"                    // 10
    "      Boundary Type = WALL\n"              // 11
    "    END\n"                                 // 12
    "  END\n"                                   // 13
    "END\n";                                    // 14

TEST(CfxCcl, ReadsObjectsLabelsParametersAndTheirLines) {
  const CclDocument d = parse_ccl(kSmall, "small.ccl");
  ASSERT_EQ(d.root.children.size(), 1u);
  const CclObject& flow = d.root.children.front();
  EXPECT_EQ(flow.type, "FLOW");
  EXPECT_EQ(flow.label, "Flow Analysis 1");
  EXPECT_EQ(flow.line, 3u);
  const CclObject* domain = flow.child("domain", "Default Domain");  // runs of blanks are one space
  ASSERT_NE(domain, nullptr);
  EXPECT_EQ(domain->label, "Default Domain");
  EXPECT_EQ(domain->line, 4u);
  const auto boundaries = domain->children_of_type("BOUNDARY");
  ASSERT_EQ(boundaries.size(), 2u);
  EXPECT_EQ(boundaries[1]->label, "wall 1");
  EXPECT_EQ(boundaries[1]->line, 10u);
  const CclParameter* type = boundaries[0]->parameter("boundary type");  // names without regard to case
  ASSERT_NE(type, nullptr);
  EXPECT_EQ(type->name, "Boundary Type");
  EXPECT_EQ(type->value, "INLET");
  EXPECT_EQ(type->line, 6u);
  const CclParameter* location = boundaries[0]->parameter("Location");
  ASSERT_NE(location, nullptr);
  EXPECT_EQ(location->value, "A,B,C");  // the continuation joined, at the first line's number
  EXPECT_EQ(location->line, 7u);
  EXPECT_EQ(boundaries[0]->title(), "BOUNDARY: inlet");
  EXPECT_EQ(boundaries[0]->parameter("Absent"), nullptr);
}

TEST(CfxCcl, CrlfLineEndsGiveTheSameTree) {
  const CclDocument lf = parse_ccl(kSmall, "small.ccl");
  const CclDocument crlf = parse_ccl(with_crlf(kSmall), "small.ccl");
  const CclObject* a = lf.root.child("FLOW")->child("DOMAIN")->child("BOUNDARY", "inlet");
  const CclObject* b = crlf.root.child("FLOW")->child("DOMAIN")->child("BOUNDARY", "inlet");
  ASSERT_NE(b, nullptr);
  EXPECT_EQ(b->parameter("Location")->value, a->parameter("Location")->value);
  EXPECT_EQ(b->parameter("Boundary Type")->value, "INLET");
  EXPECT_EQ(b->parameter("Boundary Type")->line, 6u);
}

TEST(CfxCcl, ContinuationKeepsTheSpaceBeforeTheBackslash) {
  const CclDocument d =
      parse_ccl("A:\n  Name = default temperature used \\\n       in the first simulation\nEND\n", "t.ccl");
  EXPECT_EQ(d.root.child("A")->parameter("Name")->value, "default temperature used in the first simulation");
}

TEST(CfxCcl, MergesASingletonWrittenTwiceAndKeepsTheLastValue) {
  const CclDocument d = parse_ccl(
      "LIBRARY:\n CEL:\n  EXPRESSIONS:\n   a = 1 [m]\n   b = 2 [m]\n  END\n END\nEND\n"
      "LIBRARY :\n CEL:\n  EXPRESSIONS:\n   a = 3 [m]\n  END\n END\nEND\n",
      "t.ccl");
  ASSERT_EQ(d.root.children.size(), 1u);
  const CclObject* expressions = d.root.child("LIBRARY")->child("CEL")->child("EXPRESSIONS");
  ASSERT_NE(expressions, nullptr);
  ASSERT_EQ(expressions->parameters.size(), 2u);
  EXPECT_EQ(expressions->parameter("a")->value, "3 [m]");
  EXPECT_EQ(expressions->parameter("a")->line, 12u);
  const CelEvaluator cel(d);
  EXPECT_EQ(cel.expression("a", 1).value, 3.0);
  EXPECT_EQ(cel.expression("b", 1).value, 2.0);
}

TEST(CfxCcl, RefusesMalformedTextNamingFileAndLine) {
  // A missing END is reported at the object that is still open.
  test::expect_input_error([] { parse_ccl("FLOW: f\n  DOMAIN: d\n    BOUNDARY: b\n    END\n  END\n", "a.ccl"); },
                           {"a.ccl:1:", "FLOW: f", "no END"});
  test::expect_input_error([] { parse_ccl("A:\n  B:\n  END\n", "a.ccl"); }, {"a.ccl:1:", "'A'", "no END"});
  test::expect_input_error([] { parse_ccl("A:\nEND\nEND\n", "a.ccl"); }, {"a.ccl:3:", "END without"});
  test::expect_input_error([] { parse_ccl("A:\n  just words\nEND\n", "a.ccl"); },
                           {"a.ccl:2:", "'just words'", "neither"});
  test::expect_input_error([] { parse_ccl("\nKey = 1\n", "a.ccl"); }, {"a.ccl:2:", "outside every object"});
  test::expect_input_error([] { parse_ccl("A:\n  Key = 1 \\\n", "a.ccl"); }, {"a.ccl:2:", "continuation"});
  test::expect_input_error([] { parse_ccl("A:\n!  $x = 1;\nEND\n", "a.ccl"); }, {"a.ccl:2:", "Perl"});
  test::expect_input_error([] { parse_ccl("> update\n", "a.ccl"); }, {"a.ccl:1:", "action"});
  test::expect_input_error([] { parse_ccl(std::string("A:\n\n B = \0\nEND\n", 15), "a.ccl"); }, {"a.ccl:3:", "binary"});
  test::expect_input_error([] { parse_ccl("A:\n  = 3\nEND\n", "a.ccl"); }, {"a.ccl:2:", "no name"});
}

TEST(CfxCcl, LineNumbersStartWhereTheTextStarts) {
  test::expect_input_error([] { parse_ccl("A:\n  oops\nEND\n", "run_001.out", 40); }, {"run_001.out:41:"});
}

// --- the solver output ----------------------------------------------------

TEST(CfxCcl, FindsTheCclEchoedInASolverOutputFile) {
  const std::string out = read_file(kData / "tow_u1.5_001.out");
  ASSERT_FALSE(out.empty());
  EXPECT_TRUE(looks_like_cfx_solver_output(out));
  const auto excerpt = ccl_from_solver_output(out);
  ASSERT_TRUE(excerpt.has_value());
  // The block starts on the line after the banner's closing border and ends
  // before the next banner (the Solver section with the iterations).
  EXPECT_EQ(excerpt->first_line, line_of(out, "CFX Command Language for Run") + 3);
  EXPECT_EQ(excerpt->text.find("OUTER LOOP ITERATION"), std::string_view::npos);
  EXPECT_EQ(excerpt->text.find("+----"), std::string_view::npos);
  EXPECT_NE(excerpt->text.find("EXECUTION CONTROL:"), std::string_view::npos);

  const CclDocument d = parse_ccl(excerpt->text, "tow_u1.5_001.out", excerpt->first_line);
  const CclObject* inlet = d.root.child("FLOW")->child("DOMAIN", "Tank")->child("BOUNDARY", "inlet");
  ASSERT_NE(inlet, nullptr);
  const CclParameter* u = inlet->child("BOUNDARY CONDITIONS")->child("MASS AND MOMENTUM")->parameter("U");
  ASSERT_NE(u, nullptr);
  EXPECT_EQ(u->line, line_of(out, "U = 1.5 [m s^-1]"));  // the .out's own line
  EXPECT_EQ(d.root.child("LIBRARY")->line, line_of(out, " LIBRARY:"));
  // A path with ':' after '=' is a parameter.
  const CclObject* run = d.root.child("EXECUTION CONTROL")->child("RUN DEFINITION");
  ASSERT_NE(run, nullptr);
  EXPECT_EQ(run->parameter("Solver Input File")->value, "/home/user/tow/tow_u1.5.def");
  EXPECT_EQ(d.root.child("EXECUTION CONTROL")
                ->child("PARALLEL HOST LIBRARY")
                ->child("HOST DEFINITION", "testhost")
                ->parameter("Installation Root")
                ->value,
            "/ansys_inc/v232/CFX");
}

TEST(CfxCcl, SolverOutputWithCrlfAndWithoutTheBanner) {
  const std::string out = with_crlf(read_file(kData / "tow_u1.5_001.out"));
  const auto excerpt = ccl_from_solver_output(out);
  ASSERT_TRUE(excerpt.has_value());
  const CclDocument d = parse_ccl(excerpt->text, "run.out", excerpt->first_line);
  EXPECT_EQ(d.root.child("COMMAND FILE")->parameter("Version")->value, "23.2");
  EXPECT_FALSE(ccl_from_solver_output(read_file(kData / "tow_case.ccl")).has_value());
  EXPECT_FALSE(looks_like_cfx_solver_output(read_file(kData / "tow_case.ccl")));
  // The banner beyond the lines looked at is not seen.
  EXPECT_FALSE(looks_like_cfx_solver_output(std::string(300, '\n') + " | CFX Command Language for Run |\n", 200));
  // A run still going: the block runs to the end of the text.
  const auto open = ccl_from_solver_output(" +---+\n | CFX Command Language for Run |\n +---+\nA:\nEND\n");
  ASSERT_TRUE(open.has_value());
  EXPECT_EQ(open->first_line, 4u);
  EXPECT_EQ(open->text, "A:\nEND\n");
}

// --- CEL --------------------------------------------------------------------

CclDocument with_expressions(const std::string& lines) {
  return parse_ccl("LIBRARY:\n  CEL:\n    EXPRESSIONS:\n" + lines + "    END\n  END\nEND\n", "e.ccl");
}

TEST(CfxCel, NumbersAndUnitsInSi) {
  const CclDocument d = with_expressions("");
  const CelEvaluator cel(d);
  const auto check = [&](const char* text, double value, const Dimension& dimension) {
    const CelValue v = cel.evaluate(text, 1);
    EXPECT_DOUBLE_EQ(v.value, value) << text;
    EXPECT_EQ(v.dimension, dimension) << text << ": " << si_unit_name(v.dimension);
  };
  check("2 [m s^-1]", 2.0, kVelocity);
  check("1 [atm]", 101325.0, kPressure);
  check("2 [km h^-1]", 2000.0 / 3600.0, kVelocity);
  check("997 [kg m^-3]", 997.0, kDensity);
  check("8.899E-4 [kg m^-1 s^-1]", 8.899e-4, (Dimension{{1, -1, -1, 0}}));
  check("0 [Pa]", 0.0, kPressure);
  check("1 [psi]", 6894.757293168361, kPressure);
  check("2 [atm m^2]", 2 * 101325.0, kForce);
  check("1 [N/atm]", 1.0 / 101325.0, (Dimension{{0, 2, 0, 0}}));
  check("0. [J/kg]", 0.0, (Dimension{{0, 2, -2, 0}}));
  check("3 []", 3.0, kDimensionless);
  check(".5", 0.5, kDimensionless);
  check("1.E-5", 1e-5, kDimensionless);
  check("1 + 2*3^2", 19.0, kDimensionless);
  check("-2^2", -4.0, kDimensionless);
  check("2^-1", 0.5, kDimensionless);
  check("2^3^2", 512.0, kDimensionless);
  check("(1 + 2) * 3", 9.0, kDimensionless);
  check("10 [m] / 4 [s]", 2.5, kVelocity);
  check("(2 [m])^2", 4.0, (Dimension{{0, 2, 0, 0}}));
  check("- -3 [m] + +1 [m]", 4.0, kLength);
  check("4^0.5", 2.0, kDimensionless);  // fractional powers of dimensionless values
}

TEST(CfxCel, FollowsExpressionChainsCaseSensitively) {
  const CclDocument d = with_expressions(
      "      knot = 1852 [m] / 1 [h]\n"   // line 4
      "      speedKnots = 1.2\n"          // line 5
      "      Uinf = speedKnots * knot\n"  // line 6
      "      uinf = 99 [m s^-1]\n"        // line 7
      "      dyn = 0.5 * rho * Uinf^2\n"  // line 8
      "      rho = 1025 [kg m^-3]\n");    // line 9
  const CelEvaluator cel(d);
  EXPECT_DOUBLE_EQ(cel.evaluate("-Uinf", 20).value, -1.2 * (1852.0 / 3600.0));
  EXPECT_EQ(cel.evaluate("-Uinf", 20).dimension, kVelocity);
  EXPECT_EQ(cel.evaluate("uinf", 20).value, 99.0);
  const CelValue q = cel.expression("dyn", 20);
  EXPECT_DOUBLE_EQ(q.value, 0.5 * 1025.0 * (1.2 * (1852.0 / 3600.0)) * (1.2 * (1852.0 / 3600.0)));
  EXPECT_EQ(q.dimension, kPressure);
  EXPECT_TRUE(cel.has_expression("knot"));
  EXPECT_FALSE(cel.has_expression("Knot"));
}

TEST(CfxCel, RefusesWhatIsNotAConstantNamingFileLineAndToken) {
  const CclDocument d = with_expressions(
      "      a = b + 1\n"            // line 4
      "      b = a * 2\n"            // line 5
      "      wave = sin(t)\n"        // line 6
      "      fx = force_x()@hull\n"  // line 7
      "      speed = 2 [m s^-1]\n"   // line 8
      "      self = self\n");        // line 9
  const CelEvaluator cel(d);
  const auto refuses_not_constant = [&](const char* text, std::size_t line, const std::vector<std::string>& pieces) {
    EXPECT_THROW(cel.evaluate(text, line), CelNotConstant) << text;
    test::expect_input_error([&] { cel.evaluate(text, line); }, pieces);
  };
  refuses_not_constant("sin(0.5)", 30, {"e.ccl:30:", "'sin('", "function"});
  refuses_not_constant("2 * x", 31, {"e.ccl:31:", "'x'", "variable"});
  refuses_not_constant("Time", 32, {"e.ccl:32:", "'Time'"});
  refuses_not_constant("if(speed > 1 [m s^-1], 1, 2)", 33, {"e.ccl:33:", "'if('"});
  refuses_not_constant("area()@hull", 34, {"e.ccl:34:", "'area('"});
  refuses_not_constant("@hull", 35, {"e.ccl:35:", "locator"});
  refuses_not_constant("speed@inlet", 36, {"e.ccl:36:", "locator"});
  // Inside a referenced expression: the expression's own line.
  refuses_not_constant("2 * wave", 37, {"e.ccl:6:", "'sin('"});
  refuses_not_constant("fx", 38, {"e.ccl:7:", "'force_x('"});

  // A cycle is an error of the file, not a variable.
  test::expect_input_error([&] { cel.evaluate("a", 40); }, {"e.ccl:5:", "cycle", "a -> b -> a"});
  test::expect_input_error([&] { cel.evaluate("self", 41); }, {"e.ccl:9:", "cycle", "self -> self"});
  try {
    cel.evaluate("a", 40);
  } catch (const CelNotConstant&) {
    ADD_FAILURE() << "a cycle is not 'not constant'";
  } catch (const InputError&) {}
}

TEST(CfxCel, RefusesBadDimensionsAndSyntaxNamingFileAndLine) {
  const CclDocument d = with_expressions(
      "      pin = 1 [atm]\n"        // line 4
      "      bad = 1 [m] + 1 [s]\n"  // line 5
      "      v = pin\n");            // line 6
  const CelEvaluator cel(d);
  test::expect_input_error([&] { cel.evaluate("1 [m] + 1 [s]", 50); }, {"e.ccl:50:", "a sum of m and s"});
  test::expect_input_error([&] { cel.evaluate("1 [m] - 2", 51); }, {"e.ccl:51:", "difference"});
  test::expect_input_error([&] { cel.evaluate("bad", 52); }, {"e.ccl:5:", "a sum"});
  test::expect_input_error([&] { cel.evaluate("2 [furlong]", 53); }, {"e.ccl:53:", "furlong", "'2 [furlong]'"});
  test::expect_input_error([&] { cel.evaluate("2 [m", 54); }, {"e.ccl:54:", "']'"});
  test::expect_input_error([&] { cel.evaluate("(1 + 2", 55); }, {"e.ccl:55:", "')'"});
  test::expect_input_error([&] { cel.evaluate("1 + * 2", 56); }, {"e.ccl:56:", "'*'"});
  test::expect_input_error([&] { cel.evaluate("1 2", 57); }, {"e.ccl:57:", "'2'"});
  test::expect_input_error([&] { cel.evaluate("1 / 0", 58); }, {"e.ccl:58:", "division by zero"});
  test::expect_input_error([&] { cel.evaluate("(2 [m])^0.5", 59); }, {"e.ccl:59:", "whole power"});
  test::expect_input_error([&] { cel.evaluate("2^(1 [m])", 60); }, {"e.ccl:60:", "dimensionless exponent"});
  test::expect_input_error([&] { cel.evaluate("", 61); }, {"e.ccl:61:", "empty"});
  test::expect_input_error([&] { cel.evaluate("1e999", 62); }, {"e.ccl:62:", "1e999"});
  test::expect_input_error([&] { cel.evaluate("10^400", 63); }, {"e.ccl:63:", "infinite"});
  test::expect_input_error([&] { cel.evaluate(std::string(300, '(') + "1" + std::string(300, ')'), 64); },
                           {"e.ccl:64:", "nested"});

  // A velocity with the unit of a pressure, directly and through an expression.
  const CclDocument c = parse_ccl(
      "LIBRARY:\n CEL:\n  EXPRESSIONS:\n   pin = 1 [atm]\n  END\n END\nEND\n"
      "A:\n  U = pin\n  V = 2 [Pa]\n  W = 0\n  X = 1\nEND\n",
      "v.ccl");
  const CelEvaluator cv(c);
  const CclObject* a = c.root.child("A");
  test::expect_input_error([&] { cv.evaluate_as(*a->parameter("U"), kVelocity, "a velocity"); },
                           {"v.ccl:9:", "'U = pin'", "kg m^-1 s^-2", "expected a velocity (m s^-1)"});
  test::expect_input_error([&] { cv.evaluate_as(*a->parameter("V"), kVelocity, "a velocity"); }, {"v.ccl:10:"});
  EXPECT_EQ(cv.evaluate_as(*a->parameter("W"), kVelocity, "a velocity"), 0.0);  // a bare 0 is 0 in any unit
  test::expect_input_error([&] { cv.evaluate_as(*a->parameter("X"), kVelocity, "a velocity"); },
                           {"v.ccl:12:", "has the unit 1"});
}

TEST(CfxCel, EvaluatesSharedReferencesOnce) {
  // Each expression doubles the one before: evaluated naively this would take
  // 2^60 steps; with each expression evaluated once it is immediate.
  std::string lines = "      e0 = 1\n";
  for (int i = 1; i <= 60; ++i)
    lines += "      e" + std::to_string(i) + " = e" + std::to_string(i - 1) + " + e" + std::to_string(i - 1) + "\n";
  const CclDocument d = with_expressions(lines);
  const CelEvaluator cel(d);
  EXPECT_EQ(cel.evaluate("e60", 1).value, std::ldexp(1.0, 60));

  std::string chain = "      c0 = 1\n";
  for (int i = 1; i <= 70; ++i) chain += "      c" + std::to_string(i) + " = c" + std::to_string(i - 1) + "\n";
  const CclDocument deep = with_expressions(chain);
  const CelEvaluator deep_cel(deep);
  test::expect_input_error([&] { deep_cel.evaluate("c70", 1); }, {"more than 64 deep"});
}

TEST(CfxCcl, ManyParametersAndObjectsAreEachFoundOnceAndMergedAsBefore) {
  // 200,000 parameters in one object and 20,000 objects beside each other
  // (9 MB): each parameter and object is a hash lookup, so this parses in
  // linear time (a scan per parameter took 166 s for 6.9 MB). Correctness on
  // the large input: every parameter and object found, a parameter written
  // again keeps its first place and its last value, an object written again
  // (its type in another case) is merged.
  std::string text = "LIBRARY:\n  CEL:\n    EXPRESSIONS:\n";
  constexpr int kParameters = 200000, kObjects = 20000;
  for (int i = 0; i < kParameters; ++i) text += "      p" + std::to_string(i) + " = " + std::to_string(i) + " [m]\n";
  text += "      p7 = 70 [m]\n      P7 = 7 [s]\n    END\n  END\nEND\nFLOW: f\n";
  for (int i = 0; i < kObjects; ++i)
    text += "  BOUNDARY: b" + std::to_string(i) + "\n    Location = l" + std::to_string(i) + "\n  END\n";
  text += "  boundary: b5\n    Location = again\n    Extra = 1\n  END\nEND\n";
  const CclDocument document = parse_ccl(text, "big.ccl");
  const CclObject& expressions = document.root.children[0].children[0].children[0];
  ASSERT_EQ(expressions.parameters.size(), static_cast<std::size_t>(kParameters) + 1);  // P7 differs in case
  EXPECT_EQ(expressions.parameters[7].name, "p7");
  EXPECT_EQ(expressions.parameters[7].value, "70 [m]");
  EXPECT_EQ(expressions.parameters[7].line, static_cast<std::size_t>(kParameters) + 4);
  EXPECT_EQ(expressions.parameters.back().name, "P7");
  EXPECT_EQ(expressions.parameters[123456].value, "123456 [m]");
  EXPECT_EQ(expressions.parameters[123456].line, 123456u + 4);
  const CclObject& flow = document.root.children[1];
  ASSERT_EQ(flow.children.size(), static_cast<std::size_t>(kObjects));
  EXPECT_EQ(flow.children[19999].label, "b19999");
  EXPECT_EQ(flow.children[5].type, "BOUNDARY");
  ASSERT_EQ(flow.children[5].parameters.size(), 2u);
  EXPECT_EQ(flow.children[5].parameters[0].value, "again");
  EXPECT_EQ(flow.children[5].parameter("extra")->value, "1");
  const CelEvaluator cel(document);
  EXPECT_EQ(cel.expression("p199999", 1).value, 199999.0);
  EXPECT_EQ(cel.expression("p7", 1).value, 70.0);
}

}  // namespace
}  // namespace hydrocoef
