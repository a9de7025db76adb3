// The brief of a force history a run keeps (HistoryTrace, src/core/run.hpp):
// what the report and `plot history` draw from the database alone, long after
// the CFD files are gone, with the run's window and value over it.
//
// Bins hold consecutive samples, as equal in count as the record allows (the
// first n mod kMaxBins bins one more); a bin gives its least and largest value
// per component, so a spike or an oscillation in it stays visible at any
// length of record, and the abscissa of its last sample, so the last bin ends
// at the record's last sample (the converged iterate of a converged run).
#pragma once

#include "src/core/run.hpp"
#include "src/history/force_history.hpp"

namespace hydrocoef {

/// The trace of a history's total components, in the history's own
/// components (X..N when it is in body axes, as run_from_history's input
/// is). An empty trace (samples 0) for an empty history.
HistoryTrace trace_of(const ForceHistory& history);

/// "" when a trace read from a database is whole (sizes, order, finite
/// values, low <= high, min(samples, kMaxBins) bins), else
/// what is wrong, in words.
std::string trace_problem(const HistoryTrace& trace);

}  // namespace hydrocoef
