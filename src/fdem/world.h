// The 2D FEM/DEM world: deformable triangulated bodies (constant-strain triangles), potential
// contact with Coulomb friction, explicit central-difference time integration. SI units, per unit
// thickness (masses kg/m, forces N/m, energies J/m).
#pragma once

#include "fdem/contact_list.h"
#include "fdem/fracture/joints.h"
#include "fdem/material.h"
#include "fdem/mesh.h"

#include <string>
#include <utility>
#include <vector>

namespace veridem::fdem
{

/// Contact parameters, shared by all body pairs (BENCHMARKS 1a: p_n = 10 E, p_t = p_n).
struct ContactParameters
{
    Real normalPenalty = 0;          ///< p_n of the potential contact [Pa]
    Real tangentialPenalty = 0;      ///< p_t: k_t = 3 p_t L_in / H_t per edge contact [Pa]
    Real friction = 0;               ///< Coulomb coefficient mu [1]
    Real normalDampingRatio = 0;     ///< zeta_n of the normal dashpot [1] (see world.cpp)
    Real tangentialDampingRatio = 0; ///< zeta_t of the tangential dashpot eta_t [1]
};

struct WorldSettings
{
    Real timeStep = 1e-6;        ///< dt [s]
    Vec2 gravity{0, -9.81};      ///< g [m/s^2]
    ContactParameters contact{}; ///< contact law parameters
    Real buffer = 0; ///< Verlet skin of the broad phase [m]; 0 = half the smallest element altitude
};

/// One body: a triangulation with one material.
struct BodyDefinition
{
    std::string name;
    TriangleMesh mesh;           ///< validated (counter-clockwise) triangulation [m]
    std::uint32_t material = 0;  ///< index returned by World::addMaterial
    Vec2 velocity{};             ///< initial velocity of every node [m/s]
    bool fixed = false;          ///< every node prescribed to move with `velocity`
    bool cracks = false;         ///< joints on the interior edges (all, or those in the region below)
    bool crackRegion = false;    ///< only the edges whose midpoint lies in [crackMin, crackMax]
    Vec2 crackMin{}, crackMax{}; ///< region corners [m]
};

/// Fracture summary [count, J/m].
struct FractureState
{
    std::size_t joints = 0;  ///< joint elements inserted
    std::size_t broken = 0;  ///< of which broken
    Real energyReleased = 0; ///< work done on the broken joints up to their breaking [J/m]
    Real jointWork = 0;      ///< work done on all joints since t = 0 [J/m]
};

/// Mass-weighted body summary.
struct BodyState
{
    Real mass = 0;   ///< [kg/m]
    Vec2 centroid{}; ///< [m]
    Vec2 velocity{}; ///< [m/s] (half-step velocities)
};

/// Energies per unit thickness [J/m].
struct Energies
{
    Real kinetic = 0;           ///< sum m v^2 / 2 of free nodes (half-step velocities)
    Real strain = 0;            ///< small-strain elastic energy of the elements
    Real gravity = 0;           ///< -sum m g . x of free nodes
    Real frictionWork = 0;      ///< work dissipated by the tangential contact forces since t = 0
    Real normalDampingWork = 0; ///< work dissipated by the normal contact dashpots since t = 0
};

/// Wall time spent in each phase of World::step() since the world was made [s] (fdem_bench's
/// breakdown; steady clock, two readings per phase and step).
struct StepTimes
{
    double elements = 0;    ///< CST forces of the active triangles, into their slots
    double joints = 0;      ///< joint states and end forces, into their slots
    double nodeForces = 0;  ///< weight + element + joint slots summed per node
    double detection = 0;   ///< re-detection test and, when due, the broad phase
    double contacts = 0;    ///< potential contact and friction per couple, then their scatter
    double integration = 0; ///< central-difference update of the active nodes
};

/// Step diagnostics of the friction law (sums over edge contacts of the last step) [N/m].
struct FrictionDiagnostics
{
    Real tangentialForce = 0; ///< sum |F_t|
    Real cap = 0;             ///< sum mu |F_n|
    Real normalForce = 0;     ///< sum |F_n| (elastic)
    std::size_t contacts = 0; ///< touching edge contacts
    std::size_t sliding = 0;  ///< of which at the cap
};

class World
{
  public:
    explicit World(const WorldSettings& settings);

    /// Adds a material; throws InputError for non-physical values. Returns its index.
    std::uint32_t addMaterial(const Material& material, const std::string& name = "material");
    /// Adds a body (lumped masses rho A0 / 3 per node). Returns its id.
    std::uint32_t addBody(const BodyDefinition& body);
    /// Prescribes the velocity [m/s] of the nodes of `body` inside the box [lo, hi] [m]; returns their count.
    std::size_t prescribeNodes(std::uint32_t body, Vec2 lo, Vec2 hi, Vec2 velocity);
    /// Prescribes the velocity [m/s] of one node (the copies of a split node share a position, so a
    /// box cannot tell them apart).
    void prescribeNode(std::uint32_t node, Vec2 velocity);
    /// Sets the velocity of every free node of `body` [m/s].
    void setBodyVelocity(std::uint32_t body, Vec2 velocity);
    /// Replaces the contact parameters (same checks as the constructor); history is kept.
    void setContactParameters(const ContactParameters& contact);
    /// Sets the velocity of one free node [m/s] (ignored for prescribed nodes).
    void setNodeVelocity(std::uint32_t node, Vec2 velocity);

    /// One explicit step: element forces -> detection -> contact forces -> integration.
    void step();

    Real time() const { return time_; }
    Real timeStep() const { return settings_.timeStep; }
    std::uint64_t stepCount() const { return steps_; }
    const WorldSettings& settings() const { return settings_; }
    const NodeStore& nodes() const { return nodes_; }
    const TriangleStore& triangles() const { return triangles_; }
    const std::vector<Material>& materials() const { return materials_; }
    std::size_t bodyCount() const { return bodyNames_.size(); }
    const std::string& bodyName(std::uint32_t body) const { return bodyNames_[body]; }
    bool bodyIsFixed(std::uint32_t body) const { return bodyFixed_[body] != 0; }
    BodyState bodyState(std::uint32_t body) const;
    /// Sum of the last step's forces on the prescribed nodes of `body` [N/m]: weight, elements,
    /// joints and contacts. Nodes moving at their prescribed constant velocity are unaccelerated, so
    /// the support's reaction on the body is its negative. Triangles whose three nodes are all
    /// prescribed add nothing (they are not computed).
    Vec2 prescribedForce(std::uint32_t body) const;
    Energies energies() const;
    const FrictionDiagnostics& frictionDiagnostics() const { return diagnostics_; }
    std::size_t detections() const { return detections_; }
    std::size_t coupleCount() const { return contacts_.couples().size(); }
    const std::vector<Couple>& couples() const { return contacts_.couples(); }
    const JointStore& joints() const { return joints_; }
    FractureState fractureState() const;
    const StepTimes& stepTimes() const { return stepTimes_; }

  private:
    friend struct CheckpointAccess; // fdem/checkpoint.cpp saves and restores the private state

    /// One touching edge contact's forces and sums, applied in couple order (world_contacts.cpp).
    struct EdgeContactRecord
    {
        std::array<std::uint32_t, 5> node; ///< contactor e, e+1, target 0, 1, 2
        std::array<Vec2, 5> force;         ///< added to the contactor's, subtracted from the target's [N/m]
        Real dampingWork;                  ///< work of the normal dashpot in this step [J/m]
        Real frictionWork;                 ///< F_t v_t dt [J/m]
        Real tangential, cap, normal;      ///< |F_t|, mu F_n, F_n (elastic) [N/m]
        std::uint8_t damped, friction, sliding;
    };

    void refreshActiveLists();
    void buildNodeSlots();
    void computeElementForces();
    void sumNodeForces();
    bool needsDetection() const;
    void detectContacts();
    void computeContactForces();
    void evaluateCouple(Couple& couple, std::vector<EdgeContactRecord>& records) const;
    SplitMesh splitForCracks(const BodyDefinition& body, const TriangleMesh& mesh) const;
    void insertJoints(const BodyDefinition& definition, const SplitMesh& split, std::uint32_t firstNode,
                      std::uint32_t firstTriangle);
    void computeJointForces();
    bool jointedOrAdjacent(std::uint32_t a, std::uint32_t b) const;
    void removeTiedPairs(std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs) const;
    void integrate();

    WorldSettings settings_;
    NodeStore nodes_;
    TriangleStore triangles_;
    std::vector<Material> materials_;
    std::vector<ElasticConstants> constants_;
    std::vector<Real> triangleMinAltitude_; // reference smallest altitude [m]
    std::vector<std::string> bodyNames_;
    std::vector<std::uint8_t> bodyFixed_;
    std::vector<std::uint32_t> activeNodes_;     // nodes that are not prescribed at rest
    std::vector<std::uint32_t> activeTriangles_; // triangles with at least one free node
    std::vector<Vec2> positionAtDetection_;      // of activeNodes_
    bool listsValid_ = false;
    ContactList contacts_;
    bool contactsValid_ = false;
    Real buffer_ = 0;
    Real time_ = 0;
    std::uint64_t steps_ = 0;
    std::size_t detections_ = 0;
    Real frictionWork_ = 0;
    Real normalDampingWork_ = 0;
    FrictionDiagnostics diagnostics_;
    JointStore joints_;
    std::vector<CohesiveConstants> laws_;                      // per material
    std::vector<std::uint8_t> bodyCracks_;                     // per body
    std::vector<std::array<std::uint32_t, 3>> triangleJoints_; // joint ids per triangle (~0u: none)
    std::vector<std::array<Vec2, 3>> elementForce_; // scratch of the element loop (world_elements.cpp)
    std::vector<Real> elementJacobian_;             // scratch of the element loop
    // Per node, its slots in the order of the serial scatter (world_elements.cpp): element slots
    // 3 k + i of activeTriangles_[k], then joint slots 4 j + end (a0, a1, b0, b1).
    std::vector<std::uint32_t> elementSlotStart_, elementSlots_, jointSlotStart_, jointSlots_;
    bool nodeSlotsValid_ = false;
    std::vector<std::vector<EdgeContactRecord>> contactRecords_; // per chunk of couples
    StepTimes stepTimes_;
    std::size_t brokenJoints_ = 0;
    Real energyReleased_ = 0;
};

} // namespace veridem::fdem
