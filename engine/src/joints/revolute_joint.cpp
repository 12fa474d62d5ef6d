// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Revolute joint: Box2D 2.4.1's b2RevoluteJoint, re-derived in the scalar effective mass
// form (seed: effective-mass.md). Three kinds of row act on the two bodies:
//   point    C = (cB + rB) − (cA + rA) = 0,   Cdot = vB + wB×rB − vA − wA×rA
//   motor    Cdot = wB − wA − motorSpeed,      |λ| ≤ h·maxMotorTorque
//   limits   lower C = θ − θlo ≥ 0, upper C = θhi − θ ≥ 0, θ = aB − aA − referenceAngle
//   spring   C = θ − targetAngle, soft (Box2D v3's; not in Box2D 2.4.1, so with it off
//            nothing below changes: every spring term sits behind enableSpring)
// The angular rows have the Jacobian [0 0 −1 0 0 1], so their effective mass is the seed's
// k = 1/IA + 1/IB (no lever arm) and the "axial mass" is 1/k.
//
// Every expression keeps Box2D's floating-point operation order: the engine is checked
// against Box2D frame by frame at float precision, and a·b·c rounds differently from c·a·b.
#include "joints/joint.h"

#include <cmath>

namespace meff::detail
{

namespace
{

/// Relative velocity of B's anchor with respect to A's (the point row's Cdot).
Vec2 AnchorVelocity(Vec2 vA, Real wA, Vec2 rA, Vec2 vB, Real wB, Vec2 rB)
{
    return vB + Cross(wB, rB) - vA - Cross(wA, rA);
}

/// Applies the point impulse P to B and −P to A at their anchors (equal and opposite).
void ApplyPointImpulse(Vec2 P, Real mA, Real iA, Vec2 rA, Real mB, Real iB, Vec2 rB, Vec2& vA,
                       Real& wA, Vec2& vB, Real& wB)
{
    vA -= mA * P;
    wA -= iA * Cross(rA, P);
    vB += mB * P;
    wB += iB * Cross(rB, P);
}

/// λ = −(Jv + bias)/k for one scalar row; a row no body can move along (k = 0) takes none.
Real ScalarRowImpulse(Real jvPlusBias, Real k)
{
    return k > 0 ? -jvPlusBias / k : Real(0);
}

} // namespace

void InitVelocityConstraints(RevoluteJoint& joint, const JointBody& a, const JointBody& b,
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
    const Vec2 rA = joint.rA, rB = joint.rB;

    // K = J·M⁻¹·Jᵀ of the point rows with J = [−I  −rA⊥  I  rB⊥]. Its diagonal entries are
    // the seed's scalar k for n = x̂ and n = ŷ ((r×x̂)² = r.y², (r×ŷ)² = r.x²); the
    // off-diagonal couples the two rows through the shared rotations.
    joint.K.ex.x = mA + mB + rA.y * rA.y * iA + rB.y * rB.y * iB;
    joint.K.ey.x = -rA.y * rA.x * iA - rB.y * rB.x * iB;
    joint.K.ex.y = joint.K.ey.x;
    joint.K.ey.y = mA + mB + rA.x * rA.x * iA + rB.x * rB.x * iB;

    // Angular rows: k = 1/IA + 1/IB. When neither body can turn they are meaningless and
    // their impulses are dropped rather than warm-started.
    joint.axialMass = iA + iB;
    bool fixedRotation;
    if (joint.axialMass > 0)
    {
        joint.axialMass = Real(1) / joint.axialMass;
        fixedRotation = false;
    }
    else
    {
        fixedRotation = true;
    }

    // The limit rows use the angle at the start of the step (a speculative bias, see
    // SolveVelocityConstraints), not the angle during the iterations.
    joint.angle = aB - aA - joint.referenceAngle;
    if (!joint.enableLimit || fixedRotation)
    {
        joint.lowerImpulse = 0;
        joint.upperImpulse = 0;
    }
    if (!joint.enableMotor || fixedRotation)
    {
        joint.motorImpulse = 0;
    }
    if (!joint.enableSpring || fixedRotation)
    {
        joint.springImpulse = 0;
    }
    else
    {
        // The spring's soft row over the whole step h = dt on the angular row's mass.
        joint.spring = FrequencySpringSoftness(joint.hertz, joint.dampingRatio, data.step.dt);
    }

    if (data.step.solver.warmStarting)
    {
        // Impulses are force·dt: rescale last step's to this step's dt.
        const Real dtRatio = data.step.dtRatio;
        joint.impulse *= dtRatio;
        joint.motorImpulse *= dtRatio;
        joint.lowerImpulse *= dtRatio;
        joint.upperImpulse *= dtRatio;
        joint.springImpulse *= dtRatio;

        // The upper row's impulse acts with the opposite sign (its C is θhi − θ).
        Real axialImpulse = joint.motorImpulse + joint.lowerImpulse - joint.upperImpulse;
        if (joint.enableSpring)
        {
            axialImpulse += joint.springImpulse;
        }
        const Vec2 P(joint.impulse.x, joint.impulse.y);
        vA -= mA * P;
        wA -= iA * (Cross(rA, P) + axialImpulse);
        vB += mB * P;
        wB += iB * (Cross(rB, P) + axialImpulse);
    }
    else
    {
        joint.impulse = Vec2{};
        joint.motorImpulse = 0;
        joint.lowerImpulse = 0;
        joint.upperImpulse = 0;
        joint.springImpulse = 0;
    }

    data.velocities[joint.indexA] = {vA, wA};
    data.velocities[joint.indexB] = {vB, wB};
}

void SolveVelocityConstraints(RevoluteJoint& joint, SolverData& data)
{
    auto [vA, wA] = data.velocities[joint.indexA];
    auto [vB, wB] = data.velocities[joint.indexB];

    const Real mA = joint.invMassA, mB = joint.invMassB;
    const Real iA = joint.invIA, iB = joint.invIB;
    const Vec2 rA = joint.rA, rB = joint.rB;
    const bool fixedRotation = (iA + iB == 0);

    // Spring first (as Box2D v3), so that the motor and the limits bound what it does. A soft
    // row on the angular row's mass 1/(1/IA + 1/IB), its error the angle at the step's start:
    // Δλ = −m·(massScale·Cdot + biasScale·C) − impulseScale·λ (softness.h). Its fixed point
    // over the iterations is docs/soft-step.md's exactly damped step, whatever the warm start.
    if (joint.enableSpring && !fixedRotation)
    {
        const Real C = joint.angle - joint.targetAngle;
        const Real impulse =
            SpringRowImpulse(joint.spring, joint.axialMass, wB - wA, C, joint.springImpulse);
        joint.springImpulse += impulse;
        wA -= iA * impulse;
        wB += iB * impulse;
    }

    // Motor first, so that the limits (solved after it) win when they disagree.
    if (joint.enableMotor && !fixedRotation)
    {
        const Real Cdot = wB - wA - joint.motorSpeed;
        Real impulse = -joint.axialMass * Cdot;
        const Real oldImpulse = joint.motorImpulse;
        const Real maxImpulse = data.step.dt * joint.maxMotorTorque;
        joint.motorImpulse = Clamp(joint.motorImpulse + impulse, -maxImpulse, maxImpulse);
        impulse = joint.motorImpulse - oldImpulse;
        wA -= iA * impulse;
        wB += iB * impulse;
    }

    if (joint.enableLimit && !fixedRotation)
    {
        // Each limit is a one-sided row whose accumulated impulse stays ≥ 0. The bias
        // max(C, 0)/h is speculative: while the limit is still C away, the row allows just
        // the speed that closes the gap this step; once violated (C < 0) it adds no bias and
        // the position pass removes the error.
        {
            const Real C = joint.angle - joint.lowerAngle;
            const Real Cdot = wB - wA;
            Real impulse = -joint.axialMass * (Cdot + Max(C, Real(0)) * data.step.invDt);
            const Real oldImpulse = joint.lowerImpulse;
            joint.lowerImpulse = Max(joint.lowerImpulse + impulse, Real(0));
            impulse = joint.lowerImpulse - oldImpulse;
            wA -= iA * impulse;
            wB += iB * impulse;
        }
        // The upper row is written with C = θhi − θ and Cdot = wA − wB, so that its impulse
        // is also ≥ 0 when active; it therefore acts on the bodies with flipped signs.
        {
            const Real C = joint.upperAngle - joint.angle;
            const Real Cdot = wA - wB;
            Real impulse = -joint.axialMass * (Cdot + Max(C, Real(0)) * data.step.invDt);
            const Real oldImpulse = joint.upperImpulse;
            joint.upperImpulse = Max(joint.upperImpulse + impulse, Real(0));
            impulse = joint.upperImpulse - oldImpulse;
            wA += iA * impulse;
            wB -= iB * impulse;
        }
    }

    // Point constraint last: it is the joint's hard constraint and should be the most
    // accurate after each sweep.
    if (data.step.solver.blockJoints)
    {
        // Both rows at once: λ = −K⁻¹·Cdot.
        const Vec2 Cdot = AnchorVelocity(vA, wA, rA, vB, wB, rB);
        const Vec2 impulse = joint.K.Solve(-Cdot);
        joint.impulse.x += impulse.x;
        joint.impulse.y += impulse.y;
        ApplyPointImpulse(impulse, mA, iA, rA, mB, iB, rB, vA, wA, vB, wB);
    }
    else
    {
        // Two scalar rows, n = x̂ then n = ŷ, Gauss-Seidel: the y row sees the velocities the
        // x row left. Each λ = −Jv/k with the seed's k = mA + mB + iA(rA×n)² + iB(rB×n)²,
        // which are K's diagonal entries. Converges to the block answer over iterations.
        const Real kx = joint.K.ex.x;
        const Real ky = joint.K.ey.y;

        const Real cdotX = AnchorVelocity(vA, wA, rA, vB, wB, rB).x;
        const Real lambdaX = ScalarRowImpulse(cdotX, kx);
        joint.impulse.x += lambdaX;
        ApplyPointImpulse(Vec2(lambdaX, 0), mA, iA, rA, mB, iB, rB, vA, wA, vB, wB);

        const Real cdotY = AnchorVelocity(vA, wA, rA, vB, wB, rB).y;
        const Real lambdaY = ScalarRowImpulse(cdotY, ky);
        joint.impulse.y += lambdaY;
        ApplyPointImpulse(Vec2(0, lambdaY), mA, iA, rA, mB, iB, rB, vA, wA, vB, wB);
    }

    data.velocities[joint.indexA] = {vA, wA};
    data.velocities[joint.indexB] = {vB, wB};
}

bool SolvePositionConstraints(RevoluteJoint& joint, SolverData& data)
{
    auto [cA, aA] = data.positions[joint.indexA];
    auto [cB, aB] = data.positions[joint.indexB];

    const Tolerances& tol = data.step.tolerances;
    Real angularError = 0;
    Real positionError = 0;
    const bool fixedRotation = (joint.invIA + joint.invIB == 0);

    // Angular limit: one pseudo-impulse λ = −C/k (k = 1/IA + 1/IB) on the current angle.
    if (joint.enableLimit && !fixedRotation)
    {
        const Real angle = aB - aA - joint.referenceAngle;
        Real C = 0;
        if (std::abs(joint.upperAngle - joint.lowerAngle) < Real(2) * tol.angularSlop)
        {
            // Limits closer than the slop act as one equality row.
            C = Clamp(angle - joint.lowerAngle, -tol.maxAngularCorrection,
                      tol.maxAngularCorrection);
        }
        else if (angle <= joint.lowerAngle)
        {
            // Leave angularSlop of error in place, so that a resting joint does not jitter
            // between corrected and violated; cap the step so large errors converge smoothly.
            C = Clamp(angle - joint.lowerAngle + tol.angularSlop, -tol.maxAngularCorrection,
                      Real(0));
        }
        else if (angle >= joint.upperAngle)
        {
            C = Clamp(angle - joint.upperAngle - tol.angularSlop, Real(0),
                      tol.maxAngularCorrection);
        }
        const Real limitImpulse = -joint.axialMass * C;
        aA -= joint.invIA * limitImpulse;
        aB += joint.invIB * limitImpulse;
        angularError = std::abs(C);
    }

    // Point constraint on the anchors after the angular correction. The lever arms are
    // evaluated once per call, as Box2D does; the next call (iteration) re-evaluates them.
    {
        const Rot qA(aA), qB(aB);
        const Vec2 rA = Mul(qA, joint.localAnchorA - joint.localCenterA);
        const Vec2 rB = Mul(qB, joint.localAnchorB - joint.localCenterB);
        const Vec2 C = cB + rB - cA - rA;
        positionError = C.Length();

        const Real mA = joint.invMassA, mB = joint.invMassB;
        const Real iA = joint.invIA, iB = joint.invIB;

        // Same K as the velocity rows, from this call's lever arms (Box2D writes this one
        // with the inverse inertia first, which rounds differently; kept).
        Mat22 K;
        K.ex.x = mA + mB + iA * rA.y * rA.y + iB * rB.y * rB.y;
        K.ex.y = -iA * rA.x * rA.y - iB * rB.x * rB.y;
        K.ey.x = K.ex.y;
        K.ey.y = mA + mB + iA * rA.x * rA.x + iB * rB.x * rB.x;

        if (data.step.solver.blockJoints)
        {
            // Newton step on both rows: Δ = −K⁻¹·C.
            const Vec2 impulse = -K.Solve(C);
            cA -= mA * impulse;
            aA -= iA * Cross(rA, impulse);
            cB += mB * impulse;
            aB += iB * Cross(rB, impulse);
        }
        else
        {
            // Two scalar rows, x then y, each λ = −C/k with the seed's k (K's diagonal).
            // rA and rB stay fixed within the call (as in the block step), so the y row
            // cannot re-measure its error from the moved bodies; it takes the linearised
            // change instead: C.y grows by J_y·M⁻¹·J_xᵀ·λx = K.ex.y·λx. This is one
            // Gauss-Seidel sweep over the same linear system the block step solves exactly.
            const Real lambdaX = ScalarRowImpulse(C.x, K.ex.x);
            const Vec2 Px(lambdaX, 0);
            cA -= mA * Px;
            aA -= iA * Cross(rA, Px);
            cB += mB * Px;
            aB += iB * Cross(rB, Px);

            const Real cy = C.y + K.ex.y * lambdaX;
            const Real lambdaY = ScalarRowImpulse(cy, K.ey.y);
            const Vec2 Py(0, lambdaY);
            cA -= mA * Py;
            aA -= iA * Cross(rA, Py);
            cB += mB * Py;
            aB += iB * Cross(rB, Py);
        }
    }

    data.positions[joint.indexA] = {cA, aA};
    data.positions[joint.indexB] = {cB, aB};

    return positionError <= tol.linearSlop && angularError <= tol.angularSlop;
}

JointReaction GetReaction(const RevoluteJoint& joint, Real invDt)
{
    // Impulse over the step divided by the step: the mean force. The axial impulses combine
    // with the upper limit's sign flipped (see SolveVelocityConstraints).
    JointReaction reaction;
    reaction.force = invDt * Vec2(joint.impulse.x, joint.impulse.y);
    reaction.torque = invDt * (joint.motorImpulse + joint.lowerImpulse - joint.upperImpulse);
    if (joint.enableSpring)
    {
        reaction.torque += invDt * joint.springImpulse;
    }
    return reaction;
}

} // namespace meff::detail
