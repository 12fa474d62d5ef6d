// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Pulley joint in the soft step: the rope's one equality row (pulley_joint.cpp)
//   C = L − |pA − sA| − ratio·|pB − sB| = 0,  Cdot = −uA·(vA + wA×rA) − ratio·uB·(vB + wB×rB)
// with each side's direction and length measured now, from the anchors' offsets from their
// ground anchors at the step's start and the bodies' motion since. Soft with the joints'
// softness while solving, rigid without bias while relaxing, as every rigid joint row.
#include "solvers/soft_step/soft_joint.h"

namespace meff::detail
{

namespace
{

/// The rope now: each side's unit direction and length, and the row's C.
struct Rope
{
    Vec2 uA, uB;
    Real C = 0;
};

Rope RopeNow(const PulleyJoint& joint, const SoftJointState& state)
{
    const SoftJointFrame& f = state.frame;
    const Real slop = state.context.step->tolerances.linearSlop;
    Rope rope;
    Real lengthA = 0, lengthB = 0;
    rope.uA = PulleyDirection(f.ropeA0 + state.dA.dp + (state.at.rA - f.rA0), slop, lengthA);
    rope.uB = PulleyDirection(f.ropeB0 + state.dB.dp + (state.at.rB - f.rB0), slop, lengthB);
    rope.C = joint.constant - lengthA - joint.ratio * lengthB;
    return rope;
}

/// Applies the row impulse λ: −λ·uA at A's anchor, −ratio·λ·uB at B's.
void ApplyRopeImpulse(const PulleyJoint& joint, const Rope& rope, Vec2 rA, Vec2 rB, Real lambda,
                      RowBodies& b)
{
    const Vec2 PA = -lambda * rope.uA;
    const Vec2 PB = (-joint.ratio * lambda) * rope.uB;
    b.vA += b.mA * PA;
    b.wA += b.iA * Cross(rA, PA);
    b.vB += b.mB * PB;
    b.wB += b.iB * Cross(rB, PB);
}

} // namespace

void PrepareSoft(PulleyJoint& joint, SoftJointFrame& frame, const Position& poseA,
                 const Position& poseB, const SoftStepContext&)
{
    frame.rA0 = Mul(Rot(poseA.a), joint.localAnchorA - joint.localCenterA);
    frame.rB0 = Mul(Rot(poseB.a), joint.localAnchorB - joint.localCenterB);
    frame.ropeA0 = poseA.c + frame.rA0 - joint.groundAnchorA;
    frame.ropeB0 = poseB.c + frame.rB0 - joint.groundAnchorB;
}

void WarmStartSoft(const PulleyJoint& joint, const SoftJointState& state, RowBodies& b)
{
    ApplyRopeImpulse(joint, RopeNow(joint, state), state.at.rA, state.at.rB, joint.impulse, b);
}

void SolveSoft(PulleyJoint& joint, const SoftJointState& state, bool useBias, RowBodies& b)
{
    const Rope rope = RopeNow(joint, state);
    const Vec2 rA = state.at.rA, rB = state.at.rB;
    const Real ruA = Cross(rA, rope.uA);
    const Real ruB = Cross(rB, rope.uB);
    // The seed's k of each side, B's scaled by ratio² (its rope moves ratio times as fast).
    const Real k = b.mA + b.iA * ruA * ruA + joint.ratio * joint.ratio * (b.mB + b.iB * ruB * ruB);
    const Real cdot =
        -Dot(rope.uA, b.vA + Cross(b.wA, rA)) - joint.ratio * Dot(rope.uB, b.vB + Cross(b.wB, rB));
    const Real applied = SoftRowImpulse(
        RowMass(k), cdot, EqualityTarget(rope.C, useBias, state.context.joint), joint.impulse);
    ApplyRopeImpulse(joint, rope, rA, rB, applied, b);
    joint.uB = rope.uB; // the reaction's direction (GetReaction)
}

void ScaleImpulses(PulleyJoint& joint, Real factor)
{
    joint.impulse *= factor;
}

} // namespace meff::detail
