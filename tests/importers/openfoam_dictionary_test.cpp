// OpenFOAM dictionaries (importers/openfoam_dictionary): entries, nested
// dictionaries, comments, $ references, #include, the installation's
// #includeEtc and #includeFunc recorded as not read, dimensioned scalars and
// uniform vectors; what cannot be read is refused with the file and line.
// Also the real case files of the sphere runs (data/openfoam-sphere/cases).
#include "importers/openfoam_dictionary.hpp"

#include <gtest/gtest.h>

#include <sys/stat.h>

#include <fstream>
#include <string>

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

/// The message of the InputError `read` throws; a failure when it throws none.
template <typename Read>
std::string refusal(Read&& read) {
  try {
    read();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "accepted";
  return {};
}

std::string repeated(const std::string& piece, std::size_t times) {
  std::string out;
  out.reserve(piece.size() * times);
  for (std::size_t i = 0; i < times; ++i) out += piece;
  return out;
}

TEST(OpenFoamDictionaryLimits, DefaultsAreTheDocumentedOnes) {
  const FoamReadLimits limits;
  EXPECT_EQ(limits.max_nesting, 256u);
  EXPECT_EQ(limits.max_expanded_tokens, 1'000'000u);
  EXPECT_EQ(limits.max_entry_tokens, 100'000u);
  EXPECT_EQ(limits.max_file_bytes, 16u << 20);
  EXPECT_EQ(limits.max_included_files, 64u);
  EXPECT_EQ(limits.max_included_bytes, 16u << 20);
  EXPECT_EQ(limits.max_include_depth, 8);
}

TEST(OpenFoamDictionaryLimits, DictionariesNestedTwentyThousandDeepAreRefusedNotOverflowed) {
  // 60 KB: a{a{a{...}}} 20,000 levels (the recursive parser overflowed its stack).
  const std::string deep = repeated("a{", 20000) + repeated("}", 20000) + "\n";
  const std::string message = refusal([&] { (void)FoamDictionary::parse(deep, "case/0/U"); });
  EXPECT_NE(message.find("case/0/U:1:"), std::string::npos) << message;
  EXPECT_NE(message.find("nested more than 256 deep"), std::string::npos) << message;
  // The limit itself: 256 levels are read, 257 are not.
  const auto nested = [](std::size_t levels) {
    return "FoamFile { version 2.0; }\n" + repeated("a {\n", levels) + "x 1;\n" + repeated("}\n", levels);
  };
  const auto d = FoamDictionary::parse(nested(255), "case/0/U");
  const FoamDictionary* inner = &d;
  for (int i = 0; i < 255; ++i) inner = inner->dictionary("a");
  ASSERT_TRUE(inner);
  EXPECT_EQ(foam_scalar(*inner->value("x"), "x"), 1.0);
  EXPECT_NO_THROW((void)FoamDictionary::parse(nested(256), "case/0/U"));
  EXPECT_NE(refusal([&] { (void)FoamDictionary::parse(nested(257), "case/0/U"); }).find("case/0/U:258:"),
            std::string::npos);
}

TEST(OpenFoamDictionaryLimits, ReferencesThatDoubleAreCountedBeforeTheyAreCopied) {
  // a_k = $a_{k-1} $a_{k-1}: a 16-level chain is 65,536 tokens; twenty
  // entries of it pass the read's budget of 10^6 copied tokens (3 KB of
  // text reached 3 GB before).
  std::string text = "a0 1;\n";
  for (int k = 1; k <= 16; ++k)
    text += "a" + std::to_string(k) + " $a" + std::to_string(k - 1) + " $a" + std::to_string(k - 1) + ";\n";
  const auto chain = FoamDictionary::parse(text, "case/0/U");
  EXPECT_EQ(chain.value("a16")->tokens.size(), 65536u);
  for (int b = 0; b < 20; ++b) text += "b" + std::to_string(b) + " $a16;\n";
  const std::string message = refusal([&] { (void)FoamDictionary::parse(text, "case/0/U"); });
  EXPECT_NE(message.find("case/0/U:"), std::string::npos) << message;
  EXPECT_NE(message.find("expand to more than 1000000 tokens"), std::string::npos) << message;
  // One entry is bounded on its own: the chain one level further passes 100,000 tokens.
  std::string longer = "a0 1;\n";
  for (int k = 1; k <= 17; ++k)
    longer += "a" + std::to_string(k) + " $a" + std::to_string(k - 1) + " $a" + std::to_string(k - 1) + ";\n";
  const std::string entry = refusal([&] { (void)FoamDictionary::parse(longer, "case/0/U"); });
  EXPECT_NE(entry.find("case/0/U:18:"), std::string::npos) << entry;
  EXPECT_NE(entry.find("'a17' has more than 100000 tokens"), std::string::npos) << entry;
}

/// A case folder with system/ and constant/, and a folder beside it holding
/// a file whose first line must never be quoted.
struct IncludeCase {
  test::TempDir dir;
  fs::path case_dir = dir / "case";
  fs::path control = case_dir / "system" / "controlDict";
  IncludeCase() {
    fs::create_directories(case_dir / "system");
    fs::create_directories(case_dir / "constant");
    fs::create_directories(dir / "outside");
    std::ofstream(dir / "outside" / "secret") << "secret_first_line 42 ( unbalanced\n";
  }
  void control_includes(const std::string& directive) const {
    std::ofstream(control) << "application simpleFoam;\n" << directive << "\n";
  }
  std::string refused() const {
    const std::string message = refusal([&] { (void)FoamDictionary::read(control); });
    EXPECT_NE(message.find(control.string() + ":2:"), std::string::npos) << message;
    EXPECT_EQ(message.find("secret_first_line"), std::string::npos) << message;
    return message;
  }
};

TEST(OpenFoamDictionaryIncludes, ReachRegularFilesInsideTheCaseOnly) {
  IncludeCase c;
  std::ofstream(c.case_dir / "constant" / "forceSettings") << "rhoInf 1025;\n";
  std::ofstream(c.case_dir / "system" / "more") << "#include \"<constant>/forceSettings\"\nCofR (1 2 3);\n";
  c.control_includes(
      "#include \"more\"\n#includeIfPresent \"missing\"\n#include \"$FOAM_CASE/constant/forceSettings\"");
  const auto d = FoamDictionary::read(c.control);
  EXPECT_EQ(foam_scalar(*d.value("rhoInf"), "rhoInf"), 1025.0);
  EXPECT_EQ(foam_vector(*d.value("CofR"), "CofR"), (std::array<double, 3>{1, 2, 3}));
  EXPECT_NE(d.value("CofR")->file.find("system/more"), std::string::npos);

  c.control_includes("#include \"/etc/passwd\"");
  EXPECT_NE(c.refused().find("an absolute file name"), std::string::npos);
  c.control_includes("#include \"../../outside/secret\"");
  EXPECT_NE(c.refused().find("outside the case folder"), std::string::npos);
  c.control_includes("#includeIfPresent \"../../outside/secret\"");
  EXPECT_NE(c.refused().find("outside the case folder"), std::string::npos);
  // A symbolic link inside the case to a file outside it, and to a device.
  fs::create_symlink(c.dir / "outside" / "secret", c.case_dir / "system" / "link");
  c.control_includes("#include \"link\"");
  EXPECT_NE(c.refused().find("outside the case folder"), std::string::npos);
  fs::create_symlink("/dev/zero", c.case_dir / "system" / "zero");
  c.control_includes("#include \"zero\"");
  EXPECT_NE(c.refused().find("outside the case folder"), std::string::npos);
  // A FIFO inside the case is refused before it is opened (opening it would block).
  ASSERT_EQ(::mkfifo((c.case_dir / "system" / "pipe").c_str(), 0600), 0);
  c.control_includes("#include \"pipe\"");
  EXPECT_NE(c.refused().find("not a regular file"), std::string::npos);
  c.control_includes("#include \"../system\"");
  EXPECT_NE(c.refused().find("not a regular file"), std::string::npos);
  c.control_includes("#include \"$HOME/x\"");
  EXPECT_NE(c.refused().find("a variable other than $FOAM_CASE"), std::string::npos);
  // The file read itself must be a regular file too.
  const std::string fifo = refusal([&] { (void)FoamDictionary::read(c.case_dir / "system" / "pipe"); });
  EXPECT_NE(fifo.find("not a regular file"), std::string::npos) << fifo;
}

TEST(OpenFoamDictionaryIncludes, FanOutAndBytesAreBudgeted) {
  IncludeCase c;
  // Eight includes of the next level at each of 7 levels: 2 million reads before.
  for (int level = 1; level <= 7; ++level) {
    std::ofstream out(c.case_dir / "system" / ("level" + std::to_string(level)));
    out << "x" << level << " 1;\n";
    if (level < 7)
      for (int i = 0; i < 8; ++i) out << "#include \"level" << level + 1 << "\"\n";
  }
  std::ofstream(c.control) << "application simpleFoam;\n#include \"level1\"\n";
  const std::string message = refusal([&] { (void)FoamDictionary::read(c.control); });
  EXPECT_NE(message.find("more than 64 files included in one read"), std::string::npos) << message;
  EXPECT_NE(message.find("system/level"), std::string::npos) << message;
  // The bytes of the included files together, with a small bound.
  std::ofstream(c.case_dir / "system" / "big") << "big (" << repeated("1 ", 100) << ");\n";
  c.control_includes("#include \"big\"");
  FoamReadLimits limits;
  limits.max_included_bytes = 100;
  const std::string bytes = refusal([&] { (void)FoamDictionary::read(c.control, {}, limits); });
  EXPECT_NE(bytes.find(c.control.string() + ":2:"), std::string::npos) << bytes;
  EXPECT_NE(bytes.find("pass 100 bytes together"), std::string::npos) << bytes;
  limits = {};
  limits.max_file_bytes = 10;
  const std::string file = refusal([&] { (void)FoamDictionary::read(c.control, {}, limits); });
  EXPECT_NE(file.find("expected an OpenFOAM dictionary of at most 10 bytes"), std::string::npos) << file;
}

TEST(OpenFoamDictionary, AStrayClosingBraceEndsTheFileAsOpenFoamReadsIt) {
  // OpenFOAM-10's dictionary::read stops where entry::New meets a '}' at the
  // top level: this controlDict runs in the solver.
  const auto d =
      FoamDictionary::parse("application pimpleFoam;\nfunctions\n{\n  forces { type forces; rhoInf 1025; }\n}\n}\n",
                            "case/system/controlDict");
  ASSERT_TRUE(d.dictionary("functions"));
  EXPECT_EQ(foam_scalar(*d.dictionary("functions")->dictionary("forces")->value("rhoInf"), "rhoInf"), 1025.0);
  ASSERT_EQ(d.warnings().size(), 1u);
  EXPECT_NE(d.warnings()[0].find("case/system/controlDict:6: a '}' without its '{' ends the dictionary"),
            std::string::npos)
      << d.warnings()[0];
  EXPECT_EQ(d.warnings()[0].find("not read"), std::string::npos) << d.warnings()[0];
  // What follows it is not read, as in OpenFOAM, and the warning says so.
  const auto cut = FoamDictionary::parse("a 1;\n}\nb 2;\n", "case/system/controlDict");
  EXPECT_TRUE(cut.value("a"));
  EXPECT_FALSE(cut.value("b"));
  ASSERT_EQ(cut.warnings().size(), 1u);
  EXPECT_NE(cut.warnings()[0].find(":2: a '}'"), std::string::npos) << cut.warnings()[0];
  EXPECT_NE(cut.warnings()[0].find("the text after it is not read"), std::string::npos) << cut.warnings()[0];
  // Inside a dictionary a missing '}' is still refused (a file cut short).
  EXPECT_NE(refusal([] {
              (void)FoamDictionary::parse("functions\n{\n  a 1;\n", "case/system/controlDict");
            }).find("ends inside a dictionary"),
            std::string::npos);
}

TEST(OpenFoamCase, AControlDictWithAStrayBraceIsReadWithANote) {
  test::TempDir dir;
  fs::create_directories(dir / "system");
  std::ofstream(dir.path() / "system" / "controlDict")
      << "application pimpleFoam;\nfunctions\n{\n  forces { type forces; rhoInf 1025; CofR (0 0 0); }\n}\n}\n";
  const auto settings = openfoam_case_settings(dir.path());
  EXPECT_EQ(std::get<double>(settings.layer.values.at("rho").value), 1025.0);
  ASSERT_EQ(settings.notes.size(), 1u);
  EXPECT_NE(settings.notes[0].find("controlDict:6: a '}' without its '{'"), std::string::npos) << settings.notes[0];
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
