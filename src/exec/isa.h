// Instruction-set dispatch: which variant of the vector kernels runs. "avx2" (four double lanes,
// x86-64-v3) or "portable" (two lanes, SSE2): the widest this CPU runs, unless the environment
// variable VERIDEM_KERNEL names another. Every variant gives the same bits (no fused multiply-add:
// -ffp-contract=off), so the choice changes speed only. Each kernel module maps an Isa to its own
// compiled function (e.g. dem::batch::selectPassFor). No physics here.
#pragma once

#include <string>

namespace veridem::exec
{

enum class Isa
{
    Avx2,
    Portable,
};

/// The variant in use (the first call reads VERIDEM_KERNEL; an unknown or unsupported name is an
/// InputError).
Isa isa();
/// isa() is Isa::Avx2 (cheap enough to ask every step).
inline bool isAvx2()
{
    return isa() == Isa::Avx2;
}
/// "avx2" or "portable".
const char* isaName(Isa variant);
inline const char* isaName()
{
    return isaName(isa());
}
/// True if this CPU runs `variant`.
bool isaSupported(Isa variant);
/// Selects a variant by name (tests, benchmarks); false if unknown or this CPU cannot run it.
bool selectIsa(const std::string& name);

} // namespace veridem::exec
