#include "case.h"

#include "exec/task_sharing.h"

#include <algorithm>
#include <cmath>
#include <exception>

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

void CaseContext::forEach(std::size_t count, const std::function<void(std::size_t)>& task) const
{
    if (tasks)
    {
        tasks->forEach(count, task);
        return;
    }
    std::exception_ptr first;
    for (std::size_t i = 0; i < count; ++i)
        try
        {
            task(i);
        }
        catch (...)
        {
            if (!first)
                first = std::current_exception();
        }
    if (first)
        std::rethrow_exception(first);
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
