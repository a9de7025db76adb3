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

/// The numbers of an element's text, separated by white space or commas
/// (DAVE-ML separates them with commas); none for a missing element.
inline std::vector<double> numbers_in(vtkXMLDataElement* element) {
  std::vector<double> out;
  if (!element || !element->GetCharacterData()) return out;
  std::string text = element->GetCharacterData();
  for (char& c : text)
    if (c == ',') c = ' ';
  const char* at = text.c_str();
  while (*at) {
    char* end = nullptr;
    const double value = std::strtod(at, &end);
    if (end == at) break;
    out.push_back(value);
    at = end;
  }
  return out;
}

/// The numbers in the first element called `name` below root; a test failure if there is none.
inline std::vector<double> numbers_of(vtkXMLDataElement* root, const std::string& name) {
  vtkXMLDataElement* element = root->FindNestedElementWithName(name.c_str());
  if (!element) ADD_FAILURE() << "no element <" << name << ">";
  return numbers_in(element);
}

/// The single number of that element (a test failure unless there is exactly one).
inline double number_of(vtkXMLDataElement* root, const std::string& name) {
  const auto values = numbers_of(root, name);
  EXPECT_EQ(values.size(), 1u) << name;
  return values.empty() ? std::nan("") : values.front();
}

}  // namespace hydrocoef::test
