// What a 3D DEM run writes and how it stamps its times (docs/scene-format.md, `[output]` and
// "Output"): the particle fields of particles.csv and the .vtp files, which files are on, and the
// time step, from which every output time is computed as the step count times dt (outputTime).
// Filled by readDemScene (io/dem_scene.h); the recorders (io/*_output.h) take it as it is.
#pragma once

#include "core/vec3.h"
#include "io/vtk_xml.h"

#include <cstdint>
#include <string_view>
#include <vector>

namespace veridem::io
{

/// A per-particle quantity of the particle output, beyond the id and position always written.
/// CSV columns: Velocity vx,vy,vz [m/s]; AngularVelocity wx,wy,wz [rad/s]; Radius radius [m];
/// Mass mass [kg]; Material material (its [[material]] name; in the .vtp its index in the scene's
/// order); Force fx,fy,fz [N] and Torque tx,ty,tz [N m] (the contact force and torque of the last
/// step, gravity excluded; zero before the first step); Coordination coordination (the particle's
/// touching contacts with other particles, walls not counted).
enum class ParticleField
{
    Velocity,
    AngularVelocity,
    Radius,
    Mass,
    Material,
    Force,
    Torque,
    Coordination
};

/// The scene-file name of a field ("velocity", "angular_velocity", "radius", "mass", "material",
/// "force", "torque", "coordination").
std::string_view particleFieldName(ParticleField field);
/// All fields, in the order of the enum (the names a scene may give).
std::vector<ParticleField> allParticleFields();

struct OutputOptions
{
    Real dt = 0;     // the scene's time step [s]: an output at step n is stamped outputTime(n, dt)
    bool vtk = true; // particles_NNNNNN.vtp and particles.pvd
    VtkFormat vtkFormat = VtkFormat::Ascii; // of every .vtp
    bool particlesCsv = true;               // particles.csv
    std::vector<ParticleField> particleFields = {ParticleField::Velocity, ParticleField::AngularVelocity};
    bool contactsVtk = false; // contacts_NNNNNN.vtp and contacts.pvd ([output] contacts)
    bool contactsCsv = false; // contacts_NNNNNN.csv ([output] contacts_csv)

    bool has(ParticleField field) const;
};

/// The time of step `steps` of a run with time step dt [s]: the double nearest to the exact decimal
/// product of `steps` and dt's shortest decimal form (the one written in the scene), so that 60000
/// steps of 1e-5 s give 0.6 (printed "0.6"), not the 0.6000000000000001 of the product in floating
/// point, nor the sum of the steps' dt. The same on every machine.
double outputTime(std::uint64_t steps, double dt);

} // namespace veridem::io
