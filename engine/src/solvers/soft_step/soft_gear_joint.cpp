// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Gear joint in the soft step: the gear's one equality row (gear_joint.cpp)
//   C = coordinateA + ratio·coordinateB − constant = 0
// on its four bodies, each side's coordinate and Jacobian measured now from the bodies' poses at
// the step's start and their motion since. Unlike Box2D 2.4.1's gear, a prismatic side's base
// lever is the exact one, (d + rBase)×u with d the anchors' gap, because the axis u turns with
// the base (the derivative of u·d; soft_row.h's LineRow). Soft with the joints' softness while
// solving, rigid without bias while relaxing, as every rigid joint row.
//
// The row's k is the seed's effective mass of each side, the second side's scaled by ratio²:
//   k = Σ sides: scale²·(mBody⁻¹ + mBase⁻¹)[prismatic] + IBody⁻¹·JwBody² + IBase⁻¹·JwBase².
#include "solvers/soft_step/soft_joint.h"

namespace meff::detail
{

namespace
{

/// One side of the gear as stored in the joint: its moving body and the body it is anchored
/// on (solver indices, inverse masses), its joint's frame, and its scale (1 or the ratio).
struct SoftGearSide
{
    bool prismatic = false;
    std::int32_t body = 0, base = 0;
    Real mBody = 0, mBase = 0, iBody = 0, iBase = 0;
    Vec2 localAxisBase, localAnchorBody, localAnchorBase, centerBody, centerBase;
    Real referenceAngle = 0;
    Real scale = 1;
};

SoftGearSide SideA(const GearJoint& j)
{
    return {j.prismaticA,   j.indexA,       j.indexC,          j.invMassA,     j.invMassC,
            j.invIA,        j.invIC,        j.localAxisC,      j.localAnchorA, j.localAnchorC,
            j.localCenterA, j.localCenterC, j.referenceAngleA, Real(1)};
}

SoftGearSide SideB(const GearJoint& j)
{
    return {j.prismaticB,   j.indexB,       j.indexD,          j.invMassB,     j.invMassD,
            j.invIB,        j.invID,        j.localAxisD,      j.localAnchorB, j.localAnchorD,
            j.localCenterB, j.localCenterD, j.referenceAngleB, j.ratio};
}

/// A side's row now: Jacobian terms (already × scale), its part of k and its coordinate.
struct SoftGearRow
{
    Vec2 Jv;
    Real JwBody = 0, JwBase = 0;
    Real k = 0;
    Real coordinate = 0; ///< rad or m, unscaled
};

SoftGearRow SideRowNow(const SoftGearSide& s, const SoftBodies& bodies)
{
    const Position& body0 = bodies.start[s.body];
    const Position& base0 = bodies.start[s.base];
    const SoftDelta& dBody = bodies.deltas[s.body];
    const SoftDelta& dBase = bodies.deltas[s.base];
    SoftGearRow row;
    if (!s.prismatic)
    {
        row.JwBody = s.scale;
        row.JwBase = s.scale;
        row.k = s.scale * s.scale * (s.iBody + s.iBase);
        row.coordinate =
            (body0.a - base0.a - s.referenceAngle) + RelativeRotation(dBase.dq, dBody.dq);
        return row;
    }
    const Rot qBody = Mul(dBody.dq, Rot(body0.a));
    const Rot qBase = Mul(dBase.dq, Rot(base0.a));
    const Vec2 u = Mul(qBase, s.localAxisBase);
    const Vec2 rBody = Mul(qBody, s.localAnchorBody - s.centerBody);
    const Vec2 rBase = Mul(qBase, s.localAnchorBase - s.centerBase);
    const Vec2 d = (body0.c + dBody.dp + rBody) - (base0.c + dBase.dp + rBase);
    row.Jv = s.scale * u;
    row.JwBody = s.scale * Cross(rBody, u);
    row.JwBase = s.scale * Cross(d + rBase, u);
    row.k = s.scale * s.scale * (s.mBody + s.mBase) + s.iBody * row.JwBody * row.JwBody +
            s.iBase * row.JwBase * row.JwBase;
    row.coordinate = Dot(d, u);
    return row;
}

/// The side's velocity along its row: Jv·(vBody − vBase) + JwBody·wBody − JwBase·wBase.
Real SideVelocity(const SoftGearSide& s, const SoftGearRow& row, const Velocity* v)
{
    return Dot(row.Jv, v[s.body].v - v[s.base].v) + row.JwBody * v[s.body].w -
           row.JwBase * v[s.base].w;
}

/// Applies the row impulse λ to the side: +λ·J to its body, −λ·J to its base. Written into the
/// velocity array body by body, so a body shared by both sides (the ground under both joints)
/// takes both sides' impulses.
void ApplySide(const SoftGearSide& s, const SoftGearRow& row, Real lambda, Velocity* v)
{
    v[s.body].v += (s.mBody * lambda) * row.Jv;
    v[s.body].w += s.iBody * lambda * row.JwBody;
    v[s.base].v -= (s.mBase * lambda) * row.Jv;
    v[s.base].w -= s.iBase * lambda * row.JwBase;
}

/// Runs `update(sideA, rowA, sideB, rowB, velocities)` on the four bodies' velocities in the
/// sub-step's array: A and B (held in `b` by the caller) are written back first and read again
/// after, since C or D may be one of them.
template <typename Update>
void UpdateGear(const GearJoint& joint, const SoftJointState& state, RowBodies& b, Update&& update)
{
    SoftBodies& bodies = *state.context.bodies;
    Velocity* v = bodies.velocities.data();
    StoreRowBodies(v, joint.indexA, joint.indexB, b);
    const SoftGearSide sideA = SideA(joint), sideB = SideB(joint);
    update(sideA, SideRowNow(sideA, bodies), sideB, SideRowNow(sideB, bodies), v);
    b = LoadRowBodies(v, joint.indexA, joint.indexB, b.mA, b.iA, b.mB, b.iB);
}

} // namespace

void PrepareSoft(GearJoint&, SoftJointFrame&, const Position&, const Position&,
                 const SoftStepContext&)
{
    // Every sub-step measures the gear from the bodies' start poses (SoftBodies::start).
}

void WarmStartSoft(const GearJoint& joint, const SoftJointState& state, RowBodies& b)
{
    UpdateGear(joint, state, b,
               [&](const SoftGearSide& sA, const SoftGearRow& rA, const SoftGearSide& sB,
                   const SoftGearRow& rB, Velocity* v)
               {
                   ApplySide(sA, rA, joint.impulse, v);
                   ApplySide(sB, rB, joint.impulse, v);
               });
}

void SolveSoft(GearJoint& joint, const SoftJointState& state, bool useBias, RowBodies& b)
{
    UpdateGear(joint, state, b,
               [&](const SoftGearSide& sA, const SoftGearRow& rA, const SoftGearSide& sB,
                   const SoftGearRow& rB, Velocity* v)
               {
                   const Real C = rA.coordinate + joint.ratio * rB.coordinate - joint.constant;
                   const Real cdot = SideVelocity(sA, rA, v) + SideVelocity(sB, rB, v);
                   const Real applied = SoftRowImpulse(
                       RowMass(rA.k + rB.k), cdot, EqualityTarget(C, useBias, state.context.joint),
                       joint.impulse);
                   ApplySide(sA, rA, applied, v);
                   ApplySide(sB, rB, applied, v);
                   // The reaction's rows (GetReaction).
                   joint.JvAC = rA.Jv;
                   joint.JwA = rA.JwBody;
               });
}

void ScaleImpulses(GearJoint& joint, Real factor)
{
    joint.impulse *= factor;
}

} // namespace meff::detail
