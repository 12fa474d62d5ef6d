// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// The constraint rows of one contact, as the contact solvers see them: the velocity rows
// (normal and friction at each manifold point, with their scalar effective masses
// 1/k, k = 1/mA + 1/mB + (rA×n)²/IA + (rB×n)²/IB) and the data the position pass re-evaluates
// each sweep. One contact's sequential updates are here too, shared by the island-order
// solver and the coloured solver's overflow.
#pragma once

#include "model/solver_types.h"
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
    /// The island's bodies (world body indices) in solver order, for the stages that keep
    /// per-body data by solver index (the colour back end's lanes); may be empty otherwise.
    std::span<const std::int32_t> bodyIndices = {};
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
    Real tangentSpeed = 0; ///< the friction rows' target (Contact::tangentSpeed, m/s)
    /// The spin row (rolling resistance): |impulse| ≤ rollingResistance·Σ normal impulses, on
    /// the angular row's effective mass 1/(1/IA + 1/IB). Skipped when rollingResistance is 0.
    Real rollingResistance = 0, rollingMass = 0, rollingImpulse = 0;
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
    Real rollingImpulse = 0;  ///< the spin row's (N·m·s)
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

/// Box2D's block solver for a two-point manifold's normal rows: the linear complementarity
/// problem vn = K·x + b, x ≥ 0, vn ≥ 0, x·vn = 0, solved by trying its four cases in turn (both
/// points pushing, only the first, only the second, neither). `a` holds the impulses already
/// accumulated and `b` = (vn − target) − K·a, so x is the new accumulated impulse; `mass1`,
/// `mass2` are each row's 1/k alone. Returns false when no case holds (rare, from round-off):
/// the impulses then stay as they are.
inline bool SolveTwoPointBlock(const Mat22& K, const Mat22& invK, Real mass1, Real mass2, Vec2 b,
                               Vec2& x)
{
    // Case 1: both points stay in contact (vn = 0): x = −K⁻¹·b.
    x = -Mul(invK, b);
    if (x.x >= 0 && x.y >= 0)
    {
        return true;
    }
    // Case 2: point 1 in contact, point 2 separating (x2 = 0).
    x = {-mass1 * b.x, 0};
    const Real v2 = K.ex.y * x.x + b.y;
    if (x.x >= 0 && v2 >= 0)
    {
        return true;
    }
    // Case 3: point 2 in contact, point 1 separating (x1 = 0).
    x = {0, -mass2 * b.y};
    const Real v1 = K.ey.x * x.y + b.x;
    if (x.y >= 0 && v1 >= 0)
    {
        return true;
    }
    // Case 4: both separating.
    x = {0, 0};
    return b.x >= 0 && b.y >= 0;
}

/// One contact's sequential-impulse update: friction rows, then the normal rows one by one or,
/// for a two-point manifold with `blockSolver`, as Box2D's 2×2 block.
void SolveVelocityConstraint(ContactVelocityConstraint& vc, Velocity* velocities, bool blockSolver);

/// The spin row of rolling resistance on relative angular velocity wB − wA: its accumulated
/// impulse is clamped to ±resistance·(the points' normal impulses), the torque c·r·N of a
/// rolling resistance coefficient c. Shared by every back end.
inline Real SolveRollingRow(Real mass, Real resistance, Real totalNormalImpulse, Real wA, Real wB,
                            Real& accumulated)
{
    const Real limit = resistance * totalNormalImpulse;
    const Real next = Clamp(accumulated - mass * (wB - wA), -limit, limit);
    const Real applied = next - accumulated;
    accumulated = next;
    return applied;
}

/// One contact's non-linear Gauss-Seidel position update with Baumgarte factor `baumgarte` and
/// inverse masses `masses`; returns the smallest separation it saw (≤ 0).
Real SolvePositionConstraint(const ContactPositionConstraint& pc, Position* positions,
                             const Tolerances& tol, Real baumgarte, const PositionMasses& masses);

} // namespace meff::detail
