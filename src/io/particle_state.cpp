#include "io/particle_state.h"

#include "dem/periodic.h"
#include "io/output_file.h"
#include "io/output_options.h"

namespace veridem::io
{

void writeParticleState(const std::filesystem::path& path, const dem::World& world, Real dt)
{
    const dem::ParticleStore& p = world.particles;
    AtomicFile file(path);
    std::string text = "# veridem state at t = ";
    appendNumber(text, outputTime(world.stepCount, dt));
    text += " s (step " + std::to_string(world.stepCount) + ")\n";
    text += kParticleStateHeader;
    text += '\n';
    constexpr std::size_t kChunk = 1 << 20; // bytes buffered before a write
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        if (p.retired(i))
            continue;
        text += std::to_string(p.id[i]);
        text += ',';
        text += world.materials[p.material[i]].name;
        text += ',';
        appendNumber(text, p.radius[i]);
        const Vec3 x = dem::wrapPosition(world.domain, p.position[i]);
        const Vec3 &v = p.velocity[i], &w = p.angularVelocity[i];
        for (const Real value : {x.x, x.y, x.z, v.x, v.y, v.z, w.x, w.y, w.z})
        {
            text += ',';
            appendNumber(text, value);
        }
        text += p.fixed[i] ? ",1\n" : ",0\n";
        if (text.size() >= kChunk)
        {
            file.stream().write(text.data(), static_cast<std::streamsize>(text.size()));
            text.clear();
        }
    }
    file.stream().write(text.data(), static_cast<std::streamsize>(text.size()));
    file.commit();
}

} // namespace veridem::io
