// Run keys for files that carry no settings of their own: a sweep manifest
// (the spreadsheet CFD engineers keep, one row per file) and a name pattern
// over the file's path (the folder names a sweep script makes, u0.20_v0.05).
// Both become SettingsLayers (src/pipeline/run_settings.hpp), so that their
// values merge with every other source by the one precedence rule.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "src/pipeline/run_settings.hpp"

namespace hydrocoef {

/// A sweep manifest: a CSV file (comma, tab or semicolon separated) with a
/// header row and one row per file.
///   path                  the file or case folder, relative to the manifest's folder or absolute
///   body, axes, sign, window, symmetry      texts
///   u v w p q r           body velocity; units in brackets ("r [deg s^-1]"), SI by default
///   flow_x flow_y flow_z  free stream in CFD axes [m/s] (all three, or none)
///   rho nu p_ref          fluid and reference pressure (SI, or units in brackets)
///   any other column      a disturbance parameter (an identifier), with its unit
/// An empty cell states nothing. Each value's origin is "FILE:LINE".
class Manifest {
 public:
  /// Reads and checks the whole file. InputError names FILE:LINE:COLUMN for a
  /// missing path column, a path listed twice, a bad number or unit, a
  /// column name that breaks the name rule, or a row of the wrong width.
  static Manifest read(const std::filesystem::path& file);

  /// The row of a file or case folder, matched by its normalized absolute
  /// path (or any folder above it: a row for a case folder covers its files).
  const SettingsLayer* find(const std::filesystem::path& path) const;

  const std::filesystem::path& file() const { return file_; }
  std::size_t rows() const { return rows_.size(); }
  /// The rows no file matched yet, for a note at the end of an import.
  std::vector<std::filesystem::path> paths() const;

 private:
  std::filesystem::path file_;
  std::map<std::filesystem::path, SettingsLayer> rows_;  ///< by normalized absolute path
};

/// A name pattern: literal text with fields in braces, "u{u}_v{v}" or
/// "r{r [deg s^-1]}_c{current_v}", a field being a velocity component or a
/// disturbance parameter and an optional unit (SI by default). A pattern
/// without '/' must match one whole folder or file name (without its
/// extension for files) on the path below the imported folder; with '/', a
/// run of whole names.
class NamePattern {
 public:
  /// InputError for an unbalanced brace, an empty or repeated field, a bad
  /// unit or a pattern without fields.
  explicit NamePattern(std::string pattern);

  /// The settings the path's names give, or nullopt when no name matches.
  /// `relative` is the path below the imported folder; `names_a_file` says
  /// whether its last name is a file's (matched without its extension) or a
  /// folder's (a case folder, matched whole). InputError when two names on
  /// the path match with different values.
  std::optional<SettingsLayer> match(const std::filesystem::path& relative, bool names_a_file = true) const;

  const std::string& text() const { return pattern_; }

 private:
  struct Field {
    std::string name;
    double scale = 1.0;  ///< to SI
  };
  std::string pattern_;
  std::vector<std::string> literals_;  ///< literal text before each field, and after the last
  std::vector<Field> fields_;
  bool spans_folders_ = false;
  std::optional<std::vector<double>> match_text(std::string_view text) const;
};

}  // namespace hydrocoef
