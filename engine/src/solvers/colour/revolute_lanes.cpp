// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
#include "solvers/colour/revolute_lanes.h"

#include "joints/joint.h"
#include "solvers/lanes/lane_bodies.h"

#include <algorithm>
#include <cmath>

namespace meff::detail
{

namespace
{

/// Copies what the lanes need of one joint whose bodies are stored (StoreJointBodies).
void PackLane(RevoluteJointGroup& g, int l, RevoluteJoint& joint, std::int32_t discardIndex)
{
    PackLaneBodies(g, l, joint, discardIndex);
    g.impulse.x[l] = joint.impulse.x;
    g.impulse.y[l] = joint.impulse.y;
    const Vec2 anchorA = joint.localAnchorA - joint.localCenterA;
    const Vec2 anchorB = joint.localAnchorB - joint.localCenterB;
    g.anchorA.x[l] = anchorA.x;
    g.anchorA.y[l] = anchorA.y;
    g.anchorB.x[l] = anchorB.x;
    g.anchorB.y[l] = anchorB.y;
    // No motor, no limit and no spring: their impulses are zero (as InitVelocityConstraints
    // leaves them), so that the joint's reaction torque is zero too.
    joint.motorImpulse = 0;
    joint.lowerImpulse = 0;
    joint.upperImpulse = 0;
    joint.springImpulse = 0;
}

/// RevoluteJoint's InitVelocityConstraints for kLanes joints, but the warm start (WarmStartGroup):
/// lever arms at the step's start, the point rows' K = J·M⁻¹·Jᵀ and its inverse determinant (K is
/// fixed over the velocity iterations, so it is inverted once here, not in every Mat22::Solve).
/// Reads only the positions.
void PrepareRows(RevoluteJointGroup& g, const SolverData& data)
{
    const RealW aA = Gather(data.positions, g.indexA).angular;
    const RealW aB = Gather(data.positions, g.indexB).angular;
    g.rA = Mul(SinCosW(aA), g.anchorA);
    g.rB = Mul(SinCosW(aB), g.anchorB);
    const Vec2W rA = g.rA, rB = g.rB;
    const RealW mA = g.invMassA, mB = g.invMassB, iA = g.invIA, iB = g.invIB;
    g.k11 = mA + mB + rA.y * rA.y * iA + rB.y * rB.y * iB;
    g.k12 = -rA.y * rA.x * iA - rB.y * rB.x * iB;
    g.k22 = mA + mB + rA.x * rA.x * iA + rB.x * rB.x * iB;
    g.invDetK = InverseDeterminant(g.k11, g.k12, g.k12, g.k22);
    // Impulses are force·dt: rescale last step's to this step's dt (none without warm start).
    g.impulse = data.step.solver.warmStarting ? Splat(data.step.dtRatio) * g.impulse : Vec2W{};
}

/// The warm start: last step's accumulated impulse (scaled in PrepareRows) applied again.
void WarmStartGroup(const RevoluteJointGroup& g, Velocity* velocities, DiscardSlots discard)
{
    BodyStateW a = Gather(velocities, g.indexA);
    BodyStateW b = Gather(velocities, g.indexB);
    ApplyImpulseW({g.invMassA, g.invIA, g.invMassB, g.invIB}, a, b, g.rA, g.rB, g.impulse);
    ScatterFromWorker(velocities, g.storeA, discard, a);
    ScatterFromWorker(velocities, g.storeB, discard, b);
}

/// x = K⁻¹·b for the lanes' 2×2 K, as Mat22::Solve (0 where det K = 0).
[[gnu::always_inline]] inline Vec2W SolveK(RealW k11, RealW k12, RealW k21, RealW k22, RealW invDet,
                                           Vec2W b)
{
    return {invDet * (k22 * b.x - k12 * b.y), invDet * (k11 * b.y - k21 * b.x)};
}

/// The point rows as one 2×2 block (RevoluteJoint's SolveVelocityConstraints with
/// blockJoints): Cdot = vB + wB×rB − vA − wA×rA, λ = −K⁻¹·Cdot.
void SolveVelocityGroup(RevoluteJointGroup& g, Velocity* velocities, DiscardSlots discard)
{
    BodyStateW a = Gather(velocities, g.indexA);
    BodyStateW b = Gather(velocities, g.indexB);
    const Vec2W cdot = b.linear + Cross(b.angular, g.rB) - a.linear - Cross(a.angular, g.rA);
    const Vec2W impulse = SolveK(g.k11, g.k12, g.k12, g.k22, g.invDetK, Vec2W{-cdot.x, -cdot.y});
    g.impulse = g.impulse + impulse;
    ApplyImpulseW({g.invMassA, g.invIA, g.invMassB, g.invIB}, a, b, g.rA, g.rB, impulse);
    ScatterFromWorker(velocities, g.storeA, discard, a);
    ScatterFromWorker(velocities, g.storeB, discard, b);
}

/// One Newton step on the anchor gap C = cB + rB − cA − rA with K from the current lever arms
/// (RevoluteJoint's SolvePositionConstraints with blockJoints). Returns each lane's |C|².
RealW SolvePositionGroup(const RevoluteJointGroup& g, Position* positions, DiscardSlots discard)
{
    BodyStateW a = Gather(positions, g.indexA);
    BodyStateW b = Gather(positions, g.indexB);
    const Vec2W rA = Mul(SinCosW(a.angular), g.anchorA);
    const Vec2W rB = Mul(SinCosW(b.angular), g.anchorB);
    const Vec2W C = b.linear + rB - a.linear - rA;

    const RealW mA = g.invMassA, mB = g.invMassB, iA = g.invIA, iB = g.invIB;
    const RealW k11 = mA + mB + iA * rA.y * rA.y + iB * rB.y * rB.y;
    const RealW k12 = -iA * rA.x * rA.y - iB * rB.x * rB.y;
    const RealW k22 = mA + mB + iA * rA.x * rA.x + iB * rB.x * rB.x;
    const Vec2W x = SolveK(k11, k12, k12, k22, InverseDeterminant(k11, k12, k12, k22), C);
    ApplyImpulseW({mA, iA, mB, iB}, a, b, rA, rB, Vec2W{-x.x, -x.y});
    ScatterFromWorker(positions, g.storeA, discard, a);
    ScatterFromWorker(positions, g.storeB, discard, b);
    return C.x * C.x + C.y * C.y;
}

} // namespace

void RevoluteLanes::PrepareGroup(std::int32_t i, int colour, std::span<RevoluteJoint* const> joints,
                                 const SolverData& data)
{
    const GroupRows rows = GroupRowsOf(m_groupStarts, m_colouring, i, colour);
    const std::int32_t first = rows.first, end = rows.end;
    RevoluteJointGroup& g = m_groups[i];
    g = RevoluteJointGroup{};
    // Empty lanes write the discard slot; all their masses are zero.
    std::fill(std::begin(g.storeA), std::end(g.storeA), data.discardIndex);
    std::fill(std::begin(g.storeB), std::end(g.storeB), data.discardIndex);
    for (int l = 0; l < kLanes; ++l)
    {
        RevoluteJoint* joint = first + l < end ? joints[m_colouring.order[first + l]] : nullptr;
        m_sources[static_cast<std::size_t>(i) * kLanes + l] = joint;
        if (joint != nullptr)
        {
            PackLane(g, l, *joint, data.discardIndex);
        }
        else
        {
            // Lane 0's body A, which only this group of its colour writes (body 0 may be
            // another group's, written by another thread at that moment); as both bodies, so
            // that the empty lane's anchor gap is zero in SolvePositions.
            g.indexA[l] = g.indexB[l] = g.indexA[0];
        }
    }
    PrepareRows(g, data);
}

void RevoluteLanes::Prepare(std::span<RevoluteJoint* const> joints,
                            std::span<const ConstraintBodies> bodies, const SolverData& data)
{
    // The island's bodies are the solver indices below the discard slot; last step's colouring
    // is kept while they and the joints' bodies are last step's (ColouringInputs).
    const auto bodyCount = static_cast<std::size_t>(data.discardIndex);
    if (m_colouredFrom.Changed(bodies, bodyCount))
    {
        ColourConstraints(
            joints.size(), bodyCount, [&](std::size_t i) { return bodies[i]; }, m_colouring);
        m_colouredFrom.Keep(bodies, bodyCount);
    }
    const std::int32_t groups = GroupStartsOf(m_colouring, m_groupStarts);
    m_groups.resize(static_cast<std::size_t>(groups));
    m_sources.resize(static_cast<std::size_t>(groups) * kLanes);
    m_groupLargestSquared.resize(static_cast<std::size_t>(groups));

    // Packing and the rows only read the bodies, so every group may be prepared at once.
    ForEachGroupWithColour(m_groupStarts, data.tasks, kMinJointGroupsPerTask,
                           [&](std::int32_t i, int colour)
                           { PrepareGroup(i, colour, joints, data); });
    if (data.step.solver.warmStarting)
    {
        for (int c = 0; c < m_colouring.ColourCount(); ++c)
        {
            ForEachGroupOfColour(m_groupStarts, c, data, kMinJointGroupsPerTask,
                                 [&](std::int32_t i, DiscardSlots discard)
                                 { WarmStartGroup(m_groups[i], data.velocities, discard); });
        }
    }
}

void RevoluteLanes::SolveVelocities(const SolverData& data)
{
    for (int c = 0; c < m_colouring.ColourCount(); ++c)
    {
        ForEachGroupOfColour(m_groupStarts, c, data, kMinJointGroupsPerTask,
                             [&](std::int32_t i, DiscardSlots discard)
                             { SolveVelocityGroup(m_groups[i], data.velocities, discard); });
    }
}

void RevoluteLanes::StoreImpulses(TaskSystem* tasks) const
{
    // Each group writes only its own joints: any thread may take any group.
    ForEachIndex(tasks, static_cast<int>(m_groups.size()), kMinJointGroupsPerTask,
                 [&](int i)
                 {
                     const RevoluteJointGroup& g = m_groups[static_cast<std::size_t>(i)];
                     for (int l = 0; l < kLanes; ++l)
                     {
                         if (RevoluteJoint* joint =
                                 m_sources[static_cast<std::size_t>(i) * kLanes + l])
                         {
                             joint->impulse = {g.impulse.x[l], g.impulse.y[l]};
                         }
                     }
                 });
}

bool RevoluteLanes::SolvePositions(const SolverData& data)
{
    for (int c = 0; c < m_colouring.ColourCount(); ++c)
    {
        ForEachGroupOfColour(m_groupStarts, c, data, kMinJointGroupsPerTask,
                             [&](std::int32_t i, DiscardSlots discard) {
                                 m_groupLargestSquared[i] =
                                     SolvePositionGroup(m_groups[i], data.positions, discard);
                             });
    }
    // In group order whatever the threads: the same maximum, NaN included.
    RealW largestSquared = Splat(0);
    for (const RealW groupLargest : m_groupLargestSquared)
    {
        largestSquared = MaxW(largestSquared, groupLargest);
    }
    Real largest = 0;
    for (int l = 0; l < kLanes; ++l)
    {
        largest = Max(largest, largestSquared[l]);
    }
    // √ is monotonic and correctly rounded, so √(max |C|²) is the largest |C| exactly.
    return std::sqrt(largest) <= data.step.tolerances.linearSlop;
}

} // namespace meff::detail
