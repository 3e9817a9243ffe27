// The bonds' records in a 3D checkpoint (io/dem_checkpoint.cpp calls these between the contact
// lists and the energy ledger): written only for a scene with `[bonds]`, so the checkpoint of a
// scene without keeps its records as they were; the scene (its hash) tells the reader which.
//
//   bdCr  u8     the bonds were formed
//   bdLs  Bond[] the intact bonds, in their order (ids, cached indices, the law's state)
//   bdCt  u64[4] formed, broken, dropped, overstretched
//   bdMS  f64    the largest strain of an intact bond at the last pass
#pragma once

#include "dem/bonds/bond_set.h"
#include "io/checkpoint_file.h"

namespace veridem::io
{

void writeBondRecords(CheckpointWriter& out, const dem::BondSet& set);
void readBondRecords(CheckpointReader& in, dem::BondSet& set);

} // namespace veridem::io
