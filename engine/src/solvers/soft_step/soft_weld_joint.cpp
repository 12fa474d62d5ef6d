// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Weld joint in the soft step: B's anchor held on A's (the point rows) and B's angle held to
// A's (C = θ0 + rotation since the start), the angle by the joint's own spring when it has
// stiffness (a real spring: solving and relaxing alike), rigidly otherwise.
#include "solvers/soft_step/soft_joint.h"

namespace meff::detail
{

void PrepareSoft(WeldJoint& joint, SoftJointFrame& frame, const Position& poseA,
                 const Position& poseB, const SoftStepContext& context)
{
    frame.rA0 = Mul(Rot(poseA.a), joint.localAnchorA - joint.localCenterA);
    frame.rB0 = Mul(Rot(poseB.a), joint.localAnchorB - joint.localCenterB);
    frame.angle0 = poseB.a - poseA.a - joint.referenceAngle;
    if (joint.stiffness > 0)
    {
        SetSpring(frame, joint.stiffness, joint.damping, frame.iA + frame.iB, context);
    }
}

void WarmStartSoft(const WeldJoint& joint, const SoftJointState& state, RowBodies& b)
{
    ApplyPointImpulse({joint.impulse.x, joint.impulse.y}, state.at.rA, state.at.rB, b);
    ApplyRowImpulse(AngularRow(), joint.impulse.z, b);
}

void SolveSoft(WeldJoint& joint, const SoftJointState& state, bool useBias, RowBodies& b)
{
    const SoftStepContext& context = state.context;
    const Real angle = state.frame.angle0 + state.Rotation();
    if (joint.stiffness == 0)
    {
        SolveRow(AngularRow(), RowMass(b.iA + b.iB), EqualityTarget(angle, useBias, context.joint),
                 joint.impulse.z, b);
    }
    else if (const Softness* spring = state.Spring(useBias))
    {
        SolveRow(AngularRow(), RowMass(b.iA + b.iB), RowTarget{spring->biasScale * angle, *spring},
                 joint.impulse.z, b);
    }
    Vec2 point{joint.impulse.x, joint.impulse.y};
    SolvePoint(state.at.rA, state.at.rB, state.at.d, useBias, context.joint, point, b,
               context.step->solver.blockJoints);
    joint.impulse.x = point.x;
    joint.impulse.y = point.y;
}

void ScaleImpulses(WeldJoint& joint, Real factor)
{
    joint.impulse.x *= factor;
    joint.impulse.y *= factor;
    joint.impulse.z *= factor;
}

} // namespace meff::detail
