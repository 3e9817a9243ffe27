#include "dem/walls/motion_table.h"

#include <algorithm>
#include <utility>

namespace veridem::dem
{

MotionTable::MotionTable(std::vector<Real> time, std::vector<Vec3> value)
    : time_(std::move(time)), value_(std::move(value))
{
    cumulative_.assign(time_.size(), Vec3{});
    for (std::size_t k = 1; k < time_.size(); ++k)
        cumulative_[k] = cumulative_[k - 1] + (0.5 * (time_[k] - time_[k - 1])) * (value_[k - 1] + value_[k]);
}

Vec3 MotionTable::at(Real t) const
{
    if (time_.empty())
        return {};
    if (!(t > time_.front()))
        return value_.front();
    if (t >= time_.back())
        return value_.back();
    // The piece [time_[k], time_[k+1]) that contains t.
    const std::size_t k =
        static_cast<std::size_t>(std::upper_bound(time_.begin(), time_.end(), t) - time_.begin()) - 1;
    const Real u = (t - time_[k]) / (time_[k + 1] - time_[k]);
    return value_[k] + u * (value_[k + 1] - value_[k]);
}

Vec3 MotionTable::integralFromStart(Real t) const
{
    if (!(t > time_.front()))
        return (t - time_.front()) * value_.front();
    if (t >= time_.back())
        return cumulative_.back() + (t - time_.back()) * value_.back();
    const std::size_t k =
        static_cast<std::size_t>(std::upper_bound(time_.begin(), time_.end(), t) - time_.begin()) - 1;
    // The trapezoid from time_[k] to t: its mean value times its width.
    return cumulative_[k] + (0.5 * (t - time_[k])) * (value_[k] + at(t));
}

Vec3 MotionTable::integralFromZero(Real t) const
{
    if (time_.empty())
        return {};
    return integralFromStart(t) - integralFromStart(0);
}

} // namespace veridem::dem
