// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Prismatic joint in the soft step: B's anchor slides along an axis fixed in A and B keeps its
// angle relative to A. With d the anchors' gap and a, p the axis and its perpendicular turned
// with A since the step began:
//   perpendicular  C = p·d = 0,   angular C = θ0 + (rotation since the start) = 0
//   motor          a·(vB − vA) + a2·wB − a1·wA = motorSpeed, |λ| ≤ h·maxMotorForce (h: KickTime)
//   limits         lower C = a·d − lower ≥ 0, upper C = upper − a·d ≥ 0
//   spring         C = a·d − targetTranslation, when enabled: a real spring
//                  (FrequencySpringSoftness) on the axial row, once per kick
// The perpendicular and angular rows form a 2×2 block (its diagonal the rows' scalar k), or
// two scalar rows with SolverSettings::blockJoints off.
#include "solvers/soft_step/soft_joint.h"

namespace meff::detail
{

void PrepareSoft(PrismaticJoint& joint, SoftJointFrame& frame, const Position& poseA,
                 const Position& poseB, const SoftStepContext& context)
{
    const Rot qA(poseA.a);
    frame.rA0 = Mul(qA, joint.localAnchorA - joint.localCenterA);
    frame.rB0 = Mul(Rot(poseB.a), joint.localAnchorB - joint.localCenterB);
    frame.angle0 = poseB.a - poseA.a - joint.referenceAngle;
    frame.axis0 = Mul(qA, joint.localXAxisA);
    // The reaction's directions (GetReaction), as the Box2D back end's: the axes at the
    // step's start.
    joint.axis = frame.axis0;
    joint.perp = Cross(Real(1), frame.axis0);
    if (joint.enableSpring)
    {
        SetFrequencySpring(frame, joint.hertz, joint.dampingRatio, context);
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

void WarmStartSoft(const PrismaticJoint& joint, const SoftJointState& state, RowBodies& b)
{
    const auto [axis, perp] = SlideAxesNow(state);
    const SoftAnchors& at = state.at;
    // The upper row's impulse acts with the opposite sign (its C is upper − translation).
    const Real axialImpulse =
        joint.springImpulse + joint.motorImpulse + joint.lowerImpulse - joint.upperImpulse;
    ApplyRowImpulse(LineRow(perp, at.d, at.rA, at.rB), joint.impulse.x, b);
    ApplyRowImpulse(AngularRow(), joint.impulse.y, b);
    ApplyRowImpulse(LineRow(axis, at.d, at.rA, at.rB), axialImpulse, b);
}

void SolveSoft(PrismaticJoint& joint, const SoftJointState& state, bool useBias, RowBodies& b)
{
    const SoftStepContext& context = state.context;
    const SoftAnchors& at = state.at;
    const auto [axis, perp] = SlideAxesNow(state);
    const RowJacobian axial = LineRow(axis, at.d, at.rA, at.rB);
    const Real axialMass = RowMass(InverseEffectiveMass(axial, b));
    // The spring first, so that the motor and the limits bound it (as Box2D v3 orders them).
    const Softness* spring = state.Spring(useBias);
    if (joint.enableSpring && spring != nullptr)
    {
        const Real C = Dot(axis, at.d) - joint.targetTranslation;
        SolveRow(axial, axialMass, RowTarget{spring->biasScale * C, *spring}, joint.springImpulse,
                 b);
    }
    if (joint.enableMotor)
    {
        const Real maxImpulse = context.KickTime() * joint.maxMotorForce;
        SolveRow(axial, axialMass, RowTarget{-joint.motorSpeed, kRigid}, joint.motorImpulse, b,
                 -maxImpulse, maxImpulse);
    }
    if (joint.enableLimit)
    {
        const Real translation = Dot(axis, at.d);
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
    const Vec2 C{Dot(perp, at.d), state.frame.angle0 + state.Rotation()};
    const RowTarget target = EqualityTarget(0, useBias, context.joint);
    const Vec2 bias = useBias ? BiasOf(context.joint, C) : Vec2{};
    if (!context.step->solver.blockJoints)
    {
        SolveRow(perpendicular, RowMass(InverseEffectiveMass(perpendicular, b)),
                 {bias.x, target.softness}, joint.impulse.x, b);
        SolveRow(AngularRow(), RowMass(b.iA + b.iB), {bias.y, target.softness}, joint.impulse.y, b);
        return;
    }
    // K = J·M⁻¹·Jᵀ of the two rows; when neither body can turn, k22 = 1 keeps K invertible
    // (the angular row then moves nothing).
    Mat22 K;
    K.ex.x = InverseEffectiveMass(perpendicular, b);
    K.ex.y = b.iA * perpendicular.aA + b.iB * perpendicular.aB;
    K.ey.x = K.ex.y;
    K.ey.y = b.iA + b.iB > 0 ? b.iA + b.iB : Real(1);
    const Vec2 cdot{RowVelocity(perpendicular, b), b.wB - b.wA};
    const Vec2 x = K.Solve(target.softness.massScale * cdot + bias);
    const Vec2 impulse = -x - target.softness.impulseScale * joint.impulse;
    joint.impulse += impulse;
    ApplyRowImpulse(perpendicular, impulse.x, b);
    ApplyRowImpulse(AngularRow(), impulse.y, b);
}

void ScaleImpulses(PrismaticJoint& joint, Real factor)
{
    joint.impulse *= factor;
    joint.motorImpulse *= factor;
    joint.lowerImpulse *= factor;
    joint.upperImpulse *= factor;
    joint.springImpulse *= factor;
}

} // namespace meff::detail
