// Materials and the pair-parameter table. Materials are mixed once, at set-up, into a table
// indexed by (material a, material b); the force loops only read that table.
//
// Mixing rules (each parameter's is declared in dem/model_params.h, ModelParam::mixing, and applied
// by mixMaterials; docs/models.md):
//   linear stiffness kn, kt: series springs, k = 2 k1 k2 / (k1 + k2)  (= k for equal materials)
//   Hertz: 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2,  1/G* = (2-nu1)/G1 + (2-nu2)/G2
//   restitution e, friction mu, rolling friction: arithmetic mean (a [[pair]] scene entry overrides)
//   work of adhesion: w = 2 sqrt(gamma1 gamma2) (= 2 gamma for like surfaces; the geometric-mean
//   combining rule of Girifalco & Good 1957, Israelachvili, Intermolecular and Surface Forces)
//   Thornton's limiting pressure: p_y = min(p_y1, p_y2) (the softer surface flows first)
#pragma once

#include "core/vec3.h"
#include "dem/models/thornton.h"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace veridem::dem
{

enum class NormalModel
{
    Linear,  // linear spring-dashpot
    Hertz,   // Hertz-Mindlin with restitution damping
    Jkr,     // Hertz-Mindlin elasticity with JKR adhesion (models/cohesion.h; needs surfaceEnergy)
    Dmt,     // Hertz-Mindlin elasticity with DMT adhesion (models/cohesion.h)
    Thornton // Hertz elasticity to a limiting contact pressure, then plastic (models/thornton.h)
};

/// A registered model: its enumerator, its scene name (`model`, `rolling_model`) and the number of
/// history scalars [-] a contact of the model carries from step to step (ContactHistory::scalars:
/// the model's own state, e.g. a largest overlap; scalars are invariant under swapping the
/// partners). The contact history stores keep that many doubles per contact, only in scenes that
/// use such a model (dem/contact_history.h); every store, rebuild, checkpoint and MPI exchange
/// carries them without naming the model.
template <class Model> struct ModelEntry
{
    Model model;
    const char* name;
    unsigned historyScalars = 0;
};
/// Every normal model, in the enumerators' order: the scene reader names, and the law dispatches
/// (withLawModel, forEachLawModel, dem/contact_law.h), exactly the models listed here.
inline constexpr ModelEntry<NormalModel> kNormalModelList[] = {
    {NormalModel::Linear, "linear"},
    {NormalModel::Hertz, "hertz"},
    {NormalModel::Jkr, "jkr"},
    {NormalModel::Dmt, "dmt"},
    {NormalModel::Thornton, "thornton", kThorntonHistoryScalars}};

/// True for the models whose contacts pull (JKR, DMT).
constexpr bool isAdhesive(NormalModel m)
{
    return m == NormalModel::Jkr || m == NormalModel::Dmt;
}
/// True for the models built on Hertz elasticity (they read E*, G* and R*).
constexpr bool isHertzian(NormalModel m)
{
    return m != NormalModel::Linear;
}

enum class RollingModel
{
    None,
    ConstantTorque,        // type A, the paper's eq. 3 (opposes w relative to the partner)
    Epsd,                  // type C, elastic-plastic spring-dashpot
    Viscous,               // type B, torque proportional to the relative rolling speed
    ConstantTorqueAbsolute // type A opposing the particle's own w (EDEM "standard", MUSEN)
};

/// Every rolling model, in the enumerators' order (as kNormalModelList).
inline constexpr ModelEntry<RollingModel> kRollingModelList[] = {
    {RollingModel::None, "none"},
    {RollingModel::ConstantTorque, "constant_torque"},
    {RollingModel::Epsd, "epsd"},
    {RollingModel::Viscous, "viscous"},
    {RollingModel::ConstantTorqueAbsolute, "constant_torque_absolute"}};

/// Whether each list holds its enumerators in order (entry k is enumerator k): the model index
/// (lawModelIndex) and the dispatch rely on it.
template <class Model, std::size_t kCount>
constexpr bool listedInOrder(const ModelEntry<Model> (&list)[kCount])
{
    for (std::size_t k = 0; k < kCount; ++k)
        if (static_cast<std::size_t>(list[k].model) != k)
            return false;
    return true;
}
static_assert(listedInOrder(kNormalModelList) && listedInOrder(kRollingModelList));

/// The history scalars [-] a contact of normal model m carries (its list entry's).
constexpr unsigned historyScalarsOf(NormalModel m)
{
    return kNormalModelList[static_cast<std::size_t>(m)].historyScalars;
}
/// The room for history scalars in ContactHistory: the most any listed model declares (at least
/// one, so that the array is never empty).
inline constexpr unsigned kHistoryScalarRoom = []
{
    unsigned most = 1;
    for (const auto& entry : kNormalModelList)
        most = entry.historyScalars > most ? entry.historyScalars : most;
    return most;
}();

/// A model value outside its list: never made by the scene reader, which names only listed models;
/// the law's dispatch stops the run with this message rather than run another model's law.
[[noreturn]] void unregisteredContactModel(unsigned value);

struct Material
{
    std::string name;
    Real density = 2500; // [kg/m^3]
    NormalModel normalModel = NormalModel::Linear;
    // Linear model
    Real normalStiffness = 1e5;                // kn [N/m]
    Real tangentialStiffnessRatio = 2.0 / 7.0; // kt/kn [-] (2/7: equal normal and tangential periods)
    // Hertz, JKR and DMT models
    Real youngsModulus = 0; // E [Pa]
    Real poissonRatio = 0;  // nu [-]
    Real surfaceEnergy = 0; // gamma [J/m^2] (JKR, DMT): work of adhesion w = 2 gamma for like surfaces
    Real yieldStress = 0;   // p_y [Pa] (Thornton): the limiting contact pressure of plastic flow
    // Damping
    Real restitution = 0.8; // e in (0, 1]
    Real normalDampingRate =
        -1; // gamma_n [1/s]: if >= 0, etaN = gamma_n m* (LAMMPS gran/hooke style) instead of e
    Real tangentialDampingRatio = -1; // etaT/etaN; < 0: sqrt((2/7) kt/kn), the same damping ratio
    // Friction
    Real friction = 0.5; // Coulomb mu [-]
    RollingModel rollingModel = RollingModel::None;
    Real rollingFrictionLength = 0;        // muR as a length [m] (the paper's convention)
    Real rollingFrictionDimensionless = 0; // muR' [-]; contact value muR = muR' * R_r
    Real rollingDampingRatio = 0.3;        // EPSD etaR [-]
    Real rollingViscousCoefficient = 0;    // type B c_r [s/m]: M = -c_r Fn R_r^2 w_rel
    // Which relative rotation the rolling torque opposes. true (default): all of
    // w_rel = w_i - w_partner, twist about the contact normal included. A ball moving over a curved
    // moving wall acquires spin about the normal from the geometry alone; if nothing resists that
    // spin it keeps growing and its gyroscopic coupling holds the ball at a wrong equilibrium
    // (BENCHMARKS 1c: a dish ball locks far below the stable height). false: only the part of w_rel
    // perpendicular to the normal (pure rolling) is resisted; kept for the regression case
    // dish_twist_regression that shows that failure. Pairs mix with AND (false wins).
    bool rollingTwist = true;
};

/// Parameters of one material pair, ready for the force loop.
struct PairParams
{
    NormalModel normalModel = NormalModel::Linear;
    Real kn = 0;                     // [N/m] (linear)
    Real ktRatio = 0;                // kt/kn [-] (linear and Hertz: kt = ratio * kn for linear)
    Real effectiveModulus = 0;       // E* [Pa] (Hertz)
    Real effectiveShearModulus = 0;  // G* [Pa] (Hertz-Mindlin kt = 8 G* sqrt(R* delta))
    Real workOfAdhesion = 0;         // w [J/m^2] (JKR, DMT): 2 sqrt(gamma_a gamma_b)
    Real yieldPressure = 0;          // p_y [Pa] (Thornton): the smaller of the two materials'
    Real dampingRatio = 0;           // zeta from e (linear) [-]
    Real hertzBeta = 0;              // beta from e (Hertz, JKR, DMT: hertzBetaFromRestitution) [-]
    Real dampingRate = -1;           // gamma_n [1/s] if >= 0
    Real tangentialDampingRatio = 0; // etaT / etaN [-]
    Real mu = 0;                     // [-]
    RollingModel rollingModel = RollingModel::None;
    Real rollingLength = 0;        // [m]
    Real rollingDimensionless = 0; // [-]
    Real rollingDampingRatio = 0;  // [-]
    Real rollingViscous = 0;       // type B c_r [s/m]
    bool rollingTwist = true;      // rolling torque also opposes twist about the normal
};

/// The Hertz-family damping factor beta [-] that gives restitution e (0 < e <= 1) with `model`.
Real hertzBetaFromRestitution(NormalModel model, Real e);

/// Mixes two materials into pair parameters (see the rules above).
PairParams mixMaterials(const Material& a, const Material& b);

/// Checks physical ranges; throws InputError naming the material and the value.
void validateMaterial(const Material& m);

class PairTable
{
  public:
    void build(const std::vector<Material>& materials);
    const PairParams& operator()(std::uint32_t a, std::uint32_t b) const { return table_[a * count_ + b]; }
    /// Replaces the parameters of the ordered pair (a, b).
    void set(std::uint32_t a, std::uint32_t b, const PairParams& params);
    std::uint32_t count() const { return count_; }
    /// The history scalars per contact of the table's pairs: the most any pair's model declares
    /// (0 if none declares any: the stores then keep none).
    unsigned historyScalars() const;

  private:
    std::uint32_t count_ = 0;
    std::vector<PairParams> table_;
};

} // namespace veridem::dem
