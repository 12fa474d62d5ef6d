// The constraint rows of one contact, as the contact solvers see them: the velocity rows
// (normal and friction at each manifold point, with their scalar effective masses
// 1/k, k = 1/mA + 1/mB + (rA×n)²/IA + (rB×n)²/IB) and the data the position pass re-evaluates
// each sweep. One contact's sequential updates are here too, shared by the island-order
// solver and the coloured solver's overflow.
#pragma once

#include "dynamics/solver_types.h"
#include "meff/collision.h"

#include <cstddef>
#include <cstdint>
#include <span>

namespace meff::detail
{

struct Body;
struct Contact;

/// What contact preparation reads: one island's contacts (world contact indices, in island
/// order) and the world's contacts and bodies (with their islandIndex set).
struct IslandContacts
{
    std::span<const std::int32_t> contactIndices;
    std::span<const Contact> contacts;
    std::span<const Body> bodies;
};

struct ContactVelocityPoint
{
    Vec2 rA, rB; ///< from each centre of mass to the contact point (m)
    Real normalImpulse = 0, tangentImpulse = 0;
    Real normalMass = 0, tangentMass = 0; ///< 1/k of the row (kg)
    Real velocityBias = 0;                ///< restitution target −e·vn (m/s)
    Real normalVelocity = 0; ///< vn before impulses, as restitution measures it (m/s); hit events
};

struct ContactVelocityConstraint
{
    ContactVelocityPoint points[2];
    Vec2 normal;
    Mat22 normalMass, K; ///< block solver: K and K⁻¹
    std::int32_t indexA = 0, indexB = 0;
    Real invMassA = 0, invMassB = 0, invIA = 0, invIB = 0;
    Real friction = 0, restitution = 0, threshold = 0;
    int pointCount = 0;
    std::int32_t contactIndex = 0; ///< world contact index
};

struct ContactPositionConstraint
{
    Vec2 localPoints[2];
    Vec2 localNormal, localPoint;
    std::int32_t indexA = 0, indexB = 0;
    Real invMassA = 0, invMassB = 0, invIA = 0, invIB = 0;
    Vec2 localCenterA, localCenterB;
    Manifold::Type type = Manifold::Type::Circles;
    Real radiusA = 0, radiusB = 0;
    int pointCount = 0;
};

/// What the rest of the step reads of a contact the solver has just solved: the impulses it
/// stores for the next step's warm start, the contact reports and the hit events.
struct SolvedContact
{
    std::int32_t contactIndex = 0;
    std::int32_t pointCount = 0; ///< the points solved (the block solver may drop the second)
    Real normalImpulse[2]{};     ///< accumulated over the velocity iterations (N·s)
    Real tangentImpulse[2]{};
    Real normalVelocity[2]{}; ///< vn before impulses, as restitution measures it (m/s)
};

/// Box2D's largest accepted condition number of a two-point manifold's 2×2 block before the
/// solver falls back to its first point: beyond it the two rows are nearly parallel and K⁻¹
/// amplifies round-off.
inline constexpr Real kMaxConditionNumber = 1000;

/// Inverse masses and inertias one position constraint uses.
struct PositionMasses
{
    Real mA, mB, iA, iB;
};

/// Box2D's b2ContactSolver constructor and InitializeVelocityConstraints for the island's
/// contact k: its velocity rows `vc` and position constraint `pc`. Returns whether the contact
/// has a shape that asked for hit events.
bool PrepareContactConstraint(const IslandContacts& island, std::size_t k, const SolverData& data,
                              ContactVelocityConstraint& vc, ContactPositionConstraint& pc);

/// Applies one contact's accumulated impulses of last step (scaled in the preparation).
void WarmStartConstraint(const ContactVelocityConstraint& vc, Velocity* velocities);

/// What the rest of the step reads of one solved contact.
void CollectContactResult(const ContactVelocityConstraint& vc, SolvedContact& solved);

/// One contact's sequential-impulse update: friction rows, then the normal rows one by one or,
/// for a two-point manifold with `blockSolver`, as Box2D's 2×2 block.
void SolveVelocityConstraint(ContactVelocityConstraint& vc, Velocity* velocities, bool blockSolver);

/// One contact's non-linear Gauss-Seidel position update with Baumgarte factor `baumgarte` and
/// inverse masses `masses`; returns the smallest separation it saw (≤ 0).
Real SolvePositionConstraint(const ContactPositionConstraint& pc, Position* positions,
                             const Tolerances& tol, Real baumgarte, const PositionMasses& masses);

} // namespace meff::detail
