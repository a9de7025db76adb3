// DAVE-ML export (AIAA S-119, Dynamic Aerospace Vehicle Exchange Markup
// Language, version 2.0 structure) of a gridded surface: one DAVEfunc file
//
//   <DAVEfunc>
//     <fileHeader>        author, fileCreationDate, fileVersion, description,
//                         provenance (the runs, the content hash, the build date)
//     <variableDef>       per axis (input) and per output, with its units
//     <breakpointDef>     per axis: <bpVals>
//     <griddedTableDef>   per output: <breakpointRefs>, the node standard
//                         deviations (when the surface states them) as <uncertainty
//                         effect="additive"><normalPDF numSigmas="1"><bounds><dataTable>
//                         (one sigma per node: a table, since it varies over the
//                         range), and the values as <dataTable>
//     <function>          per output: <independentVarRef> per axis (min, max,
//                         extrapolate), <dependentVarRef>, <functionDefn>
//                         <griddedTableRef>
//   </DAVEfunc>
//
// Data tables list the nodes with the LAST breakpoint set varying fastest
// (DAVE-ML's order; hydrocoef's own layout has axis 0 fastest). Names are
// data: every name is written as XML text (escape::xml_text) in "name"
// attributes and descriptions only; the IDs that refer across the file
// (varID, bpID, gtID) are made by hydrocoef ("u0", "y1", "bp0", "gt1"), so a
// hostile name cannot break a reference.
//
// DAVE-ML interpolates tables linearly (the default interpolation) and, per
// independent variable, either holds the end values (extrapolate="neither")
// or continues the end cells' lines ("both"). So only linear surfaces are
// exported; an axis "clamp" or "error" is "neither" (an error axis cannot
// refuse a query in DAVE-ML: its valid range is in min/max and the
// description), "linear" or "method" is "both". Other methods are refused.
//
// Validation: the files are well-formed XML (checked by the tests); they
// follow the DAVE-ML 2.0 element structure as the project knows it but are
// NOT validated against the official DTD, for no redistributable copy of the
// DTD is available to the project (README).
#pragma once

#include <string>

#include "src/export/export.hpp"

namespace hydrocoef {

std::string daveml_text(const GridTable& table, const ExportMetadata& metadata);

}  // namespace hydrocoef
