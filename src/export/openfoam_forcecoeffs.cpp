#include "src/export/openfoam_forcecoeffs.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include "src/core/error.hpp"
#include "src/core/numbers.hpp"

namespace hydrocoef {
namespace {

constexpr std::array<const char*, 12> kColumns = {"Cd",    "Cs",    "Cl",    "CmRoll", "CmPitch", "CmYaw",
                                                  "Cd(f)", "Cd(r)", "Cs(f)", "Cs(r)",  "Cl(f)",   "Cl(r)"};

std::string scientific(double value, int precision) {
  if (value == 0.0) value = 0.0;  // no "-0.0e+00"
  char buffer[64];
  const int n = std::snprintf(buffer, sizeof buffer, "%.*e", precision, value);
  return std::string(buffer, static_cast<std::size_t>(n));
}

double parsed(const std::string& text) {
  double value = 0.0;
  std::from_chars(text.data(), text.data() + text.size(), value);
  return value;
}

std::string padded(const std::string& text, std::size_t width) {
  return text.size() >= width ? text : text + std::string(width - text.size(), ' ');
}

/// "# " + the label padded to the width less 2, as OpenFOAM's writeCommented.
std::string commented(const std::string& label, std::size_t width) { return "# " + padded(label, width - 2); }

std::string vector_text(const std::array<double, 3>& v, int precision) {
  return "(" + scientific(v[0], precision) + " " + scientific(v[1], precision) + " " + scientific(v[2], precision) +
         ")";
}

void check_positive(double value, const char* name) {
  if (!std::isfinite(value) || !(value > 0.0))
    throw InputError(std::string("forceCoeffs: ") + name + " is " + shortest_number(value) +
                     "; expected a finite positive number");
}

}  // namespace

double inverse_of_product(double value, double scale, bool& exact) {
  const double first = value / scale;
  exact = true;
  if (first * scale == value) return first;
  // The doubles on either side, nearest first.
  double up = first, down = first;
  for (int step = 0; step < 4; ++step) {
    up = std::nextafter(up, std::numeric_limits<double>::infinity());
    down = std::nextafter(down, -std::numeric_limits<double>::infinity());
    if (up * scale == value) return up;
    if (down * scale == value) return down;
  }
  exact = false;
  // None gives the value back: the one whose product lies nearest to it.
  double best = first;
  double miss = std::abs(first * scale - value);
  up = first;
  down = first;
  for (int step = 0; step < 4; ++step) {
    up = std::nextafter(up, std::numeric_limits<double>::infinity());
    down = std::nextafter(down, -std::numeric_limits<double>::infinity());
    for (const double candidate : {up, down})
      if (const double m = std::abs(candidate * scale - value); m < miss) {
        miss = m;
        best = candidate;
      }
  }
  return best;
}

std::string openfoam_time_name(double time) {
  if (time == 0.0) time = 0.0;
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, time);
  return std::string(buffer, result.ptr);
}

ForceCoeffsText openfoam_forcecoeffs(const ForceCoeffsInput& input) {
  check_positive(input.rho, "rho");
  check_positive(input.mag_u_inf, "magUInf");
  check_positive(input.l_ref, "lRef");
  check_positive(input.a_ref, "Aref");
  if (input.precision < 1 || input.precision > 16)
    throw InputError("--precision " + std::to_string(input.precision) +
                     ": expected 1 to 16 digits after the point (16: every double exactly)");
  for (const double c : input.cofr)
    if (!std::isfinite(c)) throw InputError("forceCoeffs: CofR is not finite; expected a point");
  const std::size_t n = input.time.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(input.time[i]))
      throw InputError("forceCoeffs: time " + shortest_number(input.time[i]) + " is not finite");
    if (i > 0 && !(input.time[i] > input.time[i - 1]))
      throw InputError("forceCoeffs: time " + shortest_number(input.time[i]) + " is not after " +
                       shortest_number(input.time[i - 1]) + "; expected increasing times");
  }
  for (std::size_t c = 0; c < 6; ++c) {
    if (input.load[c].size() != n)
      throw InputError("forceCoeffs: " + std::to_string(input.load[c].size()) + " values of component " +
                       std::to_string(c) + " for " + std::to_string(n) + " times");
    for (const double v : input.load[c])
      if (!std::isfinite(v)) throw InputError("forceCoeffs: a force or moment is not finite");
  }
  for (const auto& line : input.comments)
    for (const char ch : line)
      if (ch == ':' || static_cast<unsigned char>(ch) < 0x20 || ch == 0x7f)
        throw InputError("forceCoeffs: a comment line holds ':' or a control character; expected free text");

  const int precision = input.precision;
  const std::size_t width = static_cast<std::size_t>(precision) + 8;  // writeFile::charWidth()
  const auto value_line = [&](const char* name, const std::string& value) {
    return commented(name, width) + ": " + value + "\n";
  };
  std::string out = "# Force coefficients\n";
  const std::array<std::array<double, 3>, 3> axes{{{1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}}};
  out += value_line("dragDir", vector_text(axes[0], precision));
  out += value_line("sideDir", vector_text(axes[1], precision));
  out += value_line("liftDir", vector_text(axes[2], precision));
  out += value_line("rollAxis", vector_text(axes[0], precision));
  out += value_line("pitchAxis", vector_text(axes[1], precision));
  out += value_line("yawAxis", vector_text(axes[2], precision));
  out += value_line("magUInf", scientific(input.mag_u_inf, precision));
  out += value_line("lRef", scientific(input.l_ref, precision));
  out += value_line("Aref", scientific(input.a_ref, precision));
  out += value_line("CofR", vector_text(input.cofr, precision));
  for (const auto& line : input.comments) out += "# " + line + "\n";
  out += "#\n";
  out += commented("Time", width);
  for (const char* column : kColumns) out += "\t" + padded(column, width);
  out += "\n";

  // The scales as OpenFOAM and the reader compute them, from the reference
  // values themselves (OpenFOAM divides by its own, not by the header's
  // rounded print; at precision 16 the header prints them exactly).
  const double q = 0.5 * input.rho * input.mag_u_inf * input.mag_u_inf;
  const double force_scale = q * input.a_ref;
  const double moment_scale = q * input.a_ref * input.l_ref;

  ForceCoeffsText result;
  for (auto& column : result.coefficient) column.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::array<double, 6> c{};  // as computed (OpenFOAM forms the parts from these, then rounds)
    for (std::size_t k = 0; k < 6; ++k) {
      const double scale = k < 3 ? force_scale : moment_scale;
      const double value = input.load[k][i];
      double coefficient = value / scale;
      if (precision == 16) {
        bool exact = true;
        coefficient = inverse_of_product(value, scale, exact);
        ++(exact ? result.exact : result.one_ulp);
      }
      ++result.values;
      c[k] = coefficient;
      result.coefficient[k].push_back(parsed(scientific(coefficient, precision)));
    }
    // v1912's front and rear parts.
    const std::array<double, 6> parts{0.5 * c[0] + c[3], 0.5 * c[0] - c[3], 0.5 * c[1] + c[5],
                                      0.5 * c[1] - c[5], 0.5 * c[2] + c[4], 0.5 * c[2] - c[4]};
    out += padded(openfoam_time_name(input.time[i]), width);
    for (const double v : c) out += "\t" + scientific(v, precision);
    for (const double v : parts) out += "\t" + scientific(v, precision);
    out += "\n";
  }
  result.text = std::move(out);
  return result;
}

}  // namespace hydrocoef
