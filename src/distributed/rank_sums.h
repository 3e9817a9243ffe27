// Sums of real numbers over the MPI ranks, in rank order: the outlets' masses and the energy
// ledger's amounts, each a sum over the particles or contacts of every rank. One order of the
// additions, so a run on a given rank count gives the same bits every time (a reduction by the
// MPI library may group them otherwise; distributed/collective.h offers only order-free reductions).
#pragma once

#include "core/vec3.h"
#include "dem/energy_ledger.h"
#include "distributed/collective.h"

#include <span>
#include <vector>

namespace veridem::distributed
{

/// values[k] summed over the ranks (rank 0's first), on rank 0, or on every rank with
/// `everyRank`; elsewhere this rank's own values. Collective.
std::vector<Real> sumInRankOrder(std::span<const Real> values, const Collective& comm,
                                 bool everyRank = false);

/// The whole run's ledger: every amount summed over the ranks (sumInRankOrder), on rank 0; elsewhere
/// this rank's own. Collective.
dem::EnergyLedgerState ledgerTotals(const dem::EnergyLedgerState& mine, const Collective& comm);

} // namespace veridem::distributed
