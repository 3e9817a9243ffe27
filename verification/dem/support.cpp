#include "support.h"

#include "case_stepper.h"
#include "core/error.h"

#include <algorithm>
#include <cstdint>

namespace veridem::verify
{

void runFor(World& world, Real duration, Real dt, const CaseContext& context, const std::string& label,
            const std::function<void(const World&)>& observe)
{
    CaseStepper stepper(world, context);
    dt *= context.dtScale; // a dt sweep (sweep.h) runs the case at dt/2 and dt/4 too
    const auto steps = static_cast<std::uint64_t>(std::llround(duration / dt));
    const auto start = std::chrono::steady_clock::now();
    auto lastReport = start;
    const std::uint64_t firstStep = world.stepCount;
    // Without an observer, in runs of steps (dem::advance: the bits of step() calls, the kick
    // passes fused) from one progress check to the next.
    constexpr std::uint64_t kProgressEvery = 0x10000; // steps
    for (std::uint64_t s = 0; s < steps;)
    {
        stepper.advance(dt, observe ? 1 : std::min(kProgressEvery - s % kProgressEvery, steps - s));
        s = world.stepCount - firstStep;
        if (!world.health.finite)
            throw SimulationError(label + ": step " + std::to_string(world.stepCount) + ", particle " +
                                  std::to_string(stepper.failedParticleId()) + ": state is not finite");
        if (observe)
            stepper.sample(observe);
        if (context.showProgress && s % kProgressEvery == 0)
        {
            const auto now = std::chrono::steady_clock::now();
            const double elapsed = std::chrono::duration<double>(now - start).count();
            if (elapsed > 3 && std::chrono::duration<double>(now - lastReport).count() > 2)
            {
                lastReport = now;
                const double fraction = double(s) / double(steps);
                std::fprintf(stderr, "\r  %s: %5.1f %%  t = %.3g s  ETA %.0f s   ", label.c_str(),
                             100 * fraction, world.time, elapsed / fraction - elapsed);
                std::fflush(stderr);
            }
        }
    }
    if (context.showProgress && std::chrono::duration<double>(lastReport - start).count() > 0)
        std::fprintf(stderr, "\r%*s\r", 70, "");
    stepper.finish();
}

Real fitSlope(const std::vector<Real>& x, const std::vector<Real>& y)
{
    const std::size_t n = x.size();
    Real mx = 0, my = 0;
    for (std::size_t i = 0; i < n; ++i)
    {
        mx += x[i];
        my += y[i];
    }
    mx /= Real(n);
    my /= Real(n);
    Real sxy = 0, sxx = 0;
    for (std::size_t i = 0; i < n; ++i)
    {
        sxy += (x[i] - mx) * (y[i] - my);
        sxx += (x[i] - mx) * (x[i] - mx);
    }
    return sxy / sxx;
}

std::array<Real, 3> fitCircle(const std::vector<Real>& x, const std::vector<Real>& y)
{
    // Kasa fit about the centroid: minimise sum (u^2 + v^2 - 2 a u - 2 b v - c)^2.
    const std::size_t n = x.size();
    Real mx = 0, my = 0;
    for (std::size_t i = 0; i < n; ++i)
    {
        mx += x[i];
        my += y[i];
    }
    mx /= Real(n);
    my /= Real(n);
    Real suu = 0, svv = 0, suv = 0, suuu = 0, svvv = 0, suvv = 0, svuu = 0;
    for (std::size_t i = 0; i < n; ++i)
    {
        const Real u = x[i] - mx, v = y[i] - my;
        suu += u * u;
        svv += v * v;
        suv += u * v;
        suuu += u * u * u;
        svvv += v * v * v;
        suvv += u * v * v;
        svuu += v * u * u;
    }
    const Real r1 = 0.5 * (suuu + suvv), r2 = 0.5 * (svvv + svuu);
    const Real det = suu * svv - suv * suv;
    const Real a = (r1 * svv - r2 * suv) / det, b = (suu * r2 - suv * r1) / det;
    const Real radius = std::sqrt(a * a + b * b + (suu + svv) / Real(n));
    return {a + mx, b + my, radius};
}

} // namespace veridem::verify
