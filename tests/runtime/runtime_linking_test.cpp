// libhydrocoef_runtime as a dependency-free library: the shared library
// needs libc and libm only (its ELF DT_NEEDED entries), exports the C API
// under the version nodes HYDROCOEF_RUNTIME_1 (surfaces) and _2 (the
// vehicle) and nothing else of its own;
// a C99 program compiled with -std=c99 -pedantic -Werror links it
// statically and dynamically and evaluates a surface to the library's bits.
#include <elf.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "src/export/runtime_export.hpp"
#include "src/surface/coefficient_surface.hpp"
#include "tests/support/elf_dynamic.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

using test::shell_quote;

std::string file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

TEST(RuntimeLinking, SharedLibraryNeedsLibcAndLibmOnlyAndExportsTheCApi) {
  const std::string bytes = file_bytes(HYDROCOEF_RUNTIME_SHARED);
  ASSERT_FALSE(bytes.empty()) << HYDROCOEF_RUNTIME_SHARED;
  const test::ElfDynamic dynamic = test::elf_dynamic(bytes);
  bool libc = false;
  for (const std::string& needed : dynamic.needed) {
    EXPECT_TRUE(needed == "libc.so.6" || needed == "libm.so.6") << "the runtime library needs " << needed;
    libc = libc || needed == "libc.so.6";
  }
  EXPECT_TRUE(libc);
  EXPECT_TRUE(dynamic.defined.count("hc_runtime_open"));
  EXPECT_TRUE(dynamic.defined.count("hc_runtime_evaluate"));
  EXPECT_TRUE(dynamic.defined.count("hc_runtime_vehicle_step_rk4"));
  for (const std::string& symbol : dynamic.defined) {
    // The C API, and the version nodes' own symbols; no kernel or reader helper.
    EXPECT_TRUE(symbol.rfind("hc_runtime_", 0) == 0 || symbol == "HYDROCOEF_RUNTIME_1" ||
                symbol == "HYDROCOEF_RUNTIME_2")
        << symbol;
    EXPECT_EQ(symbol.find("hc_kernel"), std::string::npos) << symbol;
    EXPECT_EQ(symbol.find("hc_read"), std::string::npos) << symbol;
    EXPECT_EQ(symbol.find("hc_motion"), std::string::npos) << symbol;
  }
  EXPECT_NE(bytes.find("HYDROCOEF_RUNTIME_1"), std::string::npos) << "no symbol version node";
  EXPECT_NE(bytes.find("HYDROCOEF_RUNTIME_2"), std::string::npos) << "no vehicle version node";
}

constexpr const char* kProgram = R"(/* A C99 consumer of libhydrocoef_runtime. */
#include <stdio.h>
#include <hydrocoef/runtime.h>

int main(int argc, char** argv) {
  hc_runtime_model* model = NULL;
  char err[256];
  size_t surface = 0;
  double x[2];
  double values[2];
  double gradients[4];
  int status;
  if (argc != 2) return 3;
  if (hc_runtime_abi_version() != HC_RUNTIME_ABI_VERSION) return 4;
  status = hc_runtime_open(argv[1], &model, err, sizeof err);
  if (status != HC_RUNTIME_OK) {
    fprintf(stderr, "%s: %s\n", hc_runtime_status_name(status), err);
    return 1;
  }
  if (hc_runtime_surface_index(model, "yaw", &surface) != HC_RUNTIME_OK) return 5;
  x[0] = 0.37;
  x[1] = -0.21;
  status = hc_runtime_evaluate(model, surface, x, values, gradients, NULL);
  if (status != HC_RUNTIME_OK) return 6;
  printf("%a %a %a %a %a %a\n", values[0], values[1], gradients[0], gradients[1], gradients[2], gradients[3]);
  hc_runtime_close(model);
  return 0;
}
)";

std::string hex(double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%a", value);
  return buffer;
}

TEST(RuntimeLinking, AC99ProgramLinksStaticallyAndDynamicallyAndEvaluates) {
  if (!std::filesystem::exists(HYDROCOEF_C_COMPILER)) GTEST_SKIP() << "no C compiler at " << HYDROCOEF_C_COMPILER;
  test::TempDir dir;
  const GridTable table(
      {{"u", {-1.0, 0.0, 0.5, 1.0}, Extrapolation::Linear}, {"v", {-0.6, -0.2, 0.3, 0.6}, Extrapolation::Method}},
      {"Y", "N"}, {1,  2,  3,  4,  5,  6,   7,   8,   9, 10, 11, 12, 13, 14, 15, 16,
                   -1, -2, -3, -5, -8, -13, -21, -34, 1, 1,  2,  3,  5,  8,  13, 21},
      Interpolation::Pchip);
  const CoefficientSurface surface(table);
  {
    std::ofstream file(dir / "model.hcrt", std::ios::binary);
    file << runtime_file_bytes(runtime_model_texts({}), {runtime_surface("yaw", surface, {})});
    std::ofstream program(dir / "consumer.c");
    program << kProgram;
  }
  const double x[2] = {0.37, -0.21};
  std::vector<double> values(2), gradient(4);
  table.evaluate_with_gradient(x, values, gradient);
  const std::string expected = hex(values[0]) + " " + hex(values[1]) + " " + hex(gradient[0]) + " " + hex(gradient[1]) +
                               " " + hex(gradient[2]) + " " + hex(gradient[3]) + "\n";
  const std::filesystem::path shared(HYDROCOEF_RUNTIME_SHARED);
  const std::string cc = shell_quote(HYDROCOEF_C_COMPILER) + " -std=c99 -pedantic -Wall -Wextra -Werror " +
                         HYDROCOEF_RUNTIME_CONSUMER_FLAGS + " -I" + shell_quote(HYDROCOEF_RUNTIME_INCLUDE) + " " +
                         shell_quote((dir / "consumer.c").string());
  const std::vector<std::pair<std::string, std::string>> links = {
      {"static", " " + shell_quote(HYDROCOEF_RUNTIME_STATIC) + " -lm"},
      {"dynamic", " -L" + shell_quote(shared.parent_path().string()) + " -lhydrocoef_runtime -Wl,-rpath," +
                      shell_quote(shared.parent_path().string())}};
  for (const auto& [kind, link] : links) {
    SCOPED_TRACE(kind);
    const std::string exe = (dir / ("consumer_" + kind)).string(), log = (dir / (kind + ".log")).string();
    ASSERT_EQ(std::system((cc + " -o " + shell_quote(exe) + link + " >" + shell_quote(log) + " 2>&1").c_str()), 0)
        << test::read_text(log);
    const std::string out = (dir / (kind + ".out")).string();
    ASSERT_EQ(std::system((shell_quote(exe) + " " + shell_quote((dir / "model.hcrt").string()) + " >" +
                           shell_quote(out) + " 2>" + shell_quote(log))
                              .c_str()),
              0)
        << test::read_text(log);
    EXPECT_EQ(test::read_text(out), expected);
  }
}

}  // namespace
}  // namespace hydrocoef
