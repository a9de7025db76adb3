// Tampered runtime files: truncated anywhere, wrong sizes and counts,
// overflowing counts, NaN and unsorted breakpoints, unknown codes, a changed
// hash. Each gives an error code and a one-line message naming what was
// wrong and where, never a crash (the suite runs under ASan and UBSan).
// Structural tampering is re-hashed (runtime/src/xxh64.h) so that the check
// behind the hash is the one that answers.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "hydrocoef/runtime.h"
#include "runtime/src/xxh64.h"
#include "src/export/runtime_export.hpp"
#include "src/surface/coefficient_surface.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

struct Opened {
  int status = HC_RUNTIME_OK;
  std::string message;
};

Opened open_bytes(const std::string& bytes) {
  hc_runtime_model* model = nullptr;
  char err[512] = "";
  Opened out;
  out.status = hc_runtime_open_memory(bytes.data(), bytes.size(), &model, err, sizeof err);
  out.message = err;
  if (out.status == HC_RUNTIME_OK) {
    EXPECT_NE(model, nullptr);
    // A model that opened evaluates without a crash.
    double x[6] = {0.1, 0.1, 0.1, 0.1, 0.1, 0.1}, values[16], gradients[96];
    for (std::size_t s = 0; s < hc_runtime_surface_count(model); ++s)
      if (hc_runtime_output_count(model, s) <= 16) (void)hc_runtime_evaluate(model, s, x, values, gradients, nullptr);
    hc_runtime_close(model);
  } else {
    EXPECT_EQ(model, nullptr);
  }
  return out;
}

void put_u32(std::string& bytes, std::size_t at, std::uint32_t value) {
  for (int i = 0; i < 4; ++i) bytes[at + static_cast<std::size_t>(i)] = static_cast<char>((value >> (8 * i)) & 0xffu);
}
void put_u64(std::string& bytes, std::size_t at, std::uint64_t value) {
  for (int i = 0; i < 8; ++i) bytes[at + static_cast<std::size_t>(i)] = static_cast<char>((value >> (8 * i)) & 0xffu);
}
std::uint64_t get_u64(const std::string& bytes, std::size_t at) {
  std::uint64_t value = 0;
  for (int i = 7; i >= 0; --i) value = value << 8 | static_cast<unsigned char>(bytes[at + static_cast<std::size_t>(i)]);
  return value;
}
void put_double(std::string& bytes, std::size_t at, double value) {
  put_u64(bytes, at, std::bit_cast<std::uint64_t>(value));
}

// The header's size and hash made right again after a change.
std::string rehashed(std::string bytes) {
  put_u64(bytes, 16, bytes.size());
  put_u64(bytes, 24, hc_xxh64(bytes.data() + 64, bytes.size() - 64, 0));
  return bytes;
}

// The file every variant starts from: section 1 a 2-axis pchip surface "s1"
// (3 x 3 nodes, outputs X and N, a sigma), section 2 a 1-axis linear "s2".
struct Original {
  GridTable pchip{{{"u", {-1.0, 0.0, 1.0}, Extrapolation::Linear}, {"v", {-0.5, 0.0, 0.5}, Extrapolation::Clamp}},
                  {"X", "N"},
                  {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18},
                  Interpolation::Pchip};
  GridTable linear{{{"u", {0.0, 1.0}, Extrapolation::Error}}, {"X"}, {1.0, 3.0}, Interpolation::Linear};
  CoefficientSurface with_sigma =
      CoefficientSurface(pchip).with_run_uncertainty(std::vector<double>(18, 0.5), {1.0, 2.0});
  CoefficientSurface plain{linear};
  std::string bytes = runtime_file_bytes(runtime_model_texts({{"body", "b"}}),
                                         {runtime_surface("s1", with_sigma, {}), runtime_surface("s2", plain, {})});
  std::size_t section(std::size_t i) const { return static_cast<std::size_t>(get_u64(bytes, 64 + 24 * i + 8)); }
};

// Offsets within s1's section (docs/runtime.md): the fixed fields, the name
// "s1" (8 bytes), no metadata (8), axis u (name 8, unit "m/s" 8, policy 8,
// count 8, 3 breakpoints), axis v likewise, outputs X [N], N [N m], then the
// 9 x 8 table, 2 leave-one-out numbers and the 9 x 8 sigma table.
constexpr std::size_t kAxisCount = 0, kOutputCount = 4, kMethod = 8, kFlags = 12, kNodes = 16, kBlock = 24, kName = 32,
                      kMetadataCount = 40, kAxisU = 48, kPolicyU = 64, kCountU = 72, kPointsU = 80, kAxisV = 104,
                      kPointsV = 136, kTable = 192, kLoo = 768, kSigma = 784, kEnd = 1360;

struct Variant {
  std::string name;
  std::string bytes;
  int status;
  std::string fragment;  // in the message
};

std::vector<Variant> variants() {
  const Original o;
  const std::string& good = o.bytes;
  const std::size_t s1 = o.section(1), s2 = o.section(2);
  std::vector<Variant> out;
  const auto add = [&](std::string name, std::string bytes, int status, std::string fragment) {
    out.push_back({std::move(name), std::move(bytes), status, std::move(fragment)});
  };
  const auto changed = [&](auto&& change) {
    std::string bytes = good;
    change(bytes);
    return rehashed(bytes);
  };
  add("empty", "", HC_RUNTIME_E_FORMAT, "the file has 0 bytes");
  add("header only", good.substr(0, 63), HC_RUNTIME_E_FORMAT, "a runtime file has at least 64");
  add("text file", std::string(100, 'a'), HC_RUNTIME_E_FORMAT, "not a hydrocoef runtime file");
  for (const std::size_t length : {64ul, 100ul, s1, s1 + 20, s1 + 500, good.size() - 8, good.size() - 1})
    add("truncated at " + std::to_string(length), good.substr(0, length), HC_RUNTIME_E_FORMAT, "truncated");
  add("extended", good + std::string(8, '\0'), HC_RUNTIME_E_FORMAT, "truncated or extended");
  add(
      "version 3",
      [&] {
        std::string b = good;
        put_u32(b, 8, 3);
        return b;
      }(),
      HC_RUNTIME_E_VERSION, "format version 3");
  add(
      "version 2 without a vehicle",
      [&] {
        std::string b = good;
        put_u32(b, 8, 2);
        return b;
      }(),
      HC_RUNTIME_E_FORMAT, "vehicle section comes last");
  add(
      "header size",
      [&] {
        std::string b = good;
        put_u32(b, 12, 72);
        return b;
      }(),
      HC_RUNTIME_E_FORMAT, "header size 72");
  add(
      "header flags",
      [&] {
        std::string b = good;
        put_u32(b, 36, 1);
        return b;
      }(),
      HC_RUNTIME_E_FORMAT, "header flags");
  add(
      "reserved header byte",
      [&] {
        std::string b = good;
        b[60] = 1;
        return b;
      }(),
      HC_RUNTIME_E_FORMAT, "reserved header byte");
  add(
      "stored hash changed",
      [&] {
        std::string b = good;
        b[24] ^= 1;
        return b;
      }(),
      HC_RUNTIME_E_HASH, "content hash");
  add(
      "a table bit flipped",
      [&] {
        std::string b = good;
        b[s1 + kTable + 3] ^= 0x10;
        return b;
      }(),
      HC_RUNTIME_E_HASH, "changed or damaged");
  add("no sections", changed([&](std::string& b) { put_u32(b, 32, 0); }), HC_RUNTIME_E_FORMAT, "0 sections");
  add("huge section count", changed([&](std::string& b) { put_u32(b, 32, 0xffffffffu); }), HC_RUNTIME_E_FORMAT,
      "sections; expected 1 to");
  add("one section too many", changed([&](std::string& b) { put_u32(b, 32, 4); }), HC_RUNTIME_E_FORMAT,
      "section 0 starts at byte");
  add("section table elsewhere", changed([&](std::string& b) { put_u64(b, 40, 128); }), HC_RUNTIME_E_FORMAT,
      "section table at byte 128");
  add("model section kind", changed([&](std::string& b) { put_u32(b, 64, 2); }), HC_RUNTIME_E_FORMAT,
      "section 0 has kind 2");
  add("section misaligned", changed([&](std::string& b) { put_u64(b, 64 + 24 + 8, s1 + 4); }), HC_RUNTIME_E_FORMAT,
      "section 1 starts at byte");
  add("huge section size", changed([&](std::string& b) { put_u64(b, 64 + 24 + 16, ~0ull - 7); }), HC_RUNTIME_E_FORMAT,
      "section 1 has");
  add("section size too small", changed([&](std::string& b) { put_u64(b, 64 + 24 + 16, kEnd - 8); }),
      HC_RUNTIME_E_FORMAT, "fit in the rest of the section");
  add("axis count 0", changed([&](std::string& b) { put_u32(b, s1 + kAxisCount, 0); }), HC_RUNTIME_E_FORMAT,
      "axis count 0");
  add("axis count 7", changed([&](std::string& b) { put_u32(b, s1 + kAxisCount, 7); }), HC_RUNTIME_E_FORMAT,
      "axis count 7");
  add("output count 0", changed([&](std::string& b) { put_u32(b, s1 + kOutputCount, 0); }), HC_RUNTIME_E_FORMAT,
      "output count 0");
  add("huge output count", changed([&](std::string& b) { put_u32(b, s1 + kOutputCount, 0x7fffffffu); }),
      HC_RUNTIME_E_FORMAT, "output count 2147483647");
  add("unknown method", changed([&](std::string& b) { put_u32(b, s1 + kMethod, 9); }), HC_RUNTIME_E_FORMAT,
      "method code 9");
  add("unknown flag", changed([&](std::string& b) { put_u32(b, s1 + kFlags, 2); }), HC_RUNTIME_E_FORMAT, "flags 0x2");
  add("sigma flag cleared", changed([&](std::string& b) { put_u32(b, s1 + kFlags, 0); }), HC_RUNTIME_E_FORMAT,
      "after the surface's last table");
  add("node count off by one", changed([&](std::string& b) { put_u64(b, s1 + kNodes, 10); }), HC_RUNTIME_E_FORMAT,
      "node count 10; expected 9");
  add("huge node count", changed([&](std::string& b) { put_u64(b, s1 + kNodes, 1ull << 62); }), HC_RUNTIME_E_FORMAT,
      "node count");
  add("numbers per node", changed([&](std::string& b) { put_u64(b, s1 + kBlock, 2); }), HC_RUNTIME_E_FORMAT,
      "2 numbers per node; expected 8");
  add("huge name length", changed([&](std::string& b) { put_u32(b, s1 + kName, 0xffffffffu); }), HC_RUNTIME_E_FORMAT,
      "the surface name has length 4294967295");
  add("NUL in a name", changed([&](std::string& b) { b[s1 + kName + 5] = '\0'; }), HC_RUNTIME_E_FORMAT,
      "holds a NUL byte");
  add("padding not zero", changed([&](std::string& b) { b[s1 + kName + 7] = 'x'; }), HC_RUNTIME_E_FORMAT,
      "padding byte");
  add("empty name", changed([&](std::string& b) { put_u32(b, s1 + kName, 0); }), HC_RUNTIME_E_FORMAT, "padding byte");
  add("huge metadata count", changed([&](std::string& b) { put_u32(b, s1 + kMetadataCount, 0x10000000u); }),
      HC_RUNTIME_E_FORMAT, "surface metadata count");
  add("axis name longer than written", changed([&](std::string& b) { put_u32(b, s1 + kAxisU, 6); }),
      HC_RUNTIME_E_FORMAT, "an axis name holds a NUL byte");
  add("unknown policy", changed([&](std::string& b) { put_u32(b, s1 + kPolicyU, 7); }), HC_RUNTIME_E_FORMAT,
      "extrapolation code 7");
  add("huge breakpoint count", changed([&](std::string& b) { put_u64(b, s1 + kCountU, 1ull << 61); }),
      HC_RUNTIME_E_FORMAT, "breakpoints: 2305843009213693952 numbers");
  add("too few breakpoints", changed([&](std::string& b) { put_u64(b, s1 + kCountU, 2); }), HC_RUNTIME_E_FORMAT,
      "has 2 breakpoints; expected at least 3");
  add("NaN breakpoint",
      changed([&](std::string& b) { put_double(b, s1 + kPointsU + 8, std::numeric_limits<double>::quiet_NaN()); }),
      HC_RUNTIME_E_FORMAT, "axis 'u' breakpoint 1 is not finite");
  add("infinite breakpoint",
      changed([&](std::string& b) { put_double(b, s1 + kPointsV + 16, std::numeric_limits<double>::infinity()); }),
      HC_RUNTIME_E_FORMAT, "axis 'v' breakpoint 2 is not finite");
  add("unsorted breakpoints", changed([&](std::string& b) { put_double(b, s1 + kPointsU + 8, -2.0); }),
      HC_RUNTIME_E_FORMAT, "is not greater than breakpoint 0");
  add("repeated breakpoint", changed([&](std::string& b) { put_double(b, s1 + kPointsV + 16, 0.0); }),
      HC_RUNTIME_E_FORMAT, "axis 'v' breakpoint 2 (0) is not greater");
  add("two axes of one name", changed([&](std::string& b) { b[s1 + kAxisV + 4] = 'u'; }), HC_RUNTIME_E_FORMAT,
      "both named 'u'");
  add("NaN in the table",
      changed([&](std::string& b) { put_double(b, s1 + kTable + 8 * 17, std::numeric_limits<double>::quiet_NaN()); }),
      HC_RUNTIME_E_FORMAT, "the table's number 17 is not finite");
  add("negative leave-one-out", changed([&](std::string& b) { put_double(b, s1 + kLoo + 8, -1.0); }),
      HC_RUNTIME_E_FORMAT, "output 'N' leave-one-out standard deviation -1");
  add("infinite sigma",
      changed([&](std::string& b) { put_double(b, s1 + kSigma, -std::numeric_limits<double>::infinity()); }),
      HC_RUNTIME_E_FORMAT, "sigma table's number 0 is not finite");
  add("two surfaces of one name", changed([&](std::string& b) { b[s2 + kName + 5] = '1'; }), HC_RUNTIME_E_FORMAT,
      "surface 's1' is also surface 1");
  add(
      "bytes after the last section", [&] { return rehashed(good + std::string(8, '\0')); }(), HC_RUNTIME_E_FORMAT,
      "bytes after the last section");
  return out;
}

TEST(RuntimeTampering, EveryVariantGivesACodeAndAMessageNeverACrash) {
  const Original o;
  ASSERT_EQ(o.section(2) - o.section(1), kEnd) << "the layout the offsets above assume changed";
  ASSERT_EQ(open_bytes(o.bytes).status, HC_RUNTIME_OK);
  const auto all = variants();
  EXPECT_GE(all.size(), 30u);
  for (const Variant& v : all) {
    SCOPED_TRACE(v.name);
    const Opened opened = open_bytes(v.bytes);
    EXPECT_EQ(opened.status, v.status) << opened.message;
    EXPECT_NE(opened.message.find(v.fragment), std::string::npos) << opened.message;
    EXPECT_EQ(opened.message.find('\n'), std::string::npos) << opened.message;
    EXPECT_EQ(opened.message.rfind("runtime file, ", 0), 0u) << opened.message;
  }
}

TEST(RuntimeTampering, TruncatedAtEveryOffsetAndRehashedIsRefused) {
  // The header told the new size and hash: the sections' own checks answer.
  const Original o;
  for (std::size_t length = 64; length < o.bytes.size(); length += 4) {
    const Opened opened = open_bytes(rehashed(o.bytes.substr(0, length)));
    EXPECT_EQ(opened.status, HC_RUNTIME_E_FORMAT) << "length " << length << ": " << opened.message;
    EXPECT_FALSE(opened.message.empty()) << "length " << length;
  }
}

TEST(RuntimeTampering, EveryByteChangedAndRehashedIsRefusedOrStillValid) {
  // Each byte in turn set to 0xff: a structural field gives a code, a number
  // changes (finite or not) and is either accepted or refused; nothing crashes.
  const Original o;
  std::size_t refused = 0;
  for (std::size_t at = 64; at < o.bytes.size(); ++at) {
    std::string bytes = o.bytes;
    bytes[at] = static_cast<char>(0xff);
    const Opened opened = open_bytes(rehashed(bytes));
    if (opened.status != HC_RUNTIME_OK) {
      ++refused;
      EXPECT_FALSE(opened.message.empty()) << "byte " << at;
    }
  }
  EXPECT_GT(refused, 200u);
}

TEST(RuntimeTampering, FileErrorsNameThePath) {
  test::TempDir dir;
  hc_runtime_model* model = nullptr;
  char err[512];
  const std::string missing = (dir / "missing.hcrt").string();
  EXPECT_EQ(hc_runtime_open(missing.c_str(), &model, err, sizeof err), HC_RUNTIME_E_IO);
  EXPECT_NE(std::string(err).find(missing + ": cannot open"), std::string::npos) << err;
  const std::string truncated = (dir / "truncated.hcrt").string();
  {
    std::ofstream file(truncated, std::ios::binary);
    const Original o;
    file << o.bytes.substr(0, 200);
  }
  EXPECT_EQ(hc_runtime_open(truncated.c_str(), &model, err, sizeof err), HC_RUNTIME_E_FORMAT);
  EXPECT_EQ(std::string(err).rfind(truncated + ": runtime file, header, byte 16:", 0), 0u) << err;
  EXPECT_EQ(model, nullptr);
  // A small buffer gets a truncated, terminated message; NULL and 0 are allowed.
  char small[8];
  EXPECT_EQ(hc_runtime_open(truncated.c_str(), &model, small, sizeof small), HC_RUNTIME_E_FORMAT);
  EXPECT_EQ(std::strlen(small), 7u);
  EXPECT_EQ(hc_runtime_open(truncated.c_str(), &model, nullptr, 0), HC_RUNTIME_E_FORMAT);
  EXPECT_EQ(hc_runtime_open(nullptr, &model, err, sizeof err), HC_RUNTIME_E_ARGUMENT);
  EXPECT_EQ(hc_runtime_open_memory(nullptr, 10, &model, err, sizeof err), HC_RUNTIME_E_ARGUMENT);
}

}  // namespace
}  // namespace hydrocoef
