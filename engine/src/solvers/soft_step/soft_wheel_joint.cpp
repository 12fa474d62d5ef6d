// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Wheel joint in the soft step: B's anchor is held on a line fixed in A (the perpendicular row,
// C = p·d = 0), a spring of the joint's stiffness and damping acts along the line (a real
// spring, once per sub-step), a motor drives wB − wA with at most h·maxMotorTorque (h: KickTime),
// and limits keep the translation a·d within [lower, upper].
#include "solvers/soft_step/soft_joint.h"

namespace meff::detail
{

void PrepareSoft(WheelJoint& joint, SoftJointFrame& frame, const Position& poseA,
                 const Position& poseB, const SoftStepContext& context)
{
    const Rot qA(poseA.a);
    frame.rA0 = Mul(qA, joint.localAnchorA - joint.localCenterA);
    frame.rB0 = Mul(Rot(poseB.a), joint.localAnchorB - joint.localCenterB);
    frame.axis0 = Mul(qA, joint.localXAxisA);
    // The reaction's directions (GetReaction), as the Box2D back end's: the axes at the
    // step's start.
    joint.ax = frame.axis0;
    joint.ay = Cross(Real(1), frame.axis0);
    if (joint.stiffness > 0)
    {
        const Vec2 d0 = frame.deltaCenter + (frame.rB0 - frame.rA0);
        const RowBodies masses{{}, 0, {}, 0, frame.mA, frame.iA, frame.mB, frame.iB};
        const Real k = InverseEffectiveMass(LineRow(frame.axis0, d0, frame.rA0, frame.rB0), masses);
        SetSpring(frame, joint.stiffness, joint.damping, k, context);
    }
    else
    {
        joint.springImpulse = 0;
    }
    if (!joint.enableLimit)
    {
        joint.lowerImpulse = 0;
        joint.upperImpulse = 0;
    }
    if (!joint.enableMotor)
    {
        joint.motorImpulse = 0;
    }
}

void WarmStartSoft(const WheelJoint& joint, const SoftJointState& state, RowBodies& b)
{
    const auto [axis, perp] = SlideAxesNow(state);
    const SoftAnchors& at = state.at;
    const Real axialImpulse = joint.springImpulse + joint.lowerImpulse - joint.upperImpulse;
    ApplyRowImpulse(LineRow(perp, at.d, at.rA, at.rB), joint.impulse, b);
    ApplyRowImpulse(LineRow(axis, at.d, at.rA, at.rB), axialImpulse, b);
    ApplyRowImpulse(AngularRow(), joint.motorImpulse, b);
}

void SolveSoft(WheelJoint& joint, const SoftJointState& state, bool useBias, RowBodies& b)
{
    const SoftStepContext& context = state.context;
    const SoftAnchors& at = state.at;
    const auto [axis, perp] = SlideAxesNow(state);
    const RowJacobian axial = LineRow(axis, at.d, at.rA, at.rB);
    const Real axialMass = RowMass(InverseEffectiveMass(axial, b));
    const Real translation = Dot(axis, at.d);
    const Softness* spring = state.Spring(useBias);
    if (joint.stiffness > 0 && spring != nullptr)
    {
        SolveRow(axial, axialMass, RowTarget{spring->biasScale * translation, *spring},
                 joint.springImpulse, b);
    }
    if (joint.enableMotor)
    {
        const Real maxImpulse = context.KickTime() * joint.maxMotorTorque;
        SolveRow(AngularRow(), RowMass(b.iA + b.iB), RowTarget{-joint.motorSpeed, kRigid},
                 joint.motorImpulse, b, -maxImpulse, maxImpulse);
    }
    if (joint.enableLimit)
    {
        SolveRow(axial, axialMass,
                 OneSidedTarget(translation - joint.lowerTranslation, useBias, context.joint,
                                context.invH),
                 joint.lowerImpulse, b, 0, kMaxReal);
        SolveRow(Negated(axial), axialMass,
                 OneSidedTarget(joint.upperTranslation - translation, useBias, context.joint,
                                context.invH),
                 joint.upperImpulse, b, 0, kMaxReal);
    }
    const RowJacobian perpendicular = LineRow(perp, at.d, at.rA, at.rB);
    SolveRow(perpendicular, RowMass(InverseEffectiveMass(perpendicular, b)),
             EqualityTarget(Dot(perp, at.d), useBias, context.joint), joint.impulse, b);
}

void ScaleImpulses(WheelJoint& joint, Real factor)
{
    joint.impulse *= factor;
    joint.motorImpulse *= factor;
    joint.springImpulse *= factor;
    joint.lowerImpulse *= factor;
    joint.upperImpulse *= factor;
}

} // namespace meff::detail
