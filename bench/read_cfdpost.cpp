// How fast a CFD-Post Generic export is imported: a closed triangulated
// sphere (latitude-longitude, 1,000,002 nodes, 2,000,000 triangles) with
// X, Y, Z [ m ], Pressure [ Pa ] and Wall Shear X/Y/Z [ Pa ] written as
// CFD-Post does ("%.8e", ", " separator, LF), about 170 MB. The text is
// generated here, once, not stored. Bytes/s is the figure to compare with the
// 300 MB/s goal; parse_cfdpost_export works on the bytes in memory,
// read_cfdpost_export adds reading the file (from the page cache after the
// first iteration).
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <stdexcept>
#include <string>

#include "importers/cfdpost_export.hpp"

namespace {

constexpr int kLongitudes = 1000;
constexpr int kLatitudes = 1001;  // rings between the poles: kLatitudes - 1
constexpr double kRadius = 0.15;  // [m]

void append_value(std::string& out, double value, const char* separator) {
  char buffer[40];
  const int length = std::snprintf(buffer, sizeof buffer, "%.8e%s", value, separator);
  out.append(buffer, static_cast<std::size_t>(length));
}

// Nodes: north pole, (kLatitudes - 1) rings of kLongitudes, south pole. Faces:
// fans at the poles and two triangles per ring quad, all walked the same way.
std::string make_sphere_export() {
  std::string text;
  text.reserve(std::size_t{180} << 20);
  text += "\n[Name]\nsphere\n\n[Data]\n";
  text += "X [ m ], Y [ m ], Z [ m ], Pressure [ Pa ], Wall Shear X [ Pa ], Wall Shear Y [ Pa ], Wall Shear Z [ Pa ]\n";
  const auto node = [&](double theta, double phi) {
    const double x = kRadius * std::sin(theta) * std::cos(phi);
    const double y = kRadius * std::sin(theta) * std::sin(phi);
    const double z = kRadius * std::cos(theta);
    const double pressure = 1.0e3 * (1.0 - 2.25 * std::sin(theta) * std::sin(theta) * std::cos(phi) * std::cos(phi));
    append_value(text, x, ", ");
    append_value(text, y, ", ");
    append_value(text, z, ", ");
    append_value(text, pressure, ", ");
    append_value(text, -2.0 * std::cos(theta) * std::cos(phi), ", ");
    append_value(text, 0.5 * std::sin(phi), ", ");
    append_value(text, 2.0 * std::sin(theta), "\n");
  };
  const int rings = kLatitudes - 1;
  node(0.0, 0.0);
  for (int ring = 1; ring <= rings; ++ring)
    for (int j = 0; j < kLongitudes; ++j)
      node(std::numbers::pi * ring / (rings + 1), 2.0 * std::numbers::pi * j / kLongitudes);
  node(std::numbers::pi, 0.0);

  text += "\n[Faces]\n";
  const auto ring_node = [](int ring, int j) { return 1 + (ring - 1) * kLongitudes + (j % kLongitudes); };
  const auto face = [&](int a, int b, int c) {
    text += std::to_string(a);
    text += ", ";
    text += std::to_string(b);
    text += ", ";
    text += std::to_string(c);
    text += '\n';
  };
  const int south = 1 + rings * kLongitudes;
  for (int j = 0; j < kLongitudes; ++j) face(0, ring_node(1, j), ring_node(1, j + 1));
  for (int ring = 1; ring < rings; ++ring)
    for (int j = 0; j < kLongitudes; ++j) {
      face(ring_node(ring, j), ring_node(ring + 1, j), ring_node(ring + 1, j + 1));
      face(ring_node(ring, j), ring_node(ring + 1, j + 1), ring_node(ring, j + 1));
    }
  for (int j = 0; j < kLongitudes; ++j) face(south, ring_node(rings, j + 1), ring_node(rings, j));
  text += '\n';
  return text;
}

const std::string& sphere_export() {
  static const std::string text = make_sphere_export();
  return text;
}

// The export on disk for the read benchmark, removed at exit.
struct ExportFile {
  std::filesystem::path path;
  ExportFile()
      : path(std::filesystem::temp_directory_path() /
             ("hydrocoef_bench_cfdpost_" + std::to_string(::getpid()) + ".csv")) {
    std::ofstream out(path, std::ios::binary);
    out.write(sphere_export().data(), static_cast<std::streamsize>(sphere_export().size()));
    if (!out) throw std::runtime_error("cannot write " + path.string());
  }
  ~ExportFile() {
    std::error_code ignored;
    std::filesystem::remove(path, ignored);
  }
  ExportFile(const ExportFile&) = delete;
  ExportFile& operator=(const ExportFile&) = delete;
};

const ExportFile& export_file() {
  static const ExportFile file;
  return file;
}

void report(benchmark::State& state, const hydrocoef::SurfaceMesh& mesh) {
  const auto bytes = static_cast<std::int64_t>(sphere_export().size());
  state.SetBytesProcessed(state.iterations() * bytes);
  state.counters["file_MB"] = static_cast<double>(bytes) / 1.0e6;
  state.counters["nodes"] = static_cast<double>(mesh.point_count());
  state.counters["faces"] = static_cast<double>(mesh.face_count());
}

void BM_ParseCfdPostSphere(benchmark::State& state) {
  const std::string& text = sphere_export();
  hydrocoef::SurfaceMesh mesh;
  for (auto _ : state) {
    (void)_;
    mesh = hydrocoef::parse_cfdpost_export(text, "sphere.csv");
    benchmark::DoNotOptimize(mesh.points_xyz.data());
  }
  report(state, mesh);
}
BENCHMARK(BM_ParseCfdPostSphere)->Unit(benchmark::kMillisecond)->MinTime(3.0)->UseRealTime();

void BM_ReadCfdPostSphereFile(benchmark::State& state) {
  const ExportFile& file = export_file();
  hydrocoef::SurfaceMesh mesh;
  for (auto _ : state) {
    (void)_;
    mesh = hydrocoef::read_cfdpost_export(file.path);
    benchmark::DoNotOptimize(mesh.points_xyz.data());
  }
  report(state, mesh);
}
BENCHMARK(BM_ReadCfdPostSphereFile)->Unit(benchmark::kMillisecond)->MinTime(3.0)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
