// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Distance joint: Box2D 2.4.1's b2DistanceJoint in the scalar effective mass form (seed:
// effective-mass.md). One direction u, from A's anchor to B's, carries every row:
//   C = |pB − pA| − L,   Cdot = u·(vB + wB×rB − vA − wA×rA),   J = [−u  −rA×u  u  rB×u]
//   k = 1/mA + (rA×u)²/IA + 1/mB + (rB×u)²/IB   (the seed's scalar effective mass)
// Three regimes, decided as 2.4.1 does:
//   minLength == maxLength      one rigid equality row (impulse), no velocity bias;
//   minLength < maxLength       optional spring row (stiffness > 0) plus two one-sided limit
//                               rows, lower (impulse ≥ 0) and upper (impulse ≥ 0, flipped).
// Note that with minLength < maxLength and no stiffness, nothing holds the rest length: the
// joint is then a rope with a minimum length, exactly as in Box2D 2.4.1.
//
// Every expression keeps Box2D's floating-point operation order (frame-by-frame validation).
#include "joints/joint.h"

#include <cmath>

namespace meff::detail
{

namespace
{

/// Velocity of B's anchor relative to A's, projected on u.
Real AxialSpeed(Vec2 u, Vec2 vA, Real wA, Vec2 rA, Vec2 vB, Real wB, Vec2 rB)
{
    const Vec2 vpA = vA + Cross(wA, rA);
    const Vec2 vpB = vB + Cross(wB, rB);
    return Dot(u, vpB - vpA);
}

/// Applies P to B and −P to A at their anchors.
void ApplyImpulse(const DistanceJoint& joint, Vec2 P, Vec2& vA, Real& wA, Vec2& vB, Real& wB)
{
    vA -= joint.invMassA * P;
    wA -= joint.invIA * Cross(joint.rA, P);
    vB += joint.invMassB * P;
    wB += joint.invIB * Cross(joint.rB, P);
}

} // namespace

void InitVelocityConstraints(DistanceJoint& joint, const JointBody& a, const JointBody& b,
                             SolverData& data)
{
    StoreJointBodies(joint, a, b);

    const auto [cA, aA] = data.positions[joint.indexA];
    auto [vA, wA] = data.velocities[joint.indexA];
    const auto [cB, aB] = data.positions[joint.indexB];
    auto [vB, wB] = data.velocities[joint.indexB];

    const Rot qA(aA), qB(aB);
    joint.rA = Mul(qA, joint.localAnchorA - joint.localCenterA);
    joint.rB = Mul(qB, joint.localAnchorB - joint.localCenterB);
    joint.u = cB + joint.rB - cA - joint.rA;

    // With the anchors (nearly) coincident the direction is undefined: the rows get u = 0,
    // so they apply nothing, and stale impulses are dropped.
    joint.currentLength = joint.u.Length();
    if (joint.currentLength > data.step.tolerances.linearSlop)
    {
        joint.u *= Real(1) / joint.currentLength;
    }
    else
    {
        joint.u = Vec2(0, 0);
        joint.mass = 0;
        joint.impulse = 0;
        joint.lowerImpulse = 0;
        joint.upperImpulse = 0;
    }

    // Seed: k = 1/mA + (rA×u)²/IA + 1/mB + (rB×u)²/IB; mass = 1/k.
    const Real crAu = Cross(joint.rA, joint.u);
    const Real crBu = Cross(joint.rB, joint.u);
    Real invMass =
        joint.invMassA + joint.invIA * crAu * crAu + joint.invMassB + joint.invIB * crBu * crBu;
    joint.mass = invMass != 0 ? Real(1) / invMass : Real(0);

    if (joint.stiffness > 0 && joint.minLength < joint.maxLength)
    {
        // Soft row (Catto's soft constraints): implicit Euler on the spring-damper
        // m·Δv = −h·(k_s·C + c·v) gives λ = −(Cdot + bias + γ·λacc)/(k + γ) with
        //   γ = 1/(h·(c + h·k_s))  (an inverse mass: λ is an impulse, hence the extra h)
        //   bias = C·h·k_s·γ
        const Real C = joint.currentLength - joint.length;
        const Real d = joint.damping;
        const Real k = joint.stiffness;
        const Real h = data.step.dt;
        joint.gamma = h * (d + h * k);
        joint.gamma = joint.gamma != 0 ? Real(1) / joint.gamma : Real(0);
        joint.bias = C * h * k * joint.gamma;

        invMass += joint.gamma;
        joint.softMass = invMass != 0 ? Real(1) / invMass : Real(0);
    }
    else
    {
        joint.gamma = 0;
        joint.bias = 0;
        joint.softMass = joint.mass;
    }

    if (data.step.solver.warmStarting)
    {
        // Impulses are force·dt: rescale last step's to this step's dt. The upper row's
        // impulse acts with the opposite sign (its C is maxLength − length).
        const Real dtRatio = data.step.dtRatio;
        joint.impulse *= dtRatio;
        joint.lowerImpulse *= dtRatio;
        joint.upperImpulse *= dtRatio;

        const Vec2 P = (joint.impulse + joint.lowerImpulse - joint.upperImpulse) * joint.u;
        ApplyImpulse(joint, P, vA, wA, vB, wB);
    }
    else
    {
        // Box2D 2.4.1 resets only the main row here; the limit rows keep (but do not apply)
        // their accumulated impulses and clamp against them in the next solve. Mirrored as
        // is, since the engine must agree with Box2D step for step.
        joint.impulse = 0;
    }

    data.velocities[joint.indexA] = {vA, wA};
    data.velocities[joint.indexB] = {vB, wB};
}

void SolveVelocityConstraints(DistanceJoint& joint, SolverData& data)
{
    auto [vA, wA] = data.velocities[joint.indexA];
    auto [vB, wB] = data.velocities[joint.indexB];

    if (joint.minLength < joint.maxLength)
    {
        if (joint.stiffness > 0)
        {
            // Spring row (see InitVelocityConstraints for γ and bias).
            const Real Cdot = AxialSpeed(joint.u, vA, wA, joint.rA, vB, wB, joint.rB);
            const Real impulse =
                -joint.softMass * (Cdot + joint.bias + joint.gamma * joint.impulse);
            joint.impulse += impulse;
            ApplyImpulse(joint, impulse * joint.u, vA, wA, vB, wB);
        }

        // Lower limit, C = length − minLength ≥ 0, accumulated impulse ≥ 0. The bias
        // max(C, 0)/h is speculative: the row lets the anchors approach by at most the
        // remaining gap this step; once violated the position pass removes the error.
        {
            const Real C = joint.currentLength - joint.minLength;
            const Real bias = Max(Real(0), C) * data.step.invDt;
            const Real Cdot = AxialSpeed(joint.u, vA, wA, joint.rA, vB, wB, joint.rB);
            Real impulse = -joint.mass * (Cdot + bias);
            const Real oldImpulse = joint.lowerImpulse;
            joint.lowerImpulse = Max(Real(0), joint.lowerImpulse + impulse);
            impulse = joint.lowerImpulse - oldImpulse;
            ApplyImpulse(joint, impulse * joint.u, vA, wA, vB, wB);
        }

        // Upper limit, C = maxLength − length ≥ 0: the row is written along −u so that its
        // impulse is also ≥ 0 when active.
        {
            const Real C = joint.maxLength - joint.currentLength;
            const Real bias = Max(Real(0), C) * data.step.invDt;
            const Vec2 vpA = vA + Cross(wA, joint.rA);
            const Vec2 vpB = vB + Cross(wB, joint.rB);
            const Real Cdot = Dot(joint.u, vpA - vpB);
            Real impulse = -joint.mass * (Cdot + bias);
            const Real oldImpulse = joint.upperImpulse;
            joint.upperImpulse = Max(Real(0), joint.upperImpulse + impulse);
            impulse = joint.upperImpulse - oldImpulse;
            ApplyImpulse(joint, -impulse * joint.u, vA, wA, vB, wB);
        }
    }
    else
    {
        // Rigid rod: λ = −Cdot/k, no bias; the length error is left to the position pass.
        const Real Cdot = AxialSpeed(joint.u, vA, wA, joint.rA, vB, wB, joint.rB);
        const Real impulse = -joint.mass * Cdot;
        joint.impulse += impulse;
        ApplyImpulse(joint, impulse * joint.u, vA, wA, vB, wB);
    }

    data.velocities[joint.indexA] = {vA, wA};
    data.velocities[joint.indexB] = {vB, wB};
}

bool SolvePositionConstraints(DistanceJoint& joint, SolverData& data)
{
    auto [cA, aA] = data.positions[joint.indexA];
    auto [cB, aB] = data.positions[joint.indexB];

    const Rot qA(aA), qB(aB);
    const Vec2 rA = Mul(qA, joint.localAnchorA - joint.localCenterA);
    const Vec2 rB = Mul(qB, joint.localAnchorB - joint.localCenterB);
    Vec2 u = cB + rB - cA - rA;
    const Real length = u.Normalize();

    // The rod's error, or the violated limit's; the spring itself is never position-
    // corrected (its error is its stored energy). 2.4.1 applies no maxLinearCorrection
    // clamp here (earlier versions did).
    Real C;
    if (joint.minLength == joint.maxLength)
    {
        C = length - joint.minLength;
    }
    else if (length < joint.minLength)
    {
        C = length - joint.minLength;
    }
    else if (joint.maxLength < length)
    {
        C = length - joint.maxLength;
    }
    else
    {
        return true;
    }

    // λ = −C/k with the k of InitVelocityConstraints (lever arms of the step's start).
    const Real impulse = -joint.mass * C;
    const Vec2 P = impulse * u;
    cA -= joint.invMassA * P;
    aA -= joint.invIA * Cross(rA, P);
    cB += joint.invMassB * P;
    aB += joint.invIB * Cross(rB, P);

    data.positions[joint.indexA] = {cA, aA};
    data.positions[joint.indexB] = {cB, aB};

    return std::abs(C) < data.step.tolerances.linearSlop;
}

JointReaction GetReaction(const DistanceJoint& joint, Real invDt)
{
    // All rows push along u; the upper limit's impulse with the flipped sign.
    JointReaction reaction;
    reaction.force = invDt * (joint.impulse + joint.lowerImpulse - joint.upperImpulse) * joint.u;
    reaction.torque = 0;
    return reaction;
}

} // namespace meff::detail
