// Comparison with a measured trajectory: the CSV reader (units, comments,
// errors), and on a synthetic experiment with a known answer: a first-order
// step response offset by a constant gives that constant as RMS and steady
// error, and the time constant as the 63 % time of both.
#include "src/dynamics/experiment.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <numbers>
#include <sstream>

#include "tests/support/expect_input_error.hpp"

namespace hydrocoef {
namespace {

using test::expect_input_error;

TEST(MeasuredTrajectory, ReadsUnitsAndIgnoresOtherColumns) {
  const MeasuredTrajectory m = parse_measured_trajectory(
      "# pool test\n"
      "time [ms];heading [deg];r [deg s^-1];u\n"
      "0;0;0;0.1\n"
      "500;1;9;0.2\n",
      "pool.csv");
  ASSERT_EQ(m.t_s.size(), 2u);
  EXPECT_EQ(m.t_s[1], 0.5);
  EXPECT_NEAR(m.nu_b[5][1], 9.0 * std::numbers::pi / 180.0, 1e-15);
  EXPECT_EQ(m.nu_b[0][1], 0.2);
  EXPECT_TRUE(m.nu_b[1].empty());
}

TEST(MeasuredTrajectory, BadFilesAreLocated) {
  expect_input_error([] { parse_measured_trajectory("x,r\n0,1\n1,2\n", "a.csv"); }, {"a.csv:1:", "no time column"});
  expect_input_error([] { parse_measured_trajectory("t,psi\n0,1\n1,2\n", "a.csv"); },
                     {"a.csv:1:", "no velocity column"});
  expect_input_error([] { parse_measured_trajectory("t [s],r [m s^-1]\n0,1\n1,2\n", "a.csv"); },
                     {"a.csv:1:", "'r'", "m s^-1"});
  expect_input_error([] { parse_measured_trajectory("t,r\n0,1\n0,2\n", "a.csv"); }, {"a.csv:3:", "increase"});
  expect_input_error([] { parse_measured_trajectory("t,r\n0,1\n1,x\n", "a.csv"); }, {"a.csv:3:", "x"});
  expect_input_error([] { parse_measured_trajectory("t,r\n0,1\n", "a.csv"); }, {"a.csv", "at least 2"});
}

TEST(Comparison, SyntheticFirstOrderExperiment) {
  const double r_ss = 0.15, time_constant = 2.0, offset = 0.01;
  auto response = [&](double t) { return r_ss * (1.0 - std::exp(-t / time_constant)); };
  std::vector<TrajectorySample> simulated;
  for (int k = 0; k <= 3000; ++k) {  // 30 s at 100 Hz
    TrajectorySample s;
    s.t_s = 0.01 * k;
    s.nu_b[5] = response(s.t_s);
    simulated.push_back(s);
  }
  std::ostringstream csv;
  csv << std::setprecision(17) << "t [s],r [rad s^-1]\n";
  for (int k = 0; k <= 2500; ++k) csv << 0.01 * k << "," << response(0.01 * k) + offset << "\n";  // 25 s
  csv << "40,0.5\n";  // outside the simulation: not compared
  const MeasuredTrajectory measured = parse_measured_trajectory(csv.str(), "synthetic.csv");
  const auto comparison = compare_with_experiment(measured, simulated);
  ASSERT_EQ(comparison.size(), 1u);
  const ComponentComparison& c = comparison[0];
  EXPECT_EQ(c.component, "r");
  EXPECT_EQ(c.samples, 2501u);
  EXPECT_NEAR(c.rms_error, offset, 1e-12);
  EXPECT_NEAR(c.steady_error, offset, 1e-12);
  // The last 20 % (20 to 25 s) is within e^-10 of steady.
  EXPECT_NEAR(c.steady_simulated, r_ss, 1e-5);
  // 63 % of the way from the start: the time constant (sampling at 10 ms, and
  // the steady value taken from the record, which is e^-10 short of r_ss).
  EXPECT_NEAR(c.t63_measured_s, time_constant, 2e-3);
  EXPECT_NEAR(c.t63_simulated_s, time_constant, 2e-3);
}

TEST(Comparison, TimeTo63PercentIsNaNWithoutChange) {
  EXPECT_TRUE(std::isnan(time_to_63_percent({0, 1, 2}, {1, 1, 1}, 1.0)));
  EXPECT_NEAR(time_to_63_percent({1, 2, 3}, {0, 0.5, 1.0}, 1.0), 1.0 + 2.0 * (1.0 - std::exp(-1.0)) - 1.0, 1e-15);
}

}  // namespace
}  // namespace hydrocoef
