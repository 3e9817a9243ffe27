#include "fdem/elements/cst.h"

#include <gtest/gtest.h>

#include <cmath>

namespace veridem::fdem
{
namespace
{

const std::array<Vec2, 3> kReference{Vec2{0, 0}, Vec2{0.02, 0}, Vec2{0.005, 0.015}};

Material material(StressLaw law, PlaneModel plane)
{
    return {2650, 1e9, 0.25, 0, law, plane};
}

std::array<Vec2, 3> mapped(const Mat2& F, Vec2 shift)
{
    std::array<Vec2, 3> x;
    for (int i = 0; i < 3; ++i)
        x[i] = F * kReference[i] + shift;
    return x;
}

TEST(Cst, RigidRotationAndTranslationGiveZeroStressAndForce)
{
    for (StressLaw law : {StressLaw::FiniteStrain, StressLaw::Linear})
        for (Real angle : {0.3, 1.7, 3.0, -2.2})
        {
            const Mat2 R{std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle)};
            const auto x = mapped(R, {0.7, -1.3});
            const std::array<Vec2, 3> v{}; // at rest
            const auto r = cstInternalForces(x, v, referenceInverse(kReference),
                                             elasticConstants(material(law, PlaneModel::Strain)));
            EXPECT_NEAR(r.jacobian, 1, 1e-14);
            // round-off: stress scale E * 1e-15
            EXPECT_NEAR(r.stress.xx, 0, 1e-5);
            EXPECT_NEAR(r.stress.yy, 0, 1e-5);
            EXPECT_NEAR(r.stress.xy, 0, 1e-5);
            for (const auto& f : r.force)
                EXPECT_LT(length(f), 1e-7);
        }
}

TEST(Cst, RigidSpinHasNoViscousStress)
{
    // v = omega x r: the rate of deformation D is zero, so the viscous stress vanishes.
    Material m = material(StressLaw::FiniteStrain, PlaneModel::Strain);
    m.viscosity = 1e4;
    const Real omega = 5;
    std::array<Vec2, 3> v;
    for (int i = 0; i < 3; ++i)
        v[i] = omega * perpendicular(kReference[i]);
    const auto r = cstInternalForces(kReference, v, referenceInverse(kReference), elasticConstants(m));
    EXPECT_NEAR(r.stress.xx, 0, 1e-9);
    EXPECT_NEAR(r.stress.xy, 0, 1e-9);
}

TEST(Cst, SmallUniformStretchGivesHookesLaw)
{
    const Real exx = 1e-6, eyy = -3e-7, gxy = 4e-7; // engineering shear
    const Mat2 F{1 + exx, gxy, 0, 1 + eyy};         // symmetric part: eps_xy = gxy / 2
    for (PlaneModel plane : {PlaneModel::Strain, PlaneModel::Stress})
        for (StressLaw law : {StressLaw::FiniteStrain, StressLaw::Linear})
        {
            const Material m = material(law, plane);
            const Real E = m.youngsModulus, nu = m.poissonRatio;
            Real sxx, syy;
            if (plane == PlaneModel::Strain)
            {
                const Real c = E / ((1 + nu) * (1 - 2 * nu));
                sxx = c * ((1 - nu) * exx + nu * eyy);
                syy = c * (nu * exx + (1 - nu) * eyy);
            }
            else
            {
                const Real c = E / (1 - nu * nu);
                sxx = c * (exx + nu * eyy);
                syy = c * (nu * exx + eyy);
            }
            const Real sxy = E / (2 * (1 + nu)) * gxy;
            const auto r =
                cstInternalForces(mapped(F, {}), {}, referenceInverse(kReference), elasticConstants(m));
            // geometric non-linearity is O(strain^2) relative: 1e-6 * 1e3 Pa
            EXPECT_NEAR(r.stress.xx, sxx, 1e-2 * 1e-3 * std::abs(sxx) + 1e-3);
            EXPECT_NEAR(r.stress.yy, syy, 1e-2 * 1e-3 * std::abs(syy) + 1e-3);
            EXPECT_NEAR(r.stress.xy, sxy, 1e-3);
        }
}

TEST(Cst, FiniteStretchFollowsMunjizasLaw)
{
    const Real s = 1.2;
    const Mat2 F{s, 0, 0, 1};
    const Material m = material(StressLaw::FiniteStrain, PlaneModel::Strain);
    const ElasticConstants c = elasticConstants(m);
    const auto r = cstInternalForces(mapped(F, {}), {}, referenceInverse(kReference), c);
    const Real J = s;
    EXPECT_NEAR(r.stress.xx, c.shear / J * (s * s - 1) + 0.5 * c.lambda * (J - 1 / J), 1e-3);
    EXPECT_NEAR(r.stress.yy, 0.5 * c.lambda * (J - 1 / J), 1e-3);
}

TEST(Cst, ForcesBalanceAndTensionPullsNodesInward)
{
    const Mat2 F{1.001, 0, 0, 1};
    const auto x = mapped(F, {});
    const auto r = cstInternalForces(x, {}, referenceInverse(kReference),
                                     elasticConstants(material(StressLaw::Linear, PlaneModel::Stress)));
    Vec2 sum{};
    Real moment = 0;
    for (int i = 0; i < 3; ++i)
    {
        sum += r.force[i];
        moment += cross(x[i], r.force[i]);
    }
    EXPECT_LT(length(sum), 1e-9);
    EXPECT_NEAR(moment, 0, 1e-10);
    // node 1 is the right-most node: tension in x pulls it back (-x)
    EXPECT_LT(r.force[1].x, 0);
    EXPECT_GT(r.force[0].x, 0);
}

TEST(Cst, ForceEqualsMinusEnergyGradientForSmallStrain)
{
    // f_i = -dW/dx_i, checked by central differences of the linear law's energy.
    const Mat2 F{1 + 2e-4, 1e-4, -5e-5, 1 - 1e-4};
    const auto x = mapped(F, {});
    const ElasticConstants c = elasticConstants(material(StressLaw::Linear, PlaneModel::Strain));
    const Mat2 inv = referenceInverse(kReference);
    const Real A0 = signedArea(kReference[0], kReference[1], kReference[2]);
    const auto r = cstInternalForces(x, {}, inv, c);
    const Real h = 1e-9;
    for (int i = 0; i < 3; ++i)
    {
        auto xp = x, xm = x;
        xp[i].x += h;
        xm[i].x -= h;
        const Real gx = (cstStrainEnergy(xp, inv, A0, c) - cstStrainEnergy(xm, inv, A0, c)) / (2 * h);
        // strain 2e-4: the spatial (Cauchy) and reference measures differ by O(strain)
        EXPECT_NEAR(r.force[i].x, -gx, 2e-3 * std::abs(gx) + 1e-3);
    }
}

TEST(Cst, InvertedElementIsReported)
{
    const std::array<Vec2, 3> x{kReference[0], kReference[2], kReference[1]};
    const auto r = cstInternalForces(x, {}, referenceInverse(kReference),
                                     elasticConstants(material(StressLaw::FiniteStrain, PlaneModel::Strain)));
    EXPECT_LT(r.jacobian, 0);
}

} // namespace
} // namespace veridem::fdem
