// The extension module veridem._veridem: api::Simulation for Python, with zero-copy numpy views
// of the particle arrays. The package's Python part (veridem/__init__.py) adds the loops with
// callbacks, the scene helpers and verify(). docs/python.md is the reference.
//
// Views and their lifetime: an array handed out points into the engine's own memory. Its base
// object holds a share of the current "generation" of the particle arrays. Before any call that
// may move those arrays (a step of a scene with inserters or outlets, add_particle,
// remove_particles, restore), a generation that still has views alive is detached: the engine
// continues on a copy, the old memory stays with the views (api::Simulation::detachParticleArrays),
// and the old views are made read-only. An old view therefore never reads freed memory; it
// reads the state as it was, and writing to it raises.
#include "api/simulation.h"
#include "core/error.h"
#include "exec/thread_pool.h"
#include "scene_dict.h"

#include <cstdlib>
#include <memory>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <string>

namespace py = pybind11;

namespace veridem::python
{

namespace
{

/// What the views of one generation of the particle arrays keep alive.
struct Generation
{
    std::shared_ptr<const dem::ParticleStore> kept; // the old arrays, once detached
    std::vector<py::weakref> views;                 // the arrays handed out (to make read-only)
};

/// The base object of every view: a share of its generation.
struct ViewBase
{
    std::shared_ptr<Generation> generation;
};

void refuseRanks()
{
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"})
        if (const char* size = std::getenv(name); size && std::atoi(size) > 1)
            throw std::runtime_error("veridem's Python module runs in one process; under mpirun use "
                                     "`mpirun -np N veridem run SCENE` (this job has " +
                                     std::string(size) + " ranks)");
}

Vec3 toVec3(const py::handle& value, const char* name)
{
    py::array_t<double, py::array::forcecast> a;
    try
    {
        a = py::array_t<double, py::array::forcecast>::ensure(value);
    }
    catch (const py::error_already_set&)
    {
    }
    if (!a || a.ndim() != 1 || a.shape(0) != 3)
        throw py::type_error(std::string(name) + ": expected 3 numbers (x, y, z)");
    const Vec3 v{a.at(0), a.at(1), a.at(2)};
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
        throw py::value_error(std::string(name) + ": every component must be finite (got NaN or infinity)");
    return v;
}

py::tuple tuple3(const Vec3& v)
{
    return py::make_tuple(v.x, v.y, v.z);
}

py::array vec3Array(const std::vector<Vec3>& v)
{
    py::array_t<double> a({py::ssize_t(v.size()), py::ssize_t(3)});
    auto m = a.mutable_unchecked<2>();
    for (std::size_t k = 0; k < v.size(); ++k)
    {
        m(py::ssize_t(k), 0) = v[k].x;
        m(py::ssize_t(k), 1) = v[k].y;
        m(py::ssize_t(k), 2) = v[k].z;
    }
    return a;
}

class PySimulation
{
  public:
    PySimulation(api::Simulation sim) : sim_(std::move(sim)) {}

    api::Simulation& sim() { return sim_; }

    /// A view of `rows` rows of `columns` values of type T starting at `data`, `stride` bytes
    /// apart; read-only unless `writable`.
    template <class T>
    py::array view(const T* data, std::size_t rows, std::size_t columns, std::size_t stride, bool writable)
    {
        py::object base = py::cast(ViewBase{generation_});
        std::vector<py::ssize_t> shape = {py::ssize_t(rows)}, strides = {py::ssize_t(stride)};
        if (columns > 1)
        {
            shape.push_back(py::ssize_t(columns));
            strides.push_back(py::ssize_t(sizeof(T)));
        }
        py::array a(py::dtype::of<T>(), shape, strides, data, base);
        if (!writable)
            a.attr("flags").attr("writeable") = false;
        generation_->views.emplace_back(a);
        return a;
    }

    /// Before a call that may move the particle arrays: detaches them if views are alive.
    void beforeMove()
    {
        if (generation_.use_count() > 1) // (views alive: each base holds a share)
        {
            generation_->kept = sim_.detachParticleArrays();
            for (const py::weakref& w : generation_->views)
                if (py::object a = w(); !a.is_none())
                    a.attr("flags").attr("writeable") = false;
        }
        generation_ = std::make_shared<Generation>();
    }

    /// Steps n steps with the GIL released, checking for Python signals (Ctrl-C) every ~10-50
    /// ms; a signal's exception is raised after the steps under way.
    std::uint64_t step(std::uint64_t n)
    {
        if (sim_.stepsMayMoveParticles())
            beforeMove();
        bool signalled = false;
        std::uint64_t done = 0;
        std::string blowUp;
        {
            py::gil_scoped_release release;
            try
            {
                done = sim_.advance(n, nullptr,
                                    [&]
                                    {
                                        py::gil_scoped_acquire acquire;
                                        signalled = PyErr_CheckSignals() != 0;
                                        return signalled;
                                    });
            }
            catch (const api::BlowUp& e)
            {
                blowUp = e.what();
            }
        }
        if (!blowUp.empty())
            throw SimulationError(blowUp);
        if (signalled)
            throw py::error_already_set();
        return done;
    }

  private:
    api::Simulation sim_;
    std::shared_ptr<Generation> generation_ = std::make_shared<Generation>();
};

api::SimulationOptions options(const py::object& out, bool quiet, bool forceDt, const std::string& restart)
{
    api::SimulationOptions o;
    if (!out.is_none())
        o.outDir = py::str(out).cast<std::string>();
    o.speak = !quiet;
    o.allowUnstableTimeStep = forceDt;
    o.restartFile = restart;
    return o;
}

} // namespace

} // namespace veridem::python

using namespace veridem;
using namespace veridem::python;

PYBIND11_MODULE(_veridem, m)
{
    m.doc() = "veridem: verified DEM contact physics (SI units throughout). See docs/python.md.";
    static py::exception<SimulationError> simulationError(m, "SimulationError", PyExc_RuntimeError);
    py::register_exception_translator(
        [](std::exception_ptr p)
        {
            try
            {
                if (p)
                    std::rethrow_exception(p);
            }
            catch (const InputError& e) // bad input: the engine's one-line message
            {
                PyErr_SetString(PyExc_ValueError, e.what());
            }
            catch (const OutputError& e)
            {
                PyErr_SetString(PyExc_OSError, e.what());
            }
            catch (const SimulationError& e)
            {
                simulationError(e.what());
            }
        });

    py::class_<ViewBase>(m, "_ViewBase");

    m.def(
        "set_threads",
        [](int n)
        {
            if (n < 1 || n > exec::kMaxThreads)
                throw py::value_error("set_threads: n must be 1 to " + std::to_string(exec::kMaxThreads) +
                                      " (got " + std::to_string(n) + ")");
            exec::setThreads(n);
        },
        py::arg("n"),
        "Threads of the DEM loops for every simulation of the process (default: the CPUs of "
        "its affinity mask); the results are the same bits on any count.");
    m.def(
        "threads", [] { return exec::threads(); }, "The threads of the DEM loops.");

    py::class_<PySimulation>(m, "_Simulation")
        .def_static(
            "from_file",
            [](const std::string& file, const py::object& out, bool quiet, bool forceDt,
               const std::string& restart)
            {
                refuseRanks();
                return new PySimulation(
                    api::Simulation::fromFile(file, options(out, quiet, forceDt, restart)));
            },
            py::arg("file"), py::arg("out"), py::arg("quiet"), py::arg("force_dt"), py::arg("restart"))
        .def_static(
            "from_dict",
            [](const py::dict& scene, const std::string& name, const py::object& out, bool quiet,
               bool forceDt, const std::string& restart)
            {
                refuseRanks();
                const toml::table table = sceneTable(scene);
                return new PySimulation(
                    api::Simulation::fromTable(table, name, options(out, quiet, forceDt, restart)));
            },
            py::arg("scene"), py::arg("name"), py::arg("out"), py::arg("quiet"), py::arg("force_dt"),
            py::arg("restart"))
        .def("step", &PySimulation::step, py::arg("n"))
        .def_property_readonly("dt", [](PySimulation& s) { return s.sim().dt(); })
        .def_property_readonly("time", [](PySimulation& s) { return s.sim().time(); })
        .def_property_readonly("step_count", [](PySimulation& s) { return s.sim().step(); })
        .def_property_readonly("end_step", [](PySimulation& s) { return s.sim().lastStep(); })
        .def_property_readonly("checkpoint_is_current",
                               [](PySimulation& s) { return s.sim().checkpointIsCurrent(); })
        .def_property_readonly("output_interval", [](PySimulation& s) { return s.sim().outputInterval(); })
        .def_property_readonly("particle_count",
                               [](PySimulation& s) { return s.sim().world().particles.size(); })
        .def("view",
             [](PySimulation& s, const std::string& name) -> py::array
             {
                 dem::ParticleStore& p = s.sim().particleStore();
                 const std::size_t n = p.size();
                 const auto row = [](auto& v) { return reinterpret_cast<const double*>(v.data()); };
                 if (name == "position")
                     return s.view(row(p.position), n, 3, sizeof(Vec3), false);
                 if (name == "velocity")
                     return s.view(row(p.velocity), n, 3, sizeof(Vec3), true);
                 if (name == "angular_velocity")
                     return s.view(row(p.angularVelocity), n, 3, sizeof(Vec3), true);
                 if (name == "force")
                     return s.view(row(p.force), n, 3, sizeof(dem::PaddedVec3), false);
                 if (name == "torque")
                     return s.view(row(p.torque), n, 3, sizeof(dem::PaddedVec3), false);
                 if (name == "radius")
                     return s.view(p.radius.data(), n, 1, sizeof(Real), false);
                 if (name == "mass")
                     return s.view(p.mass.data(), n, 1, sizeof(Real), false);
                 if (name == "material")
                     return s.view(p.material.data(), n, 1, sizeof(std::uint32_t), false);
                 if (name == "id")
                     return s.view(p.id.data(), n, 1, sizeof(std::uint32_t), false);
                 if (name == "external_force")
                     return s.view(row(s.sim().externalForces()), n, 3, sizeof(Vec3), true);
                 if (name == "external_torque")
                     return s.view(row(s.sim().externalTorques()), n, 3, sizeof(Vec3), true);
                 throw py::value_error(
                     "no particle array is named '" + name +
                     "' (position, velocity, angular_velocity, force, torque, radius, mass, "
                     "material, id, external_force, external_torque)");
             })
        .def("material_names",
             [](PySimulation& s)
             {
                 std::vector<std::string> names;
                 for (const dem::Material& material : s.sim().world().materials)
                     names.push_back(material.name);
                 return names;
             })
        .def("wall_names", [](PySimulation& s) { return s.sim().wallNames(); })
        .def("set_wall_velocity", [](PySimulation& s, const std::string& wall, const py::object& v)
             { s.sim().setWallVelocity(s.sim().wallIndex(wall), toVec3(v, "velocity")); })
        .def("set_wall_angular_velocity", [](PySimulation& s, const std::string& wall, const py::object& w)
             { s.sim().setWallAngularVelocity(s.sim().wallIndex(wall), toVec3(w, "angular_velocity")); })
        .def("wall_displacement", [](PySimulation& s, const std::string& wall)
             { return tuple3(s.sim().wallDisplacement(s.sim().wallIndex(wall))); })
        .def("wall_load",
             [](PySimulation& s, const std::string& wall)
             {
                 const api::WallLoad load = s.sim().wallLoad(s.sim().wallIndex(wall));
                 return py::make_tuple(tuple3(load.force), tuple3(load.torque));
             })
        .def("add_particle",
             [](PySimulation& s, const std::string& material, double radius, const py::object& position,
                const py::object& velocity, const py::object& angularVelocity)
             {
                 const Vec3 x = toVec3(position, "position"), v = toVec3(velocity, "velocity"),
                            w = toVec3(angularVelocity, "angular_velocity");
                 s.beforeMove();
                 return s.sim().addParticle(material, radius, x, v, w);
             })
        .def("remove_particles",
             [](PySimulation& s, const std::vector<std::uint32_t>& ids)
             {
                 s.beforeMove();
                 s.sim().removeParticles(ids);
             })
        .def("contacts",
             [](PySimulation& s)
             {
                 const api::ContactTable t = s.sim().contacts();
                 py::dict d;
                 d["i"] = py::array_t<std::uint32_t>(py::ssize_t(t.size()), t.i.data());
                 d["j"] = py::array_t<std::int64_t>(py::ssize_t(t.size()), t.j.data());
                 d["wall"] = py::array_t<std::int32_t>(py::ssize_t(t.size()), t.wall.data());
                 d["overlap"] = py::array_t<double>(py::ssize_t(t.size()), t.overlap.data());
                 d["normal"] = vec3Array(t.normal);
                 d["point"] = vec3Array(t.point);
                 d["normal_force"] = vec3Array(t.normalForce);
                 d["tangential_force"] = vec3Array(t.tangentialForce);
                 return d;
             })
        .def("energies",
             [](PySimulation& s)
             {
                 py::dict d;
                 const dem::KineticEnergyParts k = s.sim().kineticEnergy();
                 d["kinetic_translational"] = k.translational;
                 d["kinetic_rotational"] = k.rotational;
                 if (const dem::EnergyLedgerState* l = s.sim().ledger())
                 {
                     d["elastic"] = l->elasticEnergy;
                     d["work_gravity"] = l->gravityWork;
                     d["work_walls"] = l->wallWork;
                     d["dissipated_normal_damping"] = l->normalDamping;
                     d["dissipated_tangential_damping"] = l->tangentialDamping;
                     d["dissipated_friction"] = l->friction;
                     d["dissipated_rolling"] = l->rolling;
                     d["dissipated_adhesion"] = l->adhesion;
                     d["energy_initial"] = l->initialEnergy;
                 }
                 return d;
             })
        .def("checkpoint",
             [](PySimulation& s, const py::object& path)
             {
                 if (path.is_none())
                     s.sim().writeCheckpoint();
                 else
                     s.sim().writeCheckpoint(py::str(path).cast<std::string>());
             })
        .def("restore",
             [](PySimulation& s, const std::string& path)
             {
                 s.beforeMove();
                 s.sim().restore(path);
             })
        .def("close", [](PySimulation& s) { s.sim().close(); });
}
