// dt sweeps (issue 21): a case with a DtSweep runs at dt, dt/2 and dt/4 (CaseContext::dtScale;
// support.cpp's runFor and the Chung & Ooi impacts apply it), and each of its quantities gets an
// observed order of its dt error, from successive differences
//     p = log2(|q(dt) - q(dt/2)| / |q(dt/2) - q(dt/4)|),
// which is the order of the discretisation error whatever dt-independent model offset (elastic
// lever arm, Hertz-Mindlin compliance against a rigid-body formula) the quantity also carries.
// Where a difference is at rounding level (below 1e-11 of the quantity's size) no order is
// observable and the case says so in a note instead. Quantities matching a SweepOrder are
// checked against it (a quantity "dt order: ..." with the margin); the others are printed as
// notes. The levels are also returned as the series "dt_sweep" for the report's log-log plot.
#pragma once

#include "case.h"

namespace veridem::verify
{

/// Runs `c` at the context's dt and, if it declares a sweep, at dt/2 and dt/4; the result is
/// that of dt with the sweep's quantities, notes and series appended.
CaseResult runWithSweep(const Case& c, const CaseContext& context);

} // namespace veridem::verify
