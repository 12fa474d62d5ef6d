// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
#include "solvers/soft_step/soft_revolute_lanes.h"

#include "solvers/lanes/lane_bodies.h"
#include "solvers/soft_step/soft_delta_lanes.h"

#include <memory>
#include <variant>

namespace meff::detail
{

namespace
{

/// Each lane's anchors now and the gap between them (AnchorsNow).
struct AnchorsW
{
    Vec2W rA, rB, d;
};

[[gnu::always_inline]] inline AnchorsW AnchorsNowW(const SoftRevoluteGroup& g,
                                                   const SoftBodies& bodies)
{
    const DeltaW dA = GatherDeltas(bodies.deltas.data(), g.indexA);
    const DeltaW dB = GatherDeltas(bodies.deltas.data(), g.indexB);
    const Vec2W rA = Mul(dA.dq, g.rA0);
    const Vec2W rB = Mul(dB.dq, g.rB0);
    return {rA, rB, (dB.dp - dA.dp) + g.deltaCenter + (rB - rA)};
}

[[gnu::always_inline]] inline LaneMasses Masses(const SoftRevoluteGroup& g)
{
    return {g.invMassA, g.invIA, g.invMassB, g.invIB};
}

void WarmStartGroup(const SoftRevoluteGroup& g, const SoftBodies& bodies, Velocity* velocities,
                    DiscardSlots discard)
{
    const AnchorsW at = AnchorsNowW(g, bodies);
    BodyStateW a = Gather(velocities, g.indexA);
    BodyStateW b = Gather(velocities, g.indexB);
    ApplyImpulseW(Masses(g), a, b, at.rA, at.rB, g.impulse);
    ScatterFromWorker(velocities, g.storeA, discard, a);
    ScatterFromWorker(velocities, g.storeB, discard, b);
}

/// BiasOf per lane: a lane whose bias is bounded (rare: a gap beyond what a sub-step's motion
/// opens) is done one by one.
Vec2W BiasW(const Softness& soft, const Vec2W& d)
{
    Vec2W bias = Splat(soft.biasScale) * d;
    const RealW lengthSquared = bias.x * bias.x + bias.y * bias.y;
    if (AnyLane(lengthSquared > Splat(soft.maxBias * soft.maxBias)) || soft.excess)
    {
        for (int l = 0; l < kLanes; ++l)
        {
            const Vec2 b = BiasOf(soft, Vec2{d.x[l], d.y[l]});
            bias.x[l] = b.x;
            bias.y[l] = b.y;
        }
    }
    return bias;
}

/// SolvePoint's block update per lane (without a bound on the impulse's length: the revolute
/// joint has none).
void SolveGroup(SoftRevoluteGroup& g, const SoftStepContext& context, bool useBias,
                Velocity* velocities, DiscardSlots discard)
{
    const AnchorsW at = AnchorsNowW(g, *context.bodies);
    BodyStateW a = Gather(velocities, g.indexA);
    BodyStateW b = Gather(velocities, g.indexB);
    const Softness soft = useBias ? context.joint : kRigid;
    const Vec2W bias = useBias ? BiasW(context.joint, at.d) : Vec2W{};
    // PointBlock: the seed's k along x̂ and ŷ on the diagonal.
    const Vec2W rA = at.rA, rB = at.rB;
    const RealW k11 = g.invMassA + g.invMassB + rA.y * rA.y * g.invIA + rB.y * rB.y * g.invIB;
    const RealW k12 = -rA.y * rA.x * g.invIA - rB.y * rB.x * g.invIB;
    const RealW k22 = g.invMassA + g.invMassB + rA.x * rA.x * g.invIA + rB.x * rB.x * g.invIB;
    const Vec2W rhs = Splat(soft.massScale) * RelativeVelocity(a, b, rA, rB) + bias;
    // Mat22::Solve.
    const RealW det = k11 * k22 - k12 * k12;
    const MaskW invertible = det != 0;
    const RealW invDet = Select(invertible, Splat(1) / Select(invertible, det, Splat(1)), det);
    const Vec2W x{invDet * (k22 * rhs.x - k12 * rhs.y), invDet * (k11 * rhs.y - k12 * rhs.x)};
    const RealW impulseScale = Splat(soft.impulseScale);
    const Vec2W step{-x.x - impulseScale * g.impulse.x, -x.y - impulseScale * g.impulse.y};
    const Vec2W next = g.impulse + step;
    const Vec2W applied = next - g.impulse;
    g.impulse = next;
    ApplyImpulseW(Masses(g), a, b, rA, rB, applied);
    ScatterFromWorker(velocities, g.storeA, discard, a);
    ScatterFromWorker(velocities, g.storeB, discard, b);
}

} // namespace

RevoluteJoint* SoftRevoluteLanes::LaneJoint(Joint& joint, const SoftStepContext& context)
{
    auto* revolute = std::get_if<RevoluteJoint>(&joint.data);
    if (revolute == nullptr || !context.step->solver.blockJoints || revolute->enableLimit ||
        revolute->enableMotor || revolute->enableSpring)
    {
        return nullptr;
    }
    return revolute;
}

void SoftRevoluteLanes::Prepare(std::span<RevoluteJoint* const> joints,
                                std::span<const SoftJointFrame> frames,
                                std::span<const std::int32_t> rows, std::int32_t bodyCount,
                                TaskSystem* tasks)
{
    m_bodies.resize(joints.size());
    for (std::size_t i = 0; i < joints.size(); ++i)
    {
        const SoftJointFrame& f = frames[rows[i]];
        m_bodies[i] = {f.indexA, f.indexB, SolverMoves(f.mA, f.iA), SolverMoves(f.mB, f.iB)};
    }
    // Last step's colouring is kept while the joints' bodies and the body count are last
    // step's (ColouringInputs).
    const auto bodies = static_cast<std::size_t>(bodyCount);
    if (m_colouredFrom.Changed(m_bodies, bodies))
    {
        ColourSoftRows(
            joints.size(), bodyCount, [&](std::size_t i) { return m_bodies[i]; }, m_colouring);
        m_colouredFrom.Keep(m_bodies, bodies);
    }
    const std::int32_t groups = m_groupsOfColour.Cut(m_colouring, tasks, bodyCount);
    m_groups.resize(static_cast<std::size_t>(groups));
    m_sources.resize(static_cast<std::size_t>(groups) * kLanes);
    m_groupsOfColour.ForEachGroup([&](std::int32_t i) { PackGroup(i, joints, frames, rows); });
}

void SoftRevoluteLanes::PackGroup(std::int32_t i, std::span<RevoluteJoint* const> joints,
                                  std::span<const SoftJointFrame> frames,
                                  std::span<const std::int32_t> rows)
{
    const auto [first, end] = m_groupsOfColour.RowsOf(i, m_colouring);
    const std::int32_t discardIndex = m_groupsOfColour.discardIndex;
    SoftRevoluteGroup& g = m_groups[static_cast<std::size_t>(i)];
    std::construct_at(&g); // empty lanes: zero masses, nothing to write
    RevoluteJoint** sources = &m_sources[static_cast<std::size_t>(i) * kLanes];
    int filled = 0;
    for (; first + filled < end; ++filled)
    {
        const std::int32_t k = m_colouring.order[first + filled];
        const SoftJointFrame& f = frames[rows[k]];
        const RevoluteJoint& joint = *joints[k];
        const int l = filled;
        PackLaneBodies(g, l, f.indexA, f.indexB, f.mA, f.iA, f.mB, f.iB, discardIndex);
        g.rA0.x[l] = f.rA0.x;
        g.rA0.y[l] = f.rA0.y;
        g.rB0.x[l] = f.rB0.x;
        g.rB0.y[l] = f.rB0.y;
        g.deltaCenter.x[l] = f.deltaCenter.x;
        g.deltaCenter.y[l] = f.deltaCenter.y;
        g.impulse.x[l] = joint.impulse.x;
        g.impulse.y[l] = joint.impulse.y;
        sources[l] = joints[k];
    }
    // Empty lanes read lane 0's bodies, have zero masses and change nothing.
    for (int l = filled; l < kLanes; ++l)
    {
        g.indexA[l] = g.indexA[0];
        g.indexB[l] = g.indexB[0];
        g.storeA[l] = g.storeB[l] = discardIndex;
        sources[l] = nullptr;
    }
}

void SoftRevoluteLanes::WarmStart(const SoftStepContext& context)
{
    SoftRevoluteGroup* groups = m_groups.data();
    const SoftBodies* bodies = context.bodies;
    Velocity* velocities = context.bodies->velocities.data();
    m_groupsOfColour.ForEachGroupByColour(
        [groups, bodies, velocities](std::int32_t i, DiscardSlots discard)
        { WarmStartGroup(groups[i], *bodies, velocities, discard); });
}

void SoftRevoluteLanes::Solve(const SoftStepContext& context, bool useBias)
{
    SoftRevoluteGroup* groups = m_groups.data();
    const SoftStepContext* at = &context;
    Velocity* velocities = context.bodies->velocities.data();
    m_groupsOfColour.ForEachGroupByColour(
        [groups, at, useBias, velocities](std::int32_t i, DiscardSlots discard)
        { SolveGroup(groups[i], *at, useBias, velocities, discard); });
}

void SoftRevoluteLanes::ScaleImpulses(Real factor)
{
    SoftRevoluteGroup* groups = m_groups.data();
    m_groupsOfColour.ForEachGroup([groups, factor](std::int32_t i)
                                  { groups[i].impulse = Splat(factor) * groups[i].impulse; });
}

void SoftRevoluteLanes::Correct(const SoftStepContext& context)
{
    SoftRevoluteGroup* groups = m_groups.data();
    const SoftStepContext* at = &context;
    Velocity* velocities = context.bodies->velocities.data();
    m_groupsOfColour.ForEachGroupByColour(
        [groups, at, velocities](std::int32_t i, DiscardSlots discard)
        {
            // The impulse is kept aside on the stack: a member for it would make every group
            // a cache line longer in every sweep.
            SoftRevoluteGroup& g = groups[i];
            const Vec2W saved = g.impulse;
            g.impulse = Vec2W{};
            SolveGroup(g, *at, true, velocities, discard);
            g.impulse = saved;
        });
}

void SoftRevoluteLanes::CloseStep(const SoftStepContext& context)
{
    SoftRevoluteGroup* groups = m_groups.data();
    const SoftStepContext* at = &context;
    Velocity* velocities = context.bodies->velocities.data();
    m_groupsOfColour.ForEachGroupByColour(
        [groups, at, velocities](std::int32_t i, DiscardSlots discard)
        {
            SoftRevoluteGroup& g = groups[i];
            const Vec2W saved = g.impulse;
            g.impulse = Splat(Real(0.5)) * g.impulse;
            WarmStartGroup(g, *at->bodies, velocities, discard);
            SolveGroup(g, *at, false, velocities, discard);
            g.impulse = saved;
        });
}

void SoftRevoluteLanes::Store(Real factor) const
{
    // Each lane writes its own joint.
    m_groupsOfColour.ForEachGroup(
        [&](std::int32_t i)
        {
            const SoftRevoluteGroup& g = m_groups[static_cast<std::size_t>(i)];
            for (int l = 0; l < kLanes; ++l)
            {
                if (RevoluteJoint* joint = m_sources[static_cast<std::size_t>(i) * kLanes + l])
                {
                    joint->impulse = Vec2{g.impulse.x[l], g.impulse.y[l]};
                    joint->impulse *= factor;
                }
            }
        });
}

} // namespace meff::detail
