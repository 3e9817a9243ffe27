// The time-step check a run makes as it starts (its line: time_step_note.h; the rolling
// friction note: rolling_note.h).
#include "api/start_notes.h"

#include "api/time_step_note.h"
#include "core/error.h"
#include "dem/time_step.h"
#include "io/particle_flow_keys.h"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

namespace veridem::api
{

void checkTimeStep(const io::DemScene& scene, const std::string& sceneName, bool allowUnstable, bool speak)
{
    const dem::TimeStepEstimate estimate =
        scene.flow.inserters.empty()
            ? dem::estimateTimeStep(scene.world, scene.characteristicSpeed)
            : dem::estimateTimeStep(io::timeStepProbe(scene.world, scene.flow), scene.characteristicSpeed);
    if (speak) // (api/time_step_note.h)
        std::fprintf(
            stderr, "%s\n",
            timeStepNote(scene.dt, estimate, scene.world.particles.size(), scene.world.walls.size()).c_str());
    if (scene.dt > estimate.critical)
    {
        std::ostringstream s;
        s << sceneName << ": [simulation] dt = " << scene.dt << " s exceeds the stability limit "
          << estimate.critical << " s (" << estimate.limitedBy << "); use dt <= " << estimate.recommended
          << " s (tc/50)";
        if (!allowUnstable)
            throw InputError(s.str() + ", or --force-dt to run anyway");
        if (speak)
            std::fprintf(stderr, "veridem: warning: %s; running anyway (--force-dt)\n", s.str().c_str());
    }
    else if (speak && scene.dt > estimate.contactTime / 20)
        std::fprintf(
            stderr,
            "veridem: warning: dt is more than tc/20: contacts are resolved by fewer than 20 steps\n");
}

} // namespace veridem::api
