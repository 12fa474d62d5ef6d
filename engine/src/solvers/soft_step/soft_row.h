// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The row maths of the soft step, written once for contacts and every joint: a scalar row's
// Jacobian J = [−n, −aA, n, aB] (a direction n and the lever terms aA = rA×n, aB = rB×n, or an
// angular row n = 0, aA = aB = 1), its inverse effective mass — the seed's
//   k = 1/mA + 1/mB + (rA×n)²/IA + (rB×n)²/IB,
// (without the 1/m terms for an angular row) — its velocity J·v, the soft update of its
// accumulated impulse (softness.h) and the impulse's application to both bodies; and the 2×2
// point block whose diagonal entries are the seed's k along x̂ and ŷ.
#pragma once

#include "joints/softness.h"
#include "model/solver_types.h"
#include "solvers/soft_step/soft_bodies.h"

#include <cstdint>

namespace meff::detail
{

/// Two bodies' velocities while a row is solved, and their inverse masses (1/kg) and inverse
/// inertias (1/(kg·m²)).
struct RowBodies
{
    Vec2 vA;
    Real wA;
    Vec2 vB;
    Real wB;
    Real mA, iA, mB, iB;
};

/// J·v = n·(vB − vA) + aB·wB − aA·wA.
struct RowJacobian
{
    Vec2 n;
    Real aA = 0, aB = 0;
    bool linear = true; ///< false for an angular row (n = 0, no 1/m terms)
};

/// The row along unit direction n through lever arms rA, rB.
inline RowJacobian PointRow(Vec2 n, Vec2 rA, Vec2 rB)
{
    return {n, Cross(rA, n), Cross(rB, n), true};
}

/// A row holding B's anchor along direction n fixed in body A (prismatic, wheel): with d the
/// anchors' gap, A's lever is d + rA because n turns with A.
inline RowJacobian LineRow(Vec2 n, Vec2 d, Vec2 rA, Vec2 rB)
{
    return {n, Cross(d + rA, n), Cross(rB, n), true};
}

/// The same row with the opposite sign (an upper limit: C = upper − n·d).
inline RowJacobian Negated(const RowJacobian& J)
{
    return {-J.n, -J.aA, -J.aB, J.linear};
}

/// The row of the relative angular velocity wB − wA.
inline RowJacobian AngularRow()
{
    return {{0, 0}, 1, 1, false};
}

// The arithmetic of a row, written once for one row (R = Real, V = Vec2) and for a SIMD lane
// group of rows (R = RealW, V = Vec2W: soft_contact_lanes.h), with the same operations in the
// same order, so that a row gives the same bits whichever way it is solved.

/// The angular terms of the seed's k: (rA×n)²/IA + (rB×n)²/IB with aA = rA×n, aB = rB×n.
template <typename R>
[[gnu::always_inline]] inline R AngularInverseMass(R aA, R aB, R iA, R iB)
{
    return iA * aA * aA + iB * aB * aB;
}

/// The seed's k of a linear row: 1/mA + 1/mB + AngularInverseMass.
template <typename R>
[[gnu::always_inline]] inline R LinearInverseMass(R aA, R aB, R mA, R iA, R mB, R iB)
{
    return mA + mB + AngularInverseMass(aA, aB, iA, iB);
}

/// The off-diagonal entry of the block K of two linear rows along the same direction through two
/// points (levers aA1, aB1 and aA2, aB2): 1/mA + 1/mB + aA1·aA2/IA + aB1·aB2/IB.
template <typename R>
[[gnu::always_inline]] inline R RowCoupling(R aA1, R aB1, R aA2, R aB2, R mA, R iA, R mB, R iB)
{
    return mA + mB + iA * aA1 * aA2 + iB * aB1 * aB2;
}

/// J·v = n·(vB − vA) + aB·wB − aA·wA.
template <typename V, typename R>
[[gnu::always_inline]] inline R RowVelocityOf(V n, R aA, R aB, V vA, R wA, V vB, R wB)
{
    return Dot(n, vB - vA) + aB * wB - aA * wA;
}

/// The soft update's impulse before clamping (softness.h): −m_eff·(massScale·Cdot + bias) −
/// impulseScale·λ_accumulated.
template <typename R>
[[gnu::always_inline]] inline R SoftImpulseOf(R mass, R cdot, R bias, R massScale, R impulseScale,
                                              R accumulated)
{
    return -mass * (massScale * cdot + bias) - impulseScale * accumulated;
}

/// The seed's inverse effective mass of row J.
inline Real InverseEffectiveMass(const RowJacobian& J, const RowBodies& b)
{
    return J.linear ? LinearInverseMass(J.aA, J.aB, b.mA, b.iA, b.mB, b.iB)
                    : AngularInverseMass(J.aA, J.aB, b.iA, b.iB);
}

/// 1/k, or 0 for a row no body can move along.
inline Real RowMass(Real k)
{
    return k > 0 ? Real(1) / k : Real(0);
}

inline Real RowVelocity(const RowJacobian& J, const RowBodies& b)
{
    return RowVelocityOf(J.n, J.aA, J.aB, b.vA, b.wA, b.vB, b.wB);
}

/// Applies the row impulse λ along n with levers aA, aB: +λ·J to B, −λ·J to A.
template <typename V, typename R>
[[gnu::always_inline]] inline void ApplyRowImpulseOf(V n, R aA, R aB, R lambda, R mA, R iA, R mB,
                                                     R iB, V& vA, R& wA, V& vB, R& wB)
{
    const V P = lambda * n;
    vA = vA - mA * P;
    wA = wA - iA * lambda * aA;
    vB = vB + mB * P;
    wB = wB + iB * lambda * aB;
}

/// Applies the row impulse λ: +λ·J to B, −λ·J to A.
inline void ApplyRowImpulse(const RowJacobian& J, Real lambda, RowBodies& b)
{
    ApplyRowImpulseOf(J.n, J.aA, J.aB, lambda, b.mA, b.iA, b.mB, b.iB, b.vA, b.wA, b.vB, b.wB);
}

/// What a row is driven to this update: the velocity bias (for a soft row already ×
/// massScale: Softness::biasScale·C) and the softness it is solved with.
struct RowTarget
{
    Real bias = 0;
    Softness softness = kRigid;
};

/// An equality row (C = 0 wanted) at error C: soft with bias while solving, rigid without
/// bias while relaxing.
inline RowTarget EqualityTarget(Real C, bool useBias, const Softness& softness)
{
    return useBias ? RowTarget{BiasOf(softness, C), softness} : RowTarget{};
}

/// A one-sided row (C ≥ 0 wanted: a contact, a limit) at error C: while apart (C > 0) it only
/// stops the bodies from closing more than C within the sub-step (speculative, rigid);
/// overlapping, soft with bias while solving (the push-out speed at most `maxPush`), rigid
/// while relaxing.
inline RowTarget OneSidedTarget(Real C, bool useBias, const Softness& softness, Real invH,
                                Real maxPush = kMaxReal)
{
    if (C > 0)
    {
        // A gap past 1e9 (a distance joint's unbounded maxLength) is no constraint at all;
        // capping it keeps C/h finite.
        return {Min(C, Real(1e9)) * invH, kRigid};
    }
    if (useBias)
    {
        return {Max(BiasOf(softness, C), -maxPush), softness};
    }
    return {};
}

/// One soft update of a row of effective mass `mass` (1/k) at velocity `cdot`: returns the
/// impulse applied, keeping the accumulated impulse within [lower, upper].
inline Real SoftRowImpulse(Real mass, Real cdot, const RowTarget& target, Real& accumulated,
                           Real lower = -kMaxReal, Real upper = kMaxReal)
{
    const Real impulse = SoftImpulseOf(mass, cdot, target.bias, target.softness.massScale,
                                       target.softness.impulseScale, accumulated);
    const Real next = Clamp(accumulated + impulse, lower, upper);
    const Real applied = next - accumulated;
    accumulated = next;
    return applied;
}

/// Solves one scalar row with Jacobian J: velocity, soft update, application. Returns the
/// impulse applied.
inline Real SolveRow(const RowJacobian& J, Real mass, const RowTarget& target, Real& accumulated,
                     RowBodies& b, Real lower = -kMaxReal, Real upper = kMaxReal)
{
    const Real applied = SoftRowImpulse(mass, RowVelocity(J, b), target, accumulated, lower, upper);
    ApplyRowImpulse(J, applied, b);
    return applied;
}

/// K = J·M⁻¹·Jᵀ of the point rows with J = [−I −rA⊥ I rB⊥]: its diagonal entries are the
/// seed's scalar k along x̂ and ŷ ((r×x̂)² = r.y², (r×ŷ)² = r.x²); the off-diagonal couples
/// the two rows through the shared rotations.
inline Mat22 PointBlock(Vec2 rA, Vec2 rB, const RowBodies& b)
{
    Mat22 K;
    K.ex.x = b.mA + b.mB + rA.y * rA.y * b.iA + rB.y * rB.y * b.iB;
    K.ey.x = -rA.y * rA.x * b.iA - rB.y * rB.x * b.iB;
    K.ex.y = K.ey.x;
    K.ey.y = b.mA + b.mB + rA.x * rA.x * b.iA + rB.x * rB.x * b.iB;
    return K;
}

/// Relative velocity of B's anchor with respect to A's.
inline Vec2 AnchorVelocity(Vec2 rA, Vec2 rB, const RowBodies& b)
{
    return b.vB + Cross(b.wB, rB) - b.vA - Cross(b.wA, rA);
}

/// Applies the point impulse P at the anchors: +P to B, −P to A.
inline void ApplyPointImpulse(Vec2 P, Vec2 rA, Vec2 rB, RowBodies& b)
{
    b.vA -= b.mA * P;
    b.wA -= b.iA * Cross(rA, P);
    b.vB += b.mB * P;
    b.wB += b.iB * Cross(rB, P);
}

/// One soft update of a point constraint (C = the anchors' gap): as a 2×2 block, or with
/// `block` off as two scalar rows along x̂ and ŷ. `maxImpulse` bounds the accumulated impulse's
/// length (a mouse's force × h). Returns the impulse applied.
inline Vec2 SolvePoint(Vec2 rA, Vec2 rB, Vec2 C, bool useBias, const Softness& softness,
                       Vec2& accumulated, RowBodies& b, bool block, Real maxImpulse = kMaxReal)
{
    const RowTarget target = useBias ? RowTarget{0, softness} : RowTarget{};
    const Vec2 bias = useBias ? BiasOf(softness, C) : Vec2{};
    Vec2 applied;
    if (block)
    {
        const Vec2 x = PointBlock(rA, rB, b).Solve(
            target.softness.massScale * AnchorVelocity(rA, rB, b) + bias);
        applied = -x - target.softness.impulseScale * accumulated;
        Vec2 next = accumulated + applied;
        const Real length = next.Length();
        if (length > maxImpulse)
        {
            next *= maxImpulse / length;
        }
        applied = next - accumulated;
        accumulated = next;
        ApplyPointImpulse(applied, rA, rB, b);
        return applied;
    }
    const Real axes[2][2] = {{1, 0}, {0, 1}};
    Real* components[2] = {&accumulated.x, &accumulated.y};
    const Real biases[2] = {bias.x, bias.y};
    for (int axis = 0; axis < 2; ++axis)
    {
        const RowJacobian J = PointRow({axes[axis][0], axes[axis][1]}, rA, rB);
        const RowTarget rowTarget{biases[axis], target.softness};
        const Real mass = RowMass(InverseEffectiveMass(J, b));
        const Real lambda = SolveRow(J, mass, rowTarget, *components[axis], b);
        (axis == 0 ? applied.x : applied.y) = lambda;
    }
    const Real length = accumulated.Length();
    if (length > maxImpulse)
    {
        const Vec2 excess = accumulated - (maxImpulse / length) * accumulated;
        accumulated -= excess;
        applied -= excess;
        ApplyPointImpulse(-excess, rA, rB, b);
    }
    return applied;
}

/// The two bodies of a row, read from the sub-step's velocities.
inline RowBodies LoadRowBodies(const Velocity* velocities, std::int32_t indexA, std::int32_t indexB,
                               Real mA, Real iA, Real mB, Real iB)
{
    const Velocity& a = velocities[indexA];
    const Velocity& b = velocities[indexB];
    return {a.v, a.w, b.v, b.w, mA, iA, mB, iB};
}

/// Writes the two bodies back.
inline void StoreRowBodies(Velocity* velocities, std::int32_t indexA, std::int32_t indexB,
                           const RowBodies& b)
{
    velocities[indexA] = {b.vA, b.wA};
    velocities[indexB] = {b.vB, b.wB};
}

} // namespace meff::detail
