// The engine's Thornton law (contactLaw through evaluateContact, dem/contact_law.h, with the pair
// parameters mixMaterials makes) is thorntonForce with the largest overlap kept in the contact's
// history scalar; the material checks and the mixing rule of the yield stress.
#include "core/error.h"
#include "dem/contact_law.h"
#include "dem/materials.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace veridem;
using namespace veridem::dem;

namespace
{
Material plastic(Real yieldStress)
{
    Material m;
    m.name = "plastic";
    m.normalModel = NormalModel::Thornton;
    m.youngsModulus = 1e9;
    m.poissonRatio = 0.3;
    m.yieldStress = yieldStress;
    return m;
}
} // namespace

TEST(ThorntonLaw, EngineLawIsThorntonForceWithTheLargestOverlapAsHistory)
{
    const PairParams p = mixMaterials(plastic(1e7), plastic(2e7));
    EXPECT_EQ(p.yieldPressure, 1e7); // the smaller of the two
    EXPECT_EQ(historyScalarsOf(NormalModel::Thornton), kThorntonHistoryScalars);
    ContactInput in;
    in.normal = {0, 0, 1};
    in.effectiveMass = 1e-3;
    in.effectiveRadius = 5e-3;
    ContactHistory h;
    Real largest = 0;
    // Load past yield, unload part way, reload: the force is thorntonForce at each overlap with the
    // largest overlap so far, and the history holds that largest overlap. No dashpot: the force is
    // the elastic force exactly, whatever the normal speed.
    for (const Real overlap : {1e-6, 5e-5, 2e-4, 1.5e-4, 1.6e-4, 2.5e-4, 1e-4})
    {
        in.overlap = overlap;
        in.relativeVelocity = {0, 0, -0.3};
        largest = std::fmax(largest, overlap);
        const ContactOutput out = evaluateContact(p, in, h, 1e-7);
        EXPECT_EQ(out.normalForce,
                  thorntonForce(p.effectiveModulus, in.effectiveRadius, p.yieldPressure, overlap, largest));
        EXPECT_EQ(h.scalars[0], largest);
    }
}

TEST(ThorntonLaw, YieldStressIsCheckedAndBelongsToThorntonOnly)
{
    EXPECT_NO_THROW(validateMaterial(plastic(1e7)));
    EXPECT_THROW(validateMaterial(plastic(0)), InputError);
    EXPECT_THROW(validateMaterial(plastic(-1)), InputError);
    // The limit E / (pi (1 - nu^2)): a like pair's yield contact radius reaches R* there.
    const Real limit = thorntonYieldStressLimit(1e9, 0.3);
    EXPECT_NEAR(limit, 1e9 / (kPi * 0.91), 1e-6 * limit);
    EXPECT_THROW(validateMaterial(plastic(limit)), InputError);
    EXPECT_NO_THROW(validateMaterial(plastic(0.99 * limit)));
    Material hertz = plastic(1e7);
    hertz.normalModel = NormalModel::Hertz;
    EXPECT_THROW(validateMaterial(hertz), InputError);
}
