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

/// The CSV columns of a field.
const char* csvColumns(ParticleField field)
{
    switch (field)
    {
    case ParticleField::Velocity:
        return "vx,vy,vz";
    case ParticleField::AngularVelocity:
        return "wx,wy,wz";
    case ParticleField::Radius:
        return "radius";
    case ParticleField::Mass:
        return "mass";
    case ParticleField::Material:
        return "material";
    case ParticleField::Force:
        return "fx,fy,fz";
    case ParticleField::Torque:
        return "tx,ty,tz";
    case ParticleField::Coordination:
        return "coordination";
    }
    return "";
}

void appendVector(std::string& out, const Vec3& v)
{
    for (const Real value : {v.x, v.y, v.z})
    {
        out += ',';
        appendNumber(out, value);
    }
}
} // namespace

std::vector<std::uint32_t> coordinationNumbers(const dem::World& world,
                                               const std::vector<dem::ContactRecord>& contacts)
{
    std::vector<std::uint32_t> count(world.particles.size(), 0);
    for (const dem::ContactRecord& c : contacts)
        if (!c.wall)
        {
            ++count[c.i];
            ++count[c.partner];
        }
    return count;
}

ParticleRecorder::ParticleRecorder(const std::filesystem::path& directory, const OutputOptions& options,
                                   const Resume* resume)
    : directory_(directory), options_(options)
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
        if (!options_.particlesCsv || csv_.resume(directory_ / "particles.csv", resume->csvBytes))
            return;
    }
    if (!options_.particlesCsv)
        return;
    csv_.open(directory_ / "particles.csv");
    std::string header = "t,id,x,y,z";
    for (const ParticleField field : options_.particleFields)
        header += std::string(",") + csvColumns(field);
    csv_.stream() << header << '\n';
    csv_.flush();
}

void ParticleRecorder::record(const dem::World& world, const std::vector<dem::ContactRecord>* contacts)
{
    std::vector<std::uint32_t> coordination;
    if (options_.has(ParticleField::Coordination))
        coordination = contacts ? coordinationNumbers(world, *contacts)
                                : coordinationNumbers(world, dem::evaluateContacts(world, 0.0));
    if (options_.particlesCsv)
        writeCsv(world, coordination);
    if (options_.vtk)
        writeVtp(world, coordination, directory_ / vtpName(frameTimes_.size()));
    frameTimes_.push_back(outputTime(world.stepCount, options_.dt));
    listed_.push_back(true);
    if (options_.vtk)
        writePvd();
}

void ParticleRecorder::writeCsv(const dem::World& world, const std::vector<std::uint32_t>& coordination)
{
    const auto& p = world.particles;
    std::string rows;
    std::string time;
    appendNumber(time, outputTime(world.stepCount, options_.dt));
    constexpr std::size_t kChunk = 1 << 20; // bytes buffered before a write
    rows.reserve(kChunk + 512);
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        if (p.retired(i)) // (taken by an outlet, still in the store until the next list rebuild)
            continue;
        rows += time;
        rows += ',';
        rows += std::to_string(p.id[i]);
        // (Wrapped into a periodic box: between list rebuilds a particle may stand up to skin/2
        // outside it, dem/periodic.h.)
        appendVector(rows, dem::wrapPosition(world.domain, p.position[i]));
        for (const ParticleField field : options_.particleFields)
            switch (field)
            {
            case ParticleField::Velocity:
                appendVector(rows, p.velocity[i]);
                break;
            case ParticleField::AngularVelocity:
                appendVector(rows, p.angularVelocity[i]);
                break;
            case ParticleField::Radius:
                rows += ',';
                appendNumber(rows, p.radius[i]);
                break;
            case ParticleField::Mass:
                rows += ',';
                appendNumber(rows, p.mass[i]);
                break;
            case ParticleField::Material:
                rows += ',';
                rows += world.materials[p.material[i]].name;
                break;
            case ParticleField::Force:
                appendVector(rows, p.force[i]);
                break;
            case ParticleField::Torque:
                appendVector(rows, p.torque[i]);
                break;
            case ParticleField::Coordination:
                rows += ',';
                rows += std::to_string(coordination[i]);
                break;
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
}

void ParticleRecorder::close()
{
    csv_.close();
}

void ParticleRecorder::writeVtp(const dem::World& world, const std::vector<std::uint32_t>& coordination,
                                const std::filesystem::path& path) const
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
    VtkXmlArrays arrays(options_.vtkFormat);
    out << arrays.vtkFileOpening("PolyData") << "<PolyData>\n<Piece NumberOfPoints=\"" << n
        << "\" NumberOfVerts=\"0\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n";
    std::vector<double> flat(3 * n);
    auto vectors = [&](const auto& values, bool wrap = false)
    {
        for (std::size_t k = 0; k < n; ++k)
        {
            // (positions wrapped into a periodic box, dem/periodic.h)
            const Vec3 v = wrap ? dem::wrapPosition(world.domain, values[live[k]]) : Vec3(values[live[k]]);
            flat[3 * k] = v.x;
            flat[3 * k + 1] = v.y;
            flat[3 * k + 2] = v.z;
        }
        return flat.data();
    };
    std::vector<double> scalars(n);
    auto scalar = [&](const std::vector<Real>& values)
    {
        for (std::size_t k = 0; k < n; ++k)
            scalars[k] = values[live[k]];
        return scalars.data();
    };
    out << "<Points>\n";
    arrays.float64(out, "", 3, vectors(p.position, world.domain.any()), 3 * n);
    out << "</Points>\n<PointData Scalars=\"radius\""
        << (options_.has(ParticleField::Velocity) ? " Vectors=\"velocity\"" : "") << ">\n";
    std::vector<std::int64_t> ids(n);
    for (std::size_t k = 0; k < n; ++k)
        ids[k] = static_cast<std::int64_t>(p.id[live[k]]);
    arrays.int64(out, "id", 1, ids.data(), n);
    arrays.float64(out, "radius", 1, scalar(p.radius), n); // (always: ParaView's glyph scale)
    std::vector<std::int32_t> integers(n);
    for (const ParticleField field : options_.particleFields)
        switch (field)
        {
        case ParticleField::Velocity:
            arrays.float64(out, "velocity", 3, vectors(p.velocity), 3 * n);
            break;
        case ParticleField::AngularVelocity:
            arrays.float64(out, "angular_velocity", 3, vectors(p.angularVelocity), 3 * n);
            break;
        case ParticleField::Radius: // (written above)
            break;
        case ParticleField::Mass:
            arrays.float64(out, "mass", 1, scalar(p.mass), n);
            break;
        case ParticleField::Material:
            for (std::size_t k = 0; k < n; ++k)
                integers[k] = static_cast<std::int32_t>(p.material[live[k]]);
            arrays.int32(out, "material", 1, integers.data(), n);
            break;
        case ParticleField::Force:
            arrays.float64(out, "force", 3, vectors(p.force), 3 * n);
            break;
        case ParticleField::Torque:
            arrays.float64(out, "torque", 3, vectors(p.torque), 3 * n);
            break;
        case ParticleField::Coordination:
            for (std::size_t k = 0; k < n; ++k)
                integers[k] = static_cast<std::int32_t>(coordination[live[k]]);
            arrays.int32(out, "coordination", 1, integers.data(), n);
            break;
        }
    out << "</PointData>\n</Piece>\n</PolyData>\n";
    arrays.finish(out);
    file.commit();
}

void ParticleRecorder::writePvd() const
{
    writePvdCollection(directory_ / "particles.pvd", frameTimes_, listed_, vtpName);
}

} // namespace veridem::io
