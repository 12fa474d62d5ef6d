// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Revolute joint in the soft step: the point rows hold B's anchor on A's (C = anchor B − anchor
// A), a motor drives wB − wA to the motor speed with at most h·maxMotorTorque (h the kick's
// time, SoftStepContext::KickTime: half a sub-step in the half kicks), and the limits keep θ = θ0 +
// (rotation since the start) within [lower, upper], each row on the seed's scalar effective mass
// (the angular rows' k = 1/IA + 1/IB). An enabled spring pulls θ towards targetAngle: a real spring
// (FrequencySpringSoftness), once per kick.
#include "solvers/soft_step/soft_joint.h"

namespace meff::detail
{

void PrepareSoft(RevoluteJoint& joint, SoftJointFrame& frame, const Position& poseA,
                 const Position& poseB, const SoftStepContext& context)
{
    frame.rA0 = Mul(Rot(poseA.a), joint.localAnchorA - joint.localCenterA);
    frame.rB0 = Mul(Rot(poseB.a), joint.localAnchorB - joint.localCenterB);
    frame.angle0 = poseB.a - poseA.a - joint.referenceAngle;
    const bool fixedRotation = frame.iA + frame.iB == 0;
    if (!joint.enableLimit || fixedRotation)
    {
        joint.lowerImpulse = 0;
        joint.upperImpulse = 0;
    }
    if (!joint.enableMotor || fixedRotation)
    {
        joint.motorImpulse = 0;
    }
    if (!joint.enableSpring || fixedRotation)
    {
        joint.springImpulse = 0;
    }
    else
    {
        SetFrequencySpring(frame, joint.hertz, joint.dampingRatio, context);
    }
}

void WarmStartSoft(const RevoluteJoint& joint, const SoftJointState& state, RowBodies& b)
{
    // The upper row's impulse acts with the opposite sign (its C is θhi − θ).
    const Real axialImpulse =
        joint.springImpulse + joint.motorImpulse + joint.lowerImpulse - joint.upperImpulse;
    ApplyPointImpulse(joint.impulse, state.at.rA, state.at.rB, b);
    ApplyRowImpulse(AngularRow(), axialImpulse, b);
}

void SolveSoft(RevoluteJoint& joint, const SoftJointState& state, bool useBias, RowBodies& b)
{
    const SoftStepContext& context = state.context;
    const bool fixedRotation = b.iA + b.iB == 0;
    const Real axialMass = RowMass(b.iA + b.iB);
    // The spring first, so that the motor and the limits bound it (as Box2D v3 orders them).
    const Softness* spring = state.Spring(useBias);
    if (joint.enableSpring && !fixedRotation && spring != nullptr)
    {
        const Real C = state.frame.angle0 + state.Rotation() - joint.targetAngle;
        SolveRow(AngularRow(), axialMass, RowTarget{spring->biasScale * C, *spring},
                 joint.springImpulse, b);
    }
    if (joint.enableMotor && !fixedRotation)
    {
        const Real maxImpulse = context.KickTime() * joint.maxMotorTorque;
        SolveRow(AngularRow(), axialMass, RowTarget{-joint.motorSpeed, kRigid}, joint.motorImpulse,
                 b, -maxImpulse, maxImpulse);
    }
    if (joint.enableLimit && !fixedRotation)
    {
        const Real angle = state.frame.angle0 + state.Rotation();
        SolveRow(AngularRow(), axialMass,
                 OneSidedTarget(angle - joint.lowerAngle, useBias, context.joint, context.invH),
                 joint.lowerImpulse, b, 0, kMaxReal);
        // The upper row: C = θhi − θ, so its Jacobian is the angular row's negative.
        const RowJacobian upper{{0, 0}, -1, -1, false};
        SolveRow(upper, axialMass,
                 OneSidedTarget(joint.upperAngle - angle, useBias, context.joint, context.invH),
                 joint.upperImpulse, b, 0, kMaxReal);
    }
    if (!state.frame.pointInTree)
    {
        SolvePoint(state.at.rA, state.at.rB, state.at.d, useBias, context.joint, joint.impulse, b,
                   context.step->solver.blockJoints);
    }
}

void ScaleImpulses(RevoluteJoint& joint, Real factor)
{
    joint.impulse *= factor;
    joint.motorImpulse *= factor;
    joint.lowerImpulse *= factor;
    joint.upperImpulse *= factor;
    joint.springImpulse *= factor;
}

} // namespace meff::detail
