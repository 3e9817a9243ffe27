#include "io/particle_output.h"

#include "core/error.h"

#include <cstdio>
#include <iomanip>

namespace veridem::io
{

ParticleRecorder::ParticleRecorder(const std::filesystem::path& directory, bool writeVtk)
    : directory_(directory), writeVtk_(writeVtk)
{
    std::error_code error;
    std::filesystem::create_directories(directory_, error);
    if (error)
        throw InputError("cannot create output directory '" + directory_.string() + "': " + error.message());
    csv_.open(directory_ / "particles.csv");
    if (!csv_)
        throw InputError("cannot write '" + (directory_ / "particles.csv").string() + "'");
    csv_ << "t,id,x,y,z,vx,vy,vz,wx,wy,wz\n" << std::setprecision(10);
}

void ParticleRecorder::record(const dem::World& world)
{
    const auto& p = world.particles;
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        const Vec3 &x = p.position[i], &v = p.velocity[i], &w = p.angularVelocity[i];
        csv_ << world.time << ',' << i << ',' << x.x << ',' << x.y << ',' << x.z << ',' << v.x << ',' << v.y
             << ',' << v.z << ',' << w.x << ',' << w.y << ',' << w.z << '\n';
    }
    csv_.flush();
    if (writeVtk_)
    {
        char name[64];
        std::snprintf(name, sizeof name, "particles_%06zu.vtp", frameTimes_.size());
        writeVtp(world, directory_ / name);
    }
    frameTimes_.push_back(world.time);
    if (writeVtk_ && frameTimes_.size() % 50 == 1)
        writePvd();
}

ParticleRecorder::~ParticleRecorder()
{
    if (writeVtk_)
        writePvd();
}

void ParticleRecorder::writeVtp(const dem::World& world, const std::filesystem::path& path) const
{
    const auto& p = world.particles;
    std::ofstream out(path);
    out << std::setprecision(10);
    out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" "
           "byte_order=\"LittleEndian\">\n"
        << "<PolyData>\n<Piece NumberOfPoints=\"" << p.size()
        << "\" NumberOfVerts=\"0\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n";
    out << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (const Vec3& x : p.position)
        out << x.x << ' ' << x.y << ' ' << x.z << '\n';
    out << "</DataArray>\n</Points>\n<PointData Scalars=\"radius\" Vectors=\"velocity\">\n";
    out << "<DataArray type=\"Int64\" Name=\"id\" format=\"ascii\">\n";
    for (std::size_t i = 0; i < p.size(); ++i)
        out << i << '\n';
    out << "</DataArray>\n<DataArray type=\"Float64\" Name=\"radius\" format=\"ascii\">\n";
    for (Real r : p.radius)
        out << r << '\n';
    out << "</DataArray>\n";
    auto vectors = [&](const char* name, const std::vector<Vec3>& values)
    {
        out << "<DataArray type=\"Float64\" Name=\"" << name
            << "\" NumberOfComponents=\"3\" format=\"ascii\">\n";
        for (const Vec3& v : values)
            out << v.x << ' ' << v.y << ' ' << v.z << '\n';
        out << "</DataArray>\n";
    };
    vectors("velocity", p.velocity);
    vectors("angular_velocity", p.angularVelocity);
    out << "</PointData>\n</Piece>\n</PolyData>\n</VTKFile>\n";
}

void ParticleRecorder::writePvd() const
{
    std::ofstream out(directory_ / "particles.pvd");
    out << std::setprecision(12);
    out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
    for (std::size_t k = 0; k < frameTimes_.size(); ++k)
    {
        char name[64];
        std::snprintf(name, sizeof name, "particles_%06zu.vtp", k);
        out << "<DataSet timestep=\"" << frameTimes_[k] << "\" file=\"" << name << "\"/>\n";
    }
    out << "</Collection>\n</VTKFile>\n";
}

} // namespace veridem::io
