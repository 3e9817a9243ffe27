#include "fdem/contact/potential.h"

#include <gtest/gtest.h>

namespace veridem::fdem
{
namespace
{

TEST(PotentialContact, ZeroWithoutOverlap)
{
    const std::array<Vec2, 3> a{Vec2{0, 0}, Vec2{1, 0}, Vec2{0, 1}};
    const std::array<Vec2, 3> b{Vec2{1.01, 0}, Vec2{2, 0}, Vec2{1.01, 1}};
    const auto f = potentialContactForces(a, b, 1e9);
    for (int i = 0; i < 3; ++i)
    {
        EXPECT_EQ(length(f.onFirst[i]), 0);
        EXPECT_EQ(length(f.onSecond[i]), 0);
    }
    // touching along an edge (no area overlap): still zero
    const std::array<Vec2, 3> c{Vec2{0, 0}, Vec2{0, -1}, Vec2{1, 0}};
    const auto g = potentialContactForces(a, c, 1e9);
    for (int i = 0; i < 3; ++i)
        EXPECT_NEAR(length(g.onFirst[i]), 0, 1e-6);
}

TEST(PotentialContact, FlatPenetrationMatchesTheIntegral)
{
    // Contactor edge y = d, x in [-1, 1] inside a wide target whose base is y = 0 and altitude 10:
    // phi_t = 3 d / 10 along the whole edge, so F = p * 2 * 3 d / 10 upwards on the contactor.
    const Real d = 1e-3;
    const std::array<Vec2, 3> target{Vec2{-10, 0}, Vec2{10, 0}, Vec2{0, 10}};
    const std::array<Vec2, 3> contactor{Vec2{1, d}, Vec2{-1, d},
                                        Vec2{0, 1}}; // edge 0: (1,d)->(-1,d), normal -y
    const EdgePenetration pen = edgeInTriangle(contactor[0], contactor[1], target);
    EXPECT_NEAR(pen.integral, 3 * d / 10, 1e-12);
    EXPECT_NEAR(pen.centre(), 0.5, 1e-12);
    EXPECT_NEAR(pen.insideFraction, 1, 1e-12);
    Real sum = 0;
    for (Real w : pen.targetWeight)
        sum += w;
    EXPECT_NEAR(sum, 1, 1e-12);
}

TEST(PotentialContact, PiecewiseLinearPotentialIsIntegratedExactly)
{
    // An edge crossing the whole unit right triangle along y = 0.25: there lambda_1 = x, lambda_2 = 0.25,
    // lambda_0 = 0.75 - x, x in [0, 0.75]; phi = 3 min(...) is a trapezoid, integral over x is
    // 3 * (0.25 * 0.75 - 2 * 0.5 * 0.25^2) = 0.375; the edge runs x in [-1, 2] (length 3).
    const std::array<Vec2, 3> target{Vec2{0, 0}, Vec2{1, 0}, Vec2{0, 1}};
    const EdgePenetration pen = edgeInTriangle({-1, 0.25}, {2, 0.25}, target);
    EXPECT_NEAR(pen.integral * 3, 0.375, 1e-12);
    EXPECT_NEAR(pen.insideFraction * 3, 0.75, 1e-12);
    EXPECT_NEAR(-1 + 3 * pen.centre(), 0.375, 1e-12); // symmetric trapezoid centred at x = 0.375
}

TEST(PotentialContact, ForcesAreEqualAndOppositeWithZeroMoment)
{
    const std::array<Vec2, 3> a{Vec2{0, 0}, Vec2{1, 0.1}, Vec2{0.3, 1}};
    const std::array<Vec2, 3> b{Vec2{0.5, 0.4}, Vec2{1.4, 0.9}, Vec2{0.2, 1.5}};
    const auto f = potentialContactForces(a, b, 1e9);
    Vec2 sum{};
    Real moment = 0, scale = 0;
    for (int i = 0; i < 3; ++i)
    {
        sum += f.onFirst[i] + f.onSecond[i];
        moment += cross(a[i], f.onFirst[i]) + cross(b[i], f.onSecond[i]);
        scale += length(f.onFirst[i]);
    }
    EXPECT_GT(scale, 1e6);
    EXPECT_LT(length(sum), 1e-9 * scale);
    EXPECT_LT(std::abs(moment), 1e-9 * scale);
    // swapping the roles swaps the forces
    const auto g = potentialContactForces(b, a, 1e9);
    for (int i = 0; i < 3; ++i)
    {
        EXPECT_LT(length(g.onFirst[i] - f.onSecond[i]), 1e-9 * scale);
        EXPECT_LT(length(g.onSecond[i] - f.onFirst[i]), 1e-9 * scale);
    }
    // the net force pushes the triangles apart: b lies up and to the right of a
    Vec2 onB{};
    for (const auto& x : f.onSecond)
        onB += x;
    EXPECT_GT(dot(onB, Vec2{0.5, 0.6}), 0);
}

TEST(PotentialContact, ForceIsConservativeAroundAClosedPath)
{
    // Work of the contact force on a rigidly translated triangle around a closed loop is ~0.
    const std::array<Vec2, 3> a{Vec2{0, 0}, Vec2{1, 0}, Vec2{0.4, 1}};
    const std::array<Vec2, 3> b0{Vec2{0.3, 0.2}, Vec2{1.3, 0.5}, Vec2{0.6, 1.3}};
    const int n = 4000;
    Real work = 0, scale = 0;
    const auto force = [&](Vec2 shift)
    {
        std::array<Vec2, 3> b = b0;
        for (auto& p : b)
            p += shift;
        const auto f = potentialContactForces(a, b, 1.0);
        return f.onSecond[0] + f.onSecond[1] + f.onSecond[2];
    };
    for (int i = 0; i < n; ++i) // circle of radius 0.05 (midpoint rule)
    {
        const Real t0 = 2 * 3.141592653589793 * i / n, t1 = 2 * 3.141592653589793 * (i + 1) / n;
        const Vec2 p0{0.05 * std::cos(t0), 0.05 * std::sin(t0)}, p1{0.05 * std::cos(t1), 0.05 * std::sin(t1)};
        const Vec2 f = force(0.5 * (p0 + p1));
        work += dot(f, p1 - p0);
        scale += std::abs(dot(f, p1 - p0));
    }
    EXPECT_LT(std::abs(work), 1e-4 * scale);
}

} // namespace
} // namespace veridem::fdem
