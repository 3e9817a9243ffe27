#include "io/particle_output.h"

#include "core/error.h"
#include "io/vtk_xml.h"

#include <cstdio>

namespace veridem::io
{

namespace
{
std::string vtpName(std::size_t frame)
{
    char name[64];
    std::snprintf(name, sizeof name, "particles_%06zu.vtp", frame);
    return name;
}
} // namespace

ParticleRecorder::ParticleRecorder(const std::filesystem::path& directory, bool vtk, VtkFormat format,
                                   const Resume* resume)
    : directory_(directory), vtk_(vtk), format_(format)
{
    std::error_code error;
    std::filesystem::create_directories(directory_, error);
    if (error)
        throw OutputError("cannot create output directory '" + directory_.string() + "': " + error.message());
    if (resume)
    {
        frameTimes_ = resume->frameTimes;
        for (std::size_t k = 0; k < frameTimes_.size(); ++k)
            listed_.push_back(std::filesystem::is_regular_file(directory_ / vtpName(k), error));
        if (csv_.resume(directory_ / "particles.csv", resume->csvBytes))
            return;
    }
    csv_.open(directory_ / "particles.csv");
    csv_.stream() << "t,id,x,y,z,vx,vy,vz,wx,wy,wz\n";
    csv_.flush();
}

void ParticleRecorder::record(const dem::World& world)
{
    const auto& p = world.particles;
    std::string rows;
    std::string time;
    appendNumber(time, world.time);
    constexpr std::size_t kChunk = 1 << 20; // bytes buffered before a write
    rows.reserve(kChunk + 512);
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        if (p.retired(i)) // (taken by an outlet, still in the store until the next list rebuild)
            continue;
        // (Wrapped into a periodic box: between list rebuilds a particle may stand up to skin/2
        // outside it, dem/periodic.h.)
        const Vec3 x = dem::wrapPosition(world.domain, p.position[i]);
        const Vec3 &v = p.velocity[i], &w = p.angularVelocity[i];
        rows += time;
        rows += ',';
        rows += std::to_string(p.id[i]);
        for (const Real value : {x.x, x.y, x.z, v.x, v.y, v.z, w.x, w.y, w.z})
        {
            rows += ',';
            appendNumber(rows, value);
        }
        rows += '\n';
        if (rows.size() >= kChunk)
        {
            csv_.stream().write(rows.data(), static_cast<std::streamsize>(rows.size()));
            rows.clear();
        }
    }
    csv_.stream().write(rows.data(), static_cast<std::streamsize>(rows.size()));
    csv_.flush();
    if (vtk_)
        writeVtp(world, directory_ / vtpName(frameTimes_.size()));
    frameTimes_.push_back(world.time);
    listed_.push_back(true);
    if (vtk_)
        writePvd();
}

void ParticleRecorder::close()
{
    csv_.close();
}

void ParticleRecorder::writeVtp(const dem::World& world, const std::filesystem::path& path) const
{
    const auto& p = world.particles;
    std::vector<std::size_t> live; // the particles listed: all but the retired ones
    live.reserve(p.size());
    for (std::size_t i = 0; i < p.size(); ++i)
        if (!p.retired(i))
            live.push_back(i);
    const std::size_t n = live.size();
    AtomicFile file(path);
    std::ostream& out = file.stream();
    VtkXmlArrays arrays(format_);
    out << arrays.vtkFileOpening("PolyData") << "<PolyData>\n<Piece NumberOfPoints=\"" << n
        << "\" NumberOfVerts=\"0\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n";
    std::vector<double> flat(3 * n);
    auto vectors = [&](const std::vector<Vec3>& values, bool wrap = false)
    {
        for (std::size_t k = 0; k < n; ++k)
        {
            // (positions wrapped into a periodic box, dem/periodic.h)
            const Vec3 v = wrap ? dem::wrapPosition(world.domain, values[live[k]]) : values[live[k]];
            flat[3 * k] = v.x;
            flat[3 * k + 1] = v.y;
            flat[3 * k + 2] = v.z;
        }
        return flat.data();
    };
    out << "<Points>\n";
    arrays.float64(out, "", 3, vectors(p.position, world.domain.any()), 3 * n);
    out << "</Points>\n<PointData Scalars=\"radius\" Vectors=\"velocity\">\n";
    std::vector<std::int64_t> ids(n);
    std::vector<double> radii(n);
    for (std::size_t k = 0; k < n; ++k)
    {
        ids[k] = static_cast<std::int64_t>(p.id[live[k]]);
        radii[k] = p.radius[live[k]];
    }
    arrays.int64(out, "id", 1, ids.data(), n);
    arrays.float64(out, "radius", 1, radii.data(), n);
    arrays.float64(out, "velocity", 3, vectors(p.velocity), 3 * n);
    arrays.float64(out, "angular_velocity", 3, vectors(p.angularVelocity), 3 * n);
    out << "</PointData>\n</Piece>\n</PolyData>\n";
    arrays.finish(out);
    file.commit();
}

void ParticleRecorder::writePvd() const
{
    writePvdCollection(directory_ / "particles.pvd", frameTimes_, listed_, vtpName);
}

} // namespace veridem::io
