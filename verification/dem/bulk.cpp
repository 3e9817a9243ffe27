#include "bulk.h"

#include "case_stepper.h"
#include "core/error.h"
#include "dem/time_step.h"
#include "io/particle_flow_keys.h"
#include "io/toml_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <ctime>
#include <limits>

namespace veridem::verify
{

io::DemScene sceneFromText(const std::string& text, const std::string& source)
{
    return io::readDemScene(io::parseText(text, source), source);
}

void requireResolvedContacts(const io::DemScene& scene, const std::string& label)
{
    const dem::TimeStepEstimate estimate =
        dem::estimateTimeStep(io::timeStepProbe(scene.world, scene.flow), scene.characteristicSpeed);
    if (scene.dt > estimate.contactTime / 25)
        throw InputError(label + ": dt = " + std::to_string(scene.dt) + " s resolves the contact time " +
                         std::to_string(estimate.contactTime) + " s by fewer than 25 steps");
}

void runScene(io::DemScene& scene, Real duration, Real sampleInterval, const CaseContext& context,
              const std::string& label, const std::function<void(const World&)>& sample)
{
    World& world = scene.world;
    CaseStepper stepper(world, context, &scene.flow);
    const Real dt = scene.dt * context.dtScale;
    const auto steps = static_cast<std::uint64_t>(std::llround(duration / dt));
    const std::uint64_t sampleEvery =
        sampleInterval > 0 ? std::max<std::uint64_t>(1, std::llround(sampleInterval / dt)) : 0;
    const std::uint64_t flowEvery = scene.flow.empty() ? 0 : scene.flow.everySteps;
    const std::uint64_t first = world.stepCount, last = first + steps;
    const auto start = std::chrono::steady_clock::now();
    auto lastReport = start;
    while (world.stepCount < last)
    {
        const std::uint64_t s = world.stepCount;
        std::uint64_t end = last;
        if (flowEvery)
            end = std::min(end, (s / flowEvery + 1) * flowEvery);
        if (sampleEvery)
            end = std::min(end, first + ((s - first) / sampleEvery + 1) * sampleEvery);
        const std::uint64_t done = stepper.advance(dt, end - s, scene.maxOverlapFraction);
        if (done < end - s || !world.health.finite || world.health.maxOverlapRatio > scene.maxOverlapFraction)
            throw SimulationError(
                label + ": step " + std::to_string(world.stepCount) + ", particle " +
                std::to_string(stepper.failedParticleId()) +
                (world.health.finite
                     ? ": overlap " + std::to_string(world.health.maxOverlapRatio) + " of the radius"
                     : ": state is not finite"));
        if (flowEvery && world.stepCount % flowEvery == 0)
            stepper.applyFlow(dt);
        if (sampleEvery && (world.stepCount - first) % sampleEvery == 0 && sample)
            stepper.sample(sample);
        if (context.showProgress)
        {
            const auto now = std::chrono::steady_clock::now();
            if (std::chrono::duration<double>(now - lastReport).count() > 2)
            {
                lastReport = now;
                std::fprintf(stderr, "\r  %s: t = %.3g s, %zu particles   ", label.c_str(), world.time,
                             world.particles.size());
                std::fflush(stderr);
            }
        }
    }
    if (context.showProgress && lastReport != start)
        std::fprintf(stderr, "\r%*s\r", 70, "");
    stepper.finish(); // (the caller reads the whole world)
}

Real topOfParticles(const World& world)
{
    const auto& p = world.particles;
    Real top = -std::numeric_limits<Real>::infinity();
    for (std::size_t i = 0; i < p.size(); ++i)
        if (!p.fixed[i])
            top = std::max(top, p.position[i].z + p.radius[i]);
    return top;
}

void pourInStages(io::DemScene& scene, const StagedPour& pour, const CaseContext& context,
                  const std::string& label, const std::function<void(int, const World&)>& sample)
{
    if (scene.flow.inserters.empty())
        throw InputError(label + ": the staged pour needs an [[insert]]");
    dem::Inserter& inserter = scene.flow.inserters.front();
    for (int stage = 0; stage < pour.stages; ++stage)
    {
        World& world = scene.world;
        const Real top = std::max(pour.floor, topOfParticles(world));
        inserter.region.point.z = top + pour.gap;
        inserter.count = Real(pour.perStage) * Real(stage + 1); // cumulative, all due now
        inserter.from = inserter.until = world.time;
        if (!world.prepared)
            dem::prepare(world);
        scene.flow.apply(world, scene.dt * context.dtScale);
        if (inserter.inserted != std::uint64_t(inserter.count))
            throw SimulationError(label + ": stage " + std::to_string(stage) + " inserted " +
                                  std::to_string(inserter.inserted) + " of " +
                                  std::to_string(std::uint64_t(inserter.count)) + " particles");
        runScene(scene, pour.stageTime, pour.sampleInterval, context, label,
                 [&](const World& w) { sample(stage, w); });
    }
}

LineFit fitLine(const std::vector<Real>& x, const std::vector<Real>& y)
{
    const std::size_t n = x.size();
    const Real mx = meanOf(x), my = meanOf(y);
    Real sxy = 0, sxx = 0, syy = 0;
    for (std::size_t i = 0; i < n; ++i)
    {
        sxy += (x[i] - mx) * (y[i] - my);
        sxx += (x[i] - mx) * (x[i] - mx);
        syy += (y[i] - my) * (y[i] - my);
    }
    LineFit fit;
    fit.slope = sxy / sxx;
    fit.intercept = my - fit.slope * mx;
    fit.r2 = syy > 0 ? sxy * sxy / (sxx * syy) : 1;
    return fit;
}

WeightedLineFit fitLineWeighted(const std::vector<Real>& x, const std::vector<Real>& y,
                                const std::vector<Real>& sigma)
{
    // The normal equations of the weighted fit (e.g. Press et al., Numerical Recipes, sec. 15.2).
    Real s = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (std::size_t i = 0; i < x.size(); ++i)
    {
        if (!(sigma[i] > 0))
            throw InputError("fitLineWeighted: point " + std::to_string(i) + " has a standard error " +
                             std::to_string(sigma[i]) + ", expected > 0");
        const Real w = 1 / (sigma[i] * sigma[i]);
        s += w;
        sx += w * x[i];
        sy += w * y[i];
        sxx += w * x[i] * x[i];
        sxy += w * x[i] * y[i];
    }
    const Real delta = s * sxx - sx * sx;
    WeightedLineFit fit;
    fit.slope = (s * sxy - sx * sy) / delta;
    fit.intercept = (sxx * sy - sx * sxy) / delta;
    fit.slopeVariance = s / delta;
    fit.interceptVariance = sxx / delta;
    fit.covariance = -sx / delta;
    for (std::size_t i = 0; i < x.size(); ++i)
    {
        const Real r = (y[i] - fit.slope * x[i] - fit.intercept) / sigma[i];
        fit.chi2 += r * r;
    }
    return fit;
}

MeanWithError meanWithError(const std::vector<Real>& v)
{
    MeanWithError m;
    m.mean = meanOf(v);
    if (v.size() < 2)
        return m;
    Real sum = 0;
    for (const Real a : v)
        sum += (a - m.mean) * (a - m.mean);
    m.standardError = std::sqrt(sum / Real(v.size() - 1) / Real(v.size()));
    return m;
}

Real threadCpuSeconds()
{
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return Real(t.tv_sec) + 1e-9 * Real(t.tv_nsec);
}

Real meanOf(const std::vector<Real>& v, std::size_t from, std::size_t to)
{
    to = std::min(to, v.size());
    Real sum = 0;
    for (std::size_t i = from; i < to; ++i)
        sum += v[i];
    return to > from ? sum / Real(to - from) : 0;
}

std::string formatted(const char* format, ...)
{
    va_list args, again;
    va_start(args, format);
    va_copy(again, args);
    const int size = std::vsnprintf(nullptr, 0, format, args);
    va_end(args);
    std::string text(size > 0 ? std::size_t(size) : 0, '\0');
    if (size > 0)
        std::vsnprintf(text.data(), text.size() + 1, format, again);
    va_end(again);
    return text;
}

} // namespace veridem::verify
