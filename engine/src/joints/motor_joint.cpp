// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Motor joint: Box2D 2.4.1's b2MotorJoint in the scalar effective mass form (seed:
// effective-mass.md). It drives body B's pose relative to body A towards a target with a
// bounded force and torque, like friction that pulls towards a pose instead of towards rest:
//   linear   Cdot = vB + wB×rB − vA − wA×rA + (β/h)·eₗ,  |λacc| ≤ h·maxForce (a disc)
//   angular  Cdot = wB − wA + (β/h)·e_θ,                |λacc| ≤ h·maxTorque
// with rA = A's offset point − A's centre, rB = B's origin − B's centre, the pose errors
// eₗ = (cB + rB) − (cA + rA) and e_θ = aB − aA − angularOffset taken at the step's start, and
// β the correction factor. The linear rows' K = J·M⁻¹·Jᵀ has the seed's scalar k on its
// diagonal (k_x = mA + mB + iA·rA.y² + iB·rB.y², k_y with r.x²); the angular row's k is
// iA + iB. There is no position pass: the error enters only through the velocity bias.
//
// Every expression keeps Box2D's floating-point operation order (frame-by-frame validation).
#include "joints/bounded_rows.h"

namespace meff::detail
{

void InitVelocityConstraints(MotorJoint& joint, const JointBody& a, const JointBody& b,
                             SolverData& data)
{
    StoreJointBodies(joint, a, b);

    const auto [cA, aA] = data.positions[joint.indexA];
    auto [vA, wA] = data.velocities[joint.indexA];
    const auto [cB, aB] = data.positions[joint.indexB];
    auto [vB, wB] = data.velocities[joint.indexB];

    const Rot qA(aA), qB(aB);
    joint.rA = Mul(qA, joint.linearOffset - joint.localCenterA);
    joint.rB = Mul(qB, -joint.localCenterB);
    SetBoundedMasses(joint);

    joint.linearError = cB + joint.rB - cA - joint.rA;
    joint.angularError = aB - aA - joint.angularOffset;

    WarmStartBounded(joint, data.step, vA, wA, vB, wB);

    data.velocities[joint.indexA] = {vA, wA};
    data.velocities[joint.indexB] = {vB, wB};
}

void SolveVelocityConstraints(MotorJoint& joint, SolverData& data)
{
    auto [vA, wA] = data.velocities[joint.indexA];
    auto [vB, wB] = data.velocities[joint.indexB];

    const Real h = data.step.dt;
    const Real invH = data.step.invDt;

    SolveBoundedAngle(joint, wB - wA + invH * joint.correctionFactor * joint.angularError,
                      h * joint.maxTorque, wA, wB);

    // Velocity of B's origin relative to A's offset point plus the correction bias.
    const auto cdot = [&](Vec2 vA1, Real wA1, Vec2 vB1, Real wB1)
    {
        return vB1 + Cross(wB1, joint.rB) - vA1 - Cross(wA1, joint.rA) +
               invH * joint.correctionFactor * joint.linearError;
    };
    SolveBoundedPoint(joint, h * joint.maxForce, data.step.solver.blockJoints, cdot, vA, wA, vB,
                      wB);

    data.velocities[joint.indexA] = {vA, wA};
    data.velocities[joint.indexB] = {vB, wB};
}

bool SolvePositionConstraints(MotorJoint&, SolverData&)
{
    return true; // no position rows: the correction factor acts in the velocity pass
}

JointReaction GetReaction(const MotorJoint& joint, Real invDt)
{
    JointReaction reaction;
    reaction.force = invDt * joint.linearImpulse;
    reaction.torque = invDt * joint.angularImpulse;
    return reaction;
}

} // namespace meff::detail
