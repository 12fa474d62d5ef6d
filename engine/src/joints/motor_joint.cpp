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
#include "joints/joint.h"

namespace meff::detail
{

namespace
{

/// Velocity of B's origin relative to A's offset point plus the correction bias.
Vec2 LinearCdot(const MotorJoint& j, Vec2 vA, Real wA, Vec2 vB, Real wB, Real invH)
{
    return vB + Cross(wB, j.rB) - vA - Cross(wA, j.rA) + invH * j.correctionFactor * j.linearError;
}

/// Keeps the accumulated linear impulse within the disc |λ| ≤ maxImpulse (Box2D's order).
void ClampToDisc(Vec2& accumulated, Real maxImpulse)
{
    if (accumulated.LengthSquared() > maxImpulse * maxImpulse)
    {
        accumulated.Normalize();
        accumulated *= maxImpulse;
    }
}

void ApplyLinearImpulse(const MotorJoint& j, Vec2 P, Vec2& vA, Real& wA, Vec2& vB, Real& wB)
{
    vA -= j.invMassA * P;
    wA -= j.invIA * Cross(j.rA, P);
    vB += j.invMassB * P;
    wB += j.invIB * Cross(j.rB, P);
}

/// λ = −(Jv + bias)/k for one scalar row; a row no body can move along (k = 0) takes none.
Real ScalarRowImpulse(Real jvPlusBias, Real k)
{
    return k > 0 ? -jvPlusBias / k : Real(0);
}

} // namespace

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

    const Real mA = joint.invMassA, mB = joint.invMassB;
    const Real iA = joint.invIA, iB = joint.invIB;
    const Vec2 rA = joint.rA, rB = joint.rB;

    // Box2D writes this K with the inverse inertia first (unlike the weld's); kept.
    joint.K.ex.x = mA + mB + iA * rA.y * rA.y + iB * rB.y * rB.y;
    joint.K.ex.y = -iA * rA.x * rA.y - iB * rB.x * rB.y;
    joint.K.ey.x = joint.K.ex.y;
    joint.K.ey.y = mA + mB + iA * rA.x * rA.x + iB * rB.x * rB.x;
    joint.linearMass = joint.K.GetInverse();

    joint.angularMass = iA + iB;
    if (joint.angularMass > 0)
    {
        joint.angularMass = Real(1) / joint.angularMass;
    }

    joint.linearError = cB + rB - cA - rA;
    joint.angularError = aB - aA - joint.angularOffset;

    if (data.step.solver.warmStarting)
    {
        // Impulses are force·dt: rescale last step's to this step's dt.
        joint.linearImpulse *= data.step.dtRatio;
        joint.angularImpulse *= data.step.dtRatio;
        const Vec2 P(joint.linearImpulse.x, joint.linearImpulse.y);
        vA -= mA * P;
        wA -= iA * (Cross(rA, P) + joint.angularImpulse);
        vB += mB * P;
        wB += iB * (Cross(rB, P) + joint.angularImpulse);
    }
    else
    {
        joint.linearImpulse = Vec2(0, 0);
        joint.angularImpulse = 0;
    }

    data.velocities[joint.indexA] = {vA, wA};
    data.velocities[joint.indexB] = {vB, wB};
}

void SolveVelocityConstraints(MotorJoint& joint, SolverData& data)
{
    auto [vA, wA] = data.velocities[joint.indexA];
    auto [vB, wB] = data.velocities[joint.indexB];

    const Real h = data.step.dt;
    const Real invH = data.step.invDt;

    // Angular row (scalar, k = iA + iB), its accumulated impulse clamped to ±h·maxTorque.
    {
        const Real Cdot = wB - wA + invH * joint.correctionFactor * joint.angularError;
        Real impulse = -joint.angularMass * Cdot;
        const Real oldImpulse = joint.angularImpulse;
        const Real maxImpulse = h * joint.maxTorque;
        joint.angularImpulse = Clamp(joint.angularImpulse + impulse, -maxImpulse, maxImpulse);
        impulse = joint.angularImpulse - oldImpulse;
        wA -= joint.invIA * impulse;
        wB += joint.invIB * impulse;
    }

    // Linear rows, their accumulated impulse clamped to the disc of radius h·maxForce.
    const Real maxImpulse = h * joint.maxForce;
    if (data.step.solver.blockJoints)
    {
        // Both rows at once, λ = −K⁻¹·Cdot, then the disc clamp on the sum.
        const Vec2 Cdot = LinearCdot(joint, vA, wA, vB, wB, invH);
        Vec2 impulse = -Mul(joint.linearMass, Cdot);
        const Vec2 oldImpulse = joint.linearImpulse;
        joint.linearImpulse += impulse;
        ClampToDisc(joint.linearImpulse, maxImpulse);
        impulse = joint.linearImpulse - oldImpulse;
        ApplyLinearImpulse(joint, impulse, vA, wA, vB, wB);
    }
    else
    {
        // Two scalar rows, x then y, each λ = −Cdot/k with the seed's k (K's diagonal); after
        // each row the accumulated vector is clamped to the disc and only its change applied.
        for (int axis = 0; axis < 2; ++axis)
        {
            const Vec2 Cdot = LinearCdot(joint, vA, wA, vB, wB, invH);
            const Real lambda = axis == 0 ? ScalarRowImpulse(Cdot.x, joint.K.ex.x)
                                          : ScalarRowImpulse(Cdot.y, joint.K.ey.y);
            const Vec2 oldImpulse = joint.linearImpulse;
            joint.linearImpulse += axis == 0 ? Vec2(lambda, 0) : Vec2(0, lambda);
            ClampToDisc(joint.linearImpulse, maxImpulse);
            ApplyLinearImpulse(joint, joint.linearImpulse - oldImpulse, vA, wA, vB, wB);
        }
    }

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
