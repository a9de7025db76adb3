// Test support: writes a SurfaceMesh with point fields as a CFD-Post "Generic"
// export (the text File > Export writes), in the dialects real files come in
// (m/Pa or mm/kPa, CRLF or LF, ", " or tab, with or without Node Number,
// columns in any order, one [Name] block per location), so that tests can make
// twins of one surface in several formats and check they import alike.
//
// What is written:
// - A mesh without location names is one block named `default_location`
//   holding every point and face. Otherwise each location is one block with
//   the points its faces use (ascending original index, re-numbered from 0)
//   and its faces; when the mesh has a single location every point is written.
//   Re-read, a mesh round-trips exactly when its locations use disjoint,
//   contiguous, ascending point ranges and no point is unused (or there is one
//   location).
// - Columns: X, Y, Z, then every Point array with 1 component as
//   "Name [ unit ]", or a bare name when dimensionless; a 3-component array as
//   "Name X", "Name Y", "Name Z" (it comes back as three scalar arrays). Face
//   arrays are not written: a Generic export is nodal only.
// - Units: the field's unit (SI text, e.g. "kg m^-1 s^-2", "Pa" or "") is
//   read with parse_unit; in the mm/kPa system lengths are written in mm,
//   pressures in kPa, velocities in mm s^-1, everything else in SI. In the
//   m/Pa system pressures are labelled "Pa" and velocities "m s^-1".
// - Numbers as printf "%.*e" with `precision` digits (CFD-Post's Precision = 8
//   gives "%.8e"); NaN as the null token "null".
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "src/core/units.hpp"
#include "src/mesh/surface_mesh.hpp"

namespace hydrocoef::test {

enum class CfdPostUnits {
  MetrePascal,           ///< X [ m ], Pressure [ Pa ]
  MillimetreKilopascal,  ///< X [ mm ], Pressure [ kPa ], Velocity [ mm s^-1 ]
};

struct CfdPostWriterOptions {
  CfdPostUnits units = CfdPostUnits::MetrePascal;
  bool crlf = false;             ///< "\r\n" line endings, as CFD-Post writes on Windows
  std::string separator = ", ";  ///< ", " (CFD-Post's default) or "\t"
  bool node_numbers = false;     ///< a "Node Number" column first (Export Node Numbers = On)
  bool shuffle_columns = false;  ///< the other columns in a random order drawn from `seed`
  unsigned seed = 1;
  int precision = 8;               ///< digits after the decimal point
  bool faces = true;               ///< write [Faces] (Export Connectivity = On)
  bool leading_blank_line = true;  ///< as in every real file
  int trailing_blank_lines = 1;
  std::string default_location = "surface";
};

namespace cfdpost_writer_detail {

struct OutColumn {
  std::string header;
  const std::vector<double>* values = nullptr;  // nullptr for coordinates
  int components = 1;
  int component = 0;  // which component (or coordinate axis)
  double divide_by = 1.0;
  double multiply_by = 1.0;
};

inline void append_number(std::string& out, double value, int precision) {
  if (std::isnan(value)) {
    out += "null";
    return;
  }
  char buffer[64];
  const int length = std::snprintf(buffer, sizeof buffer, "%.*e", precision, value);
  if (length < 0 || length >= static_cast<int>(sizeof buffer)) throw std::runtime_error("number does not fit");
  out.append(buffer, static_cast<std::size_t>(length));
}

// Unit label and conversion of an SI value into it, for one field.
inline void choose_unit(const std::string& si_unit, CfdPostUnits units, std::string& label, double& divide_by,
                        double& multiply_by) {
  const Unit unit = parse_unit(si_unit);
  if (unit.scale != 1.0) throw std::invalid_argument("field unit '" + si_unit + "' is not SI");
  divide_by = 1.0;
  multiply_by = 1.0;
  const bool mm = units == CfdPostUnits::MillimetreKilopascal;
  if (unit.dimension == kDimensionless) {
    label.clear();
  } else if (unit.dimension == kPressure) {
    label = mm ? "kPa" : "Pa";
    divide_by = mm ? 1000.0 : 1.0;
  } else if (unit.dimension == kLength) {
    label = mm ? "mm" : "m";
    multiply_by = mm ? 1000.0 : 1.0;
  } else if (unit.dimension == kVelocity) {
    label = mm ? "mm s^-1" : "m s^-1";
    multiply_by = mm ? 1000.0 : 1.0;
  } else {
    label = unit.text;
  }
}

}  // namespace cfdpost_writer_detail

inline std::string write_cfdpost_export(const SurfaceMesh& mesh, const CfdPostWriterOptions& options = {}) {
  using namespace cfdpost_writer_detail;
  const std::string eol = options.crlf ? "\r\n" : "\n";
  const bool mm = options.units == CfdPostUnits::MillimetreKilopascal;

  std::vector<OutColumn> columns;
  for (int axis = 0; axis < 3; ++axis) {
    OutColumn column;
    column.header = std::string(1, static_cast<char>('X' + axis)) + (mm ? " [ mm ]" : " [ m ]");
    column.component = axis;
    column.multiply_by = mm ? 1000.0 : 1.0;
    columns.push_back(column);
  }
  for (const auto& field : mesh.fields) {
    if (field.association != FieldAssociation::Point) continue;
    if (field.components != 1 && field.components != 3)
      throw std::invalid_argument("array '" + field.name + "' has neither 1 nor 3 components");
    std::string label;
    double divide_by = 1.0, multiply_by = 1.0;
    choose_unit(field.unit, options.units, label, divide_by, multiply_by);
    const std::string suffix = label.empty() ? std::string() : " [ " + label + " ]";
    for (int c = 0; c < field.components; ++c) {
      OutColumn column;
      column.header = field.name;
      if (field.components == 3) column.header += std::string(" ") + static_cast<char>('X' + c);
      column.header += suffix;
      column.values = &field.values;
      column.components = field.components;
      column.component = c;
      column.divide_by = divide_by;
      column.multiply_by = multiply_by;
      columns.push_back(column);
    }
  }
  if (options.shuffle_columns) {
    std::mt19937 random(options.seed);
    std::shuffle(columns.begin(), columns.end(), random);
  }

  // Blocks: (name, points in the block, faces in the block).
  struct OutBlock {
    std::string name;
    std::vector<std::uint32_t> points;
    std::vector<std::size_t> faces;
  };
  std::vector<OutBlock> blocks;
  const std::size_t faces = mesh.face_count();
  if (mesh.location_names.size() <= 1) {
    OutBlock block;
    block.name = mesh.location_names.empty() ? options.default_location : mesh.location_names.front();
    block.points.resize(mesh.point_count());
    std::iota(block.points.begin(), block.points.end(), 0u);
    for (std::size_t f = 0; f < faces; ++f) block.faces.push_back(f);
    blocks.push_back(std::move(block));
  } else {
    if (mesh.face_location.size() != faces) throw std::invalid_argument("face_location must have one entry per face");
    for (std::size_t l = 0; l < mesh.location_names.size(); ++l) {
      OutBlock block;
      block.name = mesh.location_names[l];
      for (std::size_t f = 0; f < faces; ++f) {
        if (mesh.face_location[f] != l) continue;
        block.faces.push_back(f);
        for (auto i = mesh.face_offsets[f]; i < mesh.face_offsets[f + 1]; ++i)
          block.points.push_back(mesh.face_indices[i]);
      }
      std::sort(block.points.begin(), block.points.end());
      block.points.erase(std::unique(block.points.begin(), block.points.end()), block.points.end());
      blocks.push_back(std::move(block));
    }
  }

  std::string out;
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    const OutBlock& block = blocks[b];
    if (b > 0 || options.leading_blank_line) out += eol;
    out += "[Name]" + eol + block.name + eol + eol + "[Data]" + eol;
    std::string header;
    if (options.node_numbers) header = "Node Number";
    for (const auto& column : columns) {
      if (!header.empty()) header += options.separator;
      header += column.header;
    }
    out += header + eol;
    std::vector<std::uint32_t> local(mesh.point_count(), 0);
    for (std::size_t r = 0; r < block.points.size(); ++r) {
      const std::uint32_t point = block.points[r];
      local[point] = static_cast<std::uint32_t>(r);
      bool first = true;
      if (options.node_numbers) {
        out += std::to_string(point + 1);
        first = false;
      }
      for (const auto& column : columns) {
        if (!first) out += options.separator;
        first = false;
        const double si = column.values == nullptr
                              ? mesh.points_xyz[3 * point + static_cast<std::size_t>(column.component)]
                              : (*column.values)[static_cast<std::size_t>(column.components) * point +
                                                 static_cast<std::size_t>(column.component)];
        append_number(out, si * column.multiply_by / column.divide_by, options.precision);
      }
      out += eol;
    }
    if (options.faces) {
      out += eol + "[Faces]" + eol;
      for (const std::size_t f : block.faces) {
        for (auto i = mesh.face_offsets[f]; i < mesh.face_offsets[f + 1]; ++i) {
          if (i > mesh.face_offsets[f]) out += options.separator;
          out += std::to_string(local[mesh.face_indices[i]]);
        }
        out += eol;
      }
    }
  }
  for (int i = 0; i < options.trailing_blank_lines; ++i) out += eol;
  return out;
}

}  // namespace hydrocoef::test
