// Shared set-up of the particle-flow tests (particle_flow_test.cpp, insertion_contacts_test.cpp):
// a glass material, an empty box with a floor, an inserter raining spheres into a 5 cm box, and a
// check that no two spheres overlap.
#pragma once

#include "dem/particle_flow.h"
#include "dem/world.h"

#include <gtest/gtest.h>

namespace veridem::dem::flow_test
{

inline Material glass()
{
    Material m;
    m.name = "glass";
    m.density = 2500;
    m.normalStiffness = 500;
    m.restitution = 0.5;
    m.friction = 0.4;
    return m;
}

/// An empty world with a floor and a skin for radii of 1-1.5 mm, prepared.
inline World emptyBox()
{
    World world;
    world.addMaterial(glass());
    Wall floor;
    floor.name = "floor";
    floor.shape = PlaneShape{{0, 0, 0}, {0, 0, 1}};
    world.walls.push_back(floor);
    world.neighbors.skin = 0.3e-3;
    prepare(world);
    return world;
}

inline Inserter rain(Inserter::Mode mode, Real amount, Real from, Real until)
{
    Inserter in;
    in.name = "rain";
    in.region.kind = FlowRegion::Kind::Box;
    in.region.min = {0, 0, 0};
    in.region.max = {0.05, 0.05, 0.05};
    in.mode = mode;
    (mode == Inserter::Mode::Count ? in.count : in.rate) = amount;
    in.from = from;
    in.until = until;
    in.radius.kind = RadiusDistribution::Kind::Uniform;
    in.radius.min = 1e-3;
    in.radius.max = 1.5e-3;
    in.materials = {0};
    in.materialCumulative = {1};
    in.random = Random(11);
    return in;
}

inline void expectNoOverlaps(const World& world)
{
    const ParticleStore& p = world.particles;
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        EXPECT_GE(p.position[i].z, p.radius[i]); // above the floor
        for (std::size_t j = i + 1; j < p.size(); ++j)
            ASSERT_GE(length(p.position[i] - p.position[j]), p.radius[i] + p.radius[j]) << i << " " << j;
    }
}

} // namespace veridem::dem::flow_test
