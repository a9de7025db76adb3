// OpenFOAM force files (importers/openfoam_forces) on the real sphere cases
// in data/openfoam-sphere and on every other layout made here from their
// numbers: the ESI files with and without parentheses, the Foundation's
// forces.dat (with and without porous, with a CofR column, with local-axis
// rows), forceCoeffs' coefficient.dat (both ESI column orders, rotated
// coefficient axes) and the Foundation's forceCoeffs.dat; restarts in
// start-time folders and force_<time>.dat files joined in time order; the
// abscissa; parsing on several threads; every refusal with its location.
// Expected values come from the real files (and case.json), never from the
// reader under test alone.
#include "importers/openfoam_forces.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "src/core/error.hpp"
#include "src/core/source_file.hpp"
#include "tests/support/expect_input_error.hpp"
#include "tests/support/file_bytes.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

namespace fs = std::filesystem;
using test::expect_input_error;
using test::read_bytes;
using test::TempDir;
using test::write_bytes;

const fs::path kSphere = fs::path(HYDROCOEF_DATA_DIR) / "openfoam-sphere";
const std::vector<std::string> kCases{"cases/u0.10_v0.00", "cases/u0.10_v0.05",     "cases/u0.20_v0.10",
                                      "cases/u0.30_v0.00", "quarter-cases/U0.1000", "quarter-cases/U0.3000"};

fs::path forces_folder(const std::string& c) { return kSphere / c / "postProcessing" / "forces"; }

constexpr auto kTotal = ForcePart::Total;
constexpr auto kPressure = ForcePart::Pressure;
constexpr auto kViscous = ForcePart::Viscous;

// Every series of two histories equal, bit for bit.
void expect_same_series(const ForceHistory& a, const ForceHistory& b, const std::vector<ForcePart>& parts) {
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(a.abscissa_values, b.abscissa_values);
  for (const ForcePart part : parts)
    for (const HistoryComponent c : kAllHistoryComponents)
      EXPECT_EQ(a.values(part, c), b.values(part, c)) << part_name(part) << " " << component_name(c);
}

std::string format17(double v) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::string join_lines(const std::vector<std::string>& lines, std::size_t first, std::size_t last) {
  std::string text;
  for (std::size_t i = first; i < last; ++i) text += lines[i] + "\n";
  return text;
}

// ---------------------------------------------------------------------------
// The real files

TEST(OpenFoamForces, RealCasesGiveTheSolversFinalForcesWithTheirParts) {
  for (const std::string& c : kCases) {
    SCOPED_TRACE(c);
    const ForceHistory h = read_openfoam_forces(forces_folder(c));
    const auto json = nlohmann::json::parse(
        read_bytes(kSphere / (c.starts_with("cases") ? "full" : "quarter") / fs::path(c).filename() / "case.json"));
    const std::size_t n = json["iterations_run"].get<std::size_t>();
    ASSERT_EQ(h.size(), n);
    EXPECT_EQ(h.abscissa, HistoryAbscissa::Iteration);
    EXPECT_EQ(h.abscissa_values.front(), 1.0);
    EXPECT_EQ(h.abscissa_values.back(), double(n));
    ASSERT_TRUE(h.frame.moment_centre);
    EXPECT_EQ(*h.frame.moment_centre, (std::array<double, 3>{0, 0, 0}));
    EXPECT_FALSE(h.frame.axes_in_global);
    EXPECT_EQ(h.frame.naming, ComponentNaming::SourceAxes);

    // The last sample is the solver's final force and moment (same digits).
    for (const auto& [part, key] : {std::pair{kTotal, "total"}, {kPressure, "pressure"}, {kViscous, "viscous"}})
      for (std::size_t k = 0; k < 3; ++k) {
        const double force = json["openfoam_final_force_N"][key][k];
        const double moment = json["openfoam_final_moment_Nm"][key][k];
        EXPECT_NEAR(h.values(part, HistoryComponent(k)).back(), force, 1e-12 * std::abs(force) + 1e-300) << key << k;
        EXPECT_NEAR(h.values(part, HistoryComponent(k + 3)).back(), moment, 1e-12 * std::abs(moment) + 1e-300);
      }

    // total = pressure + viscous at every sample, to the 11 digits written.
    for (const HistoryComponent comp : kAllHistoryComponents) {
      const auto& t = h.values(kTotal, comp);
      const auto& p = h.values(kPressure, comp);
      const auto& v = h.values(kViscous, comp);
      EXPECT_TRUE(h.values(ForcePart::Porous, comp).empty());
      double scale = 0.0;
      for (std::size_t i = 0; i < n; ++i) scale = std::max({scale, std::abs(p[i]), std::abs(v[i])});
      for (std::size_t i = 0; i < n; ++i)
        ASSERT_NEAR(t[i], p[i] + v[i], 2e-10 * std::max(std::abs(p[i]), std::abs(v[i])) + 1e-12 * scale)
            << component_name(comp) << " sample " << i;
    }

    // Provenance: both files, their digests, the line of every sample.
    ASSERT_EQ(h.files.size(), 2u);
    EXPECT_EQ(h.files[0].path.filename(), "force.dat");
    EXPECT_EQ(h.files[1].path.filename(), "moment.dat");
    EXPECT_EQ(h.files[0].format, "openfoam-force");
    EXPECT_EQ(h.files[1].format, "openfoam-moment");
    for (const auto& f : h.files) {
      EXPECT_EQ(f.sha256, sha256_hex(read_bytes(f.path)));
      EXPECT_EQ(f.size_bytes, fs::file_size(f.path));
      EXPECT_EQ(f.rows, n);
      EXPECT_EQ(f.rows_used, n);
    }
    ASSERT_EQ(h.force_origin.size(), n);
    ASSERT_EQ(h.moment_origin.size(), n);
    EXPECT_EQ(h.force_origin[0].file, 0u);
    EXPECT_EQ(h.moment_origin[0].file, 1u);
    EXPECT_EQ(h.force_origin[0].line, 5u);
    EXPECT_EQ(h.moment_origin[n - 1].line, n + 4);
    EXPECT_EQ(sample_location(h, 9, HistoryComponent::My), h.files[1].path.string() + ":14");
  }
}

TEST(OpenFoamForces, AFileOrAStartTimeFolderReadsTheSame) {
  const fs::path folder = forces_folder("cases/u0.10_v0.05");
  const ForceHistory whole = read_openfoam_forces(folder);
  expect_same_series(whole, read_openfoam_forces(folder / "0"), {kTotal, kPressure, kViscous});
  expect_same_series(whole, read_openfoam_forces(folder / "0" / "force.dat"), {kTotal, kPressure, kViscous});
  const ForceHistory from_moment = read_openfoam_forces(folder / "0" / "moment.dat");
  expect_same_series(whole, from_moment, {kTotal, kPressure, kViscous});
  // The same files under full/ hold the same numbers.
  expect_same_series(whole, read_openfoam_forces(kSphere / "full" / "u0.10_v0.05" / "force.dat"),
                     {kTotal, kPressure, kViscous});
}

TEST(OpenFoamForces, ParsedTextEqualsTheFileAndNeedsNoDigest) {
  const fs::path file = forces_folder("cases/u0.20_v0.10") / "0" / "force.dat";
  const ForceHistory h = parse_openfoam_force_file(read_bytes(file), "force.dat");
  EXPECT_EQ(h.files.size(), 1u);
  EXPECT_TRUE(h.files[0].sha256.empty());
  EXPECT_TRUE(h.moment_origin.empty());
  EXPECT_TRUE(h.values(kTotal, HistoryComponent::Mx).empty());
  EXPECT_EQ(h.values(kTotal, HistoryComponent::Fx).size(), 1000u);
  EXPECT_EQ(h.abscissa, HistoryAbscissa::Iteration);
}

// ---------------------------------------------------------------------------
// The other layouts, made from the real numbers

// ESI v2206 and later: the same columns without parentheses.
std::string without_parentheses(const std::string& text) {
  std::string out;
  for (const std::string& line : lines_of(text)) {
    std::string copy = line;
    if (line.rfind("# CofR", 0) != 0) {
      std::string stripped;
      for (const char ch : copy) stripped += (ch == '(' || ch == ')') ? '\t' : ch;
      copy = stripped;
    }
    out += copy + "\n";
  }
  return out;
}

TEST(OpenFoamForces, EsiFilesWithoutParenthesesGiveTheSameNumbers) {
  const fs::path folder = forces_folder("cases/u0.30_v0.00") / "0";
  TempDir dir;
  fs::create_directories(dir / "forces" / "0");
  write_bytes(dir / "forces/0/force.dat", without_parentheses(read_bytes(folder / "force.dat")));
  write_bytes(dir / "forces/0/moment.dat", without_parentheses(read_bytes(folder / "moment.dat")));
  EXPECT_EQ(lines_of(read_bytes(dir / "forces/0/force.dat"))[3].find('('), std::string::npos);
  expect_same_series(read_openfoam_forces(folder), read_openfoam_forces(dir / "forces"), {kTotal, kPressure, kViscous});
}

TEST(OpenFoamForces, ColumnsAreFoundByNameInAnyOrderWithPorous) {
  // Header and rows in another order, with a porous part: read by name.
  const std::string text =
      "# Force\n# CofR : (1 2 3)\n#\n"
      "# Time\tviscous_x viscous_y viscous_z\tporous_x porous_y porous_z\tpressure_x pressure_y pressure_z\ttotal_x "
      "total_y total_z\n"
      "0.5\t1 2 3\t10 20 30\t100 200 300\t111 222 333\n"
      "1.5\t4 5 6\t40 50 60\t400 500 600\t444 555 666\n";
  const ForceHistory h = parse_openfoam_force_file(text, "force.dat");
  EXPECT_EQ(h.values(kViscous, HistoryComponent::Fy), (std::vector<double>{2, 5}));
  EXPECT_EQ(h.values(ForcePart::Porous, HistoryComponent::Fz), (std::vector<double>{30, 60}));
  EXPECT_EQ(h.values(kPressure, HistoryComponent::Fx), (std::vector<double>{100, 400}));
  EXPECT_EQ(h.values(kTotal, HistoryComponent::Fz), (std::vector<double>{333, 666}));
  EXPECT_EQ(*h.frame.moment_centre, (std::array<double, 3>{1, 2, 3}));
  EXPECT_EQ(h.abscissa, HistoryAbscissa::Time);
  // "internal" is the newer name of the porous part.
  const std::string internal =
      "# Moment\n# Time total_x total_y total_z internal_x internal_y internal_z\n1 1 2 3 0.5 0.5 0.5\n";
  EXPECT_EQ(parse_openfoam_force_file(internal, "moment_3.dat").values(ForcePart::Porous, HistoryComponent::Mx),
            std::vector<double>{0.5});
}

// The Foundation's forces.dat: nested groups, pressure/viscous(/porous).
std::string foundation_forces(const ForceHistory& h, bool porous, bool cofr_column, bool local_rows,
                              const char* moment_group = "moment") {
  const std::string parts = porous ? "(pressure viscous porous)" : "(pressure viscous)";
  std::string text = "# Forces\n# CofR                : (0.000000e+00 0.000000e+00 0.000000e+00)\n";
  text += std::string("# Time                ") + (cofr_column ? "CofR\t" : "") + "forces" + parts + "\t" +
          moment_group + parts;
  if (local_rows) text += "\tlocalForces(pressure,viscous,porous) localMoments(pressure,viscous,porous)";
  text += "\n";
  const auto vector = [&](ForcePart part, std::size_t first, std::size_t i) {
    return "(" + format17(h.values(part, HistoryComponent(first))[i]) + " " +
           format17(h.values(part, HistoryComponent(first + 1))[i]) + " " +
           format17(h.values(part, HistoryComponent(first + 2))[i]) + ")";
  };
  for (std::size_t i = 0; i < h.size(); ++i) {
    for (int copy = 0; copy < (local_rows ? 2 : 1); ++copy) {
      text += format17(h.abscissa_values[i]) + "\t";
      if (cofr_column) text += "(0 0 0)\t";
      text += "(" + vector(kPressure, 0, i) + " " + vector(kViscous, 0, i) + (porous ? " (0 0 0)" : "") + ") (";
      text += vector(kPressure, 3, i) + " " + vector(kViscous, 3, i) + (porous ? " (0 0 0)" : "") + ")\n";
      if (copy == 0 && local_rows) {
        // The local row: its numbers must not be taken; write rubbish-but-valid ones.
        text += format17(h.abscissa_values[i]) + "\t((9 9 9) (9 9 9) (9 9 9)) ((9 9 9) (9 9 9) (9 9 9))\n";
        break;
      }
    }
  }
  return text;
}

TEST(OpenFoamForces, FoundationForcesDatGivesTheSameForces) {
  const ForceHistory esi = read_openfoam_forces(forces_folder("cases/u0.10_v0.05"));
  for (const bool porous : {true, false})
    for (const bool cofr : {false, true}) {
      SCOPED_TRACE(std::string("porous ") + (porous ? "yes" : "no") + ", CofR column " + (cofr ? "yes" : "no"));
      TempDir dir;
      fs::create_directories(dir / "forces" / "0");
      write_bytes(dir / "forces/0/forces.dat",
                  foundation_forces(esi, porous, cofr, false, porous ? "moment" : "moments"));
      const ForceHistory h = read_openfoam_forces(dir / "forces");
      ASSERT_EQ(h.files.size(), 1u);
      EXPECT_EQ(h.files[0].format, "openfoam-forces");
      // Pressure and viscous exactly; the total is their sum (the ESI total
      // was written rounded to 11 digits).
      expect_same_series(esi, h, {kPressure, kViscous});
      for (const HistoryComponent c : kAllHistoryComponents)
        for (std::size_t i = 0; i < h.size(); ++i) {
          ASSERT_EQ(h.values(kTotal, c)[i],
                    esi.values(kPressure, c)[i] + esi.values(kViscous, c)[i] + (porous ? 0.0 : 0.0));
          ASSERT_NEAR(h.values(kTotal, c)[i], esi.values(kTotal, c)[i],
                      2e-10 * std::max({std::abs(esi.values(kTotal, c)[i]), std::abs(esi.values(kPressure, c)[i]),
                                        std::abs(esi.values(kViscous, c)[i])}) +
                          1e-16);
        }
      EXPECT_EQ(h.values(ForcePart::Porous, HistoryComponent::Fx).empty(), !porous);
      EXPECT_EQ(*h.frame.moment_centre, (std::array<double, 3>{0, 0, 0}));
    }
}

TEST(OpenFoamForces, FoundationLocalAxisRowsAreLeftOut) {
  const ForceHistory esi = read_openfoam_forces(forces_folder("cases/u0.10_v0.00"));
  const ForceHistory h = parse_openfoam_force_file(foundation_forces(esi, true, false, true), "forces.dat");
  expect_same_series(esi, h, {kPressure, kViscous});
  EXPECT_EQ(h.force_origin[1].line, 6u);  // rows 4, 6, 8, ...: every other line
  bool noted = false;
  for (const auto& note : h.notes) noted = noted || note.find("local coordinate system") != std::string::npos;
  EXPECT_TRUE(noted);
}

// forceCoeffs: coefficients from the real totals, in rotated axes.
struct Axes {
  std::array<double, 3> drag, side, lift;
};

std::string esi_coefficients(const ForceHistory& h, const Axes& axes, double rho, double u, double l, double area,
                             bool alphabetical) {
  const auto vec = [](const std::array<double, 3>& v) {
    return "(" + format17(v[0]) + " " + format17(v[1]) + " " + format17(v[2]) + ")";
  };
  std::string text = "# Force coefficients\n";
  text += "# dragDir             : " + vec(axes.drag) + "\n# sideDir             : " + vec(axes.side) +
          "\n# liftDir             : " + vec(axes.lift) + "\n# rollAxis            : " + vec(axes.drag) +
          "\n# pitchAxis           : " + vec(axes.side) + "\n# yawAxis             : " + vec(axes.lift) + "\n";
  text += "# magUInf             : " + format17(u) + "\n# lRef                : " + format17(l) +
          "\n# Aref                : " + format17(area) + "\n# CofR                : (0 0 0)\n#\n";
  text += alphabetical
              ? "# Time          \tCd\tCd(f)\tCd(r)\tCl\tCl(f)\tCl(r)\tCmPitch\tCmRoll\tCmYaw\tCs\tCs(f)\tCs(r)\n"
              : "# Time          \tCd\tCs\tCl\tCmRoll\tCmPitch\tCmYaw\tCd(f)\tCd(r)\tCs(f)\tCs(r)\tCl(f)\tCl(r)\n";
  const double q = 0.5 * rho * u * u;
  for (std::size_t i = 0; i < h.size(); ++i) {
    std::array<double, 6> c{};
    const std::array<std::array<double, 3>, 3> rows{axes.drag, axes.side, axes.lift};
    for (std::size_t k = 0; k < 3; ++k) {
      double f = 0.0, m = 0.0;
      for (std::size_t g = 0; g < 3; ++g) {
        f += rows[k][g] * h.values(kTotal, HistoryComponent(g))[i];
        m += rows[k][g] * h.values(kTotal, HistoryComponent(g + 3))[i];
      }
      c[k] = f / (q * area);
      c[k + 3] = m / (q * area * l);
    }
    const double cdf = 0.5 * c[0] + c[3], cdr = 0.5 * c[0] - c[3];
    const double csf = 0.5 * c[1] + c[5], csr = 0.5 * c[1] - c[5];
    const double clf = 0.5 * c[2] + c[4], clr = 0.5 * c[2] - c[4];
    std::vector<double> row =
        alphabetical ? std::vector<double>{c[0], cdf, cdr, c[2], clf, clr, c[4], c[3], c[5], c[1], csf, csr}
                     : std::vector<double>{c[0], c[1], c[2], c[3], c[4], c[5], cdf, cdr, csf, csr, clf, clr};
    text += format17(h.abscissa_values[i]);
    for (const double v : row) text += "\t" + format17(v);
    text += "\n";
  }
  return text;
}

TEST(OpenFoamForces, CoefficientFilesGiveTheSameForces) {
  const ForceHistory esi = read_openfoam_forces(forces_folder("cases/u0.20_v0.10"));
  const double rho = 998.2, u = 0.2236, l = 0.3, area = 0.0706858;
  const Axes straight{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (const bool alphabetical : {false, true}) {
    SCOPED_TRACE(alphabetical ? "v2206+ column order" : "v1912 column order");
    TempDir dir;
    fs::create_directories(dir / "forceCoeffs" / "0");
    write_bytes(dir / "forceCoeffs/0/coefficient.dat", esi_coefficients(esi, straight, rho, u, l, area, alphabetical));
    OpenFoamForcesOptions options;
    options.rho = rho;
    const ForceHistory h = read_openfoam_forces(dir / "forceCoeffs", options);
    ASSERT_EQ(h.size(), esi.size());
    EXPECT_EQ(h.files[0].format, "openfoam-coefficient");
    ASSERT_TRUE(h.frame.axes_in_global);
    for (const HistoryComponent c : kAllHistoryComponents) {
      ASSERT_EQ(h.values(kTotal, c).size(), esi.size());
      EXPECT_TRUE(h.values(kPressure, c).empty());
      for (std::size_t i = 0; i < h.size(); ++i)
        ASSERT_NEAR(h.values(kTotal, c)[i], esi.values(kTotal, c)[i],
                    1e-13 * std::abs(esi.values(kTotal, c)[i]) + 1e-20)
            << component_name(c) << " " << i;
    }
  }
}

TEST(OpenFoamForces, RotatedCoefficientAxesAreRecordedAndTurnBack) {
  const ForceHistory esi = read_openfoam_forces(forces_folder("cases/u0.10_v0.05"));
  // Drag along +y, side along -x, lift along +z (a right-handed set).
  const Axes rotated{{0, 1, 0}, {-1, 0, 0}, {0, 0, 1}};
  OpenFoamForcesOptions options;
  options.rho = 998.2;
  const ForceHistory h = parse_openfoam_force_file(esi_coefficients(esi, rotated, 998.2, 0.1, 0.3, 0.07, false),
                                                   "coefficient.dat", options);
  ASSERT_TRUE(h.frame.axes_in_global);
  EXPECT_EQ((*h.frame.axes_in_global)[0], rotated.drag);
  EXPECT_EQ((*h.frame.axes_in_global)[1], rotated.side);
  // Drag is the global Fy.
  EXPECT_NEAR(h.values(kTotal, HistoryComponent::Fx)[500], esi.values(kTotal, HistoryComponent::Fy)[500], 1e-15);
  const ForceHistory global = rotated_to_global_axes(h);
  EXPECT_FALSE(global.frame.axes_in_global);
  for (const HistoryComponent c : kAllHistoryComponents)
    for (std::size_t i = 0; i < h.size(); i += 97)
      EXPECT_NEAR(global.values(kTotal, c)[i], esi.values(kTotal, c)[i],
                  1e-13 * std::abs(esi.values(kTotal, c)[i]) + 1e-20);
}

TEST(OpenFoamForces, FoundationForceCoeffsDatGivesDragLiftAndPitch) {
  const ForceHistory esi = read_openfoam_forces(forces_folder("cases/u0.30_v0.00"));
  const double rho = 998.2, u = 0.3, l = 0.3, area = 0.0706858, q = 0.5 * rho * u * u;
  std::string text =
      "# Force coefficients\n# liftDir             : (0 0 1)\n# dragDir             : (1 0 0)\n"
      "# pitchAxis           : (0 1 0)\n# magUInf             : 0.3\n# lRef                : 0.3\n"
      "# Aref                : 0.0706858\n# CofR                : (0 0 0)\n# Time                "
      "\tCm\tCd\tCl\tCl(f)\tCl(r)\n";
  for (std::size_t i = 0; i < esi.size(); ++i) {
    const double cm = esi.values(kTotal, HistoryComponent::My)[i] / (q * area * l);
    const double cd = esi.values(kTotal, HistoryComponent::Fx)[i] / (q * area);
    const double cl = esi.values(kTotal, HistoryComponent::Fz)[i] / (q * area);
    text += format17(esi.abscissa_values[i]) + "\t" + format17(cm) + "\t" + format17(cd) + "\t" + format17(cl) + "\t" +
            format17(cl / 2 + cm) + "\t" + format17(cl / 2 - cm) + "\n";
  }
  OpenFoamForcesOptions options;
  options.rho = rho;
  const ForceHistory h = parse_openfoam_force_file(text, "forceCoeffs.dat", options);
  for (const HistoryComponent c : {HistoryComponent::Fx, HistoryComponent::Fz, HistoryComponent::My})
    for (std::size_t i = 0; i < h.size(); ++i)
      ASSERT_NEAR(h.values(kTotal, c)[i], esi.values(kTotal, c)[i], 1e-13 * std::abs(esi.values(kTotal, c)[i]) + 1e-20);
  for (const HistoryComponent c : {HistoryComponent::Fy, HistoryComponent::Mx, HistoryComponent::Mz})
    EXPECT_TRUE(h.values(kTotal, c).empty());
  // Side is lift x drag = +y here: the frame is the identity.
  EXPECT_EQ((*h.frame.axes_in_global)[1], (std::array<double, 3>{0, 1, 0}));
  // Only drag, lift and pitch: turning to global axes keeps them (the
  // identity needs no missing component).
  const ForceHistory global = rotated_to_global_axes(h);
  EXPECT_TRUE(global.values(kTotal, HistoryComponent::Fy).empty());
  EXPECT_EQ(global.values(kTotal, HistoryComponent::Fx), h.values(kTotal, HistoryComponent::Fx));
}

TEST(OpenFoamForces, CoefficientReferenceValues) {
  const std::string head = "# Force coefficients\n# magUInf : 2\n# Aref : 0.5\n# lRef : 3\n# Time Cd Cs Cl CmRoll\n";
  const std::string text = head + "1 0.1 0.2 0.3 0.4\n";
  OpenFoamForcesOptions options;
  expect_input_error([&] { parse_openfoam_force_file(text, "coefficient.dat", options); },
                     {"coefficient.dat", "density", "(rho)"});
  options.rho = 1000.0;
  const ForceHistory h = parse_openfoam_force_file(text, "coefficient.dat", options);
  const double q = 0.5 * 1000.0 * 4.0;
  EXPECT_DOUBLE_EQ(h.values(kTotal, HistoryComponent::Fx)[0], 0.1 * q * 0.5);
  EXPECT_DOUBLE_EQ(h.values(kTotal, HistoryComponent::Mx)[0], 0.4 * q * 0.5 * 3.0);
  EXPECT_FALSE(h.frame.axes_in_global);  // no directions in this header

  options.mag_u_inf = 2.5;  // disagrees with the header
  expect_input_error([&] { parse_openfoam_force_file(text, "coefficient.dat", options); },
                     {"coefficient.dat:2", "magUInf is 2 in the header but 2.5 was given"});
  const std::string no_area = "# Force coefficients\n# magUInf : 2\n# Time Cd\n1 0.1\n";
  options.mag_u_inf.reset();
  expect_input_error([&] { parse_openfoam_force_file(no_area, "coefficient.dat", options); },
                     {"coefficient.dat", "no Aref", "(Aref)"});
  options.a_ref = 0.25;  // fills in for the header
  EXPECT_DOUBLE_EQ(
      parse_openfoam_force_file(no_area, "coefficient.dat", options).values(kTotal, HistoryComponent::Fx)[0],
      0.1 * q * 0.25);
  options.a_ref.reset();
  const std::string skew =
      "# Force coefficients\n# dragDir : (1 0 0)\n# liftDir : (0.6 0.8 0)\n# magUInf : 2\n"
      "# Aref : 1\n# Time Cd\n1 0.1\n";
  expect_input_error([&] { parse_openfoam_force_file(skew, "coefficient.dat", options); },
                     {"coefficient.dat:2", "not a right-handed orthonormal set"});
  const std::string long_dir =
      "# Force coefficients\n# dragDir : (2 0 0)\n# liftDir : (0 0 1)\n# magUInf : 2\n# Aref : 1\n# Time Cd\n1 0.1\n";
  expect_input_error([&] { parse_openfoam_force_file(long_dir, "coefficient.dat", options); },
                     {"coefficient.dat:2", "dragDir has length 2", "unit vector"});
}

// ---------------------------------------------------------------------------
// Restarts

// A function object folder with the real rows split into restarts:
// {start-time folder, file suffix, first row, last row} (rows 1-based).
struct Piece {
  std::string folder;
  std::string suffix;
  std::size_t first, last;
};

void write_restarts(const fs::path& root, const std::string& c, const std::vector<Piece>& pieces) {
  for (const char* name : {"force", "moment"}) {
    const auto lines = lines_of(read_bytes(forces_folder(c) / "0" / (std::string(name) + ".dat")));
    for (const Piece& piece : pieces) {
      fs::create_directories(root / piece.folder);
      write_bytes(root / piece.folder / (name + piece.suffix + ".dat"),
                  join_lines(lines, 0, 4) + join_lines(lines, 3 + piece.first, 4 + piece.last));
    }
  }
}

TEST(OpenFoamForces, RestartFoldersAreJoinedAndTheLaterFileWins) {
  const ForceHistory whole = read_openfoam_forces(forces_folder("cases/u0.10_v0.05"));
  TempDir dir;
  // Ran to 600, restarted from the write at 500: rows 501-600 written twice.
  write_restarts(dir / "forces", "cases/u0.10_v0.05", {{"0", "", 1, 600}, {"500", "", 501, 1000}});
  const ForceHistory h = read_openfoam_forces(dir / "forces");
  expect_same_series(whole, h, {kTotal, kPressure, kViscous});
  ASSERT_EQ(h.files.size(), 4u);
  EXPECT_EQ(h.files[0].path, dir / "forces/0/force.dat");
  EXPECT_EQ(h.files[2].path, dir / "forces/500/force.dat");
  EXPECT_EQ(h.files[0].rows, 600u);
  EXPECT_EQ(h.files[0].rows_used, 500u);
  EXPECT_EQ(h.files[2].rows_used, 500u);
  EXPECT_EQ(h.force_origin[499].file, 0u);
  EXPECT_EQ(h.force_origin[500].file, 2u);
  EXPECT_EQ(h.force_origin[500].line, 5u);
  EXPECT_EQ(h.moment_origin[500].file, 3u);
  bool noted = false;
  for (const auto& note : h.notes)
    noted = noted || (note.find("500/force.dat starts at 501 and replaces 100 later rows") != std::string::npos);
  EXPECT_TRUE(noted);
}

TEST(OpenFoamForces, RestartFilesInOneFolderAreJoinedByTheirFirstTime) {
  const ForceHistory whole = read_openfoam_forces(forces_folder("cases/u0.30_v0.00"));
  TempDir dir;
  // force.dat to 700; force_650.dat from 651; force_900.dat from 901; a
  // start-time folder 0 and 900 mixed in.
  write_restarts(dir / "forces", "cases/u0.30_v0.00",
                 {{"0", "", 1, 700}, {"0", "_650", 651, 950}, {"900", "", 901, 1000}});
  const ForceHistory h = read_openfoam_forces(dir / "forces");
  expect_same_series(whole, h, {kTotal, kPressure, kViscous});
  EXPECT_EQ(h.files.size(), 6u);
  EXPECT_EQ(h.files[2].path.filename(), "force_650.dat");
  EXPECT_EQ(h.files[0].rows_used, 650u);
  EXPECT_EQ(h.files[2].rows_used, 250u);
  EXPECT_EQ(h.files[4].rows_used, 100u);
  // A single restart file is read with its partner.
  const ForceHistory one = read_openfoam_forces(dir / "forces/0/moment_650.dat");
  EXPECT_EQ(one.size(), 300u);
  EXPECT_EQ(one.abscissa_values.front(), 651.0);
  EXPECT_FALSE(one.values(kTotal, HistoryComponent::Fx).empty());
}

TEST(OpenFoamForces, RestartsMustAgreeOnColumnsAndFrame) {
  TempDir dir;
  write_restarts(dir / "forces", "cases/u0.10_v0.05", {{"0", "", 1, 600}, {"600", "", 601, 1000}});
  fs::remove(dir / "forces/600/moment.dat");
  expect_input_error([&] { read_openfoam_forces(dir / "forces"); },
                     {"600/force.dat", "other components or parts", "same columns"});

  TempDir other;
  write_restarts(other / "forces", "cases/u0.10_v0.05", {{"0", "", 1, 600}, {"600", "", 601, 1000}});
  for (const char* name : {"force.dat", "moment.dat"}) {
    std::string text = read_bytes(other / "forces/600" / name);
    text.replace(text.find("(0.0000000000e+00"), 17, "(1.0000000000e+00");
    write_bytes(other / "forces/600" / name, text);
  }
  expect_input_error([&] { read_openfoam_forces(other / "forces"); }, {"600/force.dat", "another CofR"});
}

TEST(OpenFoamForces, PrefersForceAndMomentOverOtherKinds) {
  TempDir dir;
  write_restarts(dir / "forces", "cases/u0.10_v0.05", {{"0", "", 1, 1000}});
  write_bytes(dir / "forces/0/coefficient.dat", "# Force coefficients\n# Time Cd\n1 0.5\n");
  write_bytes(dir / "forces/0/force_bins.dat", "# bins\n");
  const ForceHistory h = read_openfoam_forces(dir / "forces");
  EXPECT_EQ(h.size(), 1000u);
  bool noted = false;
  for (const auto& note : h.notes) noted = noted || note.find("coefficient.dat is left out") != std::string::npos;
  EXPECT_TRUE(noted);
}

TEST(OpenFoamForces, AForceFileWithoutItsMomentFileGivesForcesOnly) {
  TempDir dir;
  fs::create_directories(dir / "f" / "0");
  fs::copy_file(forces_folder("cases/u0.10_v0.05") / "0" / "force.dat", dir / "f/0/force.dat");
  const ForceHistory h = read_openfoam_forces(dir / "f");
  EXPECT_TRUE(h.moment_origin.empty());
  EXPECT_TRUE(h.values(kTotal, HistoryComponent::Mz).empty());
  EXPECT_EQ(h.files.size(), 1u);
}

// ---------------------------------------------------------------------------
// The abscissa

TEST(OpenFoamForces, TransientTimesAreTimeAndTheCallerCanSay) {
  const std::string text = "# Force\n# Time total_x total_y total_z\n0.001 1 2 3\n0.002 1 2 3\n0.003 1 2 3\n";
  EXPECT_EQ(parse_openfoam_force_file(text, "force.dat").abscissa, HistoryAbscissa::Time);
  const std::string whole = "# Force\n# Time total_x total_y total_z\n10 1 2 3\n20 1 2 3\n";
  EXPECT_EQ(parse_openfoam_force_file(whole, "force.dat").abscissa, HistoryAbscissa::Iteration);
  OpenFoamForcesOptions options;
  options.abscissa = HistoryAbscissa::Time;
  EXPECT_EQ(parse_openfoam_force_file(whole, "force.dat", options).abscissa, HistoryAbscissa::Time);
}

// ---------------------------------------------------------------------------
// Threads and large files

std::string big_force_file(std::size_t rows) {
  std::string text =
      "# Force\n# CofR : (0 0 0)\n#\n# Time (total_x total_y total_z) (pressure_x pressure_y pressure_z) "
      "(viscous_x viscous_y viscous_z)\n";
  char line[256];
  for (std::size_t i = 1; i <= rows; ++i) {
    const double t = 1e-4 * double(i);
    const double p = std::sin(0.01 * double(i)), v = 0.01 * std::cos(0.02 * double(i));
    std::snprintf(line, sizeof line, "%.6g\t(%.10e %.10e %.10e)\t(%.10e %.10e %.10e)\t(%.10e %.10e %.10e)\n", t, p + v,
                  -p, 2 * v, p, -p + v, 2 * v - v, v, v, v);
    text += line;
  }
  return text;
}

TEST(OpenFoamForces, ThreadsGiveTheSameHistoryAndTheSameErrorLines) {
  const std::string text = big_force_file(60000);  // about 13 MB: several chunks
  OpenFoamForcesOptions one;
  one.threads = 1;
  OpenFoamForcesOptions three;
  three.threads = 3;
  const ForceHistory a = parse_openfoam_force_file(text, "force.dat", one);
  const ForceHistory b = parse_openfoam_force_file(text, "force.dat", three);
  expect_same_series(a, b, {kTotal, kPressure, kViscous});
  EXPECT_EQ(a.force_origin.back().line, 60004u);
  EXPECT_EQ(b.force_origin.back().line, 60004u);
  for (std::size_t i = 0; i < b.size(); i += 7919) EXPECT_EQ(b.force_origin[i].line, i + 5);

  // A bad number far into the file: the same line and column either way.
  std::string bad = text;
  const std::size_t row = bad.find("\n5.5\t") + 1;  // row of t = 5.5 (i = 55000), line 55004
  ASSERT_NE(row, 0u);
  bad.replace(bad.find(' ', row) + 1, 3, "x.y");
  for (const auto* options : {&one, &three})
    expect_input_error([&] { parse_openfoam_force_file(bad, "force.dat", *options); },
                       {"force.dat:55004:", "column 3 'total_y'", "found 'x.y", "expected a number"});
}

// ---------------------------------------------------------------------------
// Refusals

const std::string kHead =
    "# Force\n# CofR : (0 0 0)\n#\n# Time\t(total_x total_y total_z)\t(pressure_x pressure_y pressure_z)\n";

TEST(OpenFoamForces, RefusesBadRowsWithTheirPlace) {
  expect_input_error([&] { parse_openfoam_force_file(kHead + "1\t(1 2 3)\t(1 2 abc)\n", "force.dat"); },
                     {"force.dat:5:16:", "column 7 'pressure_z'", "found 'abc'", "expected a number"});
  expect_input_error([&] { parse_openfoam_force_file(kHead + "1\t(1 2 3)\t(1 2)\n", "force.dat"); },
                     {"force.dat:5:", "found 6 fields, expected 7"});
  expect_input_error([&] { parse_openfoam_force_file(kHead + "1\t(1 2 3)\t(1 2 3) 4\n", "force.dat"); },
                     {"force.dat:5:", "found more than 7 fields"});
  expect_input_error([&] { parse_openfoam_force_file(kHead + "1\t(1 2 3\t(1 2 3)\n", "force.dat"); },
                     {"force.dat:5:", "'(' without a matching ')'"});
  expect_input_error([&] { parse_openfoam_force_file(kHead + "1\t1 2 3)\t(1 2 3)\n", "force.dat"); },
                     {"force.dat:5:8:", "')' without a matching '('"});
  expect_input_error([&] { parse_openfoam_force_file(kHead + "1\t(1 nan 3)\t(1 2 3)\n", "force.dat"); },
                     {"force.dat:5:6:", "column 3 'total_y'", "found 'nan'", "expected a finite number"});
  expect_input_error([&] { parse_openfoam_force_file(kHead + "1\t(1 1e999 3)\t(1 2 3)\n", "force.dat"); },
                     {"force.dat:5:6:", "found '1e999'", "finite"});
  expect_input_error(
      [&] { parse_openfoam_force_file(kHead + "1\t(1 2 3)\t(1 2 3)\n1\t(1 2 3)\t(1 2 3)\n", "force.dat"); },
      {"force.dat:6", "time 1 is not after 1 on line 5", "increasing"});
}

TEST(OpenFoamForces, ALastRowCutShortIsRefusedOrDropped) {
  const std::string text = kHead + "1\t(1 2 3)\t(1 2 3)\n2\t(1 2 3)\t(1 2 3";
  expect_input_error([&] { parse_openfoam_force_file(text, "force.dat"); },
                     {"force.dat:6:", "a run stopped while writing"});
  // Even with every number present, a row without its line end may have lost digits.
  expect_input_error([&] { parse_openfoam_force_file(text + ")", "force.dat"); }, {"force.dat:6", "no line end"});
  OpenFoamForcesOptions options;
  options.drop_incomplete_last_row = true;
  const ForceHistory h = parse_openfoam_force_file(text, "force.dat", options);
  EXPECT_EQ(h.size(), 1u);
  ASSERT_FALSE(h.notes.empty());
  EXPECT_NE(h.notes.front().find("cut short"), std::string::npos);
}

TEST(OpenFoamForces, ForceAndMomentFilesMustHoldTheSameTimes) {
  TempDir dir;
  fs::create_directories(dir / "f" / "0");
  write_bytes(dir / "f/0/force.dat", "# Force\n# Time total_x total_y total_z\n1 1 2 3\n2 1 2 3\n3 1 2 3\n");
  write_bytes(dir / "f/0/moment.dat", "# Moment\n# Time total_x total_y total_z\n1 1 2 3\n2.5 1 2 3\n3 1 2 3\n");
  expect_input_error([&] { read_openfoam_forces(dir / "f"); },
                     {"moment.dat:4", "time 2.5 differs from 2 on line 4 of", "force.dat", "same times"});
  // A force row whose moment row was never written.
  write_bytes(dir / "f/0/moment.dat", "# Moment\n# Time total_x total_y total_z\n1 1 2 3\n2 1 2 3\n");
  expect_input_error([&] { read_openfoam_forces(dir / "f"); },
                     {"force.dat:5", "no partner in", "3 force rows, 2 moment rows"});
  OpenFoamForcesOptions options;
  options.drop_incomplete_last_row = true;
  const ForceHistory h = read_openfoam_forces(dir / "f", options);
  EXPECT_EQ(h.size(), 2u);
  EXPECT_EQ(h.files[0].rows, 3u);
  EXPECT_EQ(h.files[0].rows_used, 2u);
}

TEST(OpenFoamForces, RefusesHeadersItDoesNotKnow) {
  expect_input_error([&] { parse_openfoam_force_file("1 (1 2 3)\n", "force.dat"); }, {"force.dat:1:1", "no header"});
  expect_input_error([&] { parse_openfoam_force_file("# Force\n# CofR : (0 0 0)\n1 (1 2 3)\n", "force.dat"); },
                     {"force.dat:2", "no '# Time ...' column line"});
  expect_input_error([&] { parse_openfoam_force_file("# Force\n# Time total_x drag_y\n1 1 2\n", "force.dat"); },
                     {"force.dat:2:", "unknown column 'drag_y'", "total_x, pressure_y"});
  expect_input_error([&] { parse_openfoam_force_file("# Stuff\n# Time total_x\n1 1\n", "data.dat"); },
                     {"data.dat:1", "cannot tell force from moment"});
  expect_input_error([&] { parse_openfoam_force_file("# Force\n# Time total_x total_x\n1 1 2\n", "force.dat"); },
                     {"force.dat:2:", "'total_x' appears twice"});
  expect_input_error(
      [&] {
        parse_openfoam_force_file("# Forces\n# Time forces(pressure viscous) moment(pressure wet)\n", "forces.dat");
      },
      {"forces.dat:2:", "unknown part 'wet'"});
  expect_input_error([&] { parse_openfoam_force_file("# Forces\n# Time forces(pressure viscous)\n", "forces.dat"); },
                     {"forces.dat:2", "forces but no moments"});
  expect_input_error([&] { parse_openfoam_force_file("# Force coefficients\n# Time Cd Cx\n", "coefficient.dat"); },
                     {"coefficient.dat:2:", "unknown column 'Cx'"});
  expect_input_error([&] { parse_openfoam_force_file("# Force\n# CofR : (0 0)\n# Time total_x\n1 1\n", "force.dat"); },
                     {"force.dat:2", "CofR: found '(0 0)'", "a point"});
}

TEST(OpenFoamForces, RefusesPathsWithoutForceFiles) {
  TempDir dir;
  fs::create_directories(dir / "f" / "0");
  write_bytes(dir / "f/0/p.dat", "x");
  expect_input_error([&] { read_openfoam_forces(dir / "f"); }, {"no OpenFOAM force files", "'0'"});
  expect_input_error([&] { read_openfoam_forces(dir / "f/0/p.dat"); }, {"p.dat", "not an OpenFOAM force file"});
  expect_input_error([&] { read_openfoam_forces(dir / "missing"); }, {"missing", "no such file"});
  write_bytes(dir / "f/0/force.dat", "# Force\n# Time total_x total_y total_z\n");
  expect_input_error([&] { read_openfoam_forces(dir / "f"); }, {"hold no rows"});
}

TEST(OpenFoamForces, RecognisesItsFiles) {
  EXPECT_TRUE(
      looks_like_openfoam_forces(read_bytes(forces_folder("cases/u0.10_v0.05") / "0" / "moment.dat").substr(0, 400)));
  EXPECT_TRUE(looks_like_openfoam_forces("# Forces\n# Time forces(pressure viscous) moment(pressure viscous)\n"));
  EXPECT_TRUE(looks_like_openfoam_forces("# Force coefficients\n# Time\tCd\tCs\tCl\n"));
  EXPECT_FALSE(looks_like_openfoam_forces("Time,Fx,Fy\n1,2,3\n"));
  EXPECT_FALSE(looks_like_openfoam_forces("# Probe 0 (0 0 0)\n# Time p\n"));
}

}  // namespace
}  // namespace hydrocoef

namespace hydrocoef {
namespace {

// Damaged files: random byte edits of small valid files of every layout must
// be read (a valid history) or refused with a one-line InputError; nothing
// else (another exception, a sanitizer report) may happen.
TEST(OpenFoamForces, DamagedFilesAreReadOrRefusedInOneLine) {
  const std::vector<std::pair<std::string, std::string>> seeds{
      {"force.dat", kHead + "1\t(1 2 3)\t(4 5 6)\n2\t(1.5e-3 -2 3)\t(4 5 6)\n3\t(1 2 3)\t(4 5 6)\n"},
      {"moment.dat",
       "# Moment\n# CofR : (0 0 1)\n#\n# Time total_x total_y total_z viscous_x viscous_y viscous_z\n"
       "0.1 1 2 3 4 5 6\n0.2 1 2 3 4 5 6\n"},
      {"forces.dat",
       "# Forces\n# CofR : (0 0 0)\n# Time CofR forces(pressure viscous porous) moment(pressure viscous "
       "porous) localForces(pressure,viscous,porous)\n1 (0 0 0) ((1 2 3) (4 5 6) (7 8 9)) ((1 2 3) (4 5 "
       "6) (7 8 9))\n1 (0 0 0) ((1 2 3) (4 5 6) (7 8 9)) ((1 2 3) (4 5 6) (7 8 9))\n"},
      {"coefficient.dat",
       "# Force coefficients\n# dragDir : (1 0 0)\n# sideDir : (0 1 0)\n# liftDir : (0 0 1)\n"
       "# magUInf : 2\n# lRef : 1\n# Aref : 0.5\n# Time Cd Cs Cl CmRoll CmPitch CmYaw Cd(f)\n"
       "1 0.1 0.2 0.3 0.4 0.5 0.6 0.7\n2 0.1 0.2 0.3 0.4 0.5 0.6 0.7\n"},
      {"forceCoeffs.dat",
       "# Force coefficients\n# liftDir : (0 0 1)\n# dragDir : (1 0 0)\n# pitchAxis : (0 1 0)\n"
       "# magUInf : 2\n# lRef : 1\n# Aref : 0.5\n# Time Cm Cd Cl Cl(f) Cl(r)\n1 0.1 0.2 0.3 0.4 0.5\n"}};
  const std::string alphabet = "0123456789.eE+-() \t\n#:_xyzCdslmtoa,\r";
  std::mt19937_64 random(2024);
  OpenFoamForcesOptions options;
  options.rho = 1000.0;
  options.threads = 2;
  int read = 0, refused = 0;
  for (int i = 0; i < 3000; ++i) {
    const auto& [name, seed] = seeds[static_cast<std::size_t>(i) % seeds.size()];
    std::string text = seed;
    for (int edits = 1 + static_cast<int>(random() % 3); edits > 0 && !text.empty(); --edits) {
      const std::size_t at = random() % text.size();
      switch (random() % 3) {
        case 0: text[at] = alphabet[random() % alphabet.size()]; break;
        case 1: text.erase(at, 1 + random() % 4); break;
        default: text.insert(at, 1, alphabet[random() % alphabet.size()]);
      }
    }
    options.drop_incomplete_last_row = i % 2 == 0;
    try {
      const ForceHistory h = parse_openfoam_force_file(text, name, options);
      check_force_history(h);
      ++read;
    } catch (const InputError& error) {
      const std::string message = error.what();
      ASSERT_EQ(message.find('\n'), std::string::npos) << message;
      ASSERT_FALSE(message.empty());
      ++refused;
    }
  }
  EXPECT_GT(read, 100);
  EXPECT_GT(refused, 100);
}

}  // namespace
}  // namespace hydrocoef

namespace hydrocoef {
namespace {

// OpenFOAM 2.x wrote commas between the parts of a group.
TEST(OpenFoamForces, OldFoundationHeadersWithCommas) {
  const std::string text =
      "# Time forces(pressure, viscous) moment(pressure, viscous)\n"
      "0.5\t((1 2 3) (0.1 0.2 0.3)) ((4 5 6) (0.4 0.5 0.6))\n";
  const ForceHistory h = parse_openfoam_force_file(text, "forces.dat");
  EXPECT_EQ(h.values(kTotal, HistoryComponent::Fy), std::vector<double>{2.2});
  EXPECT_EQ(h.values(kViscous, HistoryComponent::Mz), std::vector<double>{0.6});
  EXPECT_EQ(h.values(kPressure, HistoryComponent::Mx), std::vector<double>{4.0});
  EXPECT_FALSE(h.frame.moment_centre);  // no CofR line in this header
}

}  // namespace
}  // namespace hydrocoef
