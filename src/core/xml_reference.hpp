// XML 1.0 references in attribute values and text (&lt; &#233; &#xE9;): one
// decoder for the project's XML readers (the VTK XML reader in
// importers/vtk_xml_polydata.cpp, the FMI host's modelDescription.xml reader in
// tests/fmu/fmi_host.cpp).
#pragma once

#include <string>
#include <string_view>

namespace hydrocoef {

/// Appends what the reference `&name;` stands for to `out`: one of the five
/// predefined entities (lt, gt, amp, quot, apos) or a character reference
/// (#N decimal, #xH hexadecimal) to a character XML 1.0 can hold (tab, line
/// feed, carriage return, U+0020 and above, no surrogate, at most U+10FFFF).
/// Returns nullptr when it did, else what is wrong ("an unknown entity", "a
/// malformed character reference", "a character reference to a character XML
/// 1.0 cannot hold"), appending nothing.
const char* append_xml_reference(std::string_view name, std::string& out);

}  // namespace hydrocoef
