// What a CFX case states about its run (src/pipeline/cfx_case): the free
// stream, rho, nu and p_ref in SI with the file and line of each, from a .ccl
// written in CFX-Pre's layout and from the CCL echoed in a solver output file
// (tests/data/cfx, see its PROVENANCE.md); the notes for symmetry and wall
// boundaries, normal-speed inlets, moving domains and properties that are not
// constant; a pressure-driven case's reason for stating no flow, kept for the
// import to check; and the refusals of inlets that disagree, a velocity that
// is not a constant or not a velocity.
#include "src/pipeline/cfx_case.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "src/core/error.hpp"
#include "tests/support/expect_input_error.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

namespace fs = std::filesystem;

const fs::path kData = fs::path(HYDROCOEF_SOURCE_DIR) / "tests" / "data" / "cfx";

std::string read_file(const fs::path& path) { return test::read_text(path); }

void write_file(const fs::path& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

/// The 1-based number of the nth line of `text` that contains `needle`.
std::size_t line_of(const std::string& text, const std::string& needle, int nth = 1) {
  std::istringstream in(text);
  std::string line;
  for (std::size_t number = 1; std::getline(in, line); ++number)
    if (line.find(needle) != std::string::npos && --nth == 0) return number;
  ADD_FAILURE() << "no line contains '" << needle << "'";
  return 0;
}

double number(const SettingsLayer& layer, const std::string& name) {
  const auto it = layer.values.find(name);
  if (it == layer.values.end()) {
    ADD_FAILURE() << "no setting " << name;
    return 0.0;
  }
  return std::get<double>(it->second.value);
}

std::string where(const SettingsLayer& layer, const std::string& name) {
  const auto it = layer.values.find(name);
  return it == layer.values.end() ? std::string("(none)") : it->second.origin.where;
}

bool has_note(const CfxCaseSettings& settings, const std::vector<std::string>& pieces) {
  for (const auto& note : settings.notes) {
    bool all = true;
    for (const auto& piece : pieces) all = all && note.find(piece) != std::string::npos;
    if (all) return true;
  }
  return false;
}

std::string notes_of(const CfxCaseSettings& settings) {
  std::string out;
  for (const auto& note : settings.notes) out += note + "\n";
  return out;
}

TEST(CfxCase, ReadsTheCclOfACfxPreCase) {
  const fs::path file = kData / "tow_case.ccl";
  const std::string text = read_file(file);
  const CfxCaseSettings s = cfx_case_settings(file);
  EXPECT_EQ(s.layer.origin.source, SettingSource::CaseFiles);
  EXPECT_EQ(s.layer.origin.where, file.string());

  // U = -Uinf, Uinf = towSpeedKnots * knot (a continuation line), knot = 1852 [m] / 1 [h].
  const auto& flow = std::get<std::vector<double>>(s.layer.values.at("flow").value);
  ASSERT_EQ(flow.size(), 3u);
  EXPECT_DOUBLE_EQ(flow[0], -1.2 * (1852.0 / 3600.0));
  EXPECT_EQ(flow[1], 0.0);
  EXPECT_EQ(flow[2], 0.0);
  EXPECT_EQ(where(s.layer, "flow"),
            file.string() + ":" + std::to_string(line_of(text, "Option = Cartesian Velocity Components") - 1));

  EXPECT_EQ(number(s.layer, "rho"), 997.0);
  EXPECT_EQ(where(s.layer, "rho"), file.string() + ":" + std::to_string(line_of(text, "Density = 997.0")));
  EXPECT_DOUBLE_EQ(number(s.layer, "nu"), 8.899e-4 / 997.0);
  EXPECT_EQ(where(s.layer, "nu"), file.string() + ":" + std::to_string(line_of(text, "Dynamic Viscosity = 8.899E-4")));
  EXPECT_EQ(number(s.layer, "p_ref"), 101325.0);  // 1 [atm]
  EXPECT_EQ(where(s.layer, "p_ref"),
            file.string() + ":" +
                std::to_string(line_of(text, "Reference Pressure = 1 [atm]", 2)));  // the domain's, not the material's
  EXPECT_EQ(s.layer.values.count("flow_speed"), 0u);

  EXPECT_TRUE(has_note(s, {"symmetry boundaries (centre plane)", "half or quarter model"})) << notes_of(s);
  EXPECT_TRUE(has_note(s, {"wall boundaries", "hull, tank walls"})) << notes_of(s);
}

TEST(CfxCase, CrlfGivesTheSameSettings) {
  test::TempDir dir;
  std::string crlf;
  for (const char c : read_file(kData / "tow_case.ccl")) {
    if (c == '\n') crlf += '\r';
    crlf += c;
  }
  write_file(dir / "tow_case.ccl", crlf);
  const CfxCaseSettings s = cfx_case_settings(dir / "tow_case.ccl");
  const auto& flow = std::get<std::vector<double>>(s.layer.values.at("flow").value);
  EXPECT_DOUBLE_EQ(flow[0], -1.2 * (1852.0 / 3600.0));
  EXPECT_EQ(number(s.layer, "p_ref"), 101325.0);
  EXPECT_EQ(where(s.layer, "rho"),
            (dir / "tow_case.ccl").string() + ":" + std::to_string(line_of(crlf, "Density = 997.0")));
}

TEST(CfxCase, ReadsTheCclEchoedInASolverOutputFileWithTheOutLines) {
  const fs::path file = kData / "tow_u1.5_001.out";
  const std::string text = read_file(file);
  EXPECT_TRUE(is_cfx_case_file(file));
  const CfxCaseSettings s = cfx_case_settings(file);
  const auto& flow = std::get<std::vector<double>>(s.layer.values.at("flow").value);
  EXPECT_EQ(flow, (std::vector<double>{1.5, 0.1, 0.0}));
  EXPECT_EQ(where(s.layer, "flow"),
            file.string() + ":" + std::to_string(line_of(text, "Option = Cartesian Velocity Components") - 1));
  EXPECT_EQ(number(s.layer, "p_ref"), 0.0);
  EXPECT_EQ(where(s.layer, "p_ref"),
            file.string() + ":" + std::to_string(line_of(text, "Reference Pressure = 0 [Pa]")));
  EXPECT_EQ(number(s.layer, "rho"), 997.0);
  EXPECT_DOUBLE_EQ(number(s.layer, "nu"), 8.899e-4 / 997.0);
  EXPECT_TRUE(has_note(s, {"wall boundaries", "hull"}));
  EXPECT_FALSE(has_note(s, {"symmetry"}));
}

TEST(CfxCase, DetectsCaseFiles) {
  test::TempDir dir;
  write_file(dir / "a.CCL", "FLOW: f\nEND\n");
  write_file(dir / "other.out", "a log of some other program\n+-----+\n");
  write_file(dir / "late.out", std::string(250, '\n') + read_file(kData / "tow_u1.5_001.out"));
  EXPECT_TRUE(is_cfx_case_file(kData / "tow_case.ccl"));
  EXPECT_TRUE(is_cfx_case_file(dir / "a.CCL"));
  EXPECT_TRUE(is_cfx_case_file(kData / "tow_u1.5_001.out"));
  EXPECT_FALSE(is_cfx_case_file(dir / "other.out"));
  EXPECT_FALSE(is_cfx_case_file(dir / "late.out"));  // the banner is not in the first 200 lines
  EXPECT_FALSE(is_cfx_case_file(dir / "missing.ccl"));
  EXPECT_FALSE(is_cfx_case_file(dir.path()));
  test::expect_input_error([&] { cfx_case_settings(dir / "other.out"); },
                           {(dir / "other.out").string(), "CFX Command Language for Run"});
  test::expect_input_error([&] { cfx_case_settings(dir / "missing.ccl"); }, {(dir / "missing.ccl").string()});
}

// A case with one domain; the parts that vary are given.
struct CaseParts {
  std::string expressions;
  std::string inlet =
      "          Option = Cartesian Velocity Components\n"
      "          U = 2 [m s^-1]\n"
      "          V = 0 [m s^-1]\n"
      "          W = 0 [m s^-1]\n";
  std::string more_boundaries;
  std::string domain_models;
  std::string equation_of_state = "        Density = 1025 [kg m^-3]\n        Option = Value\n";
  std::string fluids =
      "    FLUID DEFINITION: Fluid 1\n      Material = Sea Water\n      Option = Material Library\n    END\n";
  std::string reference_pressure = "1 [bar]";
};

std::string case_text(const CaseParts& p) {
  return "LIBRARY:\n"
         "  CEL:\n"
         "    EXPRESSIONS:\n" +
         p.expressions +
         "    END\n"
         "  END\n"
         "  MATERIAL: Sea Water\n"
         "    Option = Pure Substance\n"
         "    MATERIAL PROPERTIES:\n"
         "      EQUATION OF STATE:\n" +
         p.equation_of_state +
         "      END\n"
         "      DYNAMIC VISCOSITY:\n"
         "        Dynamic Viscosity = 1.08E-3 [Pa s]\n"
         "        Option = Value\n"
         "      END\n"
         "    END\n"
         "  END\n"
         "END\n"
         "FLOW: Flow Analysis 1\n"
         "  DOMAIN: Default Domain\n"
         "    Domain Type = Fluid\n"
         "    BOUNDARY: inlet\n"
         "      Boundary Type = INLET\n"
         "      BOUNDARY CONDITIONS:\n"
         "        MASS AND MOMENTUM:\n" +
         p.inlet +
         "        END\n"
         "      END\n"
         "    END\n" +
         p.more_boundaries +
         "    DOMAIN MODELS:\n"
         "      REFERENCE PRESSURE:\n"
         "        Reference Pressure = " +
         p.reference_pressure +
         "\n"
         "      END\n" +
         p.domain_models + "    END\n" + p.fluids +
         "  END\n"
         "END\n";
}

CfxCaseSettings settings_of(const CaseParts& parts) { return cfx_case_settings(parse_ccl(case_text(parts), "c.ccl")); }

/// "c.ccl:N" for the nth line of the case that contains `needle`.
std::string at(const CaseParts& parts, const std::string& needle, int nth = 1) {
  return "c.ccl:" + std::to_string(line_of(case_text(parts), needle, nth));
}

TEST(CfxCase, MaterialPropertiesAndUnitsOfAnotherCase) {
  const CfxCaseSettings s = settings_of(CaseParts{});
  EXPECT_EQ(std::get<std::vector<double>>(s.layer.values.at("flow").value), (std::vector<double>{2.0, 0.0, 0.0}));
  EXPECT_EQ(where(s.layer, "flow"), at(CaseParts{}, "MASS AND MOMENTUM:"));
  EXPECT_EQ(number(s.layer, "rho"), 1025.0);
  EXPECT_DOUBLE_EQ(number(s.layer, "nu"), 1.08e-3 / 1025.0);  // [Pa s] is kg m^-1 s^-1
  EXPECT_EQ(number(s.layer, "p_ref"), 1e5);
  EXPECT_TRUE(s.notes.empty()) << notes_of(s);
}

TEST(CfxCase, NormalSpeedGivesASpeedAndANoteButNoDirection) {
  CaseParts parts;
  parts.expressions = "      towSpeed = 2 [km h^-1]\n";
  parts.inlet = "          Normal Speed = towSpeed\n          Option = Normal Speed\n";
  const CfxCaseSettings s = settings_of(parts);
  EXPECT_EQ(s.layer.values.count("flow"), 0u);
  EXPECT_DOUBLE_EQ(number(s.layer, "flow_speed"), 2000.0 / 3600.0);
  EXPECT_EQ(where(s.layer, "flow_speed"), at(parts, "Normal Speed = towSpeed"));
  EXPECT_TRUE(has_note(s, {"'inlet'", at(parts, "Normal Speed = towSpeed"), "normal speed of 0.555555556 m/s",
                           "does not state", "--flow"}))
      << notes_of(s);
}

TEST(CfxCase, RefusesInletsThatDisagreeAndKeepsWhyAPressureDrivenCaseStatesNoFlow) {
  CaseParts two;
  two.more_boundaries =
      "    BOUNDARY: inlet 2\n"
      "      Boundary Type = INLET\n"
      "      BOUNDARY CONDITIONS:\n"
      "        MASS AND MOMENTUM:\n"
      "          Option = Cartesian Velocity Components\n"
      "          U = 2 [m s^-1]\n"
      "          V = 0.5 [m s^-1]\n"
      "          W = 0 [m s^-1]\n"
      "        END\n"
      "      END\n"
      "    END\n";
  test::expect_input_error([&] { settings_of(two); },
                           {at(two, "MASS AND MOMENTUM:", 2) + ":", "'inlet' (" + at(two, "MASS AND MOMENTUM:") + ")",
                            "'inlet 2'", "(2, 0, 0) m/s", "(2, 0.5, 0) m/s"});

  CaseParts same = two;
  same.more_boundaries.replace(same.more_boundaries.find("0.5 [m s^-1]"), 12, "0 [km h^-1]");
  EXPECT_EQ(std::get<std::vector<double>>(settings_of(same).layer.values.at("flow").value),
            (std::vector<double>{2.0, 0.0, 0.0}));

  CaseParts mixed;
  mixed.more_boundaries =
      "    BOUNDARY: side\n"
      "      Boundary Type = INLET\n"
      "      BOUNDARY CONDITIONS:\n"
      "        MASS AND MOMENTUM:\n"
      "          Option = Normal Speed\n"
      "          Normal Speed = 2 [m s^-1]\n"
      "        END\n"
      "      END\n"
      "    END\n";
  test::expect_input_error([&] { settings_of(mixed); },
                           {at(mixed, "Normal Speed = 2") + ":", "different free streams"});

  CaseParts opening;
  opening.more_boundaries =
      "    BOUNDARY: far field\n"
      "      Boundary Type = OPENING\n"
      "      BOUNDARY CONDITIONS:\n"
      "        MASS AND MOMENTUM:\n"
      "          Option = Opening Pressure and Direction\n"
      "          Relative Pressure = 0 [Pa]\n"
      "        END\n"
      "      END\n"
      "    END\n";
  // Beside an inlet that states the velocity, a pressure opening (a far
  // field) is only noted; without one, nothing states the free stream.
  const CfxCaseSettings with_inlet = settings_of(opening);
  EXPECT_TRUE(with_inlet.layer.values.count("flow"));
  EXPECT_TRUE(std::any_of(with_inlet.notes.begin(), with_inlet.notes.end(), [](const std::string& n) {
    return n.find("opening 'far field'") != std::string::npos && n.find("pressure opening") != std::string::npos;
  }));
  // Without one, the case states why it gives no flow, at the opening's line,
  // for the import to refuse unless the flow is given elsewhere (the settings
  // are merged later, by precedence).
  opening.inlet = "          Option = Mass Flow Rate\n          Mass Flow Rate = 1 [kg s^-1]\n";
  const CfxCaseSettings driven = settings_of(opening);
  EXPECT_EQ(driven.layer.values.count("flow"), 0u);
  ASSERT_EQ(driven.layer.values.count("flow_unstated"), 1u);
  const Setting& unstated = driven.layer.values.at("flow_unstated");
  EXPECT_EQ(unstated.origin.where, at(opening, "Opening Pressure and Direction"));
  const auto& why = std::get<std::string>(unstated.value);
  EXPECT_NE(why.find("opening 'far field'"), std::string::npos) << why;
  EXPECT_NE(why.find("no inlet states a velocity"), std::string::npos) << why;
}

TEST(CfxCase, RefusesAVelocityThatIsNotAConstantVelocity) {
  CaseParts pressure;
  pressure.expressions = "      inletPressure = 1 [atm]\n";
  pressure.inlet =
      "          Option = Cartesian Velocity Components\n"
      "          U = inletPressure\n"
      "          V = 0 [m s^-1]\n"
      "          W = 0 [m s^-1]\n";
  test::expect_input_error([&] { settings_of(pressure); }, {at(pressure, "U = inletPressure") + ":",
                                                            "'U = inletPressure'", "expected a velocity (m s^-1)"});

  CaseParts profile;
  profile.inlet =
      "          Option = Cartesian Velocity Components\n"
      "          U = 2 [m s^-1]\n"
      "          V = 0.1 [s^-1] * y\n"
      "          W = 0 [m s^-1]\n";
  test::expect_input_error([&] { settings_of(profile); }, {at(profile, "* y") + ":", "'y'"});

  CaseParts missing;
  missing.inlet = "          Option = Cartesian Velocity Components\n          U = 2 [m s^-1]\n";
  test::expect_input_error([&] { settings_of(missing); }, {at(missing, "MASS AND MOMENTUM:") + ":", "without V"});

  CaseParts mass_flow;
  mass_flow.inlet = "          Option = Mass Flow Rate\n          Mass Flow Rate = 3 [kg s^-1]\n";
  const CfxCaseSettings s = settings_of(mass_flow);
  EXPECT_EQ(s.layer.values.count("flow"), 0u);
  EXPECT_TRUE(has_note(s, {"Option = Mass Flow Rate", at(mass_flow, "Option = Mass Flow Rate")})) << notes_of(s);
}

TEST(CfxCase, PropertiesThatAreNotConstantGiveNotes) {
  CaseParts gas;
  gas.equation_of_state = "        Molar Mass = 28.96 [kg kmol^-1]\n        Option = Ideal Gas\n";
  CfxCaseSettings s = settings_of(gas);
  EXPECT_EQ(s.layer.values.count("rho"), 0u);
  EXPECT_EQ(s.layer.values.count("nu"), 0u);
  EXPECT_EQ(number(s.layer, "p_ref"), 1e5);
  EXPECT_TRUE(has_note(s, {"density of material 'Sea Water'", "Option = Ideal Gas", at(gas, "Option = Ideal Gas")}))
      << notes_of(s);

  CaseParts warm;
  warm.equation_of_state =
      "        Density = 1000 [kg m^-3] - 0.2 [kg m^-3 K^-1] * (T - 277 [K])\n"
      "        Option = Value\n";
  s = settings_of(warm);
  EXPECT_EQ(s.layer.values.count("rho"), 0u);
  EXPECT_TRUE(has_note(s, {"density of material 'Sea Water' is not a constant", at(warm, "Density = 1000"), "'T'"}))
      << notes_of(s);

  CaseParts wrong;  // a density in the unit of a pressure is an error, not a note
  wrong.equation_of_state = "        Density = 1025 [Pa]\n        Option = Value\n";
  test::expect_input_error([&] { settings_of(wrong); }, {at(wrong, "Density = 1025") + ":", "expected a density"});

  CaseParts moving;
  moving.reference_pressure = "pref";
  moving.expressions = "      pref = 101.325 [kPa]\n";
  moving.domain_models =
      "      DOMAIN MOTION:\n        Option = Cartesian Velocity Components\n"
      "        U = 1 [m s^-1]\n      END\n";
  s = settings_of(moving);
  EXPECT_DOUBLE_EQ(number(s.layer, "p_ref"), 101325.0);
  EXPECT_TRUE(has_note(s, {"domain 'Default Domain' moves", "Option = Cartesian Velocity Components",
                           at(moving, "Option = Cartesian Velocity Components", 2)}))
      << notes_of(s);
  EXPECT_EQ(std::get<std::vector<double>>(s.layer.values.at("flow").value), (std::vector<double>{2.0, 0.0, 0.0}));

  CaseParts two_fluids;
  two_fluids.fluids += "    FLUID DEFINITION: Air\n      Material = Air at 25 C\n    END\n";
  s = settings_of(two_fluids);
  EXPECT_EQ(s.layer.values.count("rho"), 0u);
  EXPECT_TRUE(has_note(s, {"several fluids (Fluid 1, Air"})) << notes_of(s);

  CaseParts unknown;
  unknown.fluids = "    FLUID DEFINITION: Fluid 1\n      Material = Water\n    END\n";
  s = settings_of(unknown);
  EXPECT_EQ(s.layer.values.count("rho"), 0u);
  EXPECT_TRUE(has_note(s, {"material 'Water'", "not defined in the file's LIBRARY"})) << notes_of(s);
}

TEST(CfxCase, ALibraryWithoutAFlowStatesNothing) {
  const CfxCaseSettings s = cfx_case_settings(parse_ccl("LIBRARY:\n  MATERIAL: Water\n  END\nEND\n", "lib.ccl"));
  EXPECT_TRUE(s.layer.empty());
  EXPECT_TRUE(has_note(s, {"lib.ccl", "no FLOW"}));
}

}  // namespace
}  // namespace hydrocoef
