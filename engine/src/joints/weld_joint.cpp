// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Weld joint: Box2D 2.4.1's b2WeldJoint in the scalar effective mass form (seed:
// effective-mass.md). Three rows glue body B to body A:
//   point x, y   C = (cB + rB) − (cA + rA) = 0,   Cdot = vB + wB×rB − vA − wA×rA
//   angle        C = aB − aA − referenceAngle,     Cdot = wB − wA, J = [0 0 −1 0 0 1]
// K = J·M⁻¹·Jᵀ is 3×3; its diagonal entries are the seed's scalar k of each row
//   k_x = mA + mB + iA·rA.y² + iB·rB.y²,  k_y = mA + mB + iA·rA.x² + iB·rB.x²,  k_θ = iA + iB
// ((r×x̂)² = r.y², (r×ŷ)² = r.x²). Rigid (stiffness = 0): the three rows are solved together
// (Box2D) or as three scalar rows (blockJoints off). Soft: the angle is a scalar spring row
// and the point a 2×2 block (or two scalar rows).
//
// Every expression keeps Box2D's floating-point operation order (frame-by-frame validation).
#include "joints/joint.h"

#include <cmath>

namespace meff::detail
{

namespace
{

/// Velocity of B's anchor relative to A's (the point rows' Cdot).
Vec2 AnchorVelocity(const WeldJoint& j, Vec2 vA, Real wA, Vec2 vB, Real wB)
{
    return vB + Cross(wB, j.rB) - vA - Cross(wA, j.rA);
}

/// Applies the point impulse P and the angular impulse L to B, and their opposites to A.
void ApplyImpulse(const WeldJoint& j, Vec2 P, Real L, Vec2& vA, Real& wA, Vec2& vB, Real& wB)
{
    vA -= j.invMassA * P;
    wA -= j.invIA * (Cross(j.rA, P) + L);
    vB += j.invMassB * P;
    wB += j.invIB * (Cross(j.rB, P) + L);
}

/// λ = −(Jv + bias)/k for one scalar row; a row no body can move along (k = 0) takes none.
Real ScalarRowImpulse(Real jvPlusBias, Real k)
{
    return k > 0 ? -jvPlusBias / k : Real(0);
}

/// K = J·M⁻¹·Jᵀ for lever arms rA, rB, written in Box2D's operation order.
Mat33 EffectiveMassMatrix(Vec2 rA, Vec2 rB, Real mA, Real mB, Real iA, Real iB)
{
    Mat33 K;
    K.ex.x = mA + mB + rA.y * rA.y * iA + rB.y * rB.y * iB;
    K.ey.x = -rA.y * rA.x * iA - rB.y * rB.x * iB;
    K.ez.x = -rA.y * iA - rB.y * iB;
    K.ex.y = K.ey.x;
    K.ey.y = mA + mB + rA.x * rA.x * iA + rB.x * rB.x * iB;
    K.ez.y = rA.x * iA + rB.x * iB;
    K.ex.z = K.ez.x;
    K.ey.z = K.ez.y;
    K.ez.z = iA + iB;
    return K;
}

/// The point rows as two scalar Gauss-Seidel rows, x then y; each re-measures Cdot after the
/// previous row's impulse and uses the seed's k (K's diagonal).
void SolvePointRowsScalar(WeldJoint& j, Vec2& vA, Real& wA, Vec2& vB, Real& wB)
{
    const Real lambdaX = ScalarRowImpulse(AnchorVelocity(j, vA, wA, vB, wB).x, j.K.ex.x);
    j.impulse.x += lambdaX;
    ApplyImpulse(j, Vec2(lambdaX, 0), 0, vA, wA, vB, wB);

    const Real lambdaY = ScalarRowImpulse(AnchorVelocity(j, vA, wA, vB, wB).y, j.K.ey.y);
    j.impulse.y += lambdaY;
    ApplyImpulse(j, Vec2(0, lambdaY), 0, vA, wA, vB, wB);
}

} // namespace

void InitVelocityConstraints(WeldJoint& joint, const JointBody& a, const JointBody& b,
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

    const Real mA = joint.invMassA, mB = joint.invMassB;
    const Real iA = joint.invIA, iB = joint.invIB;
    joint.K = EffectiveMassMatrix(joint.rA, joint.rB, mA, mB, iA, iB);

    if (joint.stiffness > 0)
    {
        // Soft angle row (Catto's soft constraints, as the distance joint's spring): implicit
        // Euler on the torsional spring-damper gives λ = −(Cdot + bias + γ·λacc)/(k + γ) with
        //   γ = 1/(h·(c + h·k_s)),  bias = C·h·k_s·γ,  k = iA + iB.
        joint.mass = joint.K.GetInverse22();
        Real invM = iA + iB;
        const Real C = aB - aA - joint.referenceAngle;
        const Real d = joint.damping;
        const Real k = joint.stiffness;
        const Real h = data.step.dt;
        joint.gamma = h * (d + h * k);
        joint.gamma = joint.gamma != 0 ? Real(1) / joint.gamma : Real(0);
        joint.bias = C * h * k * joint.gamma;
        invM += joint.gamma;
        joint.mass.ez.z = invM != 0 ? Real(1) / invM : Real(0);
    }
    else if (joint.K.ez.z == 0)
    {
        // Neither body can turn: only the point block is meaningful.
        joint.mass = joint.K.GetInverse22();
        joint.gamma = 0;
        joint.bias = 0;
    }
    else
    {
        joint.mass = joint.K.GetSymInverse33();
        joint.gamma = 0;
        joint.bias = 0;
    }

    if (data.step.solver.warmStarting)
    {
        // Impulses are force·dt: rescale last step's to this step's dt.
        joint.impulse *= data.step.dtRatio;
        ApplyImpulse(joint, Vec2(joint.impulse.x, joint.impulse.y), joint.impulse.z, vA, wA, vB,
                     wB);
    }
    else
    {
        joint.impulse = Vec3();
    }

    data.velocities[joint.indexA] = {vA, wA};
    data.velocities[joint.indexB] = {vB, wB};
}

void SolveVelocityConstraints(WeldJoint& joint, SolverData& data)
{
    auto [vA, wA] = data.velocities[joint.indexA];
    auto [vB, wB] = data.velocities[joint.indexB];
    const bool block = data.step.solver.blockJoints;

    if (joint.stiffness > 0)
    {
        // Spring row on the angle first (see InitVelocityConstraints for γ and bias) ...
        const Real Cdot2 = wB - wA;
        const Real impulse2 =
            -joint.mass.ez.z * (Cdot2 + joint.bias + joint.gamma * joint.impulse.z);
        joint.impulse.z += impulse2;
        wA -= joint.invIA * impulse2;
        wB += joint.invIB * impulse2;

        // ... then the rigid point, as a block λ = −K₂₂⁻¹·Cdot or as two scalar rows.
        if (block)
        {
            const Vec2 Cdot1 = AnchorVelocity(joint, vA, wA, vB, wB);
            const Vec2 impulse1 = -Mul22(joint.mass, Cdot1);
            joint.impulse.x += impulse1.x;
            joint.impulse.y += impulse1.y;
            const Vec2 P = impulse1;
            vA -= joint.invMassA * P;
            wA -= joint.invIA * Cross(joint.rA, P);
            vB += joint.invMassB * P;
            wB += joint.invIB * Cross(joint.rB, P);
        }
        else
        {
            SolvePointRowsScalar(joint, vA, wA, vB, wB);
        }
    }
    else if (block)
    {
        // All three rows at once: λ = −K⁻¹·Cdot.
        const Vec2 Cdot1 = AnchorVelocity(joint, vA, wA, vB, wB);
        const Real Cdot2 = wB - wA;
        const Vec3 Cdot(Cdot1.x, Cdot1.y, Cdot2);
        const Vec3 impulse = -Mul(joint.mass, Cdot);
        joint.impulse += impulse;
        ApplyImpulse(joint, Vec2(impulse.x, impulse.y), impulse.z, vA, wA, vB, wB);
    }
    else
    {
        // Three scalar Gauss-Seidel rows: the angle (k = iA + iB), then the point's x and y
        // (last, so the hard point constraint is the most accurate after each sweep).
        // Converges to the block answer over iterations.
        const Real lambdaZ = ScalarRowImpulse(wB - wA, joint.K.ez.z);
        joint.impulse.z += lambdaZ;
        ApplyImpulse(joint, Vec2(0, 0), lambdaZ, vA, wA, vB, wB);
        SolvePointRowsScalar(joint, vA, wA, vB, wB);
    }

    data.velocities[joint.indexA] = {vA, wA};
    data.velocities[joint.indexB] = {vB, wB};
}

bool SolvePositionConstraints(WeldJoint& joint, SolverData& data)
{
    auto [cA, aA] = data.positions[joint.indexA];
    auto [cB, aB] = data.positions[joint.indexB];

    const Rot qA(aA), qB(aB);
    const Real mA = joint.invMassA, mB = joint.invMassB;
    const Real iA = joint.invIA, iB = joint.invIB;
    // Lever arms and K from this call's pose, evaluated once per call as Box2D does.
    const Vec2 rA = Mul(qA, joint.localAnchorA - joint.localCenterA);
    const Vec2 rB = Mul(qB, joint.localAnchorB - joint.localCenterB);
    const Mat33 K = EffectiveMassMatrix(rA, rB, mA, mB, iA, iB);

    const Vec2 C1 = cB + rB - cA - rA;
    const Real positionError = C1.Length();
    Real angularError = 0;
    // A soft weld corrects only the point; its angle error is the spring's stored energy.
    const bool soft = joint.stiffness > 0;
    const Real C2 = soft ? Real(0) : aB - aA - joint.referenceAngle;
    if (!soft)
    {
        angularError = std::abs(C2);
    }

    // The Newton step's impulse (point x, point y, angle), applied below.
    Vec3 impulse;
    if (data.step.solver.blockJoints)
    {
        if (!soft && K.ez.z > 0)
        {
            impulse = -K.Solve33(Vec3(C1.x, C1.y, C2));
        }
        else
        {
            const Vec2 impulse2 = -K.Solve22(C1);
            impulse = Vec3(impulse2.x, impulse2.y, 0);
        }
    }
    else
    {
        // Scalar rows in the velocity pass's order (angle, x, y), each λ = −C/k with the
        // seed's k (K's diagonal). The lever arms stay fixed within the call (as in the block
        // step), so each later row takes the linearised change of its error from the earlier
        // rows, C_i += K_ij·λ_j: one Gauss-Seidel sweep over the system the block step solves.
        const Real lambdaZ = soft ? Real(0) : ScalarRowImpulse(C2, K.ez.z);
        const Real cx = C1.x + K.ez.x * lambdaZ;
        const Real lambdaX = ScalarRowImpulse(cx, K.ex.x);
        const Real cy = C1.y + K.ez.y * lambdaZ + K.ex.y * lambdaX;
        const Real lambdaY = ScalarRowImpulse(cy, K.ey.y);
        impulse = Vec3(lambdaX, lambdaY, lambdaZ);
    }

    const Vec2 P(impulse.x, impulse.y);
    cA -= mA * P;
    cB += mB * P;
    if (soft)
    {
        // Box2D's soft branch adds no angular impulse term (the sum would round the same for
        // + 0, but keep its expression).
        aA -= iA * Cross(rA, P);
        aB += iB * Cross(rB, P);
    }
    else
    {
        aA -= iA * (Cross(rA, P) + impulse.z);
        aB += iB * (Cross(rB, P) + impulse.z);
    }

    data.positions[joint.indexA] = {cA, aA};
    data.positions[joint.indexB] = {cB, aB};

    const Tolerances& tol = data.step.tolerances;
    return positionError <= tol.linearSlop && angularError <= tol.angularSlop;
}

JointReaction GetReaction(const WeldJoint& joint, Real invDt)
{
    JointReaction reaction;
    reaction.force = invDt * Vec2(joint.impulse.x, joint.impulse.y);
    reaction.torque = invDt * joint.impulse.z;
    return reaction;
}

} // namespace meff::detail
