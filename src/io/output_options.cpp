#include "io/output_options.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string>

namespace veridem::io
{

std::string_view particleFieldName(ParticleField field)
{
    switch (field)
    {
    case ParticleField::Velocity:
        return "velocity";
    case ParticleField::AngularVelocity:
        return "angular_velocity";
    case ParticleField::Radius:
        return "radius";
    case ParticleField::Mass:
        return "mass";
    case ParticleField::Material:
        return "material";
    case ParticleField::Force:
        return "force";
    case ParticleField::Torque:
        return "torque";
    case ParticleField::Coordination:
        return "coordination";
    }
    return "unknown";
}

std::vector<ParticleField> allParticleFields()
{
    return {ParticleField::Velocity, ParticleField::AngularVelocity, ParticleField::Radius,
            ParticleField::Mass,     ParticleField::Material,        ParticleField::Force,
            ParticleField::Torque,   ParticleField::Coordination};
}

bool OutputOptions::has(ParticleField field) const
{
    return std::find(particleFields.begin(), particleFields.end(), field) != particleFields.end();
}

namespace
{
/// The decimal digits of a * b (a and b strings of decimal digits), schoolbook multiplication.
std::string multiplyDigits(const std::string& a, const std::string& b)
{
    std::vector<unsigned> product(a.size() + b.size(), 0);
    for (std::size_t i = a.size(); i-- > 0;)
        for (std::size_t j = b.size(); j-- > 0;)
        {
            const unsigned sum = product[i + j + 1] + unsigned(a[i] - '0') * unsigned(b[j] - '0');
            product[i + j + 1] = sum % 10;
            product[i + j] += sum / 10;
        }
    std::string digits;
    for (const unsigned d : product)
        if (!(digits.empty() && d == 0))
            digits += char('0' + d);
    return digits.empty() ? "0" : digits;
}
} // namespace

double outputTime(std::uint64_t steps, double dt)
{
    if (steps == 0 || !(dt > 0) || !std::isfinite(dt))
        return double(steps) * dt;
    // dt's shortest round-trip form in scientific notation: "d.ddde-XX" = digits * 10^(exponent).
    char text[64];
    const auto written = std::to_chars(text, text + sizeof text, dt, std::chars_format::scientific);
    const std::string form(text, written.ptr);
    const std::size_t e = form.find('e');
    std::string digits;
    for (std::size_t k = 0; k < e; ++k)
        if (form[k] != '.')
            digits += form[k];
    const int fraction = int(digits.size()) - 1; // digits after the point
    const int exponent = std::atoi(form.c_str() + e + 1) - fraction;
    const std::string product =
        multiplyDigits(digits, std::to_string(steps)) + "e" + std::to_string(exponent);
    double time = 0;
    std::from_chars(product.data(), product.data() + product.size(), time); // nearest double
    return time;
}

} // namespace veridem::io
