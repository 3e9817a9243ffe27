// Linked into every benchmark of a build configured with VERIDEM_LTO_BENCH=OFF (scripts/test, for
// CI; bench/CMakeLists.txt): one line on stderr when the program starts, so that no timing of such
// a build is taken for one of docs/performance.md.
#include <cstdio>

namespace
{

struct WithoutLtoNote
{
    WithoutLtoNote()
    {
        std::fputs("note: this benchmark was linked without link-time optimisation (VERIDEM_LTO_BENCH=OFF, "
                   "as scripts/test builds it): its timings are not those of docs/performance.md; "
                   "`cmake --preset release && cmake --build --preset release` restores it\n",
                   stderr);
    }
};

const WithoutLtoNote note;

} // namespace
