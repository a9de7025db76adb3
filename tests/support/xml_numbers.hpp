// Test support: reads an XML file back through VTK's XML parser and the
// whitespace-separated numbers of a nested element (exported SDF snippets).
#pragma once

#include <gtest/gtest.h>
#include <vtkSmartPointer.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLUtilities.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace hydrocoef::test {

inline vtkSmartPointer<vtkXMLDataElement> read_xml(const std::filesystem::path& path) {
  return vtkSmartPointer<vtkXMLDataElement>::Take(vtkXMLUtilities::ReadElementFromFile(path.c_str()));
}

/// The numbers in the first element called `name` below root; a test failure if there is none.
inline std::vector<double> numbers_of(vtkXMLDataElement* root, const std::string& name) {
  vtkXMLDataElement* element = root->FindNestedElementWithName(name.c_str());
  if (!element) {
    ADD_FAILURE() << "no element <" << name << ">";
    return {};
  }
  std::vector<double> out;
  const char* at = element->GetCharacterData();
  while (at && *at) {
    char* end = nullptr;
    const double value = std::strtod(at, &end);
    if (end == at) break;
    out.push_back(value);
    at = end;
  }
  return out;
}

/// The single number of that element (a test failure unless there is exactly one).
inline double number_of(vtkXMLDataElement* root, const std::string& name) {
  const auto values = numbers_of(root, name);
  EXPECT_EQ(values.size(), 1u) << name;
  return values.empty() ? std::nan("") : values.front();
}

}  // namespace hydrocoef::test
