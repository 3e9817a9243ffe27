#include "io/particle_flow_keys.h"

#include "core/error.h"
#include "io/scene_limits.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace veridem::io
{

namespace
{

Vec3 unit(TableReader& t, std::string_view key, Vec3 v)
{
    if (!(length(v) > 0))
        t.fail(key, "must be a non-zero vector");
    return v / length(v);
}

dem::FlowRegion readRegion(TableReader& t, bool outlet)
{
    dem::FlowRegion region;
    const std::string type = outlet ? t.choice("type", "box", {"box", "cylinder", "plane"})
                                    : t.choice("type", "box", {"box", "cylinder"});
    if (type == "box")
    {
        region.kind = dem::FlowRegion::Kind::Box;
        region.min = t.requiredVec3("min");
        region.max = t.requiredVec3("max");
        if (!(region.max.x > region.min.x && region.max.y > region.min.y && region.max.z > region.min.z))
            t.fail("max", "must be above 'min' in x, y and z");
    }
    else if (type == "cylinder")
    {
        region.kind = dem::FlowRegion::Kind::Cylinder;
        region.point = t.requiredVec3("point");
        region.axis = unit(t, "axis", t.vec3("axis", {0, 0, 1}));
        region.radius = t.requiredNumber("region_radius"); // (not "radius": the particle radius key)
        t.requirePositive("region_radius", region.radius, "m");
        region.length = t.requiredNumber("length");
        t.requirePositive("length", region.length, "m");
    }
    else
    {
        region.kind = dem::FlowRegion::Kind::HalfSpace;
        region.point = t.requiredVec3("point");
        region.normal = unit(t, "normal", t.requiredVec3("normal"));
    }
    return region;
}

/// Fractions (> 0) as an ascending cumulative sum ending in exactly 1.
std::vector<Real> cumulative(TableReader& t, std::string_view key, std::vector<Real> weights)
{
    Real total = 0;
    for (const Real w : weights)
    {
        if (!(w > 0))
            t.fail(key, "must hold fractions > 0");
        total += w;
    }
    Real sum = 0;
    for (Real& w : weights)
    {
        sum += w;
        w = sum / total;
    }
    weights.back() = 1;
    return weights;
}

dem::RadiusDistribution readRadius(TableReader& t)
{
    using Kind = dem::RadiusDistribution::Kind;
    dem::RadiusDistribution d;
    const std::string kind =
        t.choice("radius_distribution", "fixed", {"fixed", "uniform", "normal", "lognormal", "table"});
    auto range = [&](bool required)
    {
        if (required)
        {
            d.min = t.requiredNumber("min_radius");
            d.max = t.requiredNumber("max_radius");
        }
        else
        {
            d.min = t.number("min_radius", 0.0);
            d.max = t.number("max_radius", std::numeric_limits<Real>::infinity());
        }
        t.requireNonNegative("min_radius", d.min, "m");
        if (!(d.max > d.min))
            t.fail("max_radius", "must be above min_radius");
    };
    if (kind == "fixed")
    {
        d.kind = Kind::Fixed;
        d.value = t.requiredNumber("radius");
        t.requirePositive("radius", d.value, "m");
    }
    else if (kind == "uniform")
    {
        d.kind = Kind::Uniform;
        range(true);
        t.requirePositive("min_radius", d.min, "m");
    }
    else if (kind == "normal")
    {
        d.kind = Kind::Normal;
        range(true);
        t.requirePositive("min_radius", d.min, "m");
        d.mean = t.requiredNumber("mean_radius");
        d.std = t.requiredNumber("std_radius");
        t.requirePositive("std_radius", d.std, "m");
        if (!(d.mean >= d.min && d.mean <= d.max))
            t.fail("mean_radius", "must lie in [min_radius, max_radius]");
    }
    else if (kind == "lognormal")
    {
        d.kind = Kind::LogNormal;
        d.mu = t.requiredNumber("mu");
        d.sigma = t.requiredNumber("sigma");
        t.requirePositive("sigma", d.sigma, "");
        range(false);
        if (!std::isfinite(d.max))
            d.max = std::exp(d.mu + 6 * d.sigma); // (largest(): the grid's cell; beyond: p < 1e-9)
        const Real median = std::exp(d.mu);
        if (!(median >= d.min && median <= d.max))
            t.fail("mu", "its median exp(mu) must lie in [min_radius, max_radius]");
    }
    else
    {
        d.kind = Kind::Table;
        d.radii = t.numbers("radii");
        if (d.radii.empty())
            t.fail("radii", "is missing: radius_distribution = \"table\" needs radii = [...] in m");
        for (const Real r : d.radii)
            if (!(r > 0))
                t.fail("radii", "must hold radii > 0 m");
        std::vector<Real> fractions = t.numbers("fractions");
        if (fractions.size() != d.radii.size())
            t.fail("fractions", "must have one fraction per radius");
        if (t.choice("fractions_by", "number", {"number", "mass"}) == "mass")
            for (std::size_t k = 0; k < fractions.size(); ++k) // by number: mass over r^3
                fractions[k] /= d.radii[k] * d.radii[k] * d.radii[k];
        d.cumulative = cumulative(t, "fractions", fractions);
    }
    return d;
}

} // namespace

dem::ParticleFlow readParticleFlow(TableReader& top, const dem::World& world, std::uint64_t everySteps)
{
    dem::ParticleFlow flow;
    flow.everySteps = everySteps;
    std::size_t index = 0;
    for (auto& t : top.arrayOfTables("insert"))
    {
        dem::Inserter in;
        in.name = t.string("name", "insert" + std::to_string(++index));
        in.region = readRegion(t, false);
        const auto count = t.optionalNumber("count");
        const auto rate = t.optionalNumber("rate");
        const auto massRate = t.optionalNumber("mass_rate");
        if (int(count.has_value()) + int(rate.has_value()) + int(massRate.has_value()) != 1)
            t.fail("count", "give exactly one of count, rate [1/s] or mass_rate [kg/s]");
        in.from = t.number("from", 0.0);
        t.requireNonNegative("from", in.from, "s");
        if (count)
        {
            in.mode = dem::Inserter::Mode::Count;
            in.count = *count;
            if (!(in.count >= 1 && in.count == std::floor(in.count) && in.count <= 1e9))
                t.fail("count", "must be a whole number in [1, 1e9]");
            in.until = t.number("until", in.from);
        }
        else
        {
            in.mode = rate ? dem::Inserter::Mode::Rate : dem::Inserter::Mode::MassRate;
            in.rate = rate ? *rate : *massRate;
            t.requirePositive(rate ? "rate" : "mass_rate", in.rate, rate ? "1/s" : "kg/s");
            in.until = t.number("until", std::numeric_limits<Real>::infinity());
        }
        if (!(in.until >= in.from))
            t.fail("until", "must be >= from");
        in.radius = readRadius(t);
        const std::vector<std::string> names = t.strings("materials");
        if (names.empty())
            in.materials.push_back(world.materialId(t.requiredString("material")));
        else
        {
            if (t.has("material"))
                t.fail("material", "give material or materials, not both");
            for (const auto& name : names)
                in.materials.push_back(world.materialId(name));
        }
        std::vector<Real> fractions = t.numbers("material_fractions");
        if (fractions.empty())
            fractions.assign(in.materials.size(), 1.0);
        if (fractions.size() != in.materials.size())
            t.fail("material_fractions", "must have one fraction per material");
        in.materialCumulative = cumulative(t, "material_fractions", fractions);
        in.velocity = t.vec3("velocity", {});
        in.velocitySpread = t.number("velocity_spread", 0.0);
        t.requireNonNegative("velocity_spread", in.velocitySpread, "m/s");
        const std::int64_t seed = t.integer("seed", 1);
        // Each inserter its own stream, also with equal seeds: the seed mixed with its number.
        in.seed = std::uint64_t(seed) ^ (0xD1B54A32D192ED03ull * std::uint64_t(index));
        in.random = dem::Random(in.seed);
        t.finish();
        flow.inserters.push_back(std::move(in));
    }
    index = 0;
    for (auto& t : top.arrayOfTables("outlet"))
    {
        dem::Outlet o;
        o.name = t.string("name", "outlet" + std::to_string(++index));
        if (o.name.empty() || o.name.find_first_of(",\"\n") != std::string::npos)
            t.fail("name", "must be a non-empty name without commas, quotes or line breaks");
        o.region = readRegion(t, true);
        t.finish();
        flow.outlets.push_back(std::move(o));
    }
    return flow;
}

void startParticleFlow(dem::ParticleFlow& flow, dem::World& world, bool energy, const std::string& file)
{
    if (energy && !flow.empty())
        throw InputError(file + ": [output] energy = true cannot be combined with [[insert]] or [[outlet]] "
                                "(the energy ledger assumes a fixed set of particles)");
    flow.nextId = 0; // after the largest id (a [[particles]] file may give ids with gaps)
    for (const std::uint32_t id : world.particles.id)
        flow.nextId = std::max(flow.nextId, id + 1);
    if (flow.inserters.empty() || world.neighbors.skin > 0)
        return;
    Real largest = flow.largestRadius();
    for (const Real r : world.particles.radius)
        largest = std::max(largest, r);
    world.neighbors.skin = 0.2 * largest;
}

double expectedParticles(const dem::ParticleFlow& flow, const dem::World& world, Real duration,
                         const std::string& file)
{
    double count = double(world.particles.size());
    if (flow.inserters.empty())
        return count;
    for (const dem::Inserter& in : flow.inserters)
        count += in.mode == dem::Inserter::Mode::Count ? in.count
                 : in.mode == dem::Inserter::Mode::Rate
                     ? in.rate * std::fmax(0.0, std::fmin(in.until, duration) - in.from)
                     : 0.0;
    // (a mass rate's count is not known before the radii are drawn)
    checkSphereCount(count, "the spheres and those the [[insert]] tables add", file);
    return count;
}

dem::World timeStepProbe(const dem::World& world, const dem::ParticleFlow& flow)
{
    dem::World probe;
    probe.materials = world.materials;
    probe.pairs = world.pairs;
    probe.walls = world.walls;
    probe.gravity = world.gravity;
    probe.particles = world.particles;
    Real far = 0;
    for (const Vec3& x : world.particles.position)
        far = std::max(far, std::fmax(std::fabs(x.x), std::fmax(std::fabs(x.y), std::fabs(x.z))));
    for (const dem::Inserter& in : flow.inserters)
    {
        const dem::RadiusDistribution& d = in.radius;
        const Real smallest = d.kind == dem::RadiusDistribution::Kind::Fixed ? d.value
                              : d.kind == dem::RadiusDistribution::Kind::Table
                                  ? *std::min_element(d.radii.begin(), d.radii.end())
                              : d.kind == dem::RadiusDistribution::Kind::LogNormal
                                  ? std::fmax(d.min, std::exp(d.mu - 6 * d.sigma))
                                  : d.min;
        for (const std::uint32_t m : in.materials)
            for (const Real r : {smallest, d.largest()})
            {
                far += 10 * d.largest();
                probe.particles.add({far, 0, 0}, in.velocity, {}, r, world.materials[m].density, m);
            }
    }
    return probe;
}

} // namespace veridem::io
