// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Rows whose accumulated impulse is bounded by a force or torque × h: the motor and friction
// joints (Box2D 2.4.1's b2MotorJoint and b2FrictionJoint solve them alike). The angular row is
// scalar, k = iA + iB, its accumulated impulse clamped to ±h·maxTorque; the point rows
//   Cdot = vB + wB×rB − vA − wA×rA (+ a bias),  K = J·M⁻¹·Jᵀ
// are a 2×2 block (Box2D) or two scalar rows with the seed's k (K's diagonal), their
// accumulated vector clamped to the disc of radius h·maxForce. The joint types keep their own
// members with the same names (rA, rB, K, linearMass, angularMass, linearImpulse,
// angularImpulse, invMassA/B, invIA/B), which these templates read.
//
// Every expression keeps Box2D's floating-point operation order (frame-by-frame validation).
#pragma once

#include "joints/joint.h"

namespace meff::detail
{

/// λ = −(Jv + bias)/k for one scalar row; a row no body can move along (k = 0) takes none.
inline Real ScalarRowImpulse(Real jvPlusBias, Real k)
{
    return k > 0 ? -jvPlusBias / k : Real(0);
}

/// Keeps the accumulated point impulse within the disc |λ| ≤ maxImpulse (Box2D's order:
/// normalize, then scale).
inline void ClampToDisc(Vec2& accumulated, Real maxImpulse)
{
    if (accumulated.LengthSquared() > maxImpulse * maxImpulse)
    {
        accumulated.Normalize();
        accumulated *= maxImpulse;
    }
}

/// Box2D's K of the point rows through lever arms rA, rB, its inverse and the angular row's
/// mass 1/(iA + iB) (0 when nothing can turn).
template <typename BoundedJoint>
void SetBoundedMasses(BoundedJoint& joint)
{
    const Real mA = joint.invMassA, mB = joint.invMassB;
    const Real iA = joint.invIA, iB = joint.invIB;
    const Vec2 rA = joint.rA, rB = joint.rB;
    // Box2D writes this K with the inverse inertia first (unlike the weld's); kept.
    joint.K.ex.x = mA + mB + iA * rA.y * rA.y + iB * rB.y * rB.y;
    joint.K.ex.y = -iA * rA.x * rA.y - iB * rB.x * rB.y;
    joint.K.ey.x = joint.K.ex.y;
    joint.K.ey.y = mA + mB + iA * rA.x * rA.x + iB * rB.x * rB.x;
    joint.linearMass = joint.K.GetInverse();

    joint.angularMass = iA + iB;
    if (joint.angularMass > 0)
    {
        joint.angularMass = Real(1) / joint.angularMass;
    }
}

/// Warm start: rescales last step's impulses to this step's dt (they are force·dt) and
/// applies them, or zeroes them when warm starting is off.
template <typename BoundedJoint>
void WarmStartBounded(BoundedJoint& joint, const StepContext& step, Vec2& vA, Real& wA, Vec2& vB,
                      Real& wB)
{
    if (step.solver.warmStarting)
    {
        joint.linearImpulse *= step.dtRatio;
        joint.angularImpulse *= step.dtRatio;
        const Vec2 P(joint.linearImpulse.x, joint.linearImpulse.y);
        vA -= joint.invMassA * P;
        wA -= joint.invIA * (Cross(joint.rA, P) + joint.angularImpulse);
        vB += joint.invMassB * P;
        wB += joint.invIB * (Cross(joint.rB, P) + joint.angularImpulse);
    }
    else
    {
        joint.linearImpulse = Vec2(0, 0);
        joint.angularImpulse = 0;
    }
}

/// The angular row at velocity error cdot, its accumulated impulse within ±maxImpulse.
template <typename BoundedJoint>
void SolveBoundedAngle(BoundedJoint& joint, Real cdot, Real maxImpulse, Real& wA, Real& wB)
{
    Real impulse = -joint.angularMass * cdot;
    const Real oldImpulse = joint.angularImpulse;
    joint.angularImpulse = Clamp(joint.angularImpulse + impulse, -maxImpulse, maxImpulse);
    impulse = joint.angularImpulse - oldImpulse;
    wA -= joint.invIA * impulse;
    wB += joint.invIB * impulse;
}

template <typename BoundedJoint>
void ApplyBoundedPointImpulse(const BoundedJoint& j, Vec2 P, Vec2& vA, Real& wA, Vec2& vB, Real& wB)
{
    vA -= j.invMassA * P;
    wA -= j.invIA * Cross(j.rA, P);
    vB += j.invMassB * P;
    wB += j.invIB * Cross(j.rB, P);
}

/// The point rows, their accumulated vector within the disc of radius maxImpulse.
/// cdot(vA, wA, vB, wB) is the rows' velocity error (with the joint's bias, if any).
template <typename BoundedJoint, typename Cdot>
void SolveBoundedPoint(BoundedJoint& joint, Real maxImpulse, bool block, const Cdot& cdot, Vec2& vA,
                       Real& wA, Vec2& vB, Real& wB)
{
    if (block)
    {
        // Both rows at once, λ = −K⁻¹·Cdot, then the disc clamp on the sum.
        Vec2 impulse = -Mul(joint.linearMass, cdot(vA, wA, vB, wB));
        const Vec2 oldImpulse = joint.linearImpulse;
        joint.linearImpulse += impulse;
        ClampToDisc(joint.linearImpulse, maxImpulse);
        impulse = joint.linearImpulse - oldImpulse;
        ApplyBoundedPointImpulse(joint, impulse, vA, wA, vB, wB);
        return;
    }
    // Two scalar rows, x then y, each λ = −Cdot/k with the seed's k (K's diagonal); after each
    // row the accumulated vector is clamped to the disc and only its change applied.
    for (int axis = 0; axis < 2; ++axis)
    {
        const Vec2 rowCdot = cdot(vA, wA, vB, wB);
        const Real lambda = axis == 0 ? ScalarRowImpulse(rowCdot.x, joint.K.ex.x)
                                      : ScalarRowImpulse(rowCdot.y, joint.K.ey.y);
        const Vec2 oldImpulse = joint.linearImpulse;
        joint.linearImpulse += axis == 0 ? Vec2(lambda, 0) : Vec2(0, lambda);
        ClampToDisc(joint.linearImpulse, maxImpulse);
        ApplyBoundedPointImpulse(joint, joint.linearImpulse - oldImpulse, vA, wA, vB, wB);
    }
}

} // namespace meff::detail
