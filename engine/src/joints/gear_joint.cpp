// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Gear joint: Box2D 2.4.1's b2GearJoint in the scalar effective mass form (seed:
// effective-mass.md). It couples joint1 (bodies C → A) and joint2 (bodies D → B), each a
// revolute or a prismatic joint, through their coordinates
//   revolute side:  coordinate = aA − aC − referenceAngle
//   prismatic side: coordinate = u·(pA − pC), u the slide axis fixed in C
//   C = coordinateA + ratio·coordinateB − constant
//   Cdot = JvAC·(vA − vC) + JwA·wA − JwC·wC + JvBD·(vB − vD) + JwB·wB − JwD·wD
// with (revolute) Jv = 0, Jw = 1 or (prismatic) Jv = u, JwA = rA×u, JwC = rC×u, and side B's
// terms scaled by ratio. The one row's k = J·M⁻¹·Jᵀ is the seed's k of each side — angular
// only for a revolute side — side B's scaled by ratio²:
//   k = [mA⁻¹ + mC⁻¹ + IA⁻¹·JwA² + IC⁻¹·JwC²] + ratio²·[mB⁻¹ + mD⁻¹] + IB⁻¹·JwB² + ID⁻¹·JwD².
// The row is bilateral, as Box2D's. Every expression keeps Box2D's floating-point operation
// order (frame-by-frame validation); side A goes through the same code with scale 1, which
// multiplies exactly.
#include "joints/joint.h"

namespace meff::detail
{

namespace
{

/// One side's rows: its linear Jacobian, its angular terms on the moving body (A or B) and
/// the body it turns or slides on (C or D), and its part of k.
struct GearSideRows
{
    Vec2 Jv;
    Real JwBody = 0, JwBase = 0;
    Real k = 0;
};

/// The side's rows. `body`/`base` are the side's moving body and the body its joint is
/// anchored on; `scale` is 1 for side A and the ratio for side B.
struct GearSideGeometry
{
    bool prismatic = false;
    Vec2 localAxisBase, localAnchorBody, localAnchorBase, centerBody, centerBase;
    Real mBody = 0, mBase = 0, iBody = 0, iBase = 0;
};

GearSideRows SideRows(const GearSideGeometry& g, const Rot& qBody, const Rot& qBase, Real scale)
{
    GearSideRows rows;
    if (!g.prismatic)
    {
        rows.Jv = Vec2(0, 0);
        rows.JwBody = scale;
        rows.JwBase = scale;
        rows.k = scale * scale * (g.iBody + g.iBase);
        return rows;
    }
    const Vec2 u = Mul(qBase, g.localAxisBase);
    const Vec2 rBase = Mul(qBase, g.localAnchorBase - g.centerBase);
    const Vec2 rBody = Mul(qBody, g.localAnchorBody - g.centerBody);
    rows.Jv = scale * u;
    rows.JwBase = scale * Cross(rBase, u);
    rows.JwBody = scale * Cross(rBody, u);
    rows.k = scale * scale * (g.mBase + g.mBody) + g.iBase * rows.JwBase * rows.JwBase +
             g.iBody * rows.JwBody * rows.JwBody;
    return rows;
}

GearSideGeometry SideA(const GearJoint& j)
{
    return {j.prismaticA,   j.localAxisC, j.localAnchorA, j.localAnchorC, j.localCenterA,
            j.localCenterC, j.invMassA,   j.invMassC,     j.invIA,        j.invIC};
}

GearSideGeometry SideB(const GearJoint& j)
{
    return {j.prismaticB,   j.localAxisD, j.localAnchorB, j.localAnchorD, j.localCenterB,
            j.localCenterD, j.invMassB,   j.invMassD,     j.invIB,        j.invID};
}

/// A side's coordinate now: the joint's angle (rad) or its translation along the axis (m).
Real SideCoordinate(const GearSideGeometry& g, Real referenceAngle, const Position& body,
                    const Position& base, const Rot& qBody, const Rot& qBase)
{
    if (!g.prismatic)
    {
        return body.a - base.a - referenceAngle;
    }
    const Vec2 rBody = Mul(qBody, g.localAnchorBody - g.centerBody);
    const Vec2 pBase = g.localAnchorBase - g.centerBase;
    const Vec2 pBody = MulT(qBase, rBody + (body.c - base.c));
    return Dot(pBody - pBase, g.localAxisBase);
}

/// The four bodies' velocities while the row is solved.
struct GearVelocities
{
    Velocity a, b, c, d;
};

GearVelocities LoadVelocities(const GearJoint& j, const SolverData& data)
{
    return {data.velocities[j.indexA], data.velocities[j.indexB], data.velocities[j.indexC],
            data.velocities[j.indexD]};
}

void StoreVelocities(const GearJoint& j, const GearVelocities& v, SolverData& data)
{
    data.velocities[j.indexA] = v.a;
    data.velocities[j.indexB] = v.b;
    data.velocities[j.indexC] = v.c;
    data.velocities[j.indexD] = v.d;
}

/// Applies the row's impulse λ: +λ·J to A and B, −λ·J to C and D.
void ApplyGearImpulse(const GearJoint& j, Real impulse, GearVelocities& v)
{
    v.a.v += (j.invMassA * impulse) * j.JvAC;
    v.a.w += j.invIA * impulse * j.JwA;
    v.b.v += (j.invMassB * impulse) * j.JvBD;
    v.b.w += j.invIB * impulse * j.JwB;
    v.c.v -= (j.invMassC * impulse) * j.JvAC;
    v.c.w -= j.invIC * impulse * j.JwC;
    v.d.v -= (j.invMassD * impulse) * j.JvBD;
    v.d.w -= j.invID * impulse * j.JwD;
}

} // namespace

void StoreGearBodies(GearJoint& gear, const JointBody& c, const JointBody& d)
{
    gear.indexC = c.solverIndex;
    gear.indexD = d.solverIndex;
    gear.localCenterC = c.localCenter;
    gear.localCenterD = d.localCenter;
    gear.invMassC = c.invMass;
    gear.invMassD = d.invMass;
    gear.invIC = c.invI;
    gear.invID = d.invI;
}

void InitVelocityConstraints(GearJoint& joint, const JointBody& a, const JointBody& b,
                             SolverData& data)
{
    StoreJointBodies(joint, a, b);

    const Rot qA(data.positions[joint.indexA].a), qB(data.positions[joint.indexB].a);
    const Rot qC(data.positions[joint.indexC].a), qD(data.positions[joint.indexD].a);
    const GearSideRows sideA = SideRows(SideA(joint), qA, qC, 1);
    const GearSideRows sideB = SideRows(SideB(joint), qB, qD, joint.ratio);
    joint.JvAC = sideA.Jv;
    joint.JwA = sideA.JwBody;
    joint.JwC = sideA.JwBase;
    joint.JvBD = sideB.Jv;
    joint.JwB = sideB.JwBody;
    joint.JwD = sideB.JwBase;
    const Real k = sideA.k + sideB.k;
    joint.mass = k > 0 ? Real(1) / k : Real(0);

    if (data.step.solver.warmStarting)
    {
        // As Box2D 2.4.1's gear: the impulse is not rescaled by dtRatio.
        GearVelocities v = LoadVelocities(joint, data);
        ApplyGearImpulse(joint, joint.impulse, v);
        StoreVelocities(joint, v, data);
    }
    else
    {
        joint.impulse = 0;
    }
}

void SolveVelocityConstraints(GearJoint& joint, SolverData& data)
{
    GearVelocities v = LoadVelocities(joint, data);
    Real Cdot = Dot(joint.JvAC, v.a.v - v.c.v) + Dot(joint.JvBD, v.b.v - v.d.v);
    Cdot += (joint.JwA * v.a.w - joint.JwC * v.c.w) + (joint.JwB * v.b.w - joint.JwD * v.d.w);
    const Real impulse = -joint.mass * Cdot;
    joint.impulse += impulse;
    ApplyGearImpulse(joint, impulse, v);
    StoreVelocities(joint, v, data);
}

bool SolvePositionConstraints(GearJoint& joint, SolverData& data)
{
    Position pA = data.positions[joint.indexA], pB = data.positions[joint.indexB];
    Position pC = data.positions[joint.indexC], pD = data.positions[joint.indexD];
    const Rot qA(pA.a), qB(pB.a), qC(pC.a), qD(pD.a);

    const GearSideGeometry geometryA = SideA(joint), geometryB = SideB(joint);
    const GearSideRows sideA = SideRows(geometryA, qA, qC, 1);
    const GearSideRows sideB = SideRows(geometryB, qB, qD, joint.ratio);
    const Real k = sideA.k + sideB.k;
    const Real coordinateA = SideCoordinate(geometryA, joint.referenceAngleA, pA, pC, qA, qC);
    const Real coordinateB = SideCoordinate(geometryB, joint.referenceAngleB, pB, pD, qB, qD);

    const Real C = (coordinateA + joint.ratio * coordinateB) - joint.constant;
    const Real impulse = k > 0 ? -C / k : Real(0);

    pA.c += joint.invMassA * impulse * sideA.Jv;
    pA.a += joint.invIA * impulse * sideA.JwBody;
    pB.c += joint.invMassB * impulse * sideB.Jv;
    pB.a += joint.invIB * impulse * sideB.JwBody;
    pC.c -= joint.invMassC * impulse * sideA.Jv;
    pC.a -= joint.invIC * impulse * sideA.JwBase;
    pD.c -= joint.invMassD * impulse * sideB.Jv;
    pD.a -= joint.invID * impulse * sideB.JwBase;
    data.positions[joint.indexA] = pA;
    data.positions[joint.indexB] = pB;
    data.positions[joint.indexC] = pC;
    data.positions[joint.indexD] = pD;
    // As Box2D 2.4.1: the gear never holds the position iterations back.
    return true;
}

JointReaction GetReaction(const GearJoint& joint, Real invDt)
{
    // As Box2D: side A's linear and angular impulse on body A.
    JointReaction reaction;
    reaction.force = invDt * (joint.impulse * joint.JvAC);
    reaction.torque = invDt * (joint.impulse * joint.JwA);
    return reaction;
}

} // namespace meff::detail
