// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Pulley joint: Box2D 2.4.1's b2PulleyJoint in the scalar effective mass form (seed:
// effective-mass.md). With sA, sB the fixed ground anchors and pA, pB the bodies' anchors,
//   C = L − |pA − sA| − ratio·|pB − sB|,   L = lengthA + ratio·lengthB
//   uA = (pA − sA)/|pA − sA|,  uB likewise
//   Cdot = −uA·(vA + wA×rA) − ratio·uB·(vB + wB×rB)
//   J = −[uA  rA×uA  ratio·uB  ratio·rB×uB]
// and the one row's scalar k = J·M⁻¹·Jᵀ is the seed's k for each side, B's scaled by ratio²:
//   k = mA⁻¹ + IA⁻¹·(rA×uA)² + ratio²·(mB⁻¹ + IB⁻¹·(rB×uB)²).
// The row is bilateral (the accumulated impulse is not clamped), as Box2D's.
//
// Every expression keeps Box2D's floating-point operation order (frame-by-frame validation).
#include "joints/joint.h"

#include <cmath>

namespace meff::detail
{

Vec2 PulleyDirection(Vec2 d, Real linearSlop, Real& length)
{
    length = d.Length();
    if (length > Real(10) * linearSlop)
    {
        d *= Real(1) / length;
        return d;
    }
    return Vec2(0, 0);
}

namespace
{

/// 1/k of the rope's row for directions uA, uB and lever arms rA, rB (0 when nothing moves).
Real RopeMass(const PulleyJoint& j, Vec2 rA, Vec2 rB, Vec2 uA, Vec2 uB)
{
    const Real ruA = Cross(rA, uA);
    const Real ruB = Cross(rB, uB);
    const Real mA = j.invMassA + j.invIA * ruA * ruA;
    const Real mB = j.invMassB + j.invIB * ruB * ruB;
    Real mass = mA + j.ratio * j.ratio * mB;
    if (mass > 0)
    {
        mass = Real(1) / mass;
    }
    return mass;
}

} // namespace

void InitVelocityConstraints(PulleyJoint& joint, const JointBody& a, const JointBody& b,
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

    const Real slop = data.step.tolerances.linearSlop;
    Real lengthA = 0, lengthB = 0;
    joint.uA = PulleyDirection(cA + joint.rA - joint.groundAnchorA, slop, lengthA);
    joint.uB = PulleyDirection(cB + joint.rB - joint.groundAnchorB, slop, lengthB);
    joint.mass = RopeMass(joint, joint.rA, joint.rB, joint.uA, joint.uB);

    if (data.step.solver.warmStarting)
    {
        // Impulses are force·dt: rescale last step's to this step's dt.
        joint.impulse *= data.step.dtRatio;
        const Vec2 PA = -(joint.impulse) * joint.uA;
        const Vec2 PB = (-joint.ratio * joint.impulse) * joint.uB;
        vA += joint.invMassA * PA;
        wA += joint.invIA * Cross(joint.rA, PA);
        vB += joint.invMassB * PB;
        wB += joint.invIB * Cross(joint.rB, PB);
    }
    else
    {
        joint.impulse = 0;
    }

    data.velocities[joint.indexA] = {vA, wA};
    data.velocities[joint.indexB] = {vB, wB};
}

void SolveVelocityConstraints(PulleyJoint& joint, SolverData& data)
{
    auto [vA, wA] = data.velocities[joint.indexA];
    auto [vB, wB] = data.velocities[joint.indexB];

    const Vec2 vpA = vA + Cross(wA, joint.rA);
    const Vec2 vpB = vB + Cross(wB, joint.rB);
    const Real Cdot = -Dot(joint.uA, vpA) - joint.ratio * Dot(joint.uB, vpB);
    const Real impulse = -joint.mass * Cdot;
    joint.impulse += impulse;

    const Vec2 PA = -impulse * joint.uA;
    const Vec2 PB = -joint.ratio * impulse * joint.uB;
    vA += joint.invMassA * PA;
    wA += joint.invIA * Cross(joint.rA, PA);
    vB += joint.invMassB * PB;
    wB += joint.invIB * Cross(joint.rB, PB);

    data.velocities[joint.indexA] = {vA, wA};
    data.velocities[joint.indexB] = {vB, wB};
}

bool SolvePositionConstraints(PulleyJoint& joint, SolverData& data)
{
    auto [cA, aA] = data.positions[joint.indexA];
    auto [cB, aB] = data.positions[joint.indexB];

    const Rot qA(aA), qB(aB);
    const Vec2 rA = Mul(qA, joint.localAnchorA - joint.localCenterA);
    const Vec2 rB = Mul(qB, joint.localAnchorB - joint.localCenterB);

    const Real slop = data.step.tolerances.linearSlop;
    Real lengthA = 0, lengthB = 0;
    const Vec2 uA = PulleyDirection(cA + rA - joint.groundAnchorA, slop, lengthA);
    const Vec2 uB = PulleyDirection(cB + rB - joint.groundAnchorB, slop, lengthB);
    const Real mass = RopeMass(joint, rA, rB, uA, uB);

    const Real C = joint.constant - lengthA - joint.ratio * lengthB;
    const Real linearError = std::abs(C);
    const Real impulse = -mass * C;

    const Vec2 PA = -impulse * uA;
    const Vec2 PB = -joint.ratio * impulse * uB;
    cA += joint.invMassA * PA;
    aA += joint.invIA * Cross(rA, PA);
    cB += joint.invMassB * PB;
    aB += joint.invIB * Cross(rB, PB);

    data.positions[joint.indexA] = {cA, aA};
    data.positions[joint.indexB] = {cB, aB};
    return linearError < slop;
}

JointReaction GetReaction(const PulleyJoint& joint, Real invDt)
{
    // As Box2D: the rope's pull on B's side, along uB; a rope exerts no torque of its own.
    JointReaction reaction;
    reaction.force = invDt * (joint.impulse * joint.uB);
    reaction.torque = 0;
    return reaction;
}

} // namespace meff::detail
