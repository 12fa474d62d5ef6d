// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Wheel joint: Box2D 2.4.1's b2WheelJoint in the scalar effective mass form (seed:
// effective-mass.md). Body B's anchor (the wheel's hub) stays on an axis line fixed in body A
// (the chassis' suspension direction); B turns freely. With d = pB − pA, ax the axis and ay
// its perpendicular (line_rows.h):
//   point-to-line  C = ay·d = 0            k = 1/mA + 1/mB + sAy²/IA + sBy²/IB
//   spring         soft row along ax        k = 1/mA + 1/mB + sAx²/IA + sBx²/IB (axial)
//   motor          Cdot = wB − wA − motorSpeed, |λ| ≤ h·maxMotorTorque, k = 1/IA + 1/IB
//   limits         lower C = ax·d − lower ≥ 0, upper C = upper − ax·d ≥ 0 (axial k)
// Every row is scalar in Box2D already, so SolverSettings::blockJoints does not apply.
//
// Box2D 2.4.1's position pass has two quirks, mirrored because the engines must agree bit for
// bit: the limit row's lever terms use the axis of the step's start (not the fresh one), and
// the point-to-line row's mass uses the lever terms of the step's start while its impulse is
// applied with the fresh ones. Both only change how fast the position error converges.
//
// Every expression keeps Box2D's floating-point operation order (frame-by-frame validation).
#include "joints/line_rows.h"

#include <cmath>

namespace meff::detail
{

void InitVelocityConstraints(WheelJoint& joint, const JointBody& a, const JointBody& b,
                             SolverData& data)
{
    StoreJointBodies(joint, a, b);

    const auto [cA, aA] = data.positions[joint.indexA];
    auto [vA, wA] = data.velocities[joint.indexA];
    const auto [cB, aB] = data.positions[joint.indexB];
    auto [vB, wB] = data.velocities[joint.indexB];

    const Rot qA(aA), qB(aB);
    const Vec2 rA = Mul(qA, joint.localAnchorA - joint.localCenterA);
    const Vec2 rB = Mul(qB, joint.localAnchorB - joint.localCenterB);
    const Vec2 d = cB + rB - cA - rA;

    // Point-to-line row: seed k along ay; mass = 1/k.
    const LineRowMasses masses = Masses(joint);
    joint.ay = Mul(qA, joint.localYAxisA);
    const LineRow perpendicular = MakeLineRow(joint.ay, d, rA, rB, masses);
    joint.sAy = perpendicular.sA;
    joint.sBy = perpendicular.sB;
    joint.mass = perpendicular.k;
    if (joint.mass > 0)
    {
        joint.mass = Real(1) / joint.mass;
    }

    // Axial rows (spring, limits): seed k along ax.
    joint.ax = Mul(qA, joint.localXAxisA);
    const LineRow axial = MakeLineRow(joint.ax, d, rA, rB, masses);
    joint.sAx = axial.sA;
    joint.sBx = axial.sB;
    joint.axialMass = axial.k > 0 ? Real(1) / axial.k : Real(0);

    joint.springMass = 0;
    joint.bias = 0;
    joint.gamma = 0;
    if (joint.stiffness > 0 && axial.k > 0)
    {
        // Soft row (Catto's soft constraints), as the distance joint's spring: implicit Euler
        // on m·Δv = −h·(k_s·C + c·v) gives λ = −(Cdot + bias + γ·λacc)/(k + γ) with
        //   γ = 1/(h·(c + h·k_s)),  bias = C·h·k_s·γ.
        const Real C = Dot(d, joint.ax);
        const Real h = data.step.dt;
        joint.gamma = h * (joint.damping + h * joint.stiffness);
        if (joint.gamma > 0)
        {
            joint.gamma = Real(1) / joint.gamma;
        }
        joint.bias = C * h * joint.stiffness * joint.gamma;
        joint.springMass = axial.k + joint.gamma;
        if (joint.springMass > 0)
        {
            joint.springMass = Real(1) / joint.springMass;
        }
    }
    else
    {
        joint.springImpulse = 0;
    }

    // The limit rows use the translation at the start of the step (speculative bias).
    if (joint.enableLimit)
    {
        joint.translation = Dot(joint.ax, d);
    }
    else
    {
        joint.lowerImpulse = 0;
        joint.upperImpulse = 0;
    }

    // Motor row: k = 1/IA + 1/IB (Jacobian [0 0 −1 0 0 1]).
    if (joint.enableMotor)
    {
        joint.motorMass = masses.iA + masses.iB;
        if (joint.motorMass > 0)
        {
            joint.motorMass = Real(1) / joint.motorMass;
        }
    }
    else
    {
        joint.motorMass = 0;
        joint.motorImpulse = 0;
    }

    if (data.step.solver.warmStarting)
    {
        // Impulses are force·dt: rescale last step's to this step's dt. Box2D 2.4.1 leaves the
        // limit impulses unscaled here (mirrored).
        const Real dtRatio = data.step.dtRatio;
        joint.impulse *= dtRatio;
        joint.springImpulse *= dtRatio;
        joint.motorImpulse *= dtRatio;

        const Real axialImpulse = joint.springImpulse + joint.lowerImpulse - joint.upperImpulse;
        const Vec2 P = joint.impulse * joint.ay + axialImpulse * joint.ax;
        const Real LA = joint.impulse * joint.sAy + axialImpulse * joint.sAx + joint.motorImpulse;
        const Real LB = joint.impulse * joint.sBy + axialImpulse * joint.sBx + joint.motorImpulse;
        vA -= joint.invMassA * P;
        wA -= joint.invIA * LA;
        vB += joint.invMassB * P;
        wB += joint.invIB * LB;
    }
    else
    {
        joint.impulse = 0;
        joint.springImpulse = 0;
        joint.motorImpulse = 0;
        joint.lowerImpulse = 0;
        joint.upperImpulse = 0;
    }

    data.velocities[joint.indexA] = {vA, wA};
    data.velocities[joint.indexB] = {vB, wB};
}

void SolveVelocityConstraints(WheelJoint& joint, SolverData& data)
{
    const LineRowMasses m = Masses(joint);

    auto [vA, wA] = data.velocities[joint.indexA];
    auto [vB, wB] = data.velocities[joint.indexB];

    // Spring (without stiffness springMass is 0 and the row applies nothing).
    {
        const Real Cdot = LineRowSpeed(joint.ax, joint.sAx, joint.sBx, vA, wA, vB, wB);
        const Real impulse =
            -joint.springMass * (Cdot + joint.bias + joint.gamma * joint.springImpulse);
        joint.springImpulse += impulse;
        ApplyLineRowImpulse(impulse, joint.ax, joint.sAx, joint.sBx, m, vA, wA, vB, wB);
    }

    // Motor (motorMass is 0 when disabled, so the row applies nothing).
    {
        const Real Cdot = wB - wA - joint.motorSpeed;
        Real impulse = -joint.motorMass * Cdot;
        const Real oldImpulse = joint.motorImpulse;
        const Real maxImpulse = data.step.dt * joint.maxMotorTorque;
        joint.motorImpulse = Clamp(joint.motorImpulse + impulse, -maxImpulse, maxImpulse);
        impulse = joint.motorImpulse - oldImpulse;
        wA -= m.iA * impulse;
        wB += m.iB * impulse;
    }

    if (joint.enableLimit)
    {
        const TranslationLimit limit{joint.ax,
                                     joint.sAx,
                                     joint.sBx,
                                     joint.axialMass,
                                     joint.translation,
                                     joint.lowerTranslation,
                                     joint.upperTranslation};
        SolveTranslationLimits(limit, m, data.step.invDt, joint.lowerImpulse, joint.upperImpulse,
                               vA, wA, vB, wB);
    }

    // Point-to-line last, the joint's hard row: λ = −Cdot/k.
    {
        const Real Cdot = LineRowSpeed(joint.ay, joint.sAy, joint.sBy, vA, wA, vB, wB);
        const Real impulse = -joint.mass * Cdot;
        joint.impulse += impulse;
        ApplyLineRowImpulse(impulse, joint.ay, joint.sAy, joint.sBy, m, vA, wA, vB, wB);
    }

    data.velocities[joint.indexA] = {vA, wA};
    data.velocities[joint.indexB] = {vB, wB};
}

bool SolvePositionConstraints(WheelJoint& joint, SolverData& data)
{
    auto [cA, aA] = data.positions[joint.indexA];
    auto [cB, aB] = data.positions[joint.indexB];

    const Real slop = data.step.tolerances.linearSlop;
    Real linearError = 0;

    // Violated limit: one pseudo-impulse λ = −C/k along the axis.
    if (joint.enableLimit)
    {
        const Rot qA(aA), qB(aB);
        const Vec2 rA = Mul(qA, joint.localAnchorA - joint.localCenterA);
        const Vec2 rB = Mul(qB, joint.localAnchorB - joint.localCenterB);
        const Vec2 d = (cB - cA) + rB - rA;
        const Vec2 ax = Mul(qA, joint.localXAxisA);
        // Lever terms with the step's axis (Box2D 2.4.1, see the file comment).
        const Real sAx = Cross(d + rA, joint.ax);
        const Real sBx = Cross(rB, joint.ax);

        // Limits closer than the slop act as one equality row, which Box2D 2.4.1 writes as
        // translation = 0 (mirrored).
        Real C = 0;
        const Real translation = Dot(ax, d);
        if (std::abs(joint.upperTranslation - joint.lowerTranslation) < Real(2) * slop)
        {
            C = translation;
        }
        else if (translation <= joint.lowerTranslation)
        {
            C = Min(translation - joint.lowerTranslation, Real(0));
        }
        else if (translation >= joint.upperTranslation)
        {
            C = Max(translation - joint.upperTranslation, Real(0));
        }

        if (C != 0)
        {
            const Real invMass =
                joint.invMassA + joint.invMassB + joint.invIA * sAx * sAx + joint.invIB * sBx * sBx;
            Real impulse = 0;
            if (invMass != 0)
            {
                impulse = -C / invMass;
            }
            ApplyLineRowImpulse(impulse, ax, sAx, sBx, Masses(joint), cA, aA, cB, aB);
            linearError = std::abs(C);
        }
    }

    // Point-to-line row on the (possibly limit-corrected) positions.
    {
        const Rot qA(aA), qB(aB);
        const Vec2 rA = Mul(qA, joint.localAnchorA - joint.localCenterA);
        const Vec2 rB = Mul(qB, joint.localAnchorB - joint.localCenterB);
        const Vec2 d = (cB - cA) + rB - rA;
        const Vec2 ay = Mul(qA, joint.localYAxisA);
        const Real sAy = Cross(d + rA, ay);
        const Real sBy = Cross(rB, ay);
        const Real C = Dot(d, ay);

        // k with the step's lever terms (Box2D 2.4.1, see the file comment).
        const Real invMass = joint.invMassA + joint.invMassB + joint.invIA * joint.sAy * joint.sAy +
                             joint.invIB * joint.sBy * joint.sBy;
        Real impulse = 0;
        if (invMass != 0)
        {
            impulse = -C / invMass;
        }
        ApplyLineRowImpulse(impulse, ay, sAy, sBy, Masses(joint), cA, aA, cB, aB);
        linearError = Max(linearError, std::abs(C));
    }

    data.positions[joint.indexA] = {cA, aA};
    data.positions[joint.indexB] = {cB, aB};

    return linearError <= slop;
}

JointReaction GetReaction(const WheelJoint& joint, Real invDt)
{
    // Mean force over the step: the point-to-line impulse along ay plus the axial rows' along
    // ax (upper limit flipped); the motor's impulse is the torque.
    JointReaction reaction;
    reaction.force =
        invDt * (joint.impulse * joint.ay +
                 (joint.springImpulse + joint.lowerImpulse - joint.upperImpulse) * joint.ax);
    reaction.torque = invDt * joint.motorImpulse;
    return reaction;
}

} // namespace meff::detail
