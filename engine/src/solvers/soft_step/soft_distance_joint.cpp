// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Distance joint in the soft step, along u, the unit vector from A's anchor to B's:
//   rigid (minLength = maxLength)  C = |d| − length = 0
//   otherwise                      a spring towards `length` when it has stiffness (a real
//                                  spring: solving and relaxing alike), and the limits
//                                  |d| − minLength ≥ 0, maxLength − |d| ≥ 0
#include "solvers/soft_step/soft_joint.h"

namespace meff::detail
{

namespace
{

/// The row along the anchors' gap now, and its length (m). With the anchors (nearly)
/// coincident the direction is undefined: the row is then empty.
struct LengthRow
{
    RowJacobian J;
    Real length;
};

LengthRow LengthRowNow(const SoftAnchors& at, const Tolerances& tolerances)
{
    const Real length = at.d.Length();
    const Vec2 u = length > tolerances.linearSlop ? (Real(1) / length) * at.d : Vec2{};
    return {PointRow(u, at.rA, at.rB), length};
}

} // namespace

void PrepareSoft(DistanceJoint& joint, SoftJointFrame& frame, const Position& poseA,
                 const Position& poseB, const SoftStepContext& context)
{
    frame.rA0 = Mul(Rot(poseA.a), joint.localAnchorA - joint.localCenterA);
    frame.rB0 = Mul(Rot(poseB.a), joint.localAnchorB - joint.localCenterB);
    if (joint.stiffness > 0 && joint.minLength < joint.maxLength)
    {
        const SoftAnchors at0{frame.rA0, frame.rB0, frame.deltaCenter + (frame.rB0 - frame.rA0)};
        const RowBodies masses{{}, 0, {}, 0, frame.mA, frame.iA, frame.mB, frame.iB};
        const Real k = InverseEffectiveMass(LengthRowNow(at0, context.step->tolerances).J, masses);
        SetSpring(frame, joint.stiffness, joint.damping, k, context);
    }
    if (joint.minLength == joint.maxLength)
    {
        joint.lowerImpulse = 0;
        joint.upperImpulse = 0;
    }
}

void WarmStartSoft(const DistanceJoint& joint, const SoftJointState& state, RowBodies& b)
{
    const LengthRow row = LengthRowNow(state.at, state.context.step->tolerances);
    // The upper row's impulse acts with the opposite sign (its C is maxLength − length).
    ApplyRowImpulse(row.J, joint.impulse + joint.lowerImpulse - joint.upperImpulse, b);
}

void SolveSoft(DistanceJoint& joint, const SoftJointState& state, bool useBias, RowBodies& b)
{
    const SoftStepContext& context = state.context;
    const LengthRow row = LengthRowNow(state.at, context.step->tolerances);
    const Real mass = RowMass(InverseEffectiveMass(row.J, b));
    if (joint.minLength == joint.maxLength)
    {
        SolveRow(row.J, mass, EqualityTarget(row.length - joint.length, useBias, context.joint),
                 joint.impulse, b);
        return;
    }
    const Softness* spring = state.Spring(useBias);
    if (joint.stiffness > 0 && spring != nullptr)
    {
        SolveRow(row.J, mass, RowTarget{spring->biasScale * (row.length - joint.length), *spring},
                 joint.impulse, b);
    }
    SolveRow(row.J, mass,
             OneSidedTarget(row.length - joint.minLength, useBias, context.joint, context.invH),
             joint.lowerImpulse, b, 0, kMaxReal);
    SolveRow(Negated(row.J), mass,
             OneSidedTarget(joint.maxLength - row.length, useBias, context.joint, context.invH),
             joint.upperImpulse, b, 0, kMaxReal);
}

void ScaleImpulses(DistanceJoint& joint, Real factor)
{
    joint.impulse *= factor;
    joint.lowerImpulse *= factor;
    joint.upperImpulse *= factor;
}

} // namespace meff::detail
