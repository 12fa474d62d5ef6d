// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Prismatic joint: Box2D 2.4.1's b2PrismaticJoint in the scalar effective mass form (seed:
// effective-mass.md). Body B's anchor slides along an axis fixed in body A and B keeps its
// angle relative to A. With d = pB − pA, a = axis, p = its perpendicular (line_rows.h):
//   perpendicular  C = p·d = 0                          J = [−p  −s1  p  s2]
//   angular        C = aB − aA − referenceAngle = 0     J = [0 0 −1 0 0 1]
//   motor          Cdot = a·(vB − vA) + a2·wB − a1·wA − motorSpeed, |λ| ≤ h·maxMotorForce
//   limits         lower C = a·d − lower ≥ 0, upper C = upper − a·d ≥ 0
//   spring         C = a·d − targetTranslation, soft (Box2D v3's; not in Box2D 2.4.1, so with
//                  it off nothing below changes: every spring term sits behind enableSpring)
// The axial rows (motor, limits) share k = 1/mA + 1/mB + a1²/IA + a2²/IB, the "axial mass"
// being 1/k. The perpendicular and angular rows couple through the rotations; Box2D solves
// them as one 2×2 block K (its diagonal entries are each row's scalar k), and with
// SolverSettings::blockJoints off they are two scalar rows, Gauss-Seidel.
//
// Every expression keeps Box2D's floating-point operation order (frame-by-frame validation).
#include "joints/line_rows.h"

#include <cmath>

namespace meff::detail
{

namespace
{

/// λ = −(Jv + bias)/k for one scalar row; a row no body can move along (k = 0) takes none.
Real ScalarRowImpulse(Real jvPlusBias, Real k)
{
    return k > 0 ? -jvPlusBias / k : Real(0);
}

/// Applies the (perpendicular, angular, axial) impulse triple: force λx·p + λz·a on B, and the
/// angular parts λx·s + λy + λz·a on each body's turn (negated on A).
void ApplyPrismaticImpulse(Vec3 impulse, Vec2 perp, Vec2 axis, Real s1, Real s2, Real a1, Real a2,
                           const LineRowMasses& m, Vec2& cA, Real& aA, Vec2& cB, Real& aB)
{
    const Vec2 P = impulse.x * perp + impulse.z * axis;
    const Real LA = impulse.x * s1 + impulse.y + impulse.z * a1;
    const Real LB = impulse.x * s2 + impulse.y + impulse.z * a2;
    cA -= m.mA * P;
    aA -= m.iA * LA;
    cB += m.mB * P;
    aB += m.iB * LB;
}

} // namespace

void InitVelocityConstraints(PrismaticJoint& joint, const JointBody& a, const JointBody& b,
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
    const Vec2 d = (cB - cA) + rB - rA;

    const Real mA = joint.invMassA, mB = joint.invMassB;
    const Real iA = joint.invIA, iB = joint.invIB;

    // Axial rows (motor and limits): seed k = mA + mB + iA·a1² + iB·a2².
    const LineRowMasses masses = Masses(joint);
    joint.axis = Mul(qA, joint.localXAxisA);
    const LineRow axial = MakeLineRow(joint.axis, d, rA, rB, masses);
    joint.a1 = axial.sA;
    joint.a2 = axial.sB;
    joint.axialMass = axial.k;
    if (joint.axialMass > 0)
    {
        joint.axialMass = Real(1) / joint.axialMass;
    }

    // Perpendicular and angular rows: K = J·M⁻¹·Jᵀ. k11 is the perpendicular row's seed k,
    // k22 = 1/IA + 1/IB the angular row's; when neither body can turn, k22 = 1 keeps K
    // invertible (the angular row then moves nothing).
    joint.perp = Mul(qA, joint.localYAxisA);
    const LineRow perpendicular = MakeLineRow(joint.perp, d, rA, rB, masses);
    joint.s1 = perpendicular.sA;
    joint.s2 = perpendicular.sB;
    const Real k11 = perpendicular.k;
    const Real k12 = iA * joint.s1 + iB * joint.s2;
    Real k22 = iA + iB;
    if (k22 == 0)
    {
        k22 = 1;
    }
    joint.K.ex = Vec2(k11, k12);
    joint.K.ey = Vec2(k12, k22);

    // The limit rows use the translation at the start of the step (speculative bias), and so
    // does the spring.
    if (joint.enableLimit || joint.enableSpring)
    {
        joint.translation = Dot(joint.axis, d);
    }
    if (!joint.enableLimit)
    {
        joint.lowerImpulse = 0;
        joint.upperImpulse = 0;
    }
    if (!joint.enableMotor)
    {
        joint.motorImpulse = 0;
    }
    if (!joint.enableSpring || joint.axialMass == 0)
    {
        joint.springImpulse = 0;
    }
    else
    {
        // The spring's soft row over the whole step h = dt on the axial row's mass.
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

        // The upper row's impulse acts with the opposite sign (its C is upper − translation).
        Real axialImpulse = joint.motorImpulse + joint.lowerImpulse - joint.upperImpulse;
        if (joint.enableSpring)
        {
            axialImpulse += joint.springImpulse;
        }
        const Vec2 P = joint.impulse.x * joint.perp + axialImpulse * joint.axis;
        const Real LA = joint.impulse.x * joint.s1 + joint.impulse.y + axialImpulse * joint.a1;
        const Real LB = joint.impulse.x * joint.s2 + joint.impulse.y + axialImpulse * joint.a2;
        vA -= mA * P;
        wA -= iA * LA;
        vB += mB * P;
        wB += iB * LB;
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

void SolveVelocityConstraints(PrismaticJoint& joint, SolverData& data)
{
    auto [vA, wA] = data.velocities[joint.indexA];
    auto [vB, wB] = data.velocities[joint.indexB];

    const LineRowMasses m = Masses(joint);

    // Spring first (as Box2D v3), so that the motor and the limits bound what it does. A soft
    // row on the axial row's mass, its error the translation at the step's start:
    // Δλ = −m·(massScale·Cdot + biasScale·C) − impulseScale·λ (softness.h). Its fixed point
    // over the iterations is docs/soft-step.md's exactly damped step, whatever the warm start.
    if (joint.enableSpring && joint.axialMass > 0)
    {
        const Real Cdot = LineRowSpeed(joint.axis, joint.a1, joint.a2, vA, wA, vB, wB);
        const Real C = joint.translation - joint.targetTranslation;
        const Real impulse =
            SpringRowImpulse(joint.spring, joint.axialMass, Cdot, C, joint.springImpulse);
        joint.springImpulse += impulse;
        ApplyLineRowImpulse(impulse, joint.axis, joint.a1, joint.a2, m, vA, wA, vB, wB);
    }

    // Motor first, so that the limits (solved after it) win when they disagree.
    if (joint.enableMotor)
    {
        const Real Cdot = LineRowSpeed(joint.axis, joint.a1, joint.a2, vA, wA, vB, wB);
        Real impulse = joint.axialMass * (joint.motorSpeed - Cdot);
        const Real oldImpulse = joint.motorImpulse;
        const Real maxImpulse = data.step.dt * joint.maxMotorForce;
        joint.motorImpulse = Clamp(joint.motorImpulse + impulse, -maxImpulse, maxImpulse);
        impulse = joint.motorImpulse - oldImpulse;
        ApplyLineRowImpulse(impulse, joint.axis, joint.a1, joint.a2, m, vA, wA, vB, wB);
    }

    if (joint.enableLimit)
    {
        const TranslationLimit limit{joint.axis,
                                     joint.a1,
                                     joint.a2,
                                     joint.axialMass,
                                     joint.translation,
                                     joint.lowerTranslation,
                                     joint.upperTranslation};
        SolveTranslationLimits(limit, m, data.step.invDt, joint.lowerImpulse, joint.upperImpulse,
                               vA, wA, vB, wB);
    }

    // The hard rows last, so they are the most accurate after each sweep.
    if (data.step.solver.blockJoints)
    {
        // Both rows at once: λ = −K⁻¹·Cdot.
        Vec2 Cdot;
        Cdot.x = LineRowSpeed(joint.perp, joint.s1, joint.s2, vA, wA, vB, wB);
        Cdot.y = wB - wA;
        const Vec2 df = joint.K.Solve(-Cdot);
        joint.impulse += df;

        const Vec2 P = df.x * joint.perp;
        const Real LA = df.x * joint.s1 + df.y;
        const Real LB = df.x * joint.s2 + df.y;
        vA -= m.mA * P;
        wA -= m.iA * LA;
        vB += m.mB * P;
        wB += m.iB * LB;
    }
    else
    {
        // Two scalar rows, perpendicular then angular, Gauss-Seidel: each λ = −Cdot/k with
        // the seed's k, which are K's diagonal entries.
        const Real cdotPerp = LineRowSpeed(joint.perp, joint.s1, joint.s2, vA, wA, vB, wB);
        const Real lambdaPerp = ScalarRowImpulse(cdotPerp, joint.K.ex.x);
        joint.impulse.x += lambdaPerp;
        ApplyLineRowImpulse(lambdaPerp, joint.perp, joint.s1, joint.s2, m, vA, wA, vB, wB);

        const Real cdotAngle = wB - wA;
        const Real lambdaAngle = ScalarRowImpulse(cdotAngle, joint.K.ey.y);
        joint.impulse.y += lambdaAngle;
        wA -= m.iA * lambdaAngle;
        wB += m.iB * lambdaAngle;
    }

    data.velocities[joint.indexA] = {vA, wA};
    data.velocities[joint.indexB] = {vB, wB};
}

bool SolvePositionConstraints(PrismaticJoint& joint, SolverData& data)
{
    auto [cA, aA] = data.positions[joint.indexA];
    auto [cB, aB] = data.positions[joint.indexB];

    const Rot qA(aA), qB(aB);
    const LineRowMasses m = Masses(joint);
    const Real mA = m.mA, mB = m.mB, iA = m.iA, iB = m.iB;
    const Tolerances& tol = data.step.tolerances;

    // Fresh Jacobians from the current positions.
    const Vec2 rA = Mul(qA, joint.localAnchorA - joint.localCenterA);
    const Vec2 rB = Mul(qB, joint.localAnchorB - joint.localCenterB);
    const Vec2 d = cB + rB - cA - rA;
    const Vec2 axis = Mul(qA, joint.localXAxisA);
    const Real a1 = Cross(d + rA, axis);
    const Real a2 = Cross(rB, axis);
    const Vec2 perp = Mul(qA, joint.localYAxisA);
    const Real s1 = Cross(d + rA, perp);
    const Real s2 = Cross(rB, perp);

    Vec2 C1;
    C1.x = Dot(perp, d);
    C1.y = aB - aA - joint.referenceAngle;
    Real linearError = std::abs(C1.x);
    const Real angularError = std::abs(C1.y);

    // A limit joins the solve only when violated (or when the limits are closer than the slop
    // and act as one equality row). Box2D 2.4.1 then drives the translation itself, not its
    // distance from the limit, to zero: mirrored as is, since the engines must agree.
    bool active = false;
    Real C2 = 0;
    if (joint.enableLimit)
    {
        const Real translation = Dot(axis, d);
        if (std::abs(joint.upperTranslation - joint.lowerTranslation) < Real(2) * tol.linearSlop)
        {
            C2 = translation;
            linearError = Max(linearError, std::abs(translation));
            active = true;
        }
        else if (translation <= joint.lowerTranslation)
        {
            C2 = Min(translation - joint.lowerTranslation, Real(0));
            linearError = Max(linearError, joint.lowerTranslation - translation);
            active = true;
        }
        else if (translation >= joint.upperTranslation)
        {
            C2 = Max(translation - joint.upperTranslation, Real(0));
            linearError = Max(linearError, translation - joint.upperTranslation);
            active = true;
        }
    }

    // K of the perpendicular, angular and (when active) axial rows; its diagonal entries are
    // each row's seed k. k22 = 1 when neither body can turn, as in InitVelocityConstraints.
    const Real k11 = mA + mB + iA * s1 * s1 + iB * s2 * s2;
    const Real k12 = iA * s1 + iB * s2;
    Real k22 = iA + iB;
    if (k22 == 0)
    {
        k22 = 1;
    }

    Vec3 impulse;
    if (data.step.solver.blockJoints)
    {
        if (active)
        {
            // Newton step on all three rows: Δ = −K⁻¹·C.
            const Real k13 = iA * s1 * a1 + iB * s2 * a2;
            const Real k23 = iA * a1 + iB * a2;
            const Real k33 = mA + mB + iA * a1 * a1 + iB * a2 * a2;
            Mat33 K;
            K.ex = Vec3(k11, k12, k13);
            K.ey = Vec3(k12, k22, k23);
            K.ez = Vec3(k13, k23, k33);
            impulse = K.Solve33(-Vec3(C1.x, C1.y, C2));
        }
        else
        {
            Mat22 K;
            K.ex = Vec2(k11, k12);
            K.ey = Vec2(k12, k22);
            const Vec2 impulse2 = K.Solve(-C1);
            impulse = Vec3(impulse2.x, impulse2.y, 0);
        }
    }
    else
    {
        // Scalar rows, perpendicular, angular, then axial (when active), each λ = −C/k with
        // the seed's k (K's diagonal). The Jacobians stay fixed within the call (as in the
        // block step), so a later row takes the earlier rows' linearised effect on its error,
        // C_j += K_ji·λ_i: one Gauss-Seidel sweep over the system the block step solves.
        const Real k13 = iA * s1 * a1 + iB * s2 * a2;
        const Real k23 = iA * a1 + iB * a2;
        const Real k33 = mA + mB + iA * a1 * a1 + iB * a2 * a2;
        impulse.x = ScalarRowImpulse(C1.x, k11);
        impulse.y = ScalarRowImpulse(C1.y + k12 * impulse.x, k22);
        impulse.z =
            active ? ScalarRowImpulse(C2 + k13 * impulse.x + k23 * impulse.y, k33) : Real(0);
    }
    ApplyPrismaticImpulse(impulse, perp, axis, s1, s2, a1, a2, m, cA, aA, cB, aB);

    data.positions[joint.indexA] = {cA, aA};
    data.positions[joint.indexB] = {cB, aB};

    return linearError <= tol.linearSlop && angularError <= tol.angularSlop;
}

JointReaction GetReaction(const PrismaticJoint& joint, Real invDt)
{
    // Mean force over the step: the perpendicular impulse along p plus the axial rows' along
    // the axis (upper limit flipped); the angular row's impulse is the torque.
    JointReaction reaction;
    Real axialImpulse = joint.motorImpulse + joint.lowerImpulse - joint.upperImpulse;
    if (joint.enableSpring)
    {
        axialImpulse += joint.springImpulse;
    }
    reaction.force = invDt * (joint.impulse.x * joint.perp + axialImpulse * joint.axis);
    reaction.torque = invDt * joint.impulse.y;
    return reaction;
}

} // namespace meff::detail
