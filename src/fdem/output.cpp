#include "fdem/output.h"

#include "core/error.h"
#include "fdem/fragments.h"
#include "fdem/output_thermo.h"

#include <algorithm>
#include <cstdio>

namespace veridem::fdem
{

void writeFragments(const World& world, const std::filesystem::path& file)
{
    std::vector<Fragment> fragments = findFragments(world);
    std::vector<std::size_t> order(fragments.size());
    for (std::size_t i = 0; i < order.size(); ++i)
        order[i] = i;
    // By body, largest first (ties by id): the passing fraction of a row counts it and the rows after it.
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b)
                     {
                         return fragments[a].body != fragments[b].body
                                    ? fragments[a].body < fragments[b].body
                                    : fragments[a].area > fragments[b].area;
                     });
    std::vector<Real> bodyMass(world.bodyCount(), 0);
    for (const Fragment& f : fragments)
        bodyMass[f.body] += f.mass;
    io::AtomicFile atomic(file);
    std::ostream& out = atomic.stream();
    out.precision(17);
    out << "fragment,body,name,triangles,area,mass,x,y,equivalent_diameter,passing\n";
    std::vector<Real> passing(fragments.size());
    for (std::size_t k = order.size(); k-- > 0;)
    {
        const Fragment& f = fragments[order[k]];
        const bool last = k + 1 == order.size() || fragments[order[k + 1]].body != f.body;
        passing[k] = (last ? 0 : passing[k + 1]) + f.mass / bodyMass[f.body];
    }
    for (std::size_t k = 0; k < order.size(); ++k)
    {
        const Fragment& f = fragments[order[k]];
        out << order[k] << ',' << f.body << ',' << world.bodyName(f.body) << ',' << f.triangles << ','
            << f.area << ',' << f.mass << ',' << f.centroid.x << ',' << f.centroid.y << ','
            << f.equivalentDiameter << ',' << passing[k] << '\n';
    }
    atomic.commit();
}

void writeVtu(const World& world, const std::filesystem::path& file, io::VtkFormat format)
{
    const NodeStore& nodes = world.nodes();
    const TriangleStore& tris = world.triangles();
    const JointStore& joints = world.joints();
    const std::size_t n = nodes.size(), t = tris.size(), j = joints.size();
    io::AtomicFile atomic(file);
    std::ostream& out = atomic.stream();
    io::VtkXmlArrays arrays(format);
    out << arrays.vtkFileOpening("UnstructuredGrid") << "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" << n
        << "\" NumberOfCells=\"" << t + j << "\">\n<Points>\n";
    std::vector<double> flat(std::max(3 * n, 9 * (t + j)));
    auto nodeVectors = [&](auto value)
    {
        for (std::size_t i = 0; i < n; ++i)
        {
            const Vec2 v = value(i);
            flat[3 * i] = v.x;
            flat[3 * i + 1] = v.y;
            flat[3 * i + 2] = 0;
        }
        return flat.data();
    };
    arrays.float64(out, "", 3, nodeVectors([&](std::size_t i) { return nodes.position[i]; }), 3 * n);
    out << "</Points>\n<Cells>\n";
    // Triangles, then each joint as a line (VTK_LINE) along the edge of its triangle A: a threshold on
    // `broken` shows the crack paths in ParaView.
    std::vector<std::int64_t> connectivity(3 * t + 2 * j), offsets(t + j);
    for (std::size_t k = 0; k < t; ++k)
    {
        for (int c = 0; c < 3; ++c)
            connectivity[3 * k + c] = tris.nodes[k][c];
        offsets[k] = static_cast<std::int64_t>(3 * (k + 1));
    }
    for (std::size_t k = 0; k < j; ++k)
    {
        connectivity[3 * t + 2 * k] = joints.nodes[k][0];
        connectivity[3 * t + 2 * k + 1] = joints.nodes[k][1];
        offsets[t + k] = static_cast<std::int64_t>(3 * t + 2 * (k + 1));
    }
    std::vector<std::uint8_t> types(t + j, 5);                                               // VTK_TRIANGLE
    std::fill(types.begin() + static_cast<std::ptrdiff_t>(t), types.end(), std::uint8_t(3)); // VTK_LINE
    arrays.int64(out, "connectivity", 1, connectivity.data(), connectivity.size());
    arrays.int64(out, "offsets", 1, offsets.data(), offsets.size());
    arrays.uint8(out, "types", 1, types.data(), types.size());
    out << "</Cells>\n<PointData Vectors=\"velocity\">\n";
    arrays.float64(out, "displacement", 3,
                   nodeVectors([&](std::size_t i) { return nodes.position[i] - nodes.referencePosition[i]; }),
                   3 * n);
    arrays.float64(out, "velocity", 3, nodeVectors([&](std::size_t i) { return nodes.velocity[i]; }), 3 * n);
    out << "</PointData>\n<CellData Tensors=\"stress\">\n";
    for (std::size_t k = 0; k < t; ++k)
    {
        const auto& s = tris.stress[k];
        const double row[9] = {s.xx, s.xy, 0, s.xy, s.yy, 0, 0, 0, 0};
        std::copy(row, row + 9, flat.begin() + static_cast<std::ptrdiff_t>(9 * k));
    }
    std::fill(flat.begin() + static_cast<std::ptrdiff_t>(9 * t),
              flat.begin() + static_cast<std::ptrdiff_t>(9 * (t + j)),
              0.0); // joints carry no element stress
    arrays.float64(out, "stress", 9, flat.data(), 9 * (t + j));
    std::vector<std::int32_t> body(t + j);
    for (std::size_t k = 0; k < t; ++k)
        body[k] = static_cast<std::int32_t>(tris.body[k]);
    for (std::size_t k = 0; k < j; ++k)
        body[t + k] = static_cast<std::int32_t>(tris.body[joints.triangles[k][0]]);
    arrays.int32(out, "body", 1, body.data(), t + j);
    if (j > 0)
    {
        // Per cell: 1 for a joint line (0 for a triangle); its damage max(D_0, D_1) (0 for a
        // triangle), and 1 once broken.
        std::vector<std::int32_t> flag(t + j, 0);
        std::fill(flag.begin() + static_cast<std::ptrdiff_t>(t), flag.end(), 1);
        arrays.int32(out, "joint", 1, flag.data(), t + j);
        for (std::size_t k = 0; k < t + j; ++k)
            flat[k] = k < t ? 0.0 : std::max(joints.damage[k - t][0], joints.damage[k - t][1]);
        arrays.float64(out, "damage", 1, flat.data(), t + j);
        for (std::size_t k = 0; k < j; ++k)
            flag[t + k] = joints.broken[k];
        arrays.int32(out, "broken", 1, flag.data(), t + j);
    }
    out << "</CellData>\n</Piece>\n</UnstructuredGrid>\n";
    arrays.finish(out);
    atomic.commit();
}

namespace
{
std::string frameName(std::size_t frame)
{
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05zu.vtu", frame);
    return name;
}
} // namespace

OutputWriter::OutputWriter(const std::filesystem::path& directory, bool vtk, io::VtkFormat format,
                           const Resume* resume)
    : directory_(directory), vtk_(vtk), format_(format)
{
    std::error_code ec;
    std::filesystem::create_directories(directory, ec);
    if (ec)
        throw OutputError("cannot create the output directory '" + directory.string() + "': " + ec.message());
    if (resume)
    {
        frameTimes_ = resume->frameTimes;
        for (std::size_t k = 0; k < frameTimes_.size(); ++k)
            listed_.push_back(std::filesystem::is_regular_file(directory / frameName(k), ec));
    }
    const auto bytes = [&](std::size_t k)
    { return resume && k < resume->csvBytes.size() ? std::optional(resume->csvBytes[k]) : std::nullopt; };
    if (!(bytes(0) && bodies_.resume(directory / "bodies.csv", *bytes(0))))
    {
        bodies_.open(directory / "bodies.csv");
        bodies_.stream() << "t,body,name,x,y,vx,vy\n";
        bodies_.flush();
    }
    if (!(bytes(1) && energy_.resume(directory / "energy.csv", *bytes(1))))
    {
        energy_.open(directory / "energy.csv");
        energy_.stream() << "t,kinetic,strain,gravity,friction_work,normal_damping_work,broken_joints,"
                            "energy_released,joint_work\n";
        energy_.flush();
    }
    thermo_.emplace(directory, thermoColumns(), bytes(2));
}

OutputWriter::Resume OutputWriter::resumeState()
{
    return {frameTimes_, {bodies_.size(), energy_.size(), thermo_->size()}};
}

void OutputWriter::writePvd()
{
    std::string series;
    for (std::size_t k = 0; k < frameTimes_.size(); ++k)
        if (listed_[k])
        {
            series += "<DataSet timestep=\"";
            io::appendNumber(series, frameTimes_[k]);
            series += "\" file=\"" + frameName(k) + "\"/>\n";
        }
    io::AtomicFile pvd(directory_ / "series.pvd");
    pvd.stream() << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n"
                 << series << "</Collection>\n</VTKFile>\n";
    pvd.commit();
}

void OutputWriter::write(const World& world, Real time)
{
    if (vtk_)
        writeVtu(world, directory_ / frameName(frameTimes_.size()), format_);
    frameTimes_.push_back(time);
    listed_.push_back(true);
    if (vtk_)
        writePvd();
    std::string rows;
    for (std::uint32_t b = 0; b < world.bodyCount(); ++b)
    {
        const BodyState s = world.bodyState(b);
        io::appendNumber(rows, time);
        rows += "," + std::to_string(b) + "," + world.bodyName(b);
        for (const Real v : {s.centroid.x, s.centroid.y, s.velocity.x, s.velocity.y})
        {
            rows += ',';
            io::appendNumber(rows, v);
        }
        rows += '\n';
    }
    bodies_.stream() << rows;
    bodies_.flush();
    const Energies e = world.energies();
    rows.clear();
    io::appendNumber(rows, time);
    for (const Real v : {e.kinetic, e.strain, e.gravity, e.frictionWork, e.normalDampingWork})
    {
        rows += ',';
        io::appendNumber(rows, v);
    }
    const FractureState f = world.fractureState();
    rows += "," + std::to_string(f.broken) + ",";
    io::appendNumber(rows, f.energyReleased);
    rows += ',';
    io::appendNumber(rows, f.jointWork);
    rows += '\n';
    energy_.stream() << rows;
    energy_.flush();
    recordThermo(*thermo_, world, time);
}

void OutputWriter::finish()
{
    bodies_.close();
    energy_.close();
    thermo_->close();
}

} // namespace veridem::fdem
