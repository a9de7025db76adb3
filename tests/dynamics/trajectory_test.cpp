// Trajectory CSV: one header field per value, numbers that read back exactly,
// and a located error for a file that cannot be written.
#include "src/dynamics/trajectory.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "src/core/error.hpp"

namespace hydrocoef {
namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream in(line);
  std::string field;
  while (std::getline(in, field, ',')) out.push_back(field);
  return out;
}

TEST(Trajectory, CsvHasOneHeaderFieldPerValueAndRoundTrips) {
  TrajectorySample s;
  s.t_s = 0.1;
  s.p_n = Vector3(1.0 / 3.0, -2.0, 3.5);
  s.q_nb = Quaternion4(0.5, 0.5, 0.5, 0.5);
  s.euler_rad = Vector3(0.1, 0.2, 0.3);
  s.nu_b << 0.1, 0.2, 0.3, 0.4, 0.5, 0.6;
  s.forces.damping_b[5] = -0.0027;
  s.forces.nu_r_b[0] = 0.05;
  std::ostringstream out;
  write_trajectory_csv(out, {s, s});
  std::istringstream in(out.str());
  std::string header, row;
  std::getline(in, header);
  std::getline(in, row);
  const auto names = split(header);
  const auto values = split(row);
  ASSERT_EQ(names.size(), values.size());
  ASSERT_EQ(names.size(), 1u + 3 + 3 + 4 + 6 + 6 + 24);
  auto value_of = [&](const std::string& name) {
    for (std::size_t i = 0; i < names.size(); ++i)
      if (names[i] == name) return std::stod(values[i]);
    ADD_FAILURE() << "no column " << name;
    return 0.0;
  };
  EXPECT_EQ(value_of("t [s]"), 0.1);
  EXPECT_EQ(value_of("x_n [m]"), 1.0 / 3.0);
  EXPECT_EQ(value_of("r [rad s^-1]"), 0.6);
  EXPECT_EQ(value_of("N_damping [N m]"), -0.0027);
  EXPECT_EQ(value_of("u_r [m s^-1]"), 0.05);
  EXPECT_EQ(value_of("q_eps3"), 0.5);
}

TEST(Trajectory, UnwritableFileIsAnInputError) {
  EXPECT_THROW(write_trajectory_csv(std::filesystem::path("/nonexistent/dir/t.csv"), {}), InputError);
}

}  // namespace
}  // namespace hydrocoef
