#include "exec/isa.h"

#include "core/error.h"

#include <cstdlib>
#include <cstring>

namespace veridem::exec
{

namespace
{

constexpr Isa kVariants[] = {Isa::Avx2, Isa::Portable}; // widest first

Isa& current()
{
    static Isa variant = []
    {
        const char* wanted = std::getenv("VERIDEM_KERNEL");
        for (const Isa v : kVariants)
            if (isaSupported(v) && (!wanted || !*wanted || std::strcmp(wanted, isaName(v)) == 0))
                return v;
        throw InputError(std::string("VERIDEM_KERNEL=") + wanted +
                         ": not a contact kernel this CPU can run (avx2, portable)");
    }();
    return variant;
}

} // namespace

Isa isa()
{
    return current();
}

const char* isaName(Isa variant)
{
    return variant == Isa::Avx2 ? "avx2" : "portable";
}

bool isaSupported(Isa variant)
{
    if (variant == Isa::Portable)
        return true;
#if defined(__x86_64__) && defined(__GNUC__)
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") && __builtin_cpu_supports("bmi2");
#else
    return false;
#endif
}

bool selectIsa(const std::string& name)
{
    for (const Isa v : kVariants)
        if (name == isaName(v) && isaSupported(v))
        {
            current() = v;
            return true;
        }
    return false;
}

} // namespace veridem::exec
