#include "fdem/contact/friction.h"

#include <gtest/gtest.h>

namespace veridem::fdem
{
namespace
{

TEST(Friction, SticksBelowTheCap)
{
    const auto r = coulombFriction(0, 1e-3, 1e-6, 1e9, 0, 10); // xi = 1e-9 m, F* = -1 N/m
    EXPECT_FALSE(r.sliding);
    EXPECT_DOUBLE_EQ(r.spring, 1e-9);
    EXPECT_DOUBLE_EQ(r.force, -1);
}

TEST(Friction, CapsAndResetsTheSpringOnSlip)
{
    const Real k = 1e9, eta = 50, cap = 10, v = 2, dt = 1e-6;
    const auto r = coulombFriction(0, v, dt, k, eta, cap); // F* = -2000 - 100
    EXPECT_TRUE(r.sliding);
    EXPECT_DOUBLE_EQ(r.force, -cap);
    // the spring is reset so that -k xi - eta v equals the capped force (dashpot inside the cap)
    EXPECT_NEAR(-k * r.spring - eta * v, r.force, 1e-9);
    // sliding on: the force stays exactly at the cap, never mu F_n + eta v
    const auto s = coulombFriction(r.spring, v, dt, k, eta, cap);
    EXPECT_TRUE(s.sliding);
    EXPECT_DOUBLE_EQ(s.force, -cap);
}

TEST(Friction, ReversalUnloadsElasticallyFromTheCap)
{
    const Real k = 1e9, cap = 10, dt = 1e-6;
    auto r = coulombFriction(0, 1, dt, k, 0, cap); // slide forward: spring at cap/k
    ASSERT_TRUE(r.sliding);
    EXPECT_NEAR(r.spring, cap / k, 1e-18);
    r = coulombFriction(r.spring, -1e-3, dt, k, 0, cap); // reverse slowly: elastic unloading
    EXPECT_FALSE(r.sliding);
    EXPECT_NEAR(r.force, -(cap - k * 1e-9), 1e-9);
}

TEST(Friction, CapIsSymmetric)
{
    const auto r = coulombFriction(0, -3, 1e-6, 1e9, 0, 7);
    EXPECT_TRUE(r.sliding);
    EXPECT_DOUBLE_EQ(r.force, 7);
}

} // namespace
} // namespace veridem::fdem
