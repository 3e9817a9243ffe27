#include "io/contact_output.h"

#include "io/output_file.h"
#include "io/vtk_xml.h"

#include <cstdio>

namespace veridem::io
{

namespace
{
std::string vtpName(std::size_t frame)
{
    char name[64];
    std::snprintf(name, sizeof name, "contacts_%06zu.vtp", frame);
    return name;
}

std::string csvName(std::size_t frame)
{
    char name[64];
    std::snprintf(name, sizeof name, "contacts_%06zu.csv", frame);
    return name;
}
} // namespace

ContactRecorder::ContactRecorder(const std::filesystem::path& directory, const OutputOptions& options,
                                 const std::vector<double>& frameTimes)
    : directory_(directory), options_(options), frameTimes_(frameTimes)
{
    std::error_code error;
    for (std::size_t k = 0; k < frameTimes_.size(); ++k)
        listed_.push_back(std::filesystem::is_regular_file(directory_ / vtpName(k), error));
}

void ContactRecorder::record(const dem::World& world, const std::vector<dem::ContactRecord>& contacts)
{
    if (options_.contactsVtk)
        writeVtp(world, contacts);
    if (options_.contactsCsv)
        writeCsv(world, contacts);
    frameTimes_.push_back(outputTime(world.stepCount, options_.dt));
    listed_.push_back(options_.contactsVtk);
    if (options_.contactsVtk)
        writePvd();
}

void ContactRecorder::writeCsv(const dem::World& world, const std::vector<dem::ContactRecord>& contacts) const
{
    AtomicFile file(directory_ / csvName(frameTimes_.size()));
    std::string time;
    appendNumber(time, outputTime(world.stepCount, options_.dt));
    std::string text = "t,id,partner,wall,overlap,cx,cy,cz,nx,ny,nz,fnx,fny,fnz,ftx,fty,ftz\n";
    for (const dem::ContactRecord& c : contacts)
    {
        text += time;
        text += ',' + std::to_string(world.particles.id[c.i]) + ',';
        if (c.wall)
        {
            const std::string& name = world.walls[c.partner].name;
            text += ',' + (name.empty() ? std::to_string(c.partner) : name);
        }
        else
            text += std::to_string(world.particles.id[c.partner]) + ',';
        text += ',';
        appendNumber(text, c.overlap);
        for (const Vec3& v : {c.point, c.normal, c.normalForce, c.tangentialForce})
            for (const Real value : {v.x, v.y, v.z})
            {
                text += ',';
                appendNumber(text, value);
            }
        text += '\n';
    }
    file.stream() << text;
    file.commit();
}

void ContactRecorder::writeVtp(const dem::World& world, const std::vector<dem::ContactRecord>& contacts) const
{
    const std::size_t n = contacts.size();
    AtomicFile file(directory_ / vtpName(frameTimes_.size()));
    std::ostream& out = file.stream();
    VtkXmlArrays arrays(options_.vtkFormat);
    out << arrays.vtkFileOpening("PolyData") << "<PolyData>\n<Piece NumberOfPoints=\"" << 2 * n
        << "\" NumberOfVerts=\"0\" NumberOfLines=\"" << n << "\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n";
    std::vector<double> points(6 * n);
    for (std::size_t c = 0; c < n; ++c)
    {
        const dem::ContactRecord& r = contacts[c];
        const Vec3 a = world.particles.position[r.i];
        const Vec3 b = r.wall ? r.point : world.particles.position[r.partner];
        const double row[6] = {a.x, a.y, a.z, b.x, b.y, b.z};
        for (std::size_t k = 0; k < 6; ++k)
            points[6 * c + k] = row[k];
    }
    out << "<Points>\n";
    arrays.float64(out, "", 3, points.data(), 6 * n);
    out << "</Points>\n<Lines>\n";
    std::vector<std::int64_t> connectivity(2 * n), offsets(n), ids(2 * n);
    std::vector<std::uint8_t> wall(n);
    for (std::size_t c = 0; c < n; ++c)
    {
        connectivity[2 * c] = static_cast<std::int64_t>(2 * c);
        connectivity[2 * c + 1] = static_cast<std::int64_t>(2 * c + 1);
        offsets[c] = static_cast<std::int64_t>(2 * c + 2);
        ids[2 * c] = world.particles.id[contacts[c].i]; // (stable ids; a wall by its index)
        ids[2 * c + 1] = contacts[c].wall ? contacts[c].partner : world.particles.id[contacts[c].partner];
        wall[c] = contacts[c].wall ? 1 : 0;
    }
    arrays.int64(out, "connectivity", 1, connectivity.data(), 2 * n);
    arrays.int64(out, "offsets", 1, offsets.data(), n);
    out << "</Lines>\n<CellData Scalars=\"force_magnitude\" Vectors=\"normal_force\">\n";
    arrays.int64(out, "ids", 2, ids.data(), 2 * n);
    arrays.uint8(out, "wall", 1, wall.data(), n);
    std::vector<double> flat(3 * n), magnitude(n);
    const auto vectors = [&](Vec3 dem::ContactRecord::*field)
    {
        for (std::size_t c = 0; c < n; ++c)
        {
            const Vec3 v = contacts[c].*field;
            flat[3 * c] = v.x;
            flat[3 * c + 1] = v.y;
            flat[3 * c + 2] = v.z;
        }
        return flat.data();
    };
    arrays.float64(out, "contact_point", 3, vectors(&dem::ContactRecord::point), 3 * n);
    arrays.float64(out, "normal", 3, vectors(&dem::ContactRecord::normal), 3 * n);
    arrays.float64(out, "normal_force", 3, vectors(&dem::ContactRecord::normalForce), 3 * n);
    arrays.float64(out, "tangential_force", 3, vectors(&dem::ContactRecord::tangentialForce), 3 * n);
    for (std::size_t c = 0; c < n; ++c)
        magnitude[c] = length(contacts[c].normalForce + contacts[c].tangentialForce);
    arrays.float64(out, "force_magnitude", 1, magnitude.data(), n);
    out << "</CellData>\n</Piece>\n</PolyData>\n";
    arrays.finish(out);
    file.commit();
}

void ContactRecorder::writePvd() const
{
    writePvdCollection(directory_ / "contacts.pvd", frameTimes_, listed_, vtpName);
}

} // namespace veridem::io
