// OpenFOAM dictionaries (importers/openfoam_dictionary): entries, nested
// dictionaries, comments, $ references, #include, the installation's
// #includeEtc and #includeFunc recorded as not read, dimensioned scalars and
// uniform vectors; what cannot be read is refused with the file and line.
// Also the real case files of the sphere runs (data/openfoam-sphere/cases).
#include "importers/openfoam_dictionary.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "src/core/error.hpp"
#include "src/pipeline/openfoam_case.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

namespace fs = std::filesystem;

constexpr const char* kVelocity = R"foam(/*--------------------------------*- C++ -*----------------------------------*\
  a header comment */
FoamFile { version 2.0; format ascii; class volVectorField; object U; }
// the free stream
Uinf            (0.2 -0.05 0);
dimensions      [0 1 -1 0 0 0 0];
internalField   uniform $Uinf;
boundaryField
{
    #includeEtc "caseDicts/setConstraintTypes"
    inlet   { type fixedValue; value uniform (0.2 -0.05 0); }
    outlet  { type inletOutlet; inletValue uniform (0 0 0); value $internalField; }
    hull    { type noSlip; }
    "(front|back)" { type symmetryPlane; }
}
)foam";

TEST(OpenFoamDictionary, ReadsEntriesNestedDictionariesReferencesAndComments) {
  const auto d = FoamDictionary::parse(kVelocity, "case/0/U");
  ASSERT_TRUE(d.dictionary("FoamFile"));
  EXPECT_EQ(foam_word(d.dictionary("FoamFile")->value("class")), "volVectorField");
  ASSERT_TRUE(d.value("internalField"));
  EXPECT_EQ(foam_vector(*d.value("internalField"), "internalField"), (std::array<double, 3>{0.2, -0.05, 0.0}));
  EXPECT_EQ(d.value("internalField")->line, 7u);
  const FoamDictionary* boundary = d.dictionary("boundaryField");
  ASSERT_TRUE(boundary);
  EXPECT_EQ(boundary->dictionary_keys(), (std::vector<std::string>{"inlet", "outlet", "hull", "(front|back)"}));
  EXPECT_EQ(boundary->unread_includes().size(), 1u);
  // $internalField in a patch: the enclosing dictionary's entry.
  EXPECT_EQ(foam_vector(*boundary->dictionary("outlet")->value("value"), "value"),
            (std::array<double, 3>{0.2, -0.05, 0.0}));
  EXPECT_EQ(foam_scalar(*FoamDictionary::parse("nu [0 2 -1 0 0 0 0] 1.004e-06;", "t").value("nu"), "nu"), 1.004e-06);
  EXPECT_EQ(foam_scalar(*FoamDictionary::parse("nu nu [0 2 -1 0 0 0 0] 1e-06;", "t").value("nu"), "nu"), 1e-06);
}

TEST(OpenFoamDictionary, FollowsIncludesRelativeToTheIncludingFile) {
  test::TempDir dir;
  fs::create_directories(dir / "system");
  std::ofstream(dir.path() / "system" / "forces") << "forces { type forces; rhoInf 1025; CofR (1 2 3); }\n";
  std::ofstream(dir.path() / "system" / "controlDict")
      << "application simpleFoam;\nfunctions\n{\n  #include \"forces\"\n}\n";
  const auto d = FoamDictionary::read(dir.path() / "system" / "controlDict");
  const FoamDictionary* forces = d.dictionary("functions")->dictionary("forces");
  ASSERT_TRUE(forces);
  EXPECT_EQ(foam_scalar(*forces->value("rhoInf"), "rhoInf"), 1025.0);
  EXPECT_EQ(foam_vector(*forces->value("CofR"), "CofR"), (std::array<double, 3>{1, 2, 3}));
}

TEST(OpenFoamDictionary, WhatCannotBeReadIsRefusedWithTheLine) {
  const auto refused = [](const std::string& text, const std::string& piece) {
    try {
      (void)FoamDictionary::parse(text, "case/0/U");
      ADD_FAILURE() << "accepted: " << text;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(piece), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("case/0/U"), std::string::npos) << e.what();
    }
  };
  refused("a 1;\nb #calc \"$a*2\";\n", "'#calc'");
  refused("a 1;\n#codeStream { code #{ #}; }\n", "case/0/U:2:");
  refused("a $missing;\n", "'$missing' refers to no entry");
  refused("boundaryField\n{\n  inlet { type fixedValue;\n", "ends inside a dictionary");
  refused("a (1 2 3;\n", "has no ';'");
  refused("a 1; /* not closed\n", "not closed");
  const auto d = FoamDictionary::parse("v uniform (1 2);\ns abc;\n", "case/0/U");
  EXPECT_THROW((void)foam_vector(*d.value("v"), "v"), InputError);
  EXPECT_THROW((void)foam_scalar(*d.value("s"), "s"), InputError);
}

TEST(OpenFoamCase, TheSphereCasesStateTheirFreeStreamDensityCentreAndViscosity) {
  const fs::path cases = fs::path(HYDROCOEF_DATA_DIR) / "openfoam-sphere" / "cases";
  const auto settings = openfoam_case_settings(cases / "u0.10_v0.05");
  const auto& values = settings.layer.values;
  ASSERT_TRUE(values.count("flow"));
  EXPECT_EQ(std::get<std::vector<double>>(values.at("flow").value), (std::vector<double>{0.1, 0.05, 0.0}));
  EXPECT_EQ(values.at("flow").origin.source, SettingSource::CaseFiles);
  EXPECT_NE(values.at("flow").origin.where.find("0/U:"), std::string::npos);
  EXPECT_EQ(std::get<double>(values.at("rho").value), 998.2);
  EXPECT_EQ(std::get<std::vector<double>>(values.at("cofr").value), (std::vector<double>{0.0, 0.0, 0.0}));
  EXPECT_EQ(std::get<double>(values.at("nu").value), 1.004e-06);
}

TEST(OpenFoamCase, TwoPatchesWithDifferentFreeStreamsAreRefused) {
  test::TempDir dir;
  fs::create_directories(dir / "0");
  std::ofstream(dir.path() / "0" / "U") << "boundaryField\n{\n"
                                           "  a { type freestreamVelocity; freestreamValue uniform (1 0 0); }\n"
                                           "  b { type freestreamVelocity; freestreamValue uniform (0 1 0); }\n}\n";
  try {
    (void)openfoam_case_settings(dir.path());
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("different free streams"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(":4"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace hydrocoef
