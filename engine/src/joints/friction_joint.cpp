// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Friction joint: Box2D 2.4.1's b2FrictionJoint in the scalar effective mass form (seed:
// effective-mass.md). Top-down friction: it resists the relative motion of B's anchor against
// A's and their relative turning, each with a bounded impulse, and restores nothing:
//   linear   Cdot = vB + wB×rB − vA − wA×rA,  |λacc| ≤ h·maxForce (a disc)
//   angular  Cdot = wB − wA,                  |λacc| ≤ h·maxTorque
// with rA, rB the anchors from the centres of mass. The point rows' K = J·M⁻¹·Jᵀ has the
// seed's scalar k on its diagonal (k_x = mA + mB + iA·rA.y² + iB·rB.y², k_y with r.x²); the
// angular row's k is iA + iB (bounded_rows.h). A body held to the ground by it and sliding
// at speed v slows at maxForce/m until it stops (no bias, no position pass).
//
// Every expression keeps Box2D's floating-point operation order (frame-by-frame validation).
#include "joints/bounded_rows.h"

namespace meff::detail
{

void InitVelocityConstraints(FrictionJoint& joint, const JointBody& a, const JointBody& b,
                             SolverData& data)
{
    StoreJointBodies(joint, a, b);

    const Real aA = data.positions[joint.indexA].a;
    auto [vA, wA] = data.velocities[joint.indexA];
    const Real aB = data.positions[joint.indexB].a;
    auto [vB, wB] = data.velocities[joint.indexB];

    const Rot qA(aA), qB(aB);
    joint.rA = Mul(qA, joint.localAnchorA - joint.localCenterA);
    joint.rB = Mul(qB, joint.localAnchorB - joint.localCenterB);
    SetBoundedMasses(joint);
    WarmStartBounded(joint, data.step, vA, wA, vB, wB);

    data.velocities[joint.indexA] = {vA, wA};
    data.velocities[joint.indexB] = {vB, wB};
}

void SolveVelocityConstraints(FrictionJoint& joint, SolverData& data)
{
    auto [vA, wA] = data.velocities[joint.indexA];
    auto [vB, wB] = data.velocities[joint.indexB];

    const Real h = data.step.dt;
    SolveBoundedAngle(joint, wB - wA, h * joint.maxTorque, wA, wB);
    const auto cdot = [&](Vec2 vA1, Real wA1, Vec2 vB1, Real wB1)
    { return vB1 + Cross(wB1, joint.rB) - vA1 - Cross(wA1, joint.rA); };
    SolveBoundedPoint(joint, h * joint.maxForce, data.step.solver.blockJoints, cdot, vA, wA, vB,
                      wB);

    data.velocities[joint.indexA] = {vA, wA};
    data.velocities[joint.indexB] = {vB, wB};
}

bool SolvePositionConstraints(FrictionJoint&, SolverData&)
{
    return true; // friction only removes velocity: nothing to correct
}

JointReaction GetReaction(const FrictionJoint& joint, Real invDt)
{
    JointReaction reaction;
    reaction.force = invDt * joint.linearImpulse;
    reaction.torque = invDt * joint.angularImpulse;
    return reaction;
}

} // namespace meff::detail
