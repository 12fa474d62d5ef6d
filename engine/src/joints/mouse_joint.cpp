// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Mouse joint: Box2D 2.4.1's b2MouseJoint in the scalar effective mass form (seed:
// effective-mass.md). A soft, force-limited point constraint pulls body B's grabbed point p
// towards a world target t; body A takes no part:
//   C = p − t,   Cdot = vB + wB×rB,   J = [I  rB⊥] (body B only)
// Soft constraint (Catto): implicit Euler on the spring-damper m·Δv = −h·(k_s·C + c·v) gives
//   λ = −(K + γ·I)⁻¹·(Cdot + β·C + γ·λacc),  γ = 1/(h·(c + h·k_s)),  β = h·k_s·γ
// so each row's scalar k is the seed's mB + iB·(rB×n)² (K's diagonal) plus γ. The
// accumulated impulse stays within the disc |λacc| ≤ h·maxForce.
//
// Every expression keeps Box2D's floating-point operation order (frame-by-frame validation).
#include "joints/joint.h"

namespace meff::detail
{

namespace
{

/// Keeps the accumulated impulse within |λ| ≤ maxImpulse (Box2D's order: scale by max/|λ|).
void ClampToDisc(Vec2& accumulated, Real maxImpulse)
{
    if (accumulated.LengthSquared() > maxImpulse * maxImpulse)
    {
        accumulated *= maxImpulse / accumulated.Length();
    }
}

/// λ = −(Jv + bias)/k for one scalar row; a row nothing can move along (k = 0) takes none.
Real ScalarRowImpulse(Real jvPlusBias, Real k)
{
    return k > 0 ? -jvPlusBias / k : Real(0);
}

} // namespace

void InitVelocityConstraints(MouseJoint& joint, const JointBody& a, const JointBody& b,
                             SolverData& data)
{
    StoreJointBodies(joint, a, b);

    const auto [cB, aB] = data.positions[joint.indexB];
    auto [vB, wB] = data.velocities[joint.indexB];

    const Rot qB(aB);

    // γ has units of inverse mass, β of inverse time (see the header comment).
    const Real d = joint.damping;
    const Real k = joint.stiffness;
    const Real h = data.step.dt;
    joint.gamma = h * (d + h * k);
    if (joint.gamma != 0)
    {
        joint.gamma = Real(1) / joint.gamma;
    }
    joint.beta = h * k * joint.gamma;

    joint.rB = Mul(qB, joint.localAnchorB - joint.localCenterB);
    const Vec2 rB = joint.rB;
    joint.K.ex.x = joint.invMassB + joint.invIB * rB.y * rB.y + joint.gamma;
    joint.K.ex.y = -joint.invIB * rB.x * rB.y;
    joint.K.ey.x = joint.K.ex.y;
    joint.K.ey.y = joint.invMassB + joint.invIB * rB.x * rB.x + joint.gamma;
    joint.mass = joint.K.GetInverse();

    joint.C = cB + rB - joint.target;
    joint.C *= joint.beta;

    // Box2D damps the dragged body's spin by 2% every step here, so that it does not keep
    // spinning about the grabbed point. Mirrored, since results must agree step for step.
    wB *= Real(0.98);

    if (data.step.solver.warmStarting)
    {
        joint.impulse *= data.step.dtRatio;
        vB += joint.invMassB * joint.impulse;
        wB += joint.invIB * Cross(rB, joint.impulse);
    }
    else
    {
        joint.impulse = Vec2(0, 0);
    }

    data.velocities[joint.indexB] = {vB, wB};
}

void SolveVelocityConstraints(MouseJoint& joint, SolverData& data)
{
    auto [vB, wB] = data.velocities[joint.indexB];
    const Real maxImpulse = data.step.dt * joint.maxForce;

    if (data.step.solver.blockJoints)
    {
        // Both rows at once, then the disc clamp on the accumulated impulse.
        const Vec2 Cdot = vB + Cross(wB, joint.rB);
        Vec2 impulse = Mul(joint.mass, -(Cdot + joint.C + joint.gamma * joint.impulse));
        const Vec2 oldImpulse = joint.impulse;
        joint.impulse += impulse;
        ClampToDisc(joint.impulse, maxImpulse);
        impulse = joint.impulse - oldImpulse;
        vB += joint.invMassB * impulse;
        wB += joint.invIB * Cross(joint.rB, impulse);
    }
    else
    {
        // Two scalar rows, x then y, each with k = mB + iB·(rB×n)² + γ (K's diagonal); each
        // re-measures Cdot, clamps the accumulated vector to the disc and applies its change.
        for (int axis = 0; axis < 2; ++axis)
        {
            const Vec2 rhs = vB + Cross(wB, joint.rB) + joint.C + joint.gamma * joint.impulse;
            const Real lambda = axis == 0 ? ScalarRowImpulse(rhs.x, joint.K.ex.x)
                                          : ScalarRowImpulse(rhs.y, joint.K.ey.y);
            const Vec2 oldImpulse = joint.impulse;
            joint.impulse += axis == 0 ? Vec2(lambda, 0) : Vec2(0, lambda);
            ClampToDisc(joint.impulse, maxImpulse);
            const Vec2 impulse = joint.impulse - oldImpulse;
            vB += joint.invMassB * impulse;
            wB += joint.invIB * Cross(joint.rB, impulse);
        }
    }

    data.velocities[joint.indexB] = {vB, wB};
}

bool SolvePositionConstraints(MouseJoint&, SolverData&)
{
    return true; // soft: the position error acts through the velocity bias β·C only
}

JointReaction GetReaction(const MouseJoint& joint, Real invDt)
{
    JointReaction reaction;
    reaction.force = invDt * joint.impulse;
    reaction.torque = invDt * Real(0);
    return reaction;
}

} // namespace meff::detail
