// Scaling a resistance curve with the ITTC-1957 line and a form factor
// (src/derivatives/scaling.hpp): the line against published tables, a
// model-to-ship extrapolation worked by hand, round trips, a submerged body's
// consistency, Prohaska's plot on synthetic data, a surge law, and every
// refusal with its message.
#include "src/derivatives/scaling.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "src/core/error.hpp"

#include "tests/support/expect_input_error.hpp"

namespace hydrocoef {
namespace {

using test::input_error_message;

double relative_error(double value, double expected) { return std::abs(value - expected) / std::abs(expected); }

// The same line written out here, for synthetic data.
double line(double reynolds) { return 0.075 / std::pow(std::log10(reynolds) - 2.0, 2); }

constexpr double kFreshNu = 1.13902e-6;  // m^2/s, fresh water at 15 C (the ITTC value Morrall's example uses)
constexpr double kSeaNu = 1.18831e-6;    // m^2/s, sea water at 15 C (ITTC)

ScaleConditions model_tank() { return {5.0, 4.0, kFreshNu, 999.1, 0.0, 0.0}; }
ScaleConditions ship_sea() { return {125.0, 2500.0, kSeaNu, 1025.9, 0.0, 0.0}; }

// Tupper, "Introduction to Naval Architecture" (4th ed.), Table 8.3
// "Coefficients for the ITTC 1957 model-ship correlation line", p. 191
// (digilib.universitaspertamina.ac.id/ebook/Introduction%20to%20Naval%20Architecture/files/basic-html/page205.html),
// printed to four significant digits. The scan reads 0.002085 at Re = 1e8,
// where the formula gives 0.075/36 = 0.0020833: a misprint or a misread
// digit, so that entry is checked against the formula (below), not the table.
TEST(Ittc1957Line, TuppersTable) {
  const struct {
    double reynolds;
    double printed;
  } table[] = {{1e5, 0.008333}, {5e5, 0.005482}, {1e6, 0.004688}, {5e6, 0.003397},  {1e7, 0.003000}, {5e7, 0.002309},
               {5e8, 0.001671}, {1e9, 0.001531}, {5e9, 0.001265}, {1e10, 0.001172}, {5e10, 0.000991}};
  for (const auto& row : table) {
    // Half a unit of the last printed digit (1e6: 0.0046875 rounds up to 0.004688).
    EXPECT_NEAR(ittc1957_friction(row.reynolds), row.printed, 0.5e-6 * (1 + 1e-9)) << row.reynolds;
  }
}

// Morrall (1970), "1957 ITTC model-ship correlation line values of frictional
// resistance coefficient", NPL Ship Report 142 (scribd.com/document/379886867),
// worked example: a model at 1.5 m/s in water of nu = 1.13902e-6 m^2/s,
// "Model R_n = 5.62 x 10^6 ... Model C_F = 3.325 x 10^-3" (from its Table 2).
// The model's length is not legible in the scan; 14 ft = 4.2672 m gives the
// printed Re: Re = 1.5 * 4.2672 / 1.13902e-6 = 5.619567e6, where the line
// gives 3.324516e-3, printed 3.325e-3. (At Re = 5.62e6 exactly it gives
// 3.324469e-3: the rounded Re sits just past the point, 5.619712e6, where
// C_F rounds to 3.324e-3, so the unrounded Re is the one to use.)
TEST(Ittc1957Line, MorrallsExample) {
  const double reynolds = 1.5 * 4.2672 / kFreshNu;
  EXPECT_NEAR(reynolds, 5.62e6, 0.005e6);
  EXPECT_NEAR(ittc1957_friction(reynolds), 3.325e-3, 0.5e-6);
  EXPECT_NEAR(ittc1957_friction(reynolds), 3.324516e-3, 0.5e-9);
}

// Points where the formula is exact: log10 Re - 2 = 3, 4, 5, 6.
TEST(Ittc1957Line, ExactPoints) {
  EXPECT_NEAR(ittc1957_friction(1e5), 0.075 / 9.0, 1e-18);
  EXPECT_EQ(ittc1957_friction(1e6), 0.075 / 16.0);  // a power of two: exact in binary
  EXPECT_NEAR(ittc1957_friction(1e7), 0.003, 1e-18);
  EXPECT_NEAR(ittc1957_friction(1e8), 0.075 / 36.0, 1e-18);
  // Decreasing in Re.
  EXPECT_GT(ittc1957_friction(2e6), ittc1957_friction(3e6));
}

TEST(Ittc1957Line, RefusesLowAndNonFiniteReynolds) {
  for (const double reynolds : {99'999.0, 1e4, 100.0, 0.0, -1.0, std::nan("")}) {
    const std::string message = input_error_message([&] { ittc1957_friction(reynolds, "run 2"); });
    EXPECT_NE(message.find("run 2: the Reynolds number"), std::string::npos) << message;
    EXPECT_NE(message.find("is below 100000, the lowest the ITTC-1957 line is used at"), std::string::npos) << message;
  }
  EXPECT_NO_THROW(ittc1957_friction(kIttc1957MinimumReynolds));
}

// ITTC 1978: dC_F = (105 (k_s/L)^(1/3) - 0.64) 10^-3, C_AA = 0.001 A_T/S.
// k_s = 150e-6 m, L = 125 m: (150e-6/125)^(1/3) = (1.2e-6)^(1/3) = 0.010626586,
// 105 * 0.010626586 = 1.1157915, less 0.64 = 0.4757915 -> dC_F = 4.757915e-4.
TEST(Ittc1978Allowances, RoughnessAndAir) {
  EXPECT_NEAR(ittc1978_roughness_allowance(150e-6, 125.0), 4.757915e-4, 1e-10);
  EXPECT_DOUBLE_EQ(ittc1978_air_resistance(300.0, 2500.0), 1.2e-4);
  EXPECT_NE(input_error_message([] { ittc1978_roughness_allowance(0.0, 125.0); }).find("k_s = 0 m"), std::string::npos);
  EXPECT_NE(input_error_message([] { ittc1978_air_resistance(300.0, -1.0); }).find("S = -1 m^2"), std::string::npos);
}

// A model-to-ship extrapolation worked by hand (no published example with
// legible digits was found: Tupper's (4th ed., pp. 194-195) prints its
// equations as images). Every number below was computed to 30 digits
// (mpmath) from the data and the formulas of the header, printed here to 7
// significant digits; the test checks the code's values to those digits.
//
// Model (fresh water, 15 C): L = 5 m, S = 4 m^2, nu = 1.13902e-6 m^2/s,
// rho = 999.1 kg/m^3; run: U = 1.5 m/s, X = -30 N (on the body), R = 30 N.
// Ship (sea water, 15 C): scale 25, L = 125 m, S = 2500 m^2,
// nu = 1.18831e-6 m^2/s, rho = 1025.9 kg/m^3, dC_F for k_s = 150e-6 m.
// Form factor 1 + k = 1.15 (given); surface ship: C_W at equal Froude number.
//   Fn    = 1.5 / sqrt(9.80665 * 5)            = 0.2142130
//   Re_m  = 1.5 * 5 / 1.13902e-6               = 6584608   (6.584608e6)
//   C_Fm  = 0.075 / (log10 6.584608e6 - 2)^2   = 3.230220e-3
//   C_Tm  = 30 / (0.5 * 999.1 * 4 * 1.5^2)     = 6.672672e-3
//   C_W   = C_Tm - 1.15 C_Fm                   = 2.957919e-3
//   U_s   = 1.5 sqrt(125 / 5)                  = 7.5 m/s
//   Re_s  = 7.5 * 125 / 1.18831e-6             = 7.889355e8
//   C_Fs  = 0.075 / (log10 7.889355e8 - 2)^2   = 1.576651e-3
//   dC_F  = (105 (150e-6/125)^(1/3) - 0.64)e-3 = 4.757915e-4
//   C_Ts  = 1.15 C_Fs + C_W + dC_F             = 5.246859e-3
//   R_s   = 0.5 * 1025.9 * 2500 * 7.5^2 * C_Ts = 378474.8 N, X_s = -378474.8 N
TEST(Scaling, WorkedModelToShip) {
  ScalingOptions options;
  options.from = model_tank();
  options.to = ship_sea();
  options.to.roughness_allowance = ittc1978_roughness_allowance(150e-6, 125.0);
  options.wave = {WaveStatement::FroudeMatched, 0.0};
  options.form_factor = given_form_factor(1.15);
  const std::vector<ResistanceRun> runs{{1.5, -30.0}};
  const ScalingResult result = scale_resistance(runs, options);
  ASSERT_EQ(result.points.size(), 1U);
  const ScaledPoint& p = result.points[0];
  const double digits = 5e-7;  // half a unit of the 7th significant digit, relative
  EXPECT_LT(relative_error(p.froude_from, 0.2142130), digits);
  EXPECT_LT(relative_error(p.froude_to, 0.2142130), digits);
  EXPECT_LT(relative_error(p.reynolds_from, 6.584608e6), digits);
  EXPECT_LT(relative_error(p.friction_from, 3.230220e-3), digits);
  EXPECT_LT(relative_error(p.total_from, 6.672672e-3), digits);
  EXPECT_LT(relative_error(p.wave, 2.957919e-3), digits);
  EXPECT_DOUBLE_EQ(p.speed_to, 7.5);
  EXPECT_LT(relative_error(p.reynolds_to, 7.889355e8), digits);
  EXPECT_LT(relative_error(p.friction_to, 1.576651e-3), digits);
  EXPECT_LT(relative_error(p.total_to, 5.246859e-3), digits);
  EXPECT_LT(relative_error(p.resistance_to, 378474.8), digits);
  EXPECT_LT(relative_error(p.force_to, -378474.8), digits);
  EXPECT_EQ(p.residual, 0.0);
  EXPECT_DOUBLE_EQ(p.force_from, -30.0);
  EXPECT_DOUBLE_EQ(p.resistance_from, 30.0);

  // The assumptions, in words.
  std::string all;
  for (const std::string& line_text : result.assumptions) all += line_text + "\n";
  EXPECT_NE(all.find("C_W equal at equal Froude number"), std::string::npos) << all;
  EXPECT_NE(all.find("1+k = 1.15 (given), independent of scale and Reynolds number"), std::string::npos) << all;
  EXPECT_NE(all.find("scale 1: no roughness allowance, no air resistance"), std::string::npos) << all;
  EXPECT_NE(all.find("scale 2: roughness allowance dC_F = 0.000475791"), std::string::npos) << all;
  EXPECT_NE(all.find("resistance R = -X (forces on-body"), std::string::npos) << all;

  // A form factor larger than C_T/C_F gives a negative C_W, which is said.
  EXPECT_EQ(all.find("C_W < 0"), std::string::npos) << all;
  ScalingOptions too_large = options;
  too_large.form_factor = given_form_factor(2.5);  // 2.5 C_Fm = 8.08e-3 > C_Tm = 6.67e-3
  std::string said;
  for (const std::string& text : scale_resistance(runs, too_large).assumptions) said += text + "\n";
  EXPECT_NE(said.find("C_W < 0 at run(s) 1: (1+k) C_F exceeds their C_T"), std::string::npos) << said;

  // The same run given as a resistance magnitude: the same coefficients, a positive force out.
  options.convention = SignConvention::OpposingMotion;
  const std::vector<ResistanceRun> magnitudes{{1.5, 30.0}};
  const ScalingResult opposing = scale_resistance(magnitudes, options);
  EXPECT_EQ(opposing.points[0].total_to, p.total_to);
  EXPECT_EQ(opposing.points[0].force_to, -p.force_to);
}

// Model runs over a speed range (a made-up curve, not on any formula) to a
// ship with allowances and back: the runs return to 1e-12.
TEST(Scaling, RoundTripFroudeMatched) {
  ScalingOptions there;
  there.from = model_tank();
  there.to = ship_sea();
  there.to.roughness_allowance = 3.1e-4;
  there.to.air_resistance = 8e-5;
  there.wave = {WaveStatement::FroudeMatched, 0.0};
  there.form_factor = given_form_factor(1.21);
  std::vector<ResistanceRun> runs;
  for (int i = 0; i < 12; ++i) {
    const double u = 0.4 + 0.2 * i;
    runs.push_back({u, -(9.0 * u * u + 0.7 * std::pow(u, 5) + 0.3 * std::sin(3.0 * u) + 0.5)});
  }
  const ScalingResult ship = scale_resistance(runs, there);
  std::vector<ResistanceRun> ship_runs;
  for (const ScaledPoint& p : ship.points) ship_runs.push_back({p.speed_to, p.force_to});

  ScalingOptions back = there;
  std::swap(back.from, back.to);
  const ScalingResult model = scale_resistance(ship_runs, back);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    EXPECT_LT(relative_error(model.points[i].speed_to, runs[i].speed), 1e-12) << i;
    EXPECT_LT(relative_error(model.points[i].force_to, runs[i].force), 1e-12) << i;
    EXPECT_LT(relative_error(model.points[i].wave, ship.points[i].wave), 1e-12) << i;
    // Equal Froude numbers at both scales.
    EXPECT_LT(relative_error(ship.points[i].froude_to, ship.points[i].froude_from), 1e-12) << i;
  }
}

// An AUV (deeply submerged): model 1 m long, CFD runs that follow the
// form-factor law only roughly (the residuals are carried), scaled to 4 m
// at chosen speeds and back.
TEST(Scaling, RoundTripSubmerged) {
  ScalingOptions there;
  there.from = {1.0, 1.2, 1.0e-6, 998.0, 0.0, 0.0};
  there.to = {4.0, 19.2, 1.19e-6, 1025.0, 2e-4, 0.0};
  there.wave = {WaveStatement::Submerged, 0.0};
  std::vector<ResistanceRun> runs;
  for (int i = 0; i < 8; ++i) {
    const double u = 0.5 + 0.25 * i;
    runs.push_back({u, -(0.5 * 998.0 * 1.2 * u * u * 1.3 * line(u / 1.0e-6)) * (1.0 + 0.02 * std::cos(5.0 * u))});
    there.target_speeds.push_back(1.1 * u + 0.3);
  }
  const ScalingResult big = scale_resistance(runs, there);
  EXPECT_EQ(big.form_factor.method, FormFactorMethod::MeanRatio);
  std::vector<ResistanceRun> big_runs;
  for (const ScaledPoint& p : big.points) big_runs.push_back({p.speed_to, p.force_to});

  ScalingOptions back = there;
  std::swap(back.from, back.to);
  back.form_factor = big.form_factor;
  back.target_speeds.clear();
  for (const ResistanceRun& run : runs) back.target_speeds.push_back(run.speed);
  const ScalingResult small = scale_resistance(big_runs, back);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    EXPECT_LT(relative_error(small.points[i].force_to, runs[i].force), 1e-12) << i;
    EXPECT_LT(std::abs(small.points[i].residual - big.points[i].residual), 1e-15) << i;
  }
}

// A submerged body whose model runs follow C_T = 1.3 C_F exactly: the mean
// ratio finds 1+k = 1.3; scaled to the model itself at the same speeds the
// forces are the data; at a larger scale C_T falls as C_F does, C_T/C_F
// staying 1+k.
TEST(Scaling, SubmergedConsistencyAndLargerScale) {
  const ScaleConditions model{1.0, 1.2, 1.0e-6, 998.0, 0.0, 0.0};
  std::vector<ResistanceRun> runs;
  std::vector<double> same_speeds;
  for (int i = 0; i < 6; ++i) {
    const double u = 0.3 + 0.4 * i;
    runs.push_back({u, -0.5 * 998.0 * 1.2 * u * u * 1.3 * line(u * 1.0 / 1.0e-6)});
    same_speeds.push_back(u);
  }
  const WaveResistance submerged = parse_wave_resistance("submerged");
  const FormFactor factor = mean_ratio_form_factor(runs, model, submerged, SignConvention::OnBody);
  EXPECT_NEAR(factor.one_plus_k, 1.3, 1e-13);
  EXPECT_EQ(factor.runs, 6U);
  EXPECT_NE(factor.text.find("mean of (C_T - C_W)/C_F over 6 runs, submerged (C_W = 0)"), std::string::npos)
      << factor.text;

  ScalingOptions self;
  self.from = model;
  self.to = model;
  self.wave = submerged;
  self.target_speeds = same_speeds;
  const ScalingResult same = scale_resistance(runs, self);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    EXPECT_LT(relative_error(same.points[i].force_to, runs[i].force), 1e-12) << i;
    EXPECT_LT(std::abs(same.points[i].residual), 1e-15) << i;
  }

  ScalingOptions larger = self;
  larger.to = {8.0, 76.8, 1.0e-6, 998.0, 0.0, 0.0};  // 8 times longer, same water, same speeds
  const ScalingResult big = scale_resistance(runs, larger);
  for (const ScaledPoint& p : big.points) {
    EXPECT_LT(p.friction_to, p.friction_from);
    EXPECT_LT(p.total_to, p.total_from);
    EXPECT_NEAR(p.total_to / p.friction_to, 1.3, 1e-12);
    EXPECT_NEAR(p.total_from / p.friction_from, 1.3, 1e-12);
    EXPECT_EQ(p.wave, 0.0);
  }
  std::string all;
  for (const std::string& text : big.assumptions) all += text + "\n";
  EXPECT_NE(all.find("deeply submerged body: no wave resistance (C_W = 0)"), std::string::npos) << all;
  EXPECT_NE(all.find("residual) is carried unchanged"), std::string::npos) << all;
}

// Runs generated from C_T = (1+k) C_F + c Fn^4 with 1+k = 1.12, c = 0.9
// (model at Fn 0.08 to 0.2): Prohaska's plot finds both to 1e-10.
TEST(Scaling, ProhaskaRecoversFormFactorAndSlope) {
  const ScaleConditions model = model_tank();
  const double g = 9.80665;
  std::vector<ResistanceRun> runs;
  for (int i = 0; i < 7; ++i) {
    const double froude = 0.08 + 0.02 * i;
    const double u = froude * std::sqrt(g * model.length);
    const double total = 1.12 * line(u * model.length / model.kinematic_viscosity) + 0.9 * std::pow(froude, 4);
    runs.push_back({u, -0.5 * model.density * model.wetted_area * u * u * total});
  }
  const FormFactor factor = prohaska_form_factor(runs, model, SignConvention::OnBody, g);
  EXPECT_NEAR(factor.one_plus_k, 1.12, 1e-10);
  EXPECT_NEAR(factor.prohaska_slope, 0.9, 1e-10 * 0.9);
  EXPECT_EQ(factor.method, FormFactorMethod::Prohaska);
  EXPECT_NE(factor.text.find("Prohaska's plot"), std::string::npos);

  // With a model-scale allowance in the data, the allowance is taken out first.
  ScaleConditions rough = model;
  rough.roughness_allowance = 2e-4;
  std::vector<ResistanceRun> rough_runs = runs;
  for (ResistanceRun& run : rough_runs)
    run.force -= 0.5 * model.density * model.wetted_area * run.speed * run.speed * 2e-4;
  EXPECT_NEAR(prohaska_form_factor(rough_runs, rough, SignConvention::OnBody, g).one_plus_k, 1.12, 1e-10);
}

// The surge law X = a u + b u|u|: scaled to itself it is unchanged; scaled
// Froude-wise to the ship its scaled points are fitted closely, and the
// law's coefficients follow the scale (b grows about as lambda^3 * C_T ratio).
TEST(Scaling, SurgeLaw) {
  const DampingLawSpec spec = parse_damping_terms("u,u|u|");
  const std::vector<double> coefficients{-2.0, -12.0};  // on-body: X = -2 u - 12 u|u|
  const std::vector<double> speeds{0.6, 0.9, 1.2, 1.5, 1.8, 2.1};

  ScalingOptions identity;
  identity.from = model_tank();
  identity.to = model_tank();
  identity.wave = {WaveStatement::FroudeMatched, 0.0};
  identity.form_factor = given_form_factor(1.1);
  const ScaledLaw same = scale_damping_law(spec, coefficients, speeds, identity);
  EXPECT_NEAR(same.coefficients[0], -2.0, 1e-12);
  EXPECT_NEAR(same.coefficients[1], -12.0, 1e-12);
  EXPECT_LT(same.max_relative_deviation, 1e-13);

  ScalingOptions ship = identity;
  ship.to = ship_sea();
  const ScaledLaw big = scale_damping_law(spec, coefficients, speeds, ship);
  ASSERT_EQ(big.curve.points.size(), speeds.size());
  // C_F falls with Re, so the ship's curve is not exactly a u + b u|u|: the
  // fit is close, not exact (2.5 % here).
  EXPECT_LT(big.max_relative_deviation, 0.05);
  EXPECT_GT(big.max_relative_deviation, 1e-4);
  for (const ScaledPoint& p : big.curve.points) {
    const double fitted = damping_law_value(big.spec.terms, big.coefficients, p.speed_to);
    EXPECT_LT(relative_error(fitted, p.force_to), big.max_relative_deviation + 1e-15);
    EXPECT_LT(p.force_to, 0.0);
  }

  EXPECT_NE(input_error_message([&] {
              scale_damping_law(parse_damping_terms("v,v|v|"), coefficients, speeds, ship);
            }).find("the law is in v, expected a surge law in u"),
            std::string::npos);
  EXPECT_NE(input_error_message([&] {
              scale_damping_law(spec, std::vector<double>{1.0}, speeds, ship);
            }).find("1 coefficients for the 2 terms u,u|u|"),
            std::string::npos);
  EXPECT_NE(input_error_message([&] {
              scale_damping_law(spec, coefficients, std::vector<double>{1.0}, ship);
            }).find("1 sample speeds for the 2 terms u,u|u|: give at least as many speeds as terms"),
            std::string::npos);
  EXPECT_NE(input_error_message([&] {
              scale_damping_law(spec, coefficients, std::vector<double>{1.0, 1.0}, ship);
            }).find("cannot tell the terms u,u|u| apart"),
            std::string::npos);
  EXPECT_NE(input_error_message([&] {
              scale_damping_law(spec, coefficients, std::vector<double>{1.0, -1.0}, ship);
            }).find("the sample speed -1 is not finite and positive"),
            std::string::npos);
}

TEST(Scaling, WaveStatementParsing) {
  EXPECT_EQ(parse_wave_resistance(" Submerged ").statement, WaveStatement::Submerged);
  EXPECT_EQ(parse_wave_resistance("froude").statement, WaveStatement::FroudeMatched);
  const WaveResistance given = parse_wave_resistance("0.0004");
  EXPECT_EQ(given.statement, WaveStatement::Given);
  EXPECT_EQ(given.coefficient, 0.0004);
  EXPECT_EQ(describe(given), "C_W = 0.0004 (given)");
  for (const char* text : {"", "surface", "-0.001", "nan"}) {
    const std::string message = input_error_message([&] { parse_wave_resistance(text); });
    EXPECT_NE(message.find("expected 'submerged' (C_W = 0), 'froude' (C_W from the runs at equal Froude number) or a "
                           "wave-resistance coefficient C_W >= 0"),
              std::string::npos)
        << message;
  }
}

// A given C_W: in the mean-ratio form factor and equal at both scales.
TEST(Scaling, GivenWaveCoefficient) {
  const ScaleConditions model{1.0, 1.2, 1.0e-6, 998.0, 0.0, 0.0};
  std::vector<ResistanceRun> runs;
  std::vector<double> speeds;
  for (int i = 0; i < 4; ++i) {
    const double u = 0.5 + 0.5 * i;
    runs.push_back({u, -0.5 * 998.0 * 1.2 * u * u * (1.25 * line(u / 1.0e-6) + 4e-4)});
    speeds.push_back(2.0 * u);
  }
  ScalingOptions options;
  options.from = model;
  options.to = {3.0, 10.8, 1.0e-6, 998.0, 0.0, 0.0};
  options.wave = parse_wave_resistance("4e-4");
  options.target_speeds = speeds;
  const ScalingResult result = scale_resistance(runs, options);
  EXPECT_NEAR(result.form_factor.one_plus_k, 1.25, 1e-13);
  for (const ScaledPoint& p : result.points) {
    EXPECT_EQ(p.wave, 4e-4);
    EXPECT_NEAR(p.total_to, 1.25 * p.friction_to + 4e-4, 1e-15);
  }
}

// Every refusal, each with its one-line message.
TEST(Scaling, Refusals) {
  const std::vector<ResistanceRun> runs{{1.5, -30.0}, {2.0, -50.0}};
  ScalingOptions good;
  good.from = model_tank();
  good.to = ship_sea();
  good.wave = {WaveStatement::FroudeMatched, 0.0};
  good.form_factor = given_form_factor(1.15);
  ASSERT_NO_THROW(scale_resistance(runs, good));

  const auto refused = [&](const std::function<void(ScalingOptions&)>& change,
                           const std::vector<ResistanceRun>& with = {}) {
    ScalingOptions options = good;
    change(options);
    const std::vector<ResistanceRun>& used = with.empty() ? runs : with;
    const std::string message = input_error_message([&] { scale_resistance(used, options); });
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    return message;
  };

  EXPECT_EQ(refused([](ScalingOptions& o) { o.wave = {}; }),
            "scaling: wave resistance not stated: say 'submerged' (deeply submerged body, C_W = 0), give a "
            "wave-resistance coefficient C_W, or say 'froude' (surface ship: C_W from the runs at equal Froude "
            "number)");
  EXPECT_EQ(refused([](ScalingOptions& o) { o.from.length = 0.0; }),
            "scaling, scale 1: the length L = 0 is not finite and positive: give the body's length in m (waterline "
            "length of a ship)");
  EXPECT_EQ(refused([](ScalingOptions& o) { o.to.wetted_area = -3.0; }),
            "scaling, scale 2: the wetted area S = -3 is not finite and positive: give the wetted surface area in "
            "m^2");
  EXPECT_EQ(refused([](ScalingOptions& o) { o.from.kinematic_viscosity = 0.0; }),
            "scaling, scale 1: the kinematic viscosity nu = 0 is not finite and positive: give the water's viscosity "
            "in m^2/s (about 1.1e-6)");
  EXPECT_EQ(refused([](ScalingOptions& o) { o.to.density = std::nan(""); }),
            "scaling, scale 2: the density rho = nan is not finite and positive: give the water's density in kg/m^3");
  EXPECT_NE(refused([](ScalingOptions& o) {
              o.to.roughness_allowance = INFINITY;
            }).find("scale 2: the roughness allowance dC_F = inf is not finite"),
            std::string::npos);
  EXPECT_NE(refused([](ScalingOptions& o) { o.gravity = 0.0; }).find("the acceleration of gravity g = 0"),
            std::string::npos);
  EXPECT_EQ(refused([](ScalingOptions& o) { o.form_factor.reset(); }),
            "scaling: form factor not given: with C_W at equal Froude number give 1+k, or estimate it with "
            "Prohaska's plot over the model's low-speed runs");
  EXPECT_EQ(refused([](ScalingOptions& o) {
              o.target_speeds = {1.0, 2.0};
            }),
            "scaling: 2 target speeds given, but with C_W at equal Froude number the speeds at scale 2 follow from "
            "U_2 = U_1 sqrt(L_2/L_1): give none");
  EXPECT_EQ(refused([](ScalingOptions& o) {
              o.wave = {WaveStatement::Submerged, 0.0};
            }),
            "scaling: 0 target speeds for 2 runs: with submerged (C_W = 0) give the speed at scale 2 of each run "
            "(the Froude number does not pair them)");
  EXPECT_EQ(refused([](ScalingOptions& o) {
              o.wave = {WaveStatement::Submerged, 0.0};
              o.target_speeds = {1.0, 0.0};
            }),
            "scaling, scale 2, run 2 (u = 2 m/s): the target speed 0 is not finite and positive: give ahead speeds in "
            "m/s");
  EXPECT_EQ(refused([](ScalingOptions& o) {
              o.wave = {WaveStatement::Given, -1e-4};
            }),
            "scaling: the wave-resistance coefficient C_W = -0.0001 is not finite and non-negative: give C_W >= 0");
  EXPECT_EQ(refused([](ScalingOptions& o) { o.form_factor->one_plus_k = 0.0; }),
            "scaling: the form factor 1+k = 0 is not finite and positive: give 1+k");
  EXPECT_EQ(refused([](ScalingOptions&) {}, {{1.5, 30.0}}),
            "scaling, scale 1, run 1 (u = 1.5 m/s): the force X = 30 N (on-body) does not oppose the motion: an "
            "on-body surge force is negative for u > 0; check the sign convention");
  EXPECT_EQ(refused([](ScalingOptions& o) { o.convention = SignConvention::OpposingMotion; }),
            "scaling, scale 1, run 1 (u = 1.5 m/s): the force X = -30 N (opposing) does not oppose the motion: a "
            "resistance magnitude is positive; check the sign convention");
  EXPECT_EQ(refused([](ScalingOptions&) {}, {{-1.5, 30.0}}),
            "scaling, scale 1, run 1 (u = -1.5 m/s): the speed is not finite and positive: give ahead speeds u > 0 in "
            "m/s");
  EXPECT_EQ(refused([](ScalingOptions&) {}, {{1.5, std::nan("")}}),
            "scaling, scale 1, run 1 (u = 1.5 m/s): the force X = nan is not finite: give the surge force in N");
  // Re = 0.01 * 5 / 1.13902e-6 = 43898 at the model.
  EXPECT_EQ(refused([](ScalingOptions&) {}, {{0.01, -0.001}}),
            "scaling, scale 1, run 1 (u = 0.01 m/s): the Reynolds number U L / nu = 43897.4 is below 100000, the "
            "lowest the ITTC-1957 line is used at (it describes turbulent flow): give a higher speed, a longer body "
            "or check the viscosity");
  // At scale 2 (a smaller model, slow, in viscous water): Re_2 = 0.3 * 0.2 / 1e-6 = 60000.
  EXPECT_EQ(refused([](ScalingOptions& o) {
              o.wave = {WaveStatement::Submerged, 0.0};
              o.to = {0.2, 0.05, 1e-6, 998.0, 0.0, 0.0};
              o.target_speeds = {0.3, 0.4};
            }),
            "scaling, scale 2, run 1 (u = 1.5 m/s): the Reynolds number U L / nu = 60000 is below 100000, the lowest "
            "the ITTC-1957 line is used at (it describes turbulent flow): give a higher speed, a longer body or check "
            "the viscosity");
  EXPECT_EQ(input_error_message([&] { scale_resistance({}, good); }),
            "scaling: no runs given: give the runs (speed, force) at scale 1");

  // Form-factor estimates.
  EXPECT_EQ(input_error_message([&] { given_form_factor(-1.0); }),
            "scaling: the form factor 1+k = -1 is not finite and positive: give 1+k (about 1.05 to 1.5 for a hull)");
  EXPECT_EQ(input_error_message([&] {
              prohaska_form_factor(std::vector<ResistanceRun>{{1.5, -30.0}}, model_tank(), SignConvention::OnBody);
            }),
            "Prohaska's plot: 1 run(s) given: give two or more low-speed runs at different Froude numbers");
  EXPECT_EQ(input_error_message([&] {
              prohaska_form_factor(std::vector<ResistanceRun>{{1.5, -30.0}, {1.5, -31.0}}, model_tank(),
                                   SignConvention::OnBody);
            }),
            "Prohaska's plot: the 2 runs are at one Froude number: give runs at two or more speeds");
  EXPECT_NE(input_error_message([&] {
              // Resistance growing far faster than Fn^4 allows: a negative intercept (-0.56).
              prohaska_form_factor(std::vector<ResistanceRun>{{1.0, -1.0}, {2.0, -300.0}}, model_tank(),
                                   SignConvention::OnBody);
            }).find("is not positive: the runs do not follow C_T/C_F = (1+k) + c Fn^4/C_F"),
            std::string::npos);
  EXPECT_EQ(input_error_message([&] {
              mean_ratio_form_factor(runs, model_tank(), {WaveStatement::FroudeMatched, 0.0}, SignConvention::OnBody);
            }),
            "form factor: the mean of C_T/C_F needs a known C_W (submerged or given); with C_W at equal Froude "
            "number give 1+k or use Prohaska's plot over low-speed runs");
  EXPECT_NE(input_error_message([&] {
              mean_ratio_form_factor(runs, model_tank(), {WaveStatement::Given, 0.5}, SignConvention::OnBody);
            }).find("C_W = 0.5 is larger than the runs' resistance"),
            std::string::npos);
  EXPECT_EQ(input_error_message([&] {
              mean_ratio_form_factor(std::vector<ResistanceRun>{}, model_tank(), {WaveStatement::Submerged, 0.0},
                                     SignConvention::OnBody);
            }),
            "form factor: no runs given: give one or more runs, or the form factor 1+k");
}

}  // namespace
}  // namespace hydrocoef
