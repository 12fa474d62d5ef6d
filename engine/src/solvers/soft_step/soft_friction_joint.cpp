// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Friction joint in the soft step: the point and angular rows hold the relative velocity of
// B's anchor against A's, and of their turning, with at most h·maxForce and h·maxTorque per
// sub-step (h the sub-step's length, so the bound per step is the same force × the step; in
// velocity Verlet's half kicks, half a sub-step's).
// Friction rows are not soft: they restore no pose, so they have no bias and are solved rigid
// (kRigid) while solving and while relaxing alike.
#include "solvers/soft_step/soft_joint.h"

namespace meff::detail
{

void PrepareSoft(FrictionJoint& joint, SoftJointFrame& frame, const Position& poseA,
                 const Position& poseB, const SoftStepContext&)
{
    frame.rA0 = Mul(Rot(poseA.a), joint.localAnchorA - joint.localCenterA);
    frame.rB0 = Mul(Rot(poseB.a), joint.localAnchorB - joint.localCenterB);
}

void WarmStartSoft(const FrictionJoint& joint, const SoftJointState& state, RowBodies& b)
{
    ApplyPointImpulse(joint.linearImpulse, state.at.rA, state.at.rB, b);
    ApplyRowImpulse(AngularRow(), joint.angularImpulse, b);
}

void SolveSoft(FrictionJoint& joint, const SoftJointState& state, bool, RowBodies& b)
{
    const SoftStepContext& context = state.context;
    const Real h = context.KickTime();
    const Real maxTorque = h * joint.maxTorque;
    SolveRow(AngularRow(), RowMass(b.iA + b.iB), RowTarget{}, joint.angularImpulse, b, -maxTorque,
             maxTorque);
    SolvePoint(state.at.rA, state.at.rB, state.at.d, false, kRigid, joint.linearImpulse, b,
               context.step->solver.blockJoints, h * joint.maxForce);
}

void ScaleImpulses(FrictionJoint& joint, Real factor)
{
    joint.linearImpulse *= factor;
    joint.angularImpulse *= factor;
}

} // namespace meff::detail
