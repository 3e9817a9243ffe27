#include "api/time_step_note.h"

#include <cmath>
#include <cstdio>

namespace veridem::api
{

std::string timeStepNote(Real dt, const dem::TimeStepEstimate& estimate, std::size_t particles,
                         std::size_t walls)
{
    char line[512];
    if (std::isfinite(estimate.critical) && std::isfinite(estimate.contactTime) &&
        !estimate.limitedBy.empty())
        std::snprintf(line, sizeof line,
                      "veridem: dt = %.4g s; stability limit %.4g s (%s); shortest contact time %.4g s, "
                      "recommended dt <= tc/50 = %.4g s",
                      dt, estimate.critical, estimate.limitedBy.c_str(), estimate.contactTime,
                      estimate.recommended);
    else
        std::snprintf(line, sizeof line,
                      "veridem: dt = %.4g s; no contact limits the step: %zu particle(s) and %zu wall(s) at "
                      "the start, so no contact can occur (dt is checked only against the particles' speed)",
                      dt, particles, walls);
    return line;
}

} // namespace veridem::api
