#include "sweep.h"

#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

namespace veridem::verify
{

namespace
{
std::vector<std::pair<std::string, DtSweep>>& sweeps()
{
    static std::vector<std::pair<std::string, DtSweep>> declared;
    return declared;
}

const SweepOrder* orderFor(const DtSweep& sweep, const std::string& quantity)
{
    for (const SweepOrder& o : sweep.orders)
        if (quantity.compare(0, o.prefix.size(), o.prefix) == 0)
            return &o;
    return nullptr;
}
} // namespace

SweepRegistrar::SweepRegistrar(std::string caseName, DtSweep sweep)
{
    sweeps().emplace_back(std::move(caseName), std::move(sweep));
}

const DtSweep* sweepOf(const std::string& caseName)
{
    for (const auto& [name, sweep] : sweeps())
        if (name == caseName)
            return &sweep;
    return nullptr;
}

CaseResult runWithSweep(const Case& c, const CaseContext& context)
{
    CaseResult result = c.run(context);
    const DtSweep* sweep = sweepOf(c.name);
    if (!sweep)
        return result;
    CaseContext half = context, quarter = context;
    half.dtScale = context.dtScale / 2;
    quarter.dtScale = context.dtScale / 4;
    const CaseResult r2 = c.run(half), r4 = c.run(quarter);
    Series levels{"dt_sweep", {"quantity", "dt_scale", "difference", "difference_expected_slope"}, {}};
    std::vector<Quantity> orders;
    int index = 0;
    for (std::size_t i = 0; i < result.quantities.size(); ++i)
    {
        const Quantity& q = result.quantities[i];
        if (i >= r2.quantities.size() || i >= r4.quantities.size() || r2.quantities[i].name != q.name ||
            r4.quantities[i].name != q.name)
            continue;
        const double q1 = q.measured, q2 = r2.quantities[i].measured, q4 = r4.quantities[i].measured;
        const double d1 = std::fabs(q1 - q2), d2 = std::fabs(q2 - q4);
        const double size = std::fmax(std::fmax(std::fabs(q1), std::fabs(q.expected)), 1e-300);
        const SweepOrder* expected = orderFor(*sweep, q.name);
        char text[400];
        // Rounding level: the round-off accumulated over up to 1e7 steps (N eps ~ 1e-9 of the
        // quantity), a dimensionless quantity's 1e-12, or a millionth of an absolute tolerance.
        const double floor = std::fmax(std::fmax(1e-9 * size, q.unit.empty() ? 1e-12 : 0.0),
                                       q.relative ? 0.0 : 1e-6 * q.tolerance);
        if (!std::isfinite(d1) || !std::isfinite(d2) || d1 <= floor || d2 <= floor)
        {
            std::snprintf(
                text, sizeof text,
                "dt sweep, %s: q(dt) - q(dt/2) = %.2g, q(dt/2) - q(dt/4) = %.2g: below the rounding "
                "floor %.2g (round-off of up to 1e7 steps), no order observable",
                q.name.c_str(), q1 - q2, q2 - q4, floor);
            result.notes.push_back(text);
            continue;
        }
        const double p = std::log2(d1 / d2);
        levels.rows.push_back({double(index), context.dtScale, d1, expected ? d1 : std::nan("")});
        levels.rows.push_back({double(index), half.dtScale, d2,
                               expected ? d1 / std::pow(2.0, expected->expected) : std::nan("")});
        std::snprintf(text, sizeof text, "dt sweep %d, %s: differences %.3g, %.3g: order %.2f%s", index,
                      q.name.c_str(), d1, d2, p,
                      expected ? "" : " (not checked: no expected order declared)");
        result.notes.push_back(text);
        if (expected)
        {
            char name[300];
            std::snprintf(name, sizeof name, "dt order >= %.2f - margin: %s", expected->expected,
                          q.name.c_str());
            Quantity order = absoluteQuantity(name, "", expected->expected, p, sweep->margin,
                                              expected->why + "; lower bound, margin 0.3 (sweep.h)");
            order.tolerance = sweep->margin;
            order.atLeast = true;
            orders.push_back(order);
        }
        ++index;
    }
    result.quantities.insert(result.quantities.end(), orders.begin(), orders.end());
    result.series.push_back(std::move(levels));
    return result;
}

} // namespace veridem::verify
