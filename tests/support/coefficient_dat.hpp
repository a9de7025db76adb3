// Reading OpenFOAM forceCoeffs coefficient.dat files in tests: the last data
// row by the header's column names.
#pragma once

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace hydrocoef::test {

/// Column name -> value of the last data row of a coefficient.dat (the
/// column names from its last "# Time ..." header line).
inline std::map<std::string, double> last_coefficient_row(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::vector<std::string> names;
  std::vector<double> values;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("# Time", 0) == 0) {
      std::istringstream words(line.substr(1));
      names.clear();
      for (std::string word; words >> word;) names.push_back(word);
    } else if (!line.empty() && line[0] != '#') {
      std::istringstream words(line);
      values.clear();
      for (double value; words >> value;) values.push_back(value);
    }
  }
  std::map<std::string, double> out;
  for (std::size_t i = 0; i < names.size() && i < values.size(); ++i) out[names[i]] = values[i];
  return out;
}

}  // namespace hydrocoef::test
