// Reading a 3D DEM scene (TOML) into a World. Every key, its unit and default is documented in
// docs/scene-format.md; unknown keys, wrong types and non-physical values are InputErrors that
// name the file, the line and what was expected.
#pragma once

#include "dem/particle_flow.h"
#include "dem/world.h"
#include "io/measurement_keys.h"
#include "io/output_options.h"
#include "io/vtk_xml.h"

#include <toml++/toml.h>

#include <string>

namespace veridem::io
{

struct DemScene
{
    dem::World world;
    Real dt = 0;                   // [s]
    Real duration = 0;             // [s]
    Real outputInterval = 0;       // [s]
    Real checkpointInterval = 0;   // [s] between checkpoints (0: none)
    Real maxOverlapFraction = 0.5; // blow-up threshold: overlap / radius [-]
    Real characteristicSpeed = 1;  // [m/s], sizes the Hertz stiffness in the time-step estimate
    bool writeVtk = true;
    io::VtkFormat vtkFormat = io::VtkFormat::Ascii; // vtk_format, "auto" resolved by the sphere count
    MeasurementOptions measurements;                // [output] (io/measurement_keys.h)
    OutputOptions output;   // the files written, their particle fields and dt (io/output_options.h)
    dem::ParticleFlow flow; // [[insert]], [[outlet]] (io/particle_flow_keys.h)
};

/// Builds the scene; `file` is used in messages and to resolve relative particle-file paths.
DemScene readDemScene(const toml::table& root, const std::string& file);

} // namespace veridem::io
