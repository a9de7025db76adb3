// Scenario files: every part read back (degrees converted), the ASR-V
// example scenarios, and bad files failing with the file and the key.
#include "src/dynamics/scenario.hpp"

#include <gtest/gtest.h>

#include <numbers>

#include "tests/support/expect_input_error.hpp"

namespace hydrocoef {
namespace {

using test::expect_input_error;

const std::string kValid = R"({
  "name": "turn",
  "duration": 20,
  "output_rate": 50,
  "integrator": {"method": "dopri5", "rtol": 1e-7, "atol": 1e-9, "max_step": 0.05},
  "initial": {"position": [1, 2, 3], "euler_deg": [0, 90, 180], "velocity": [0.1, 0, 0, 0, 0, 0.2]},
  "segments": [
    {"start": 0, "tau": {"N": 0.0027, "X": 0.5}},
    {"start": 5, "thrusters": [0.1, -0.1], "current": [0.05, 0, 0]},
    {"start": 10.5, "thrusters": {"port": 0.2}, "disturbances": {"current_v": 0.05}}
  ]
})";

TEST(Scenario, ParsesEveryPart) {
  const Scenario s = parse_scenario(kValid, "turn.json");
  EXPECT_EQ(s.duration_s, 20.0);
  EXPECT_EQ(s.output_rate_Hz, 50.0);
  EXPECT_EQ(s.integrator.method, IntegratorSettings::Method::DormandPrince45);
  EXPECT_EQ(s.integrator.relative_tolerance, 1e-7);
  EXPECT_EQ(s.integrator.max_step_s, 0.05);
  EXPECT_EQ(s.initial_position_n, Vector3(1, 2, 3));
  EXPECT_NEAR(s.initial_euler_rad[1], std::numbers::pi / 2, 1e-15);
  EXPECT_NEAR(s.initial_euler_rad[2], std::numbers::pi, 1e-15);
  EXPECT_EQ(s.initial_nu_b[5], 0.2);
  ASSERT_EQ(s.segments.size(), 3u);
  EXPECT_EQ(s.segments[0].tau_b[5], 0.0027);
  EXPECT_EQ(s.segments[0].tau_b[0], 0.5);
  EXPECT_EQ(s.segments[1].thrust_N, (std::vector<double>{0.1, -0.1}));
  EXPECT_EQ(s.segments[1].current_n.x(), 0.05);
  EXPECT_EQ(s.segments[1].tau_b, Vector6::Zero());  // what a segment omits is zero
  EXPECT_EQ(s.segments[2].thrust_by_name_N.at("port"), 0.2);
  EXPECT_EQ(s.segments[2].disturbances.at("current_v"), 0.05);
}

TEST(Scenario, AsrVExamplesLoad) {
  for (const char* tau : {"0.0027", "0.0045"}) {
    const Scenario s = load_scenario(std::string(HYDROCOEF_SOURCE_DIR "/examples/asr-v/scenario-yaw-") + tau + ".json");
    ASSERT_EQ(s.segments.size(), 1u);
    EXPECT_EQ(s.segments[0].tau_b[5], std::stod(tau));
    EXPECT_EQ(s.integrator.method, IntegratorSettings::Method::Rk4);
  }
}

std::string replaced(const std::string& from, const std::string& to) {
  std::string text = kValid;
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(Scenario, BadFilesNameFileAndKey) {
  auto parse = [](const std::string& text) { return [text] { parse_scenario(text, "bad.json"); }; };
  expect_input_error(parse(replaced("\"duration\": 20,", "")), {"bad.json", "'duration'", "missing"});
  expect_input_error(parse(replaced("\"duration\": 20", "\"duration\": -20")), {"bad.json", "'duration'", "positive"});
  expect_input_error(parse(replaced("\"output_rate\": 50", "\"output_rate\": [50]")),
                     {"bad.json", "'output_rate'", "array"});
  expect_input_error(parse(replaced("\"dopri5\"", "\"euler\"")), {"bad.json", "'integrator.method'", "rk4"});
  expect_input_error(parse(replaced("\"start\": 0,", "\"start\": 1,")),
                     {"bad.json", "segments[0].start", "start at 0"});
  expect_input_error(parse(replaced("\"start\": 10.5", "\"start\": 4")), {"bad.json", "segments[2].start", "after"});
  expect_input_error(parse(replaced("\"N\": 0.0027", "\"Q\": 0.0027")),
                     {"bad.json", "segments[0].tau.Q", "unknown key"});
  expect_input_error(parse(replaced("[0.05, 0, 0]", "[0.05, 0]")), {"bad.json", "segments[1].current", "3 numbers"});
  expect_input_error(
      parse(replaced("\"euler_deg\": [0, 90, 180]", "\"euler_deg\": [0, 90, 180], \"euler_rad\": [0, 0, 0]")),
      {"bad.json", "initial.euler_deg", "not both"});
}

}  // namespace
}  // namespace hydrocoef
