// Tampered vehicle sections (docs/runtime.md, "Vehicle section"): wrong
// counts, out-of-range codes and indices, a surface index beyond the file, a
// NaN or inconsistent mass matrix, a version that does not hold a vehicle,
// truncation. Each is re-hashed so that the section's own checks answer, and
// each gives an error code and a one-line message naming what was wrong,
// never a crash (the suite runs under ASan and UBSan); sweeps truncate the
// vehicle section everywhere and set each of its bytes to 0xff, and a model
// that still opens is stepped without a crash.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "hydrocoef/runtime.h"
#include "runtime/src/xxh64.h"
#include "src/dynamics/vehicle.hpp"
#include "src/dynamics/vehicle_model.hpp"
#include "src/export/runtime_export.hpp"
#include "src/surface/coefficient_surface.hpp"

namespace hydrocoef {
namespace {

void put_u32(std::string& bytes, std::size_t at, std::uint32_t value) {
  for (int i = 0; i < 4; ++i) bytes[at + static_cast<std::size_t>(i)] = static_cast<char>((value >> (8 * i)) & 0xffu);
}
void put_u64(std::string& bytes, std::size_t at, std::uint64_t value) {
  for (int i = 0; i < 8; ++i) bytes[at + static_cast<std::size_t>(i)] = static_cast<char>((value >> (8 * i)) & 0xffu);
}
std::uint32_t get_u32(const std::string& bytes, std::size_t at) {
  std::uint32_t value = 0;
  for (int i = 3; i >= 0; --i) value = value << 8 | static_cast<unsigned char>(bytes[at + static_cast<std::size_t>(i)]);
  return value;
}
std::uint64_t get_u64(const std::string& bytes, std::size_t at) {
  return get_u32(bytes, at) | static_cast<std::uint64_t>(get_u32(bytes, at + 4)) << 32;
}
void put_double(std::string& bytes, std::size_t at, double value) {
  put_u64(bytes, at, std::bit_cast<std::uint64_t>(value));
}
std::string rehashed(std::string bytes) {
  put_u64(bytes, 16, bytes.size());
  put_u64(bytes, 24, hc_xxh64(bytes.data() + 64, bytes.size() - 64, 0));
  return bytes;
}

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
    // A model that opened steps without a crash, whatever its numbers.
    EXPECT_NE(model, nullptr);
    std::vector<double> disturbances(hc_runtime_vehicle_disturbance_count(model) + 1, 0.1);
    double x[13] = {0, 0, 0, 1, 0, 0, 0, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1}, tau[6] = {0.1, 0, 0, 0, 0, 0.1};
    const double current[3] = {0.1, 0.0, 0.0};
    char step_err[256];
    (void)hc_runtime_vehicle_step_rk4(model, x, tau, current, disturbances.data(), 0.01, step_err, sizeof step_err);
    std::vector<double> thrust(hc_runtime_vehicle_thruster_count(model) + 1, 0.5);
    (void)hc_runtime_vehicle_thrust_force(model, thrust.data(), tau);
    hc_runtime_close(model);
  } else {
    EXPECT_EQ(model, nullptr);
    EXPECT_EQ(out.message.find('\n'), std::string::npos) << out.message;
  }
  return out;
}

// The vehicle: a law (X), a derivative model with a disturbance (Y), two
// surfaces (M: 1-D; N: 2-D with an axis bound to the disturbance), one thruster.
struct Original {
  CoefficientSurface sm{
      GridTable({{"q", {-1.0, 0.0, 1.0}, Extrapolation::Clamp}}, {"M"}, {0.5, 0.0, -0.5}, Interpolation::Linear)};
  CoefficientSurface sn{GridTable({{"r", {-1.0, 1.0}, Extrapolation::Linear}, {"h", {0.0, 1.0}, Extrapolation::Clamp}},
                                  {"N", "K"}, {0.1, 0.0, -0.1, 0.0, 0.2, 0.0, -0.2, 0.0}, Interpolation::Linear)};
  VehicleModel model{parse_vehicle(R"({"name": "t", "mass": 2.0, "inertia": [0.1, 0.1, 0.1],
      "center_of_gravity": [0, 0, 0.01], "neutrally_buoyant": true, "added_mass": {"sphere_radius": 0.08},
      "thrusters": [{"name": "main", "position": [-0.1, 0, 0], "direction": [1, 0, 0], "min_thrust": -1, "max_thrust": 1}],
      "damping": {"X": {"law": {"u": -0.1, "u|u|": -2.0}, "sign": "on-body"},
                  "Y": {"derivatives": {"terms": "v, u*v, wave", "coefficients": [-1.0, -0.5, 0.1]}, "sign": "on-body"},
                  "M": {"surface": "sm", "output": "M", "sign": "on-body", "allow_unphysical": true},
                  "N": {"surface": "sn", "output": "N", "axes": {"h": "wave"}, "sign": "on-body", "allow_unphysical": true}}})",
                                   "t.json"),
                     [this](const std::string& name) { return name == "sm" ? sm : sn; }};
  RuntimeVehicle vehicle{&model, {{"name", "t"}}};
  std::string bytes = runtime_file_bytes(runtime_model_texts({}, true),
                                         {runtime_surface("sm", sm, {}), runtime_surface("sn", sn, {})}, &vehicle);
  std::size_t sections = get_u32(bytes, 32);
  std::size_t vehicle_at = static_cast<std::size_t>(get_u64(bytes, 64 + 24 * (sections - 1) + 8));

  // Offsets in the vehicle section, walked as docs/runtime.md lays it out.
  std::size_t counts = 0, m_rb = 0, m = 0, m_inv = 0, scalars = 0, names = 0, thruster = 0;
  std::size_t dof[6] = {};
  Original() {
    std::size_t at = vehicle_at;
    const auto text = [&] { at += (4 + get_u32(bytes, at) + 1 + 7) / 8 * 8; };
    const std::uint32_t pairs = get_u32(bytes, at);
    at += 8;
    for (std::uint32_t i = 0; i < 2 * pairs; ++i) text();
    counts = at;
    const std::uint32_t disturbances = get_u32(bytes, at), thrusters = get_u32(bytes, at + 4);
    at += 8;
    m_rb = at;
    m = at + 2 * 288;
    m_inv = at + 3 * 288;
    scalars = at + 4 * 288;
    at = scalars + 72;
    names = at;
    for (std::uint32_t i = 0; i < disturbances; ++i) text();
    for (std::uint32_t i = 0; i < thrusters; ++i) {
      text();
      if (i == 0) thruster = at;
      at += 64;
    }
    for (std::size_t d = 0; d < 6; ++d) {
      dof[d] = at;
      const std::uint32_t kind = get_u32(bytes, at), a = get_u32(bytes, at + 4), b = get_u32(bytes, at + 8),
                          c = get_u32(bytes, at + 12);
      at += 16;
      const auto words = [](std::size_t n) { return (4 * n + 7) / 8 * 8; };
      if (kind == 1) at += words(a) + 8 * a;
      if (kind == 2) at += words(a) + 16 * b + 8 * a;
      if (kind == 3) at += 8 + words(c);
    }
    EXPECT_EQ(at, bytes.size());
  }
};

struct Variant {
  std::string name;
  std::string bytes;
  int status;
  std::string fragment;
};

std::vector<Variant> variants() {
  const Original o;
  std::vector<Variant> out;
  const auto add = [&](std::string name, auto&& change, int status, std::string fragment) {
    std::string bytes = o.bytes;
    change(bytes);
    out.push_back({std::move(name), rehashed(bytes), status, std::move(fragment)});
  };
  const std::size_t law = o.dof[0], derivatives = o.dof[1], sm = o.dof[4], sn = o.dof[5];
  add(
      "disturbance count", [&](std::string& b) { put_u32(b, o.counts, 2); }, HC_RUNTIME_E_FORMAT, "vehicle section");
  add(
      "huge disturbance count", [&](std::string& b) { put_u32(b, o.counts, 0xffffffffu); }, HC_RUNTIME_E_FORMAT,
      "disturbances");
  add(
      "huge thruster count", [&](std::string& b) { put_u32(b, o.counts + 4, 1u << 30); }, HC_RUNTIME_E_FORMAT,
      "thrusters");
  add(
      "no thruster", [&](std::string& b) { put_u32(b, o.counts + 4, 0); }, HC_RUNTIME_E_FORMAT, "vehicle section");
  add(
      "NaN in M_RB", [&](std::string& b) { put_double(b, o.m_rb + 8, std::nan("")); }, HC_RUNTIME_E_FORMAT,
      "not finite");
  add(
      "NaN in M^-1", [&](std::string& b) { put_double(b, o.m_inv + 8 * 14, std::nan("")); }, HC_RUNTIME_E_FORMAT,
      "M^-1 number 14 is not finite");
  add(
      "infinite M", [&](std::string& b) { put_double(b, o.m, std::numeric_limits<double>::infinity()); },
      HC_RUNTIME_E_FORMAT, "M number 0 is not finite");
  add(
      "M not M_RB + M_A", [&](std::string& b) { put_double(b, o.m + 8 * 7, 123.0); }, HC_RUNTIME_E_FORMAT,
      "expected M_RB + M_A");
  add(
      "NaN weight", [&](std::string& b) { put_double(b, o.scalars, std::nan("")); }, HC_RUNTIME_E_FORMAT, "not finite");
  add(
      "velocity named disturbance",
      [&](std::string& b) {
        put_u32(b, o.names, 1);
        b.replace(o.names + 4, 4, std::string("v\0\0\0", 4));
      },
      HC_RUNTIME_E_FORMAT, "a velocity component");
  add(
      "empty disturbance name",
      [&](std::string& b) {
        put_u32(b, o.names, 0);
        b.replace(o.names + 4, 4, std::string(4, '\0'));
      },
      HC_RUNTIME_E_FORMAT, "name is empty");
  add(
      "thruster limits", [&](std::string& b) { put_double(b, o.thruster + 48, 2.0); }, HC_RUNTIME_E_FORMAT,
      "above max");
  add(
      "thruster NaN", [&](std::string& b) { put_double(b, o.thruster + 8, std::nan("")); }, HC_RUNTIME_E_FORMAT,
      "not finite");
  add(
      "DOF kind", [&](std::string& b) { put_u32(b, law, 7); }, HC_RUNTIME_E_FORMAT, "damping of X: kind 7");
  add(
      "none with counts", [&](std::string& b) { put_u32(b, o.dof[2] + 4, 1); }, HC_RUNTIME_E_FORMAT,
      "damping of Z: none");
  add(
      "law term code", [&](std::string& b) { put_u32(b, law + 16, 9); }, HC_RUNTIME_E_FORMAT, "term code 9");
  add(
      "law of no terms", [&](std::string& b) { put_u32(b, law + 4, 0); }, HC_RUNTIME_E_FORMAT, "a law of 0 terms");
  add(
      "law of 7 terms", [&](std::string& b) { put_u32(b, law + 4, 7); }, HC_RUNTIME_E_FORMAT, "a law of 7 terms");
  add(
      "law of 3 terms", [&](std::string& b) { put_u32(b, law + 4, 3); }, HC_RUNTIME_E_FORMAT, "vehicle section");
  add(
      "law variable", [&](std::string& b) { put_u32(b, law + 8, 6); }, HC_RUNTIME_E_FORMAT, "law variable 6");
  add(
      "law reserved", [&](std::string& b) { put_u32(b, law + 12, 1); }, HC_RUNTIME_E_FORMAT, "reserved word 1");
  add(
      "law coefficient NaN", [&](std::string& b) { put_double(b, law + 24, std::nan("")); }, HC_RUNTIME_E_FORMAT,
      "not finite");
  // Y: terms v, u*v, wave: 3 factor counts (1, 2, 1) and a padding word, 4 factors.
  const std::size_t factors = derivatives + 16 + 16;
  add(
      "derivative terms 0", [&](std::string& b) { put_u32(b, derivatives + 4, 0); }, HC_RUNTIME_E_FORMAT,
      "0 derivative terms");
  add(
      "derivative factor count", [&](std::string& b) { put_u32(b, derivatives + 8, 5); }, HC_RUNTIME_E_FORMAT,
      "add up to 4");
  add(
      "term's factor count", [&](std::string& b) { put_u32(b, derivatives + 16, 99); }, HC_RUNTIME_E_FORMAT,
      "has 99 factors");
  add(
      "factor source", [&](std::string& b) { put_u32(b, factors + 48, 7); }, HC_RUNTIME_E_FORMAT, "source 7");
  add(
      "factor power", [&](std::string& b) { put_u32(b, factors + 4, 5); }, HC_RUNTIME_E_FORMAT, "factor power 5");
  add(
      "factor power 0", [&](std::string& b) { put_u32(b, factors + 4, 0); }, HC_RUNTIME_E_FORMAT, "factor power 0");
  add(
      "factor odd", [&](std::string& b) { put_u32(b, factors + 8, 2); }, HC_RUNTIME_E_FORMAT, "odd flag 2");
  add(
      "factor reserved", [&](std::string& b) { put_u32(b, factors + 12, 2); }, HC_RUNTIME_E_FORMAT, "reserved");
  add(
      "padding word", [&](std::string& b) { put_u32(b, derivatives + 28, 1); }, HC_RUNTIME_E_FORMAT, "padding word");
  add(
      "surface beyond the file", [&](std::string& b) { put_u32(b, sm + 4, 2); }, HC_RUNTIME_E_FORMAT,
      "surface index 2; the file has 2 surfaces");
  add(
      "huge surface index", [&](std::string& b) { put_u32(b, sn + 4, 0xffffffffu); }, HC_RUNTIME_E_FORMAT,
      "surface index 4294967295");
  add(
      "output index", [&](std::string& b) { put_u32(b, sn + 8, 2); }, HC_RUNTIME_E_FORMAT, "output 2 of surface 'sn'");
  add(
      "axis source count", [&](std::string& b) { put_u32(b, sn + 12, 1); }, HC_RUNTIME_E_FORMAT, "1 axis sources");
  add(
      "axis source", [&](std::string& b) { put_u32(b, sn + 28, 8); }, HC_RUNTIME_E_FORMAT, "source 8");
  add(
      "surface sign", [&](std::string& b) { put_double(b, sm + 16, 0.5); }, HC_RUNTIME_E_FORMAT, "sign 0.5");
  add(
      "surface sign NaN", [&](std::string& b) { put_double(b, sm + 16, std::nan("")); }, HC_RUNTIME_E_FORMAT,
      "expected 1 or -1");
  add(
      "trailing bytes",
      [&](std::string& b) {
        b += std::string(8, '\0');
        const std::size_t entry = 64 + 24 * (o.sections - 1);
        put_u64(b, entry + 16, get_u64(b, entry + 16) + 8);
      },
      HC_RUNTIME_E_FORMAT, "after the vehicle's last DOF");
  add(
      "cut short",
      [&](std::string& b) {
        b.resize(b.size() - 8);
        const std::size_t entry = 64 + 24 * (o.sections - 1);
        put_u64(b, entry + 16, get_u64(b, entry + 16) - 8);
      },
      HC_RUNTIME_E_FORMAT, "vehicle section");
  add(
      "version 1 with a vehicle", [&](std::string& b) { put_u32(b, 8, 1); }, HC_RUNTIME_E_FORMAT,
      "has kind 3; expected 2");
  add(
      "vehicle kind in version 2 swapped", [&](std::string& b) { put_u32(b, 64 + 24 * (o.sections - 1), 2); },
      HC_RUNTIME_E_FORMAT, "vehicle section comes last");
  add(
      "version 3", [&](std::string& b) { put_u32(b, 8, 3); }, HC_RUNTIME_E_VERSION, "format version 3");
  return out;
}

TEST(RuntimeVehicleTampering, OriginalOpens) {
  const Original o;
  EXPECT_EQ(get_u32(o.bytes, 8), 2u);
  const Opened opened = open_bytes(o.bytes);
  EXPECT_EQ(opened.status, HC_RUNTIME_OK) << opened.message;
}

TEST(RuntimeVehicleTampering, EachVariantIsRefusedWithAMessage) {
  const auto all = variants();
  EXPECT_GE(all.size(), 40u);
  for (const Variant& v : all) {
    SCOPED_TRACE(v.name);
    const Opened opened = open_bytes(v.bytes);
    EXPECT_EQ(opened.status, v.status) << opened.message;
    EXPECT_NE(opened.message.find(v.fragment), std::string::npos) << opened.message;
  }
}

TEST(RuntimeVehicleTampering, SweepsNeverCrash) {
  const Original o;
  std::size_t refused = 0;
  for (std::size_t length = o.vehicle_at; length < o.bytes.size(); length += 4) {
    std::string b = o.bytes.substr(0, length);
    const std::size_t entry = 64 + 24 * (o.sections - 1);
    put_u64(b, entry + 16, length - o.vehicle_at);
    refused += open_bytes(rehashed(b)).status != HC_RUNTIME_OK;
  }
  EXPECT_GT(refused, 0u);
  for (std::size_t at = o.vehicle_at; at < o.bytes.size(); ++at) {
    std::string b = o.bytes;
    b[at] = static_cast<char>(0xff);
    (void)open_bytes(rehashed(b));
  }
}

// Writes the fuzz target's vehicle seeds (tests/data/fuzz-seeds/runtime-vehicle-*.bin,
// at most 4096 bytes: the smoke run's -max_len); run by hand with
// --gtest_also_run_disabled_tests --gtest_filter=*WriteFuzzSeeds.
TEST(RuntimeVehicleTampering, DISABLED_WriteFuzzSeeds) {
  const Original o;
  const VehicleModel laws(
      parse_vehicle(R"({"mass": 1.5, "inertia": [0.02, 0.03, 0.04], "center_of_gravity": [0, 0, 0.01],
      "buoyancy_force": 14.0, "added_mass": {"diagonal": [0.5, 0.6, 0.7, 0.01, 0.02, 0.03]},
      "damping": {"X": {"law": {"1": 0.01, "u": -0.1, "u|u|": -2.0, "u^3": -0.5}, "sign": "on-body"},
                  "N": {"derivatives": {"terms": "r, r*|r|, u*r, gust^2", "coefficients": [0.1, 1.0, 0.2, 0.01]},
                        "sign": "opposing"}}})",
                    "laws.json"));
  const RuntimeVehicle vehicle{&laws, {{"name", "laws"}}};
  const std::string laws_bytes = runtime_file_bytes(runtime_model_texts({}, true), {}, &vehicle);
  for (const auto& [name, bytes] :
       {std::pair{"runtime-vehicle-surfaces.bin", o.bytes}, std::pair{"runtime-vehicle-laws.bin", laws_bytes}}) {
    ASSERT_LE(bytes.size(), 4096u) << name;
    std::ofstream(std::string(HYDROCOEF_SOURCE_DIR "/tests/data/fuzz-seeds/") + name, std::ios::binary) << bytes;
  }
}

}  // namespace
}  // namespace hydrocoef
