// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Contact preparation by colour: each colour's contacts, kLanes at a time, go from the world's
// contacts straight into SIMD lanes. The lanes do what ContactSolver's scalar preparation (and
// Box2D 2.4.1's b2ContactSolver::InitializeVelocityConstraints) does for one contact, with the
// same floating-point operations in the same order: the world manifold at the step's start
// (b2WorldManifold::Initialize), lever arms, the scalar effective masses of the seed
//   k = 1/mA + 1/mB + (rA×n)²/IA + (rB×n)²/IB,
// the restitution bias −e·vn, and the block solver's K with its condition test. The contacts no
// colour could take (the overflow) are prepared one by one by the scalar preparation
// (ColourContactSolver). The warm start applies the same impulses, group by group in colour order;
// where a body has several contacts their sum is rounded in another order than in Box2D's.
#include "solvers/colour/contact_lanes.h"

#include "model/body.h"
#include "model/contact.h"
#include "solvers/lanes/lane_bodies.h"
#include "solvers/shared/island.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>

namespace meff::detail
{

namespace
{

/// What the lanes read of their contacts besides what the groups keep.
struct LaneInputs
{
    RealW restitution, threshold;              ///< e; restitution threshold (m/s)
    BodyStateW startVelocityA, startVelocityB; ///< with restitutionFromStepStart
    ContactGroupExtras extras{};               ///< the group's, where its header names them
    std::int32_t source[kLanes];               ///< constraint index, −1 for an empty lane
    bool hitEvents = false;                    ///< a lane's contact has hit events
};

/// Lane l's contact: the bodies and manifold, into the group's header and rows.
void GatherLane(ContactGroupHeader& h, ContactVelocityGroup& vg, ContactPositionGroup& pg,
                LaneInputs& in, int l, std::int32_t source, const Contact& contact,
                const IslandContacts& island, Real impulseScale, bool fromStepStart)
{
    const Body& bodyA = island.bodies[contact.bodyA];
    const Body& bodyB = island.bodies[contact.bodyB];
    const Manifold& manifold = contact.manifold;
    const auto bit = static_cast<std::uint8_t>(1U << l);

    in.source[l] = source;
    h.indexA[l] = bodyA.islandIndex;
    h.indexB[l] = bodyB.islandIndex;
    h.storesA |= SolverMoves(bodyA.invMass, bodyA.invI) ? bit : 0;
    h.storesB |= SolverMoves(bodyB.invMass, bodyB.invI) ? bit : 0;
    h.valid |= bit;
    vg.friction[l] = contact.friction;
    if (!IsPositiveZero(contact.tangentSpeed))
    {
        in.extras.tangentSpeed[l] = contact.tangentSpeed;
        h.extras |= ContactGroupHeader::kTangentSpeed;
    }
    if (contact.rollingResistance > 0)
    {
        const Real k = bodyA.invI + bodyB.invI;
        in.extras.rollingResistance[l] = contact.rollingResistance;
        in.extras.rollingMass[l] = k > 0 ? Real(1) / k : Real(0);
        in.extras.rollingImpulse[l] = impulseScale * contact.rollingImpulse;
        h.extras |= ContactGroupHeader::kRolling;
    }
    in.restitution[l] = contact.restitution;
    in.threshold[l] = contact.restitutionThreshold;
    in.hitEvents = in.hitEvents || (contact.flags & Contact::HitEvents) != 0;
    if (fromStepStart)
    {
        // Only then: the velocities lie beyond the body's first cache line (body.h).
        in.startVelocityA.linear.x[l] = bodyA.linearVelocity.x;
        in.startVelocityA.linear.y[l] = bodyA.linearVelocity.y;
        in.startVelocityA.angular[l] = bodyA.angularVelocity;
        in.startVelocityB.linear.x[l] = bodyB.linearVelocity.x;
        in.startVelocityB.linear.y[l] = bodyB.linearVelocity.y;
        in.startVelocityB.angular[l] = bodyB.angularVelocity;
    }

    pg.localNormal.x[l] = manifold.localNormal.x;
    pg.localNormal.y[l] = manifold.localNormal.y;
    pg.localPoint.x[l] = manifold.localPoint.x;
    pg.localPoint.y[l] = manifold.localPoint.y;
    pg.radiusA[l] = contact.radiusA;
    pg.radiusB[l] = contact.radiusB;
    h.circles |= manifold.type == Manifold::Type::Circles ? bit : 0;
    h.faceB |= manifold.type == Manifold::Type::FaceB ? bit : 0;
    // A missing point's lanes are zero (PrepareGroup clears only a group with empty lanes).
#pragma GCC unroll 2
    for (int j = 0; j < 2; ++j)
    {
        const bool has = j < manifold.pointCount;
        const ManifoldPoint& mp = manifold.points[j];
        pg.localPoints[j].x[l] = has ? mp.localPoint.x : Real(0);
        pg.localPoints[j].y[l] = has ? mp.localPoint.y : Real(0);
        h.hasPoint[j] |= has ? bit : 0;
        // Impulses are scaled by dt/dt0 so that a changed step size keeps the same force.
        vg.normalImpulse[j][l] = has ? impulseScale * mp.normalImpulse : Real(0);
        vg.tangentImpulse[j][l] = has ? impulseScale * mp.tangentImpulse : Real(0);
    }
}

/// The scalar effective mass's inverse along n (seed: 1/m_eff = Σ 1/m + (r×n)²/I).
[[gnu::always_inline]] inline RealW InverseEffectiveMass(const LaneMasses& m, Vec2W rA, Vec2W rB,
                                                         Vec2W n)
{
    const RealW rnA = Cross(rA, n), rnB = Cross(rB, n);
    return m.invMassA + m.invMassB + m.invIA * rnA * rnA + m.invIB * rnB * rnB;
}

/// The manifold's points and normal in world space at the step's start, per lane, as
/// WorldManifold::Initialize: FaceA and circles take A as the reference (face or centre), FaceB
/// takes B and turns the normal round at the end.
struct WorldPointsW
{
    Vec2W normal;    ///< from A to B
    Vec2W points[2]; ///< midway between the two surfaces (m)
};

WorldPointsW WorldPoints(const ContactGroupHeader& h, const ContactPositionGroup& g,
                         Vec2W localCenterA, Vec2W localCenterB, const BodyStateW& positionA,
                         const BodyStateW& positionB)
{
    const MaskW circles = LanesOf(h.circles), faceB = LanesOf(h.faceB);
    TransformW xfA, xfB;
    TransformsFromCenter(positionA, localCenterA, positionB, localCenterB, xfA, xfB);
    // Where no lane is FaceB (most groups), the selects by faceB would give their second operand.
    const bool anyFaceB = h.faceB != 0;
    const TransformW reference = anyFaceB ? Select(faceB, xfB, xfA) : xfA;
    const TransformW incident = anyFaceB ? Select(faceB, xfA, xfB) : xfB;
    const RealW radiusReference = anyFaceB ? Select(faceB, g.radiusB, g.radiusA) : g.radiusA;
    const RealW radiusIncident = anyFaceB ? Select(faceB, g.radiusA, g.radiusB) : g.radiusB;
    const Vec2W planePoint = Mul(reference, g.localPoint);
    const Vec2W clipPoints[2] = {Mul(incident, g.localPoints[0]), Mul(incident, g.localPoints[1])};

    Vec2W normal = Mul(reference.q, g.localNormal);
    if (h.circles != 0)
    {
        // Circles: the normal joins the centres (+x when they coincide), normalized as
        // Vec2::Normalize does.
        const Vec2W d = clipPoints[0] - planePoint;
        const MaskW apart = d.x * d.x + d.y * d.y > Splat(kEpsilon * kEpsilon);
        const Vec2W circleNormal = Select(apart, NormalizeW(d), Vec2W{Splat(1), Splat(0)});
        normal = Select(circles, circleNormal, normal);
    }

    WorldPointsW out{};
    for (int j = 0; j < 2; ++j)
    {
        const Vec2W clip = clipPoints[j];
        // The reference surface: the face through the clip point's projection, or the
        // reference circle's rim.
        const Vec2W onFace = clip + (radiusReference - Dot(clip - planePoint, normal)) * normal;
        const Vec2W onRim = planePoint + radiusReference * normal;
        const Vec2W surfaceReference = h.circles != 0 ? Select(circles, onRim, onFace) : onFace;
        const Vec2W surfaceIncident = clip - radiusIncident * normal;
        out.points[j] = Splat(Real(0.5)) * (surfaceReference + surfaceIncident);
    }
    out.normal = anyFaceB ? Select(faceB, Vec2W{-normal.x, -normal.y}, normal) : normal;
    return out;
}

/// What the rest of the step reads of a coloured contact besides its impulses.
struct PreparedLanes
{
    MaskW solvesTwo;         ///< lanes whose both points are solved
    RealW normalVelocity[2]; ///< vn before impulses (m/s), as ContactVelocityPoint
};

/// The velocity rows of one group from its gathered contacts (ContactSolver::Prepare's
/// position-dependent part, kLanes contacts at once).
PreparedLanes PrepareRows(ContactGroupHeader& h, ContactVelocityGroup& vg,
                          const ContactPositionGroup& pg, LaneInputs& in, const BodyMass* bodies,
                          const SolverData& data)
{
    const BodyMassW A = GatherBodyMass(bodies, h.indexA);
    const BodyMassW B = GatherBodyMass(bodies, h.indexB);
    const LaneMasses masses{A.invMass, A.invI, B.invMass, B.invI};
    const BodyStateW positionA = Gather(data.positions, h.indexA);
    const BodyStateW positionB = Gather(data.positions, h.indexB);
    const WorldPointsW world =
        WorldPoints(h, pg, A.localCenter, B.localCenter, positionA, positionB);
    vg.normal = world.normal;
    const Vec2W tangent{world.normal.y, -world.normal.x};
    // The approach velocity for restitution: this step's (gravity already added, as Box2D) or
    // the bodies' velocities at the start of the step (restitutionFromStepStart).
    const bool fromStepStart = data.step.solver.restitutionFromStepStart;
    const BodyStateW velocityA =
        fromStepStart ? in.startVelocityA : Gather(data.velocities, h.indexA);
    const BodyStateW velocityB =
        fromStepStart ? in.startVelocityB : Gather(data.velocities, h.indexB);

    PreparedLanes out{};
    for (int j = 0; j < 2; ++j)
    {
        const MaskW has = LanesOf(h.hasPoint[j]);
        const Vec2W rA = world.points[j] - positionA.linear;
        const Vec2W rB = world.points[j] - positionB.linear;
        vg.rA[j] = Select(has, rA, Vec2W{});
        vg.rB[j] = Select(has, rB, Vec2W{});
        vg.tangentMass[j] =
            Select(has, RowMass(InverseEffectiveMass(masses, rA, rB, tangent)), Splat(0));

        // Restitution (seed: P = (1+e)(u2−u1)·m_red) as the target velocity −e·vn.
        const RealW vn = Dot(world.normal, RelativeVelocity(velocityA, velocityB, rA, rB));
        out.normalVelocity[j] = vn;
        const RealW bias = Select(has & (vn < -in.threshold), -in.restitution * vn, Splat(0));
        in.extras.velocityBias[j] = bias;
        // +0 in every lane is all bits clear.
        MaskW biasBits;
        std::memcpy(&biasBits, &bias, sizeof(MaskW));
        if (AnyLane(biasBits != 0))
        {
            h.extras |= ContactGroupHeader::kRestitution;
        }
    }

    // Two points, block solver on: K (K⁻¹ and the normal rows' masses are left to the sweeps,
    // which recompute them as ContactSolver's preparation computes them: k11 and k22 are the
    // rows' InverseEffectiveMass along the normal, lever arms and all), unless the rows are nearly
    // parallel, in which case only the first point is solved (Box2D; the second keeps its stored
    // impulse).
    const RealW mA = masses.invMassA, mB = masses.invMassB, iA = masses.invIA, iB = masses.invIB;
    const RealW rn1A = Cross(vg.rA[0], vg.normal), rn1B = Cross(vg.rB[0], vg.normal);
    const RealW rn2A = Cross(vg.rA[1], vg.normal), rn2B = Cross(vg.rB[1], vg.normal);
    vg.k11 = mA + mB + iA * rn1A * rn1A + iB * rn1B * rn1B;
    vg.k22 = mA + mB + iA * rn2A * rn2A + iB * rn2B * rn2B;
    vg.k12 = mA + mB + iA * rn1A * rn2A + iB * rn1B * rn2B;
    const MaskW twoPoints = LanesOf(h.hasPoint[1]);
    const MaskW wellConditioned =
        vg.k11 * vg.k11 < Splat(kMaxConditionNumber) * (vg.k11 * vg.k22 - vg.k12 * vg.k12);
    const bool blockSolver = data.step.solver.blockSolver;
    const MaskW block = blockSolver ? (twoPoints & wellConditioned) : MaskW{};
    h.block = static_cast<std::uint8_t>(BitsOf(block));
    const MaskW dropSecond = blockSolver ? (twoPoints & ~wellConditioned) : MaskW{};
    vg.tangentMass[1] = Select(dropSecond, Splat(0), vg.tangentMass[1]);
    vg.normalImpulse[1] = Select(dropSecond, Splat(0), vg.normalImpulse[1]);
    vg.tangentImpulse[1] = Select(dropSecond, Splat(0), vg.tangentImpulse[1]);
    out.solvesTwo = twoPoints & ~dropSecond;
    h.solvesTwo = static_cast<std::uint8_t>(BitsOf(out.solvesTwo));
    return out;
}

/// What the rest of the step reads of a coloured contact besides its impulses (which
/// CollectResults adds): its contact index, the points solved and their approach velocities.
void WriteBack(const LaneInputs& in, const PreparedLanes& prepared, const IslandContacts& island,
               std::span<SolvedContact> solved)
{
    for (int l = 0; l < kLanes && in.source[l] >= 0; ++l)
    {
        SolvedContact& s = solved[in.source[l]];
        s.contactIndex = island.contactIndices[in.source[l]];
        s.pointCount = prepared.solvesTwo[l] != 0 ? 2 : 1;
        for (int j = 0; j < s.pointCount; ++j)
        {
            s.normalVelocity[j] = prepared.normalVelocity[j][l];
        }
    }
}

/// Applies a group's warm-start impulses (its accumulated impulses, scaled in Prepare).
void WarmStartGroup(const ContactGroupHeader& h, const ContactVelocityGroup& g,
                    const ContactGroupExtras& extras, const BodyMass* bodies, Velocity* velocities,
                    DiscardSlots discard)
{
    const BodyMassW A = GatherBodyMass(bodies, h.indexA);
    const BodyMassW B = GatherBodyMass(bodies, h.indexB);
    const LaneMasses m{A.invMass, A.invI, B.invMass, B.invI};
    BodyStateW a = Gather(velocities, h.indexA);
    BodyStateW b = Gather(velocities, h.indexB);
    const Vec2W tangent{g.normal.y, -g.normal.x};
    for (int j = 0; j < 2; ++j)
    {
        const Vec2W P = g.normalImpulse[j] * g.normal + g.tangentImpulse[j] * tangent;
        ApplyImpulseW(m, a, b, g.rA[j], g.rB[j], P);
    }
    if ((h.extras & ContactGroupHeader::kRolling) != 0)
    {
        a.angular = a.angular - m.invIA * extras.rollingImpulse;
        b.angular = b.angular + m.invIB * extras.rollingImpulse;
    }
    ScatterStores(velocities, h.indexA, h.storesA, discard.own, a);
    ScatterStores(velocities, h.indexB, h.storesB, discard.own, b);
}

} // namespace

bool ContactLanes::PrepareGroup(std::int32_t i, int colour, const IslandContacts& island,
                                std::span<SolvedContact> solved, const SolverData& data)
{
    const GroupRows rows = GroupRowsOf(m_groupStarts, m_colouring, i, colour);
    const std::int32_t first = rows.first, end = rows.end;
    ContactGroupHeader& h = m_headers[i];
    ContactVelocityGroup& vg = m_velocityGroups[i];
    ContactPositionGroup& pg = m_positionGroups[i];
    h = ContactGroupHeader{};
    // A full group writes every lane of its rows (GatherLane, PrepareRows): only a colour's last
    // group, which may have empty lanes, is cleared first.
    const bool full = end - first >= kLanes;
    if (!full)
    {
        vg = ContactVelocityGroup{};
        pg = ContactPositionGroup{};
    }
    const Real impulseScale = data.step.solver.warmStarting ? data.step.dtRatio : Real(0);
    LaneInputs in;
    int filled = 0;
    for (; filled < kLanes && first + filled < end; ++filled)
    {
        const std::int32_t k = m_colouring.order[first + filled];
        GatherLane(h, vg, pg, in, filled, k, island.contacts[island.contactIndices[k]], island,
                   impulseScale, data.step.solver.restitutionFromStepStart);
    }
    // Empty lanes read lane 0's bodies, which only this group of its colour writes (body 0 may
    // be another group's, being written by another thread at that moment), and write the
    // discard slot.
    for (int l = filled; l < kLanes; ++l)
    {
        in.source[l] = -1;
        in.restitution[l] = in.threshold[l] = 0;
        for (BodyStateW* start : {&in.startVelocityA, &in.startVelocityB})
        {
            start->linear.x[l] = start->linear.y[l] = start->angular[l] = 0;
        }
        h.indexA[l] = h.indexA[0];
        h.indexB[l] = h.indexB[0];
    }
    WriteBack(in, PrepareRows(h, vg, pg, in, m_bodies.data(), data), island, solved);
    if (h.extras != 0)
    {
        m_extras[i] = in.extras;
    }
    return in.hitEvents;
}

void ContactLanes::GatherBodies(const IslandContacts& island, const SolverData& data)
{
    m_bodies.resize(island.bodyIndices.size());
    ForRanges(data.tasks, static_cast<int>(island.bodyIndices.size()), kMinBodiesPerTask,
              [&](int begin, int end, int)
              {
                  for (int i = begin; i < end; ++i)
                  {
                      const Body& body = island.bodies[island.bodyIndices[i]];
                      m_bodies[i] = {body.invMass, body.invI, body.sweep.localCenter};
                  }
              });
}

void ContactLanes::Colour(const IslandContacts& island, std::size_t bodyCount)
{
    if (island.contactIndices.empty())
    {
        // A body in free fall: skip the colouring's fixed cost (its per-body scratch).
        m_colouring.overflow.clear();
        return;
    }
    ColourContacts(island, bodyCount, m_colouring);
}

bool ContactLanes::Prepare(const IslandContacts& island, std::span<SolvedContact> solved,
                           const SolverData& data)
{
    if (island.contactIndices.empty())
    {
        m_groupStarts.assign(1, 0);
        m_headers.clear();
        m_velocityGroups.clear();
        m_positionGroups.clear();
        m_groupMinSeparation.clear();
        return false;
    }
    // Each colour's contacts kLanes to a group, colour after colour.
    const std::int32_t groups = GroupStartsOf(m_colouring, m_groupStarts);
    m_headers.resize(static_cast<std::size_t>(groups));
    m_velocityGroups.resize(static_cast<std::size_t>(groups));
    m_positionGroups.resize(static_cast<std::size_t>(groups));
    m_extras.resize(static_cast<std::size_t>(groups));
    GatherBodies(island, data);
    m_groupMinSeparation.resize(static_cast<std::size_t>(groups));

    // Groups only read the bodies here, so every group may be prepared at once.
    std::atomic<bool> hitEvents{false};
    ForEachGroupWithColour(m_groupStarts, data.tasks, kMinGroupsPerTask,
                           [&](std::int32_t i, int colour)
                           {
                               if (PrepareGroup(i, colour, island, solved, data))
                               {
                                   hitEvents.store(true, std::memory_order_relaxed);
                               }
                           });
    return hitEvents.load(std::memory_order_relaxed);
}

void ContactLanes::WarmStart(SolverData& data)
{
    for (int c = 0; c < GroupColourCount(); ++c)
    {
        ForEachGroupOfColour(c, data,
                             [&](std::int32_t i, DiscardSlots discard)
                             {
                                 WarmStartGroup(m_headers[i], m_velocityGroups[i], m_extras[i],
                                                m_bodies.data(), data.velocities, discard);
                             });
    }
}

} // namespace meff::detail
