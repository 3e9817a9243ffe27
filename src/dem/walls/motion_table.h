// A prescribed wall motion given as a piecewise-linear table in time: a velocity [m/s] or an
// angular velocity [rad/s] (a vector) at increasing times [s], linear between points and held
// constant outside them. Its integral (the displacement from t = 0) is exact: the integral of a
// piecewise-linear function is the sum of its trapezoids, kept at the table points, plus the
// exact integral of the linear piece that contains t.
#pragma once

#include "core/vec3.h"

#include <vector>

namespace veridem::dem
{

class MotionTable
{
  public:
    MotionTable() = default;
    /// `time` strictly increasing [s], one `value` per time (checked by the scene reader).
    MotionTable(std::vector<Real> time, std::vector<Vec3> value);

    bool empty() const { return time_.empty(); }
    /// The value at time t [s] (linear between points, constant outside).
    Vec3 at(Real t) const;
    /// The integral of the value from 0 to t [s] (value [1/s] -> value x s).
    Vec3 integralFromZero(Real t) const;

    const std::vector<Real>& times() const { return time_; }
    const std::vector<Vec3>& values() const { return value_; }

  private:
    /// The integral from time_[0] to t (negative before it).
    Vec3 integralFromStart(Real t) const;

    std::vector<Real> time_;
    std::vector<Vec3> value_;
    std::vector<Vec3> cumulative_; // integral from time_[0] to time_[k]
};

} // namespace veridem::dem
