// What `hydrocoef export-fmu` writes: a zip that the host's reader and
// Python's zipfile both read (CRC-32 checked), holding modelDescription.xml,
// binaries/linux64/<modelIdentifier>.so and resources/model.hcr. The XML is
// well-formed (parsed back), states FMI 2.0 Co-Simulation with the
// capabilities the binary has, the variables in the binary's value-reference
// order with causality, units (UnitDefinitions with SI base units), start
// values and the outputs' dependencies on every input; hostile body and
// surface names come back exactly, escaped; the modelIdentifier is a C
// identifier derived from the surface's name; the GUID is the runtime file's
// content hash, and a model description of another export is refused at
// instantiation. The host's XML and zip readers refuse malformed input.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <regex>

#include "hydrocoef/error.hpp"
#include "hydrocoef/runtime.h"
#include "src/export/fmu_model_description.hpp"
#include "src/export/zip_writer.hpp"
#include "tests/fmu/fmi_host.hpp"
#include "tests/fmu/fmu_test_database.hpp"

namespace hydrocoef {
namespace {

using test::FmiHost;
using test::TempDir;

const std::string kHostile = "s<&\"'>]]>%s%n --&#38;";

class FmuDescription : public ::testing::Test {
 protected:
  void SetUp() override {
    test::make_fmu_database(dir_);
    // The grid surface again, under a hostile name, of a hostile body.
    test::write_fmu_grid_csv(dir_ / "hostile.csv", 0.25);
    auto imported = test::run_cli({"import", (dir_ / "hostile.csv").string(), "--body", "b<\"&'>"}, dir_.path());
    ASSERT_EQ(imported.exit_code, 0) << imported.err;
    const auto built = test::run_cli({"surface", "build", kHostile, "--body", "b<\"&'>", "--outputs", "X,Y", "--axes",
                                      "u,v", "--method", "linear", "--extrapolate", "clamp"},
                                     dir_.path());
    ASSERT_EQ(built.exit_code, 0) << built.err;
  }
  TempDir dir_;
};

TEST_F(FmuDescription, TheArchiveAndItsModelDescriptionStateTheSurface) {
  test::export_fmu_file(dir_, "grid", "grid", "grid.fmu");
  const auto files = test::unzip_stored(test::read_text(dir_ / "grid.fmu"));
  ASSERT_EQ(files.size(), 3u);
  ASSERT_TRUE(files.count("modelDescription.xml"));
  ASSERT_TRUE(files.count("binaries/linux64/hc_grid.so"));
  ASSERT_TRUE(files.count("resources/model.hcr"));
  // The embedded binary is the built one, byte for byte.
  EXPECT_EQ(files.at("binaries/linux64/hc_grid.so"), test::read_text(HYDROCOEF_FMU_BINARY));

  // Python's zipfile reads the archive and checks every CRC.
  const auto python = std::system(("cd " + test::shell_quote(dir_.path().string()) +
                                   " && /usr/bin/python3 -c \"import zipfile, sys; z = zipfile.ZipFile('grid.fmu'); "
                                   "sys.exit(0 if z.testzip() is None and len(z.namelist()) == 3 else 1)\"")
                                      .c_str());
  EXPECT_EQ(python, 0);

  const auto md = test::read_model_description(files.at("modelDescription.xml"));
  EXPECT_EQ(md.fmi_version, "2.0");
  EXPECT_EQ(md.model_name, "grid");
  EXPECT_EQ(md.model_identifier, "hc_grid");
  EXPECT_EQ(md.co_simulation.at("canHandleVariableCommunicationStepSize"), "true");
  EXPECT_EQ(md.co_simulation.at("canGetAndSetFMUstate"), "false");
  EXPECT_EQ(md.co_simulation.at("providesDirectionalDerivative"), "false");
  EXPECT_EQ(md.co_simulation.at("canInterpolateInputs"), "false");

  // The GUID is the resource's content hash.
  hc_runtime_model* model = nullptr;
  char err[256];
  const std::string& hcr = files.at("resources/model.hcr");
  ASSERT_EQ(hc_runtime_open_memory(hcr.data(), hcr.size(), &model, err, sizeof err), HC_RUNTIME_OK) << err;
  EXPECT_EQ(md.guid, fmu_guid(hc_runtime_content_hash(model)));
  EXPECT_TRUE(std::regex_match(md.guid, std::regex("hcrt-xxh64-[0-9a-f]{16}"))) << md.guid;
  EXPECT_STREQ(hc_runtime_metadata(model, "fmu_model"), "surface");
  EXPECT_STREQ(hc_runtime_metadata(model, "fmu_surface"), "grid");
  EXPECT_STREQ(hc_runtime_metadata(model, "body"), "grid");
  hc_runtime_close(model);

  // Variables: u, v (inputs), X, Y, sigma(X), sigma(Y) (outputs), value references 0..5 in order.
  const std::vector<std::string> names = {"u", "v", "X", "Y", "sigma(X)", "sigma(Y)"};
  ASSERT_EQ(md.variables.size(), names.size());
  for (std::size_t i = 0; i < names.size(); ++i) {
    const auto& v = md.variables[i];
    EXPECT_EQ(v.name, names[i]);
    EXPECT_EQ(v.value_reference, i);
    EXPECT_EQ(v.causality, i < 2 ? "input" : "output");
    EXPECT_EQ(v.variability, "continuous");
    EXPECT_EQ(v.unit, i < 2 ? "m/s" : "N");
    EXPECT_EQ(v.start.has_value(), i < 2);
    if (i >= 2) {
      ASSERT_TRUE(md.outputs.count(v.index)) << v.name;
      EXPECT_EQ(md.outputs.at(v.index), (std::vector<std::size_t>{1, 2})) << v.name;
    }
  }
  EXPECT_EQ(md.outputs.size(), 4u);
  EXPECT_EQ(*md.variables[0].start, 0.0);  // 0 inside u's breakpoints [0, 0.5]
  EXPECT_EQ(*md.variables[1].start, 0.0);
  EXPECT_EQ(md.units, (std::vector<std::string>{"N", "m/s"}));
  const std::string xml = files.at("modelDescription.xml");
  EXPECT_NE(xml.find(R"(<Unit name="m/s"><BaseUnit m="1" s="-1"/></Unit>)"), std::string::npos);
  EXPECT_NE(xml.find(R"(<Unit name="N"><BaseUnit kg="1" m="1" s="-2"/></Unit>)"), std::string::npos);
}

TEST_F(FmuDescription, HostileNamesAreEscapedAndComeBackExactly) {
  const auto exported =
      test::run_cli({"export-fmu", "b<\"&'>", "--surface", kHostile, "-o", "hostile.fmu", "--json"}, dir_.path());
  ASSERT_EQ(exported.exit_code, 0) << exported.err;
  const auto files = test::unzip_stored(test::read_text(dir_ / "hostile.fmu"));
  const std::string xml = files.at("modelDescription.xml");
  const auto md = test::read_model_description(xml);  // well-formed
  EXPECT_EQ(md.model_name, kHostile);
  // "hc_" + the name, each byte outside [A-Za-z0-9_] as '_'.
  EXPECT_EQ(md.model_identifier, "hc_s_________s_n_____38_");
  EXPECT_TRUE(std::regex_match(md.model_identifier, std::regex("[A-Za-z_][A-Za-z0-9_]*")));
  EXPECT_TRUE(files.count("binaries/linux64/" + md.model_identifier + ".so"));
  EXPECT_EQ(xml.find("]]>%s"), std::string::npos);
  EXPECT_EQ(xml.find("b<\""), std::string::npos);
  // The body is named in the description attribute, exactly.
  const auto root = test::parse_xml(xml);
  EXPECT_NE(root.at("description").find("of body 'b<\"&'>'"), std::string::npos) << root.at("description");
  // The JSON the command printed names the same identifier and GUID.
  const auto report = nlohmann::json::parse(exported.out);
  EXPECT_EQ(report.at("model_identifier"), md.model_identifier);
  EXPECT_EQ(report.at("guid"), md.guid);
  EXPECT_EQ(report.at("surface"), kHostile);

  // It instantiates and steps.
  TempDir unzipped;
  FmiHost host(dir_ / "hostile.fmu", unzipped.path());
  ASSERT_EQ(host.instantiate(), fmi2OK);
  ASSERT_EQ(host.enter_initialization_mode(), fmi2OK);
  ASSERT_EQ(host.exit_initialization_mode(), fmi2OK);
  ASSERT_EQ(host.do_step(0.0, 0.01), fmi2OK);
}

TEST_F(FmuDescription, TheModelDescriptionOfAnotherExportIsRefusedAtInstantiate) {
  test::export_fmu_file(dir_, "asr-v", "surge", "one.fmu");
  test::export_fmu_file(dir_, "asr-v", "surge-strict", "two.fmu");
  TempDir a, b;
  FmiHost one(dir_ / "one.fmu", a.path());
  FmiHost two(dir_ / "two.fmu", b.path());
  // Two models, two GUIDs.
  ASSERT_NE(one.model().guid, two.model().guid);
  // one's binary and description with two's resources.
  EXPECT_EQ(one.instantiate("mixed", std::nullopt, two.resource_uri()), fmi2Error);
  ASSERT_FALSE(one.log().empty());
  EXPECT_NE(one.log().back().message.find("fmuGUID '" + one.model().guid + "' does not match"), std::string::npos)
      << one.log().back().message;
  EXPECT_NE(one.log().back().message.find(two.model().guid), std::string::npos);
  EXPECT_EQ(one.instantiate(), fmi2OK);
}

TEST(FmuModelIdentifier, IsACIdentifierDerivedFromTheName) {
  EXPECT_EQ(fmu_model_identifier("surge"), "hc_surge");
  EXPECT_EQ(fmu_model_identifier("asr-v:yaw 2"), "hc_asr_v_yaw_2");
  EXPECT_EQ(fmu_model_identifier("9"), "hc_9");
  EXPECT_EQ(fmu_model_identifier("\xc3\xa9"), "hc___");
  EXPECT_EQ(fmu_model_identifier(std::string(200, 'a')).size(), 64u);
  EXPECT_EQ(fmu_guid(0x0123456789abcdefULL), "hcrt-xxh64-0123456789abcdef");
}

TEST(FmuModelDescription, RefusesVariablesSharingAName) {
  FmuModelSpec spec;
  spec.variables = {{"X", 0, "input", "continuous", "N", "", 0.0, {}},
                    {"X", 1, "output", "continuous", "N", "", {}, {0}}};
  EXPECT_THROW(fmu_model_description(spec), InputError);
}

TEST(FmuHostReaders, MalformedXmlIsRefused) {
  for (const std::string& bad : {"", "<a>", "<a></b>", "<a x=\"1\" x=\"2\"/>", "<a x=\"<\"/>", "<a x=\"&bogus;\"/>",
                                 "<a/><b/>", "<a x=1/>", "<a>&#0;</a>", "<!DOCTYPE a><a/>", "<a><!-- -- --></a>"}) {
    SCOPED_TRACE(bad);
    EXPECT_THROW(test::parse_xml(bad), std::runtime_error);
  }
  const auto ok = test::parse_xml("<?xml version=\"1.0\"?>\n<!-- c --><a x='&lt;&amp;&#x41;&#66;'><b/>t</a>\n");
  EXPECT_EQ(ok.at("x"), "<&AB");
  EXPECT_EQ(ok.children.size(), 1u);
}

TEST(FmuHostReaders, DamagedZipsAreRefused) {
  const std::string content = "hello";
  const std::string zip = zip_stored({{"a/b.txt", content}});
  EXPECT_EQ(test::unzip_stored(zip).at("a/b.txt"), "hello");
  // Truncated anywhere, or any byte of the entry changed: refused, never read past the end.
  for (std::size_t cut = 0; cut < zip.size(); ++cut)
    EXPECT_THROW(test::unzip_stored(zip.substr(0, cut)), std::runtime_error) << cut;
  for (std::size_t at = 0; at < zip.size(); ++at) {
    std::string damaged = zip;
    damaged[at] = static_cast<char>(damaged[at] ^ 0x5a);
    try {
      const auto files = test::unzip_stored(damaged);
      // A change the reader accepts (time, attributes, version) leaves the content intact.
      ASSERT_EQ(files.size(), 1u) << at;
      EXPECT_EQ(files.begin()->second, "hello") << at;
    } catch (const std::runtime_error&) {}
  }
  EXPECT_THROW(zip_stored({{"../x", content}}), InputError);
  EXPECT_THROW(zip_stored({{"/x", content}}), InputError);
  EXPECT_THROW(zip_stored({{"a//x", content}}), InputError);
}

}  // namespace
}  // namespace hydrocoef
