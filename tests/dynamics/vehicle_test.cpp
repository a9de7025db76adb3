// Vehicle files: a complete description read back, the ASR-V example, and
// bad files (syntax, missing key, wrong type, negative mass, non-symmetric
// inertia, mass matrix not positive definite, unknown key, bad law, bad
// thruster) each failing with the file and the key in the message.
#include "src/dynamics/vehicle.hpp"

#include <gtest/gtest.h>

#include <numbers>
#include <string>

#include "src/dynamics/rigid_body.hpp"
#include "tests/support/expect_input_error.hpp"

namespace hydrocoef {
namespace {

using test::expect_input_error;

const std::string kValid = R"({
  // a comment
  "name": "box",
  "notes": ["one", "two"],
  "mass": 10.0,
  "inertia": [[1.0, 0.1, 0.0], [0.1, 2.0, 0.0], [0.0, 0.0, 3.0]],
  "center_of_gravity": [0.0, 0.0, 0.05],
  "displaced_volume": 0.011,
  "added_mass": {"diagonal": [1, 2, 3, 0.1, 0.2, 0.3]},
  "thrusters": [{"name": "t1", "position": [0.1, 0.2, 0.0], "direction": [0, 2, 0], "min_thrust": -2, "max_thrust": 3}],
  "damping": {
    "X": {"law": {"u": -1.5, "u|u|": -20.0, "1": 0.01}, "sign": "on-body"},
    "N": {"surface": "yaw", "output": "N", "axes": {"r": "r", "speed": "u"}, "sign": "opposing"}
  }
})";

TEST(Vehicle, ParsesEveryPart) {
  const VehicleDescription v = parse_vehicle(kValid, "box.json");
  EXPECT_EQ(v.name, "box");
  EXPECT_EQ(v.notes, "one\ntwo");
  EXPECT_EQ(v.mass_kg, 10.0);
  EXPECT_EQ(v.inertia_cg_b(0, 1), 0.1);
  EXPECT_EQ(v.r_g_b.z(), 0.05);
  EXPECT_NEAR(v.buoyancy_N, 998.2 * 9.81 * 0.011, 1e-12);
  EXPECT_EQ(v.added_mass_b(4, 4), 0.2);
  ASSERT_EQ(v.thrusters.size(), 1u);
  EXPECT_EQ(v.thrusters[0].direction_b, Vector3(0, 1, 0));
  EXPECT_EQ(v.thrusters[0].max_thrust_N, 3.0);
  const DofDamping& x = v.damping[0];
  ASSERT_EQ(x.kind, DofDamping::Kind::Law);
  EXPECT_EQ(x.law.variable, "u");
  // Each coefficient stays with its own term whatever the order of the keys.
  for (std::size_t k = 0; k < x.law.terms.size(); ++k) {
    const double expected = x.law.terms[k] == DampingTerm::Constant ? 0.01
                            : x.law.terms[k] == DampingTerm::Linear ? -1.5
                                                                    : -20.0;
    EXPECT_EQ(x.coefficients[k], expected);
  }
  const DofDamping& n = v.damping[5];
  ASSERT_EQ(n.kind, DofDamping::Kind::Surface);
  EXPECT_EQ(n.surface, "yaw");
  EXPECT_EQ(n.axis_sources.at("speed"), "u");
  EXPECT_EQ(n.sign, SignConvention::OpposingMotion);
  EXPECT_EQ(v.damping[1].kind, DofDamping::Kind::None);
}

TEST(Vehicle, AsrVExampleLoads) {
  const VehicleDescription v = load_vehicle(HYDROCOEF_SOURCE_DIR "/examples/asr-v/vehicle.json");
  EXPECT_EQ(v.mass_kg, 6.7);
  EXPECT_NEAR(v.buoyancy_N, 6.7 * 9.81, 1e-12);
  EXPECT_NEAR(v.added_mass_b(0, 0), 2.0 / 3.0 * std::numbers::pi * 998.2 * 0.15 * 0.15 * 0.15, 1e-12);
  EXPECT_EQ(v.thrusters.size(), 4u);
  EXPECT_GT(v.r_g_b.z(), v.r_b_b.z());  // CG below CB
  for (const auto& d : v.damping) EXPECT_EQ(d.kind, DofDamping::Kind::Law);
  EXPECT_NE(v.notes.find("ASSUMED"), std::string::npos);
  EXPECT_NE(v.notes.find("FROM THE PAPER"), std::string::npos);
}

std::string replaced(const std::string& from, const std::string& to) {
  std::string text = kValid;
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(Vehicle, BadFilesNameFileAndKey) {
  auto parse = [](const std::string& text) { return [text] { parse_vehicle(text, "bad.json"); }; };
  expect_input_error(parse(replaced("\"mass\": 10.0,", "")), {"bad.json", "'mass'", "missing"});
  expect_input_error(parse(replaced("\"mass\": 10.0", "\"mass\": \"10\"")),
                     {"bad.json", "'mass'", "string", "expected a number"});
  expect_input_error(parse(replaced("\"mass\": 10.0", "\"mass\": -1")), {"bad.json", "'mass'", "-1", "positive"});
  expect_input_error(parse(replaced("[0.1, 2.0, 0.0]", "[0.2, 2.0, 0.0]")), {"bad.json", "'inertia'", "symmetric"});
  expect_input_error(parse(replaced("[1, 2, 3, 0.1, 0.2, 0.3]", "[1, 2, 3, -5, 0.2, 0.3]")),
                     {"bad.json", "'added_mass'", "positive definite"});
  expect_input_error(parse(replaced("\"name\": \"box\"", "\"nmae\": \"box\"")), {"bad.json", "'nmae'", "unknown key"});
  expect_input_error(parse(replaced("\"u|u|\": -20.0", "\"r|r|\": -20.0")), {"bad.json", "'damping.X.law'", "r|r|"});
  expect_input_error(parse(replaced("\"sign\": \"on-body\"", "\"sign\": \"positive\"")),
                     {"bad.json", "'damping.X.sign'", "on-body"});
  expect_input_error(parse(replaced("\"min_thrust\": -2", "\"min_thrust\": 5")),
                     {"bad.json", "thrusters[0]", "min_thrust"});
  expect_input_error(parse(replaced("[0, 2, 0]", "[0, 0, 0]")), {"bad.json", "thrusters[0].direction", "zero"});
  expect_input_error(
      parse(replaced("\"displaced_volume\": 0.011", "\"neutrally_buoyant\": true, \"buoyancy_force\": 9")),
      {"bad.json", "exactly one"});
  expect_input_error(parse(replaced("\"mass\": 10.0,", "\"mass\": 10.0")), {"bad.json:6:", "JSON"});
  expect_input_error([] { load_vehicle("/nonexistent/vehicle.json"); }, {"/nonexistent/vehicle.json", "cannot read"});
}

}  // namespace
}  // namespace hydrocoef
