#include "fdem/output.h"

#include "core/error.h"

#include <cstdio>
#include <iomanip>

namespace veridem::fdem
{

void writeVtu(const World& world, const std::filesystem::path& file)
{
    std::ofstream out(file);
    if (!out)
        throw InputError(file.string() + ": cannot write the output file");
    const NodeStore& nodes = world.nodes();
    const TriangleStore& tris = world.triangles();
    out << std::setprecision(10);
    out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" "
           "byte_order=\"LittleEndian\">\n"
        << "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" << nodes.size() << "\" NumberOfCells=\""
        << tris.size()
        << "\">\n<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (std::size_t n = 0; n < nodes.size(); ++n)
        out << nodes.position[n].x << " " << nodes.position[n].y << " 0\n";
    out << "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" "
           "format=\"ascii\">\n";
    for (const auto& t : tris.nodes)
        out << t[0] << " " << t[1] << " " << t[2] << "\n";
    out << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
    for (std::size_t t = 0; t < tris.size(); ++t)
        out << 3 * (t + 1) << "\n";
    out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
    for (std::size_t t = 0; t < tris.size(); ++t)
        out << "5\n";
    out << "</DataArray>\n</Cells>\n<PointData Vectors=\"velocity\">\n";
    out << "<DataArray type=\"Float64\" Name=\"displacement\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (std::size_t n = 0; n < nodes.size(); ++n)
    {
        const Vec2 u = nodes.position[n] - nodes.referencePosition[n];
        out << u.x << " " << u.y << " 0\n";
    }
    out << "</DataArray>\n<DataArray type=\"Float64\" Name=\"velocity\" NumberOfComponents=\"3\" "
           "format=\"ascii\">\n";
    for (std::size_t n = 0; n < nodes.size(); ++n)
        out << nodes.velocity[n].x << " " << nodes.velocity[n].y << " 0\n";
    out << "</DataArray>\n</PointData>\n<CellData Tensors=\"stress\">\n";
    out << "<DataArray type=\"Float64\" Name=\"stress\" NumberOfComponents=\"9\" format=\"ascii\">\n";
    for (const auto& s : tris.stress)
        out << s.xx << " " << s.xy << " 0 " << s.xy << " " << s.yy << " 0 0 0 0\n";
    out << "</DataArray>\n<DataArray type=\"Int32\" Name=\"body\" format=\"ascii\">\n";
    for (auto b : tris.body)
        out << b << "\n";
    out << "</DataArray>\n</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
}

OutputWriter::OutputWriter(const std::filesystem::path& directory) : directory_(directory)
{
    std::error_code ec;
    std::filesystem::create_directories(directory, ec);
    bodies_.open(directory / "bodies.csv");
    energy_.open(directory / "energy.csv");
    if (ec || !bodies_ || !energy_)
        throw InputError(directory.string() + ": cannot create the output directory or its files");
    bodies_ << "time,body,name,x,y,vx,vy\n" << std::setprecision(12);
    energy_ << "time,kinetic,strain,gravity,friction_work,normal_damping_work\n" << std::setprecision(12);
}

OutputWriter::~OutputWriter()
{
    try
    {
        finish();
    }
    catch (...)
    {
    }
}

void OutputWriter::write(const World& world, Real time)
{
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05zu.vtu", frames_.size());
    writeVtu(world, directory_ / name);
    frames_.emplace_back(time, name);
    for (std::uint32_t b = 0; b < world.bodyCount(); ++b)
    {
        const BodyState s = world.bodyState(b);
        bodies_ << time << "," << b << "," << world.bodyName(b) << "," << s.centroid.x << "," << s.centroid.y
                << "," << s.velocity.x << "," << s.velocity.y << "\n";
    }
    const Energies e = world.energies();
    energy_ << time << "," << e.kinetic << "," << e.strain << "," << e.gravity << "," << e.frictionWork << ","
            << e.normalDampingWork << "\n";
}

void OutputWriter::finish()
{
    if (finished_)
        return;
    finished_ = true;
    bodies_.flush();
    energy_.flush();
    std::ofstream pvd(directory_ / "series.pvd");
    pvd << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
    for (const auto& [t, f] : frames_)
        pvd << "<DataSet timestep=\"" << std::setprecision(12) << t << "\" file=\"" << f << "\"/>\n";
    pvd << "</Collection>\n</VTKFile>\n";
}

} // namespace veridem::fdem
