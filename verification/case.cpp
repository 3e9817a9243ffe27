#include "case.h"

#include <algorithm>
#include <cmath>

namespace veridem::verify
{

double Quantity::error() const
{
    if (atLeast)
        return std::fmax(expected - measured, 0.0);
    const double diff = std::abs(measured - expected);
    if (!relative)
        return diff;
    return expected != 0 ? diff / std::abs(expected) : diff;
}

bool Quantity::passed() const
{
    return std::isfinite(measured) && error() <= tolerance;
}

bool CaseResult::passed() const
{
    return !quantities.empty() &&
           std::all_of(quantities.begin(), quantities.end(), [](const Quantity& q) { return q.passed(); });
}

std::vector<Case>& registry()
{
    static std::vector<Case> cases;
    return cases;
}

Registrar::Registrar(Case c)
{
    auto& cases = registry();
    auto at = std::lower_bound(cases.begin(), cases.end(), c.name,
                               [](const Case& a, const std::string& n) { return a.name < n; });
    cases.insert(at, std::move(c));
}

Quantity relativeQuantity(std::string name, std::string unit, double expected, double measured,
                          double tolerance, std::string why)
{
    return {std::move(name), std::move(unit), expected, measured, tolerance, true, std::move(why)};
}

Quantity absoluteQuantity(std::string name, std::string unit, double expected, double measured,
                          double tolerance, std::string why)
{
    return {std::move(name), std::move(unit), expected, measured, tolerance, false, std::move(why)};
}

} // namespace veridem::verify
