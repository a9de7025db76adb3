// JSBSim-style XML tables: one <function> per output holding a <table> with
// <independentVar lookup="row|column|table"> and <tableData> (3-D tables as
// one <tableData breakPoint="..."> per breakpoint of the third axis), as
// JSBSim's FGTable reads them. Paste the <function> elements where the
// vehicle file needs them (an <external_reactions> force, a <system>).
//
// JSBSim interpolates tables linearly and holds the end values outside the
// breakpoints, so only linear surfaces whose axes are "clamp" (or "error":
// in range both agree; JSBSim cannot refuse a query, so the valid range is
// written in each description) are exported, with 1 to 3 axes. Anything
// else is refused, naming what JSBSim lacks. Independent variables are the
// properties "hydrocoef/<axis name>" in the axis's SI unit: bind them to the
// vehicle's state with a function that converts JSBSim's units (ft/s).
#pragma once

#include <string>

#include "src/export/export.hpp"

namespace hydrocoef {

std::string jsbsim_text(const GridTable& table, const ExportMetadata& metadata);

}  // namespace hydrocoef
