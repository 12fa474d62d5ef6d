// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Mouse joint in the soft step: a spring of the joint's stiffness and damping pulls B's
// grabbed point to the target (a real spring, once per sub-step), with at most
// h·maxForce per sub-step. Body A takes no part.
#include "solvers/soft_step/soft_joint.h"

namespace meff::detail
{

void PrepareSoft(MouseJoint& joint, SoftJointFrame& frame, const Position&, const Position& poseB,
                 const SoftStepContext& context)
{
    frame.mA = 0;
    frame.iA = 0;
    frame.rA0 = {};
    frame.rB0 = Mul(Rot(poseB.a), joint.localAnchorB - joint.localCenterB);
    frame.deltaCenter = poseB.c - joint.target; // C = cB + rB − target
    // The stiffness and damping were set from B's mass (N/m, N·s/m), so the spring acts on
    // the translational effective mass 1/mB, as Box2D 2.4.1's does.
    SetSpring(frame, joint.stiffness, joint.damping, frame.mB, context);
    // Box2D 2.4.1 damps the grabbed body's turning a little every step (b2MouseJoint).
    context.bodies->velocities[frame.indexB].w *= Real(0.98);
}

void WarmStartSoft(const MouseJoint& joint, const SoftJointState& state, RowBodies& b)
{
    ApplyPointImpulse(joint.impulse, {}, state.at.rB, b);
}

void SolveSoft(MouseJoint& joint, const SoftJointState& state, bool useBias, RowBodies& b)
{
    const Softness* spring = state.Spring(useBias);
    if (spring == nullptr)
    {
        return;
    }
    const SoftStepContext& context = state.context;
    // The target is a world point: only B's motion counts.
    const Vec2 C = state.dB.dp + state.frame.deltaCenter + state.at.rB;
    SolvePoint({}, state.at.rB, C, true, *spring, joint.impulse, b,
               context.step->solver.blockJoints, context.KickTime() * joint.maxForce);
}

void ScaleImpulses(MouseJoint& joint, Real factor)
{
    joint.impulse *= factor;
}

} // namespace meff::detail
