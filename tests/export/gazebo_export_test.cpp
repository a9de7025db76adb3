// Gazebo export: the coefficients written for uuv_simulator's fossen model
// and gz-sim's Hydrodynamics system, parsed back with VTK's XML parser, equal
// what the fits give (opposing fits negated to on-body, FRD couplings turned
// into FLU ones); what the plugins cannot express is refused by name, and a
// refusal writes nothing.
#include "src/export/gazebo_export.hpp"

#include <gtest/gtest.h>
#include <vtkSmartPointer.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLUtilities.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <numbers>

#include "src/core/error.hpp"
#include "src/dynamics/rigid_body.hpp"
#include "tests/support/expect_input_error.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"
#include "tests/support/xml_numbers.hpp"

namespace hydrocoef {
namespace {

using test::expect_input_error;
using test::TempDir;

FitRecord make_fit(std::string name, std::string dof, std::string variable,
                   std::vector<std::pair<std::string, double>> coefficients,
                   SignConvention sign = SignConvention::OnBody) {
  static std::int64_t next_id = 1;
  FitRecord fit;
  fit.id = next_id++;
  fit.name = std::move(name);
  fit.body = "auv";
  fit.dof = std::move(dof);
  fit.variable = std::move(variable);
  for (std::size_t k = 0; k < coefficients.size(); ++k) fit.terms += (k ? "," : "") + coefficients[k].first;
  for (const auto& [term, value] : coefficients) fit.coefficients.push_back({term, value, std::nullopt});
  fit.sign = sign;
  fit.n = 5;
  fit.rmse = 0.01;
  fit.run_ids = {fit.id * 10, fit.id * 10 + 1};
  return fit;
}

// One on-body law per DOF in its own velocity: F = a x + b x|x|.
std::vector<FitRecord> diagonal_fits() {
  return {make_fit("auv:X", "X", "u", {{"u", -2.5}, {"u|u|", -30.25}}),
          make_fit("auv:Y", "Y", "v", {{"v", -4.0}, {"v|v|", -80.5}}),
          make_fit("auv:Z", "Z", "w", {{"w", -4.5}, {"w|w|", -90.0}}),
          make_fit("auv:K", "K", "p", {{"p", -0.1}, {"p|p|", -0.2}}),
          make_fit("auv:M", "M", "q", {{"q", -0.3}, {"q|q|", -0.7}}),
          make_fit("auv:N", "N", "r", {{"r", -0.35}, {"r|r|", -0.9}})};
}

GazeboRequest request_with_mass() {
  GazeboRequest request;
  request.body = "auv";
  request.added_mass = added_mass_diagonal({5.5, 12.0, 13.0, 0.25, 1.5, 1.75});
  request.added_mass_source = "diagonal 5.5,12,13,0.25,1.5,1.75";
  return request;
}

using test::number_of;
using test::numbers_of;
using test::read_xml;

TEST(GazeboExport, UuvFileRoundTripsToTheFittedCoefficients) {
  TempDir dir;
  const auto fits = diagonal_fits();
  const GazeboCoefficients coefficients = gazebo_coefficients(fits, request_with_mass());
  const auto path = dir / "auv-uuv.xml";
  write_gazebo(coefficients, {GazeboFlavor::Uuv}, path);

  const auto root = read_xml(path);
  ASSERT_NE(root, nullptr) << test::read_text(path);
  EXPECT_STREQ(root->GetName(), "hydrodynamic_model");
  ASSERT_NE(root->FindNestedElementWithName("type"), nullptr);
  EXPECT_STREQ(root->FindNestedElementWithName("type")->GetCharacterData(), "fossen");
  const auto linear = numbers_of(root, "linear_damping");
  const auto quadratic = numbers_of(root, "quadratic_damping");
  ASSERT_EQ(linear.size(), 6u);
  ASSERT_EQ(quadratic.size(), 6u);
  for (std::size_t i = 0; i < 6; ++i) {
    EXPECT_EQ(linear[i], fits[i].coefficients[0].value) << fits[i].name;
    EXPECT_EQ(quadratic[i], fits[i].coefficients[1].value) << fits[i].name;
  }
  EXPECT_EQ(numbers_of(root, "linear_damping_forward_speed"), std::vector<double>(6, 0.0));
  const auto added = numbers_of(root, "added_mass");
  ASSERT_EQ(added.size(), 36u);
  const Matrix6 expected = request_with_mass().added_mass;
  for (std::size_t k = 0; k < 36; ++k) EXPECT_EQ(added[k], expected(k / 6, k % 6)) << "entry " << k;

  // Provenance and conventions are in the file.
  const std::string text = test::read_text(path);
  for (const char* piece : {"fit 'auv:X' (id", "runs [", "on-body", "FRD",
                            "Added mass: diagonal 5.5,12,13,0.25,1.5,1.75", "N/(m/s)^2", "N m/(rad/s)"})
    EXPECT_NE(text.find(piece), std::string::npos) << "file lacks '" << piece << "'\n" << text;
}

TEST(GazeboExport, GzFileNegatesAnOpposingFitAndAddedMass) {
  TempDir dir;
  auto fits = diagonal_fits();
  // The ASR-V surge law as its table prints it: positive opposes motion.
  fits[0] = make_fit("auv:X-opposing", "X", "u", {{"u", 0.0155077}, {"u|u|", 11.0364}}, SignConvention::OpposingMotion);
  fits[0].body = "auv";
  const GazeboCoefficients coefficients = gazebo_coefficients(fits, request_with_mass());
  const auto path = dir / "auv-gz.sdf";
  GazeboWriteOptions options;
  options.flavor = GazeboFlavor::Gz;
  options.link_name = "hull";
  write_gazebo(coefficients, options, path);

  const auto root = read_xml(path);
  ASSERT_NE(root, nullptr) << test::read_text(path);
  EXPECT_STREQ(root->GetName(), "plugin");
  EXPECT_STREQ(root->GetAttribute("name"), "gz::sim::systems::Hydrodynamics");
  EXPECT_STREQ(root->FindNestedElementWithName("link_name")->GetCharacterData(), "hull");
  EXPECT_EQ(number_of(root, "xU"), -0.0155077);
  EXPECT_EQ(number_of(root, "xUabsU"), -11.0364);
  // Diagonal terms are the same in FLU and FRD.
  EXPECT_EQ(number_of(root, "yV"), -4.0);
  EXPECT_EQ(number_of(root, "yVabsV"), -80.5);
  EXPECT_EQ(number_of(root, "nR"), -0.35);
  EXPECT_EQ(number_of(root, "nRabsR"), -0.9);
  EXPECT_EQ(number_of(root, "mQabsQ"), -0.7);
  // SNAME added-mass derivatives are -Ma.
  EXPECT_EQ(number_of(root, "xDotU"), -5.5);
  EXPECT_EQ(number_of(root, "zDotW"), -13.0);
  EXPECT_EQ(number_of(root, "nDotR"), -1.75);
  // No couplings were given, so none is written.
  EXPECT_EQ(root->FindNestedElementWithName("xDotQ"), nullptr);
  EXPECT_EQ(root->FindNestedElementWithName("nV"), nullptr);
  const std::string text = test::read_text(path);
  EXPECT_NE(text.find("stored opposing, negated to on-body"), std::string::npos) << text;
  EXPECT_NE(text.find("FLU"), std::string::npos);
}

TEST(GazeboExport, GzCouplingsChangeSignFromFrdToFlu) {
  TempDir dir;
  auto fits = diagonal_fits();
  fits.push_back(make_fit("auv:Z(u)", "Z", "u", {{"u", 0.75}}));
  fits.push_back(make_fit("auv:N(v)", "N", "v", {{"v", -0.125}, {"v|v|", -0.5}}));
  GazeboRequest request = request_with_mass();
  request.fits = {{"Z", "auv:Z(u)"}, {"N", "auv:N(v)"}};
  request.added_mass(0, 4) = request.added_mass(4, 0) = 0.3;  // X-q coupling, kg m
  request.added_mass(1, 5) = request.added_mass(5, 1) = 0.2;  // Y-r coupling, kg m
  const GazeboCoefficients coefficients = gazebo_coefficients(fits, request);
  EXPECT_EQ(coefficients.linear_b(2, 0), 0.75);
  EXPECT_EQ(coefficients.linear_b(2, 2), -4.5);  // Z's own law is still chosen by default

  GazeboWriteOptions options;
  options.flavor = GazeboFlavor::Gz;
  write_gazebo(coefficients, options, dir / "flu.sdf");
  const auto flu = read_xml(dir / "flu.sdf");
  ASSERT_NE(flu, nullptr);
  EXPECT_EQ(number_of(flu, "zU"), -0.75);   // z flips, u does not
  EXPECT_EQ(number_of(flu, "nV"), -0.125);  // r and v both flip
  EXPECT_EQ(number_of(flu, "nVabsV"), -0.5);
  EXPECT_EQ(number_of(flu, "xDotQ"), 0.3);  // -(T Ma T)(x,q) = -(-0.3)
  EXPECT_EQ(number_of(flu, "mDotU"), 0.3);
  EXPECT_EQ(number_of(flu, "yDotR"), -0.2);  // y and r both flip
  EXPECT_EQ(number_of(flu, "zW"), -4.5);

  options.link_axes = GazeboLinkAxes::Frd;
  write_gazebo(coefficients, options, dir / "frd.sdf");
  const auto frd = read_xml(dir / "frd.sdf");
  ASSERT_NE(frd, nullptr);
  EXPECT_EQ(number_of(frd, "zU"), 0.75);
  EXPECT_EQ(number_of(frd, "xDotQ"), -0.3);
  EXPECT_EQ(number_of(frd, "yDotR"), -0.2);

  // uuv takes the linear coupling as a full 36-number matrix in FRD, and
  // refuses the quadratic one (it reads only the diagonal).
  expect_input_error([&] { write_gazebo(coefficients, {GazeboFlavor::Uuv}, dir / "uuv.xml"); },
                     {"N in v|v|", "only the diagonal of quadratic_damping", "nVabsV"});
  EXPECT_FALSE(std::filesystem::exists(dir / "uuv.xml"));
  fits.back() = make_fit("auv:N(v)", "N", "v", {{"v", -0.125}});
  write_gazebo(gazebo_coefficients(fits, request), {GazeboFlavor::Uuv}, dir / "uuv.xml");
  const auto uuv = read_xml(dir / "uuv.xml");
  ASSERT_NE(uuv, nullptr);
  const auto linear = numbers_of(uuv, "linear_damping");
  ASSERT_EQ(linear.size(), 36u);
  EXPECT_EQ(linear[6 * 2 + 0], 0.75);
  EXPECT_EQ(linear[6 * 5 + 1], -0.125);
  EXPECT_EQ(linear[6 * 0 + 0], -2.5);
  const auto added = numbers_of(uuv, "added_mass");
  ASSERT_EQ(added.size(), 36u);
  EXPECT_EQ(added[6 * 0 + 4], 0.3);
}

TEST(GazeboExport, LinearizeAtForwardSpeedWritesTheTangentSlope) {
  GazeboRequest request = request_with_mass();
  request.linearize_at = 0.5;
  const GazeboCoefficients c = gazebo_coefficients(diagonal_fits(), request);
  EXPECT_EQ(c.linear_b(0, 0), -2.5 + 2.0 * -30.25 * 0.5);  // d(b u|u|)/du at U0 = 2 b |U0|
  EXPECT_EQ(c.linear_b(5, 5), -0.35);                      // r0 = 0: the r|r| slope is 0
  EXPECT_TRUE((c.quadratic_b.array() == 0.0).all()) << c.quadratic_b;
  GazeboWriteOptions options;
  options.flavor = GazeboFlavor::Gz;
  const std::string text = gazebo_text(c, options);
  EXPECT_NE(text.find("<xU>-32.75</xU>"), std::string::npos) << text;
  EXPECT_NE(text.find("<xUabsU>0</xUabsU>"), std::string::npos);
  EXPECT_NE(text.find("linearised about forward speed U0 = 0.5 m/s"), std::string::npos);
}

TEST(GazeboExport, ConstantTermIsRefusedUnlessDroppedAndThenReported) {
  auto fits = diagonal_fits();
  fits[5] = make_fit("auv:N(1,r,r|r|)", "N", "r", {{"1", 1.89812e-05}, {"r", -0.00607516}, {"r|r|", -0.0771371}});
  expect_input_error([&] { gazebo_coefficients(fits, request_with_mass()); },
                     {"auv:N(1,r,r|r|)", "constant term '1'", "1.89812e-05", "--drop-constant"});
  GazeboRequest request = request_with_mass();
  request.drop_constant = true;
  const GazeboCoefficients c = gazebo_coefficients(fits, request);
  EXPECT_EQ(c.linear_b(5, 5), -0.00607516);
  EXPECT_EQ(c.quadratic_b(5, 5), -0.0771371);
  ASSERT_TRUE(c.sources[5].dropped_constant.has_value());
  EXPECT_EQ(*c.sources[5].dropped_constant, 1.89812e-05);
  const std::string text = gazebo_text(c, {GazeboFlavor::Uuv});
  EXPECT_NE(text.find("constant term 1.89812e-05 N m (on-body) of fit 'auv:N(1,r,r|r|)' dropped"), std::string::npos)
      << text;
}

TEST(GazeboExport, TermsTheFormatCannotExpressAreRefusedByName) {
  for (const auto& [term, why] : std::vector<std::pair<std::string, std::string>>{
           {"u^3", "is cubic"}, {"u^2", "is even in u"}, {"|u|", "is even in u"}}) {
    auto fits = diagonal_fits();
    fits[0] = make_fit("auv:X(u," + term + ")", "X", "u", {{"u", -1.0}, {term, -2.0}});
    expect_input_error([&] { gazebo_coefficients(fits, request_with_mass()); },
                       {"auv:X(u," + term + ")", "term '" + term + "'", why});
  }
}

TEST(GazeboExport, AddedMassMustBeSymmetricPositiveDefinite) {
  GazeboRequest request = request_with_mass();
  request.added_mass = added_mass_diagonal({5, 5, 5, 1, 1, -2});
  expect_input_error([&] { gazebo_coefficients(diagonal_fits(), request); },
                     {"not positive semi-definite", "smallest eigenvalue -2"});
  request.added_mass = Matrix6::Zero();
  expect_input_error([&] { gazebo_coefficients(diagonal_fits(), request); }, {"not positive semi-definite"});
  request.added_mass = added_mass_diagonal({5, 5, 5, 1, 1, 1});
  request.added_mass(1, 5) = 0.5;
  expect_input_error([&] { gazebo_coefficients(diagonal_fits(), request); },
                     {"not symmetric", "(2,6) = 0.5", "(6,2) = 0"});
  // Indefinite although every diagonal entry is positive: eigenvalues 1 +- 2.
  request.added_mass = added_mass_diagonal({1, 1, 5, 1, 1, 1});
  request.added_mass(0, 1) = request.added_mass(1, 0) = 2.0;
  try {
    check_added_mass(request.added_mass);
    ADD_FAILURE() << "an indefinite added mass was accepted";
  } catch (const InputError& error) {
    const std::string message = error.what();
    const auto at = message.find("smallest eigenvalue ");
    ASSERT_NE(at, std::string::npos) << message;
    EXPECT_NEAR(std::strtod(message.c_str() + at + 20, nullptr), -1.0, 1e-12) << message;
  }

  const Matrix6 sphere = sphere_added_mass(998.2, 0.15, Vector3(0.01, 0.02, 0.03));
  EXPECT_NEAR(sphere(0, 0), 2.0 / 3.0 * std::numbers::pi * 998.2 * 0.15 * 0.15 * 0.15, 1e-12);
  EXPECT_EQ(sphere(0, 0), sphere(1, 1));
  EXPECT_EQ(sphere(5, 5), 0.03);
  EXPECT_EQ(check_added_mass(sphere), "");
  // Without rotational entries: a sphere has none; the singular Ma is accepted with a note.
  const Matrix6 bare = sphere_added_mass(998.2, 0.15);
  EXPECT_EQ(bare(0, 0), sphere(0, 0));
  EXPECT_EQ(bare(3, 3), 0.0);
  EXPECT_EQ(bare(4, 4), 0.0);
  EXPECT_EQ(bare(5, 5), 0.0);
  const std::string note = check_added_mass(bare);
  EXPECT_NE(note.find("singular"), std::string::npos) << note;
  request = request_with_mass();
  request.added_mass = bare;
  const GazeboCoefficients coefficients = gazebo_coefficients(diagonal_fits(), request);
  EXPECT_TRUE(std::any_of(coefficients.notes.begin(), coefficients.notes.end(),
                          [](const std::string& n) { return n.find("Ma is singular") != std::string::npos; }));
}

TEST(GazeboExport, MissingAndAmbiguousFitsAreRefused) {
  auto fits = diagonal_fits();
  fits.erase(fits.begin() + 1, fits.begin() + 3);  // no Y, no Z
  expect_input_error([&] { gazebo_coefficients(fits, request_with_mass()); },
                     {"no damping law of Y in v, Z in w", "--allow-missing"});
  GazeboRequest request = request_with_mass();
  request.allow_missing = true;
  const GazeboCoefficients c = gazebo_coefficients(fits, request);
  EXPECT_EQ(c.missing_dofs, (std::vector<std::size_t>{1, 2}));
  EXPECT_EQ(c.linear_b(1, 1), 0.0);
  EXPECT_NE(gazebo_text(c, {GazeboFlavor::Uuv}).find("Y in v: no damping law; written as 0"), std::string::npos);

  fits = diagonal_fits();
  fits.push_back(make_fit("auv:X-huber", "X", "u", {{"u", -2.0}, {"u|u|", -31.0}}));
  expect_input_error([&] { gazebo_coefficients(fits, request_with_mass()); },
                     {"2 fits of X in u", "'auv:X'", "'auv:X-huber'", "--fit X=NAME"});
  request = request_with_mass();
  request.fits = {{"X", "auv:X-huber"}};
  EXPECT_EQ(gazebo_coefficients(fits, request).linear_b(0, 0), -2.0);
  request.fits = {{"X", "auv:nope"}};
  expect_input_error([&] { gazebo_coefficients(fits, request); }, {"no fit named 'auv:nope'", "auv:X-huber"});
  request.fits = {{"Y", "auv:X"}};
  expect_input_error([&] { gazebo_coefficients(fits, request); }, {"is a law of X, not Y"});
  request.fits = {{"X", "auv:X"}, {"X", "auv:X-huber"}};
  expect_input_error([&] { gazebo_coefficients(fits, request); }, {"X in u is already given by fit 'auv:X'"});
  // Another body's fit is not a candidate.
  fits.back().body = "other";
  EXPECT_NO_THROW(gazebo_coefficients(fits, request_with_mass()));
}

TEST(GazeboExport, RefusalsWriteNothingAndLeaveAnOldFileAlone) {
  TempDir dir;
  const auto path = dir / "out.sdf";
  {
    std::ofstream old(path);
    old << "old contents\n";
  }
  auto fits = diagonal_fits();
  fits.push_back(make_fit("auv:N(v)", "N", "v", {{"v|v|", -0.5}}));
  GazeboRequest request = request_with_mass();
  request.fits = {{"N", "auv:N(v)"}};
  const GazeboCoefficients coupled = gazebo_coefficients(fits, request);
  EXPECT_THROW(write_gazebo(coupled, {GazeboFlavor::Uuv}, path), InputError);
  GazeboWriteOptions no_link;
  no_link.link_name = "";
  EXPECT_THROW(write_gazebo(coupled, no_link, path), InputError);
  EXPECT_EQ(test::read_text(path), "old contents\n");
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir.path())) ++files;
  EXPECT_EQ(files, 1u) << "a temporary file was left behind";
  EXPECT_THROW(write_gazebo(coupled, {}, dir / "missing-dir" / "out.sdf"), InputError);
}

TEST(GazeboExport, AddedMassMatrixFileIsReadRowByRow) {
  TempDir dir;
  {
    std::ofstream file(dir / "ma.txt");
    file << "# Ma of the AUV, kg / kg m / kg m^2\n";
    for (int i = 0; i < 6; ++i) {
      // The anti-diagonal 0.25, and 7 at (X, v) only: rows are read as rows.
      for (int j = 0; j < 6; ++j)
        file << (i == j ? 10.0 + i : 0.0) + (i + j == 5 ? 0.25 : 0.0) + (i == 0 && j == 1 ? 7.0 : 0.0)
             << (j < 5 ? ", " : "");
      file << "  # row " << i << "\n";
    }
  }
  const Matrix6 ma = read_added_mass_matrix(dir / "ma.txt");
  EXPECT_EQ(ma(0, 0), 10.0);
  EXPECT_EQ(ma(0, 5), 0.25);
  EXPECT_EQ(ma(5, 5), 15.0);
  EXPECT_EQ(ma(0, 1), 7.0);
  EXPECT_EQ(ma(1, 0), 0.0);
  {
    std::ofstream file(dir / "bad.txt");
    file << "1 2 3\n4 five 6\n";
  }
  expect_input_error([&] { read_added_mass_matrix(dir / "bad.txt"); }, {"bad.txt:2:3", "'five'"});
  {
    std::ofstream file(dir / "short.txt");
    file << "1 2 3\n";
  }
  expect_input_error([&] { read_added_mass_matrix(dir / "short.txt"); }, {"short.txt", "3 numbers; expected 36"});
}

}  // namespace
}  // namespace hydrocoef
