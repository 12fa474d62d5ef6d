// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Motor joint in the soft step: drives B to a pose relative to A (the linear and angular
// offsets) with at most h·maxForce and h·maxTorque per sub-step. While solving, a velocity
// bias closes correctionFactor of the pose error per step (Box2D 2.4.1's correction, spread
// over the sub-steps); while relaxing the rows only hold the relative velocity.
#include "solvers/soft_step/soft_joint.h"

namespace meff::detail
{

void PrepareSoft(MotorJoint& joint, SoftJointFrame& frame, const Position& poseA,
                 const Position& poseB, const SoftStepContext&)
{
    frame.rA0 = Mul(Rot(poseA.a), joint.linearOffset - joint.localCenterA);
    frame.rB0 = Mul(Rot(poseB.a), -joint.localCenterB);
    frame.angle0 = poseB.a - poseA.a - joint.angularOffset;
}

void WarmStartSoft(const MotorJoint& joint, const SoftJointState& state, RowBodies& b)
{
    ApplyPointImpulse(joint.linearImpulse, state.at.rA, state.at.rB, b);
    ApplyRowImpulse(AngularRow(), joint.angularImpulse, b);
}

void SolveSoft(MotorJoint& joint, const SoftJointState& state, bool useBias, RowBodies& b)
{
    const SoftStepContext& context = state.context;
    const Real rate = joint.correctionFactor * context.step->invDt;
    const Real maxTorque = context.KickTime() * joint.maxTorque;
    const Real angularBias = useBias ? rate * (state.frame.angle0 + state.Rotation()) : Real(0);
    SolveRow(AngularRow(), RowMass(b.iA + b.iB), RowTarget{angularBias, kRigid},
             joint.angularImpulse, b, -maxTorque, maxTorque);
    const Softness correction{rate, 1, 0};
    SolvePoint(state.at.rA, state.at.rB, state.at.d, useBias, correction, joint.linearImpulse, b,
               context.step->solver.blockJoints, context.KickTime() * joint.maxForce);
}

void ScaleImpulses(MotorJoint& joint, Real factor)
{
    joint.linearImpulse *= factor;
    joint.angularImpulse *= factor;
}

} // namespace meff::detail
