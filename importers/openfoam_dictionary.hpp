// OpenFOAM dictionary files (0/U, system/controlDict,
// constant/transportProperties, ...) as far as hydrocoef reads them: entries
// `keyword value...;` and sub-dictionaries `keyword { ... }`, // and /* */
// comments, `#include "file"` (relative to the including file), `$name`
// references to an entry of the same or an enclosing dictionary, and the
// FoamFile header. `#includeEtc` and `#includeFunc` name files of the
// OpenFOAM installation, which hydrocoef does not read: they are recorded,
// so that a caller can say what it could not see. Anything else starting with
// '#' (#calc, #codeStream, #if) is refused with the file and line, as is a
// `$` reference that names nothing.
//
// Grammar (OpenFOAM User Guide, "Input/output file format"; the dictionary
// parser of src/OpenFOAM/db/dictionary): a primitive entry is a keyword and
// the tokens up to its ';', lists in parentheses included.
#pragma once

#include <array>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hydrocoef {

/// A primitive entry: its tokens ("uniform", "(", "0.1", "0.05", "0", ")")
/// and where it was written.
struct FoamValue {
  std::vector<std::string> tokens;
  std::string file;
  std::size_t line = 0;
};

class FoamDictionary {
 public:
  /// Reads a dictionary file (and the files it #includes, at most 8 deep).
  /// InputError naming the file and line for what cannot be read.
  static FoamDictionary read(const std::filesystem::path& file);
  /// Parses text as the content of `file` (for #include, relative to it).
  static FoamDictionary parse(std::string_view text, const std::filesystem::path& file, int depth = 0);

  const FoamValue* value(std::string_view key) const;
  const FoamDictionary* dictionary(std::string_view key) const;
  /// The primitive entries by key (quoted keys keep their quotes).
  const std::map<std::string, FoamValue, std::less<>>& values() const { return values_; }
  /// Keys of the sub-dictionaries, in file order.
  const std::vector<std::string>& dictionary_keys() const { return dictionary_order_; }
  /// The #includeEtc and #includeFunc directives met (their arguments).
  const std::vector<std::string>& unread_includes() const { return unread_includes_; }
  const std::string& file() const { return file_; }

 private:
  static FoamDictionary read_nested(const std::filesystem::path& file, int depth);
  std::map<std::string, FoamValue, std::less<>> values_;
  std::map<std::string, std::shared_ptr<FoamDictionary>, std::less<>> dictionaries_;
  std::vector<std::string> dictionary_order_;
  std::vector<std::string> unread_includes_;
  std::string file_;
  const FoamDictionary* parent_ = nullptr;
  friend class FoamParser;
};

/// A scalar entry (`rhoInf 998.2;`, or with dimensions `nu [0 2 -1 0 0 0 0] 1e-06;`).
/// InputError at the entry when it is not one finite number.
double foam_scalar(const FoamValue& value, std::string_view what);

/// A vector entry (`(0 0 0)`, or a field value `uniform (0.1 0.05 0)`).
/// InputError at the entry when it is not three finite numbers.
std::array<double, 3> foam_vector(const FoamValue& value, std::string_view what);

/// The single word of an entry (`type freestreamVelocity;`), or nullopt.
std::optional<std::string> foam_word(const FoamValue* value);

}  // namespace hydrocoef
