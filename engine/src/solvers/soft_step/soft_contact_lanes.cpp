// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
#include "solvers/soft_step/soft_contact_lanes.h"

#include "solvers/lanes/block_lanes.h"
#include "solvers/lanes/contact_colouring.h"
#include "solvers/lanes/lane_bodies.h"
#include "solvers/lanes/rolling_lanes.h"
#include "solvers/shared/contact_constraint.h"
#include "solvers/soft_step/soft_contact_solver.h"
#include "solvers/soft_step/soft_delta_lanes.h"

#include <memory>

namespace meff::detail
{

namespace
{

/// Clamp with Box2D's tie rule, as the scalar Clamp: Max(low, Min(a, high)).
[[gnu::always_inline]] inline RealW ClampW(RealW a, RealW low, RealW high)
{
    return MaxW(low, MinW(a, high));
}

/// 1/k, or 0 for a row no body can move along (as RowMass).
[[gnu::always_inline]] inline RealW RowMassW(RealW k)
{
    const MaskW positive = k > 0;
    return Select(positive, Splat(1) / Select(positive, k, Splat(1)), Splat(0));
}

/// A row's target per lane (RowTarget): the bias and the softness it is solved with.
struct TargetW
{
    RealW bias, massScale, impulseScale;
};

/// OneSidedTarget per lane for a normal row at error C.
[[gnu::always_inline]] inline TargetW NormalTarget(const SoftContactGroup& g, RealW C, bool pushOut,
                                                   Real invH, Real maxPush)
{
    const MaskW apart = C > 0;
    const RealW speculative = MinW(C, Splat(Real(1e9))) * invH;
    if (!pushOut)
    {
        return {Select(apart, speculative, Splat(0)), Splat(1), Splat(0)};
    }
    const RealW push = MaxW(g.softBias * C, Splat(-maxPush));
    return {Select(apart, speculative, push), Select(apart, Splat(1), g.softMass),
            Select(apart, Splat(0), g.softImpulse)};
}

/// Applies impulse λ along n at point j's levers (ApplyRowImpulse).
[[gnu::always_inline]] inline void ApplyRow(const SoftContactGroup& g, Vec2W n, RealW aA, RealW aB,
                                            RealW lambda, BodyStateW& a, BodyStateW& b)
{
    ApplyRowImpulseOf(n, aA, aB, lambda, g.invMassA, g.invIA, g.invMassB, g.invIB, a.linear,
                      a.angular, b.linear, b.angular);
}

/// J·v of the row along n through point j's levers.
[[gnu::always_inline]] inline RealW RowVelocityW(Vec2W n, RealW aA, RealW aB, const BodyStateW& a,
                                                 const BodyStateW& b)
{
    return RowVelocityOf(n, aA, aB, a.linear, a.angular, b.linear, b.angular);
}

/// The normal rows one by one (SolveRow, accumulated impulse ≥ 0).
[[gnu::always_inline]] inline void SolveNormalRows(SoftContactGroup& g, const TargetW (&t)[2],
                                                   BodyStateW& a, BodyStateW& b)
{
    for (int j = 0; j < 2; ++j)
    {
        const RealW aA = Cross(g.rA[j], g.normal), aB = Cross(g.rB[j], g.normal);
        const RealW impulse =
            SoftImpulseOf(g.normalMass[j], RowVelocityW(g.normal, aA, aB, a, b), t[j].bias,
                          t[j].massScale, t[j].impulseScale, g.normalImpulse[j]);
        const RealW next = ClampW(g.normalImpulse[j] + impulse, Splat(0), Splat(kMaxReal));
        const RealW applied = next - g.normalImpulse[j];
        g.normalImpulse[j] = next;
        ApplyRow(g, g.normal, aA, aB, applied, a, b);
        g.totalNormalImpulse[j] += applied;
    }
}

/// The two normal rows as one block (SolveTwoPointBlock's cases in its order); a lane where no
/// case holds keeps its impulses.
[[gnu::always_inline]] inline void SolveNormalBlock(SoftContactGroup& g, const TargetW (&t)[2],
                                                    BodyStateW& a, BodyStateW& b)
{
    const RealW aA1 = Cross(g.rA[0], g.normal), aB1 = Cross(g.rB[0], g.normal);
    const RealW aA2 = Cross(g.rA[1], g.normal), aB2 = Cross(g.rB[1], g.normal);
    const RealW a1 = g.normalImpulse[0], a2 = g.normalImpulse[1];
    const RealW v1 = RowVelocityW(g.normal, aA1, aB1, a, b) + t[0].bias;
    const RealW v2 = RowVelocityW(g.normal, aA2, aB2, a, b) + t[1].bias;
    const RealW b1 = v1 - (g.k11 * a1 + g.k12 * a2);
    const RealW b2 = v2 - (g.k12 * a1 + g.k22 * a2);
    const auto [new1, new2] = SolveBlockLanes(g, a1, a2, b1, b2);
    const RealW applied1 = new1 - a1, applied2 = new2 - a2;
    ApplyRow(g, g.normal, aA1, aB1, applied1, a, b);
    ApplyRow(g, g.normal, aA2, aB2, applied2, a, b);
    g.normalImpulse[0] = new1;
    g.normalImpulse[1] = new2;
    g.totalNormalImpulse[0] += applied1;
    g.totalNormalImpulse[1] += applied2;
}

/// Friction of both points (rigid, driven to the conveyor's speed, |λt| ≤ μ·λn), in the lanes
/// with μ > 0.
[[gnu::always_inline]] inline void SolveFriction(SoftContactGroup& g, BodyStateW& a, BodyStateW& b)
{
    const Vec2W tangent{g.normal.y, -g.normal.x};
    const RealW bias = -g.tangentSpeed;
    for (int j = 0; j < 2; ++j)
    {
        const RealW aA = Cross(g.rA[j], tangent), aB = Cross(g.rB[j], tangent);
        const RealW maxFriction = g.friction * g.normalImpulse[j];
        const RealW impulse = SoftImpulseOf(g.tangentMass[j], RowVelocityW(tangent, aA, aB, a, b),
                                            bias, Splat(1), Splat(0), g.tangentImpulse[j]);
        const RealW next = ClampW(g.tangentImpulse[j] + impulse, -maxFriction, maxFriction);
        const RealW applied = Select(g.hasFriction, next - g.tangentImpulse[j], Splat(0));
        g.tangentImpulse[j] = Select(g.hasFriction, next, g.tangentImpulse[j]);
        ApplyRow(g, tangent, aA, aB, applied, a, b);
        g.totalTangentImpulse[j] += applied;
    }
}

/// The spin rows of rolling resistance, their impulses totalled over the step.
void SolveRolling(SoftContactGroup& g, BodyStateW& a, BodyStateW& b)
{
    SolveRollingLanes(g, a, b, [&](int l, Real lambda) { g.totalRollingImpulse[l] += lambda; });
}

void WarmStartGroup(SoftContactGroup& g, Velocity* velocities, DiscardSlots discard)
{
    BodyStateW a = Gather(velocities, g.indexA);
    BodyStateW b = Gather(velocities, g.indexB);
    const Vec2W tangent{g.normal.y, -g.normal.x};
    for (int j = 0; j < 2; ++j)
    {
        const Vec2W P = g.normalImpulse[j] * g.normal + g.tangentImpulse[j] * tangent;
        ApplyImpulseW({g.invMassA, g.invIA, g.invMassB, g.invIB}, a, b, g.rA[j], g.rB[j], P);
        g.totalNormalImpulse[j] += g.normalImpulse[j];
        g.totalTangentImpulse[j] += g.tangentImpulse[j];
    }
    // Without rolling resistance every lane's spin impulse is 0 and would change nothing.
    if (g.anyRolling)
    {
        a.angular = a.angular - g.invIA * g.rollingImpulse;
        b.angular = b.angular + g.invIB * g.rollingImpulse;
        g.totalRollingImpulse += g.rollingImpulse;
    }
    ScatterFromWorker(velocities, g.storeA, discard, a);
    ScatterFromWorker(velocities, g.storeB, discard, b);
}

/// Each point's C at the bodies' poses now, into g.error.
void MeasureErrors(SoftContactGroup& g, const SoftStepContext& context)
{
    const SoftDelta* deltas = context.bodies->deltas.data();
    const DeltaW dA = GatherDeltas(deltas, g.indexA);
    const DeltaW dB = GatherDeltas(deltas, g.indexB);
    const RealW slop = Splat(context.rowSlop);
    for (int j = 0; j < 2; ++j)
    {
        g.error[j] = SeparationOf(g.baseSeparation[j], g.normal, dA.dp, dA.dq, dB.dp, dB.dq,
                                  g.rA[j], g.rB[j], slop);
    }
}

/// One sweep of the group; `measure`: the bodies moved since g.error was measured.
void SolveGroup(SoftContactGroup& g, const SoftStepContext& context, bool useBias, bool friction,
                bool measure, DiscardSlots discard)
{
    Velocity* velocities = context.bodies->velocities.data();
    BodyStateW a = Gather(velocities, g.indexA);
    BodyStateW b = Gather(velocities, g.indexB);
    if (measure)
    {
        MeasureErrors(g, context);
    }
    // Rigid contacts leave the overlap to CorrectPositions; soft ones push it out here.
    const bool pushOut = useBias && context.contactModel == SoftContactModel::Soft;
    TargetW targets[2];
    for (int j = 0; j < 2; ++j)
    {
        targets[j] = NormalTarget(g, g.error[j], pushOut, context.invH, context.maxPushOut);
    }
    // The block only where both rows are rigid now (always for rigid contacts).
    MaskW block = g.block;
    if (pushOut)
    {
        for (const TargetW& t : targets)
        {
            block = block & (t.massScale == 1) & (t.impulseScale == 0);
        }
    }
    if (!AnyLane(block))
    {
        SolveNormalRows(g, targets, a, b);
    }
    else if (!AnyLane(g.valid & ~block))
    {
        SolveNormalBlock(g, targets, a, b);
    }
    else
    {
        // Mixed: each lane takes the velocities and impulses of its own kind of solve.
        BodyStateW aRows = a, bRows = b;
        SoftContactGroup rows = g;
        SolveNormalRows(rows, targets, aRows, bRows);
        SolveNormalBlock(g, targets, a, b);
        a.linear = Select(block, a.linear, aRows.linear);
        a.angular = Select(block, a.angular, aRows.angular);
        b.linear = Select(block, b.linear, bRows.linear);
        b.angular = Select(block, b.angular, bRows.angular);
        for (int j = 0; j < 2; ++j)
        {
            g.normalImpulse[j] = Select(block, g.normalImpulse[j], rows.normalImpulse[j]);
            g.totalNormalImpulse[j] =
                Select(block, g.totalNormalImpulse[j], rows.totalNormalImpulse[j]);
        }
    }
    if (friction)
    {
        SolveFriction(g, a, b);
        if (g.anyRolling)
        {
            SolveRolling(g, a, b);
        }
    }
    ScatterFromWorker(velocities, g.storeA, discard, a);
    ScatterFromWorker(velocities, g.storeB, discard, b);
}

void CorrectGroup(const SoftContactGroup& g, const SoftStepContext& context, DiscardSlots discard)
{
    SoftDelta* deltas = context.bodies->deltas.data();
    DeltaW dA = GatherDeltas(deltas, g.indexA);
    DeltaW dB = GatherDeltas(deltas, g.indexB);
    const RealW slop = Splat(context.step->tolerances.linearSlop);
    const RealW maxCorrection = Splat(context.maxPushOut * context.h);
    bool moved = false;
    for (int j = 0; j < 2; ++j)
    {
        // Non-linear Gauss-Seidel on the separation: each point sees the last one's move.
        const RealW C = ClampW(context.contactCorrection *
                                   SeparationOf(g.baseSeparation[j], g.normal, dA.dp, dA.dq, dB.dp,
                                                dB.dq, g.rA[j], g.rB[j], slop),
                               -maxCorrection, Splat(0));
        const MaskW move = g.hasPoint[j] & (C != 0);
        if (!AnyLane(move))
        {
            continue;
        }
        moved = true;
        const Vec2W rA = Mul(dA.dq, g.rA[j]);
        const Vec2W rB = Mul(dB.dq, g.rB[j]);
        const RealW aA = Cross(rA, g.normal), aB = Cross(rB, g.normal);
        const RealW k = g.invMassA + g.invMassB + AngularInverseMass(aA, aB, g.invIA, g.invIB);
        const RealW lambda = -C * RowMassW(k);
        const Vec2W P = lambda * g.normal;
        const DeltaW nextA{dA.dp - g.invMassA * P,
                           MulRot(SmallRotationW(-g.invIA * lambda * aA), dA.dq)};
        const DeltaW nextB{dB.dp + g.invMassB * P,
                           MulRot(SmallRotationW(g.invIB * lambda * aB), dB.dq)};
        dA = {Select(move, nextA.dp, dA.dp),
              {Select(move, nextA.dq.s, dA.dq.s), Select(move, nextA.dq.c, dA.dq.c)}};
        dB = {Select(move, nextB.dp, dB.dp),
              {Select(move, nextB.dq.s, dB.dq.s), Select(move, nextB.dq.c, dB.dq.c)}};
    }
    if (moved)
    {
        ScatterDeltasFromWorker(deltas, g.storeA, discard, dA);
        ScatterDeltasFromWorker(deltas, g.storeB, discard, dB);
    }
}

/// Lane l of group g from contact c (prepared by SoftContactSolver).
void PackLane(SoftContactGroup& g, int l, std::int32_t source, const SoftContact& c,
              std::int32_t discardIndex)
{
    g.source[l] = source;
    PackLaneBodies(g, l, c.indexA, c.indexB, c.mA, c.iA, c.mB, c.iB, discardIndex);
    g.friction[l] = c.friction;
    g.tangentSpeed[l] = c.tangentSpeed;
    g.rollingResistance[l] = c.rollingResistance;
    g.rollingMass[l] = c.rollingMass;
    g.rollingImpulse[l] = c.rollingImpulse;
    g.totalRollingImpulse[l] = c.totalRollingImpulse;
    g.anyRolling = g.anyRolling || c.rollingResistance > 0;
    g.softBias[l] = c.softness.biasScale;
    g.softMass[l] = c.softness.massScale;
    g.softImpulse[l] = c.softness.impulseScale;
    g.normal.x[l] = c.normal.x;
    g.normal.y[l] = c.normal.y;
    for (int j = 0; j < c.pointCount; ++j)
    {
        const SoftContactPoint& p = c.points[j];
        g.rA[j].x[l] = p.rA.x;
        g.rA[j].y[l] = p.rA.y;
        g.rB[j].x[l] = p.rB.x;
        g.rB[j].y[l] = p.rB.y;
        g.baseSeparation[j][l] = p.baseSeparation;
        g.normalMass[j][l] = p.normalMass;
        g.tangentMass[j][l] = p.tangentMass;
        g.normalImpulse[j][l] = p.normalImpulse;
        g.tangentImpulse[j][l] = p.tangentImpulse;
        g.totalNormalImpulse[j][l] = p.totalNormalImpulse;
        g.totalTangentImpulse[j][l] = p.totalTangentImpulse;
        g.hasPoint[j][l] = -1;
    }
    if (c.block)
    {
        g.block[l] = -1;
        g.k11[l] = c.K.ex.x;
        g.k12[l] = c.K.ex.y;
        g.k22[l] = c.K.ey.y;
        g.inv11[l] = c.invK.ex.x;
        g.inv12[l] = c.invK.ey.x;
        g.inv22[l] = c.invK.ey.y;
    }
    g.hasFriction[l] = c.friction > 0 ? -1 : 0;
    g.valid[l] = -1;
}

} // namespace

void SoftContactLanes::Colour(const IslandContacts& island, std::int32_t bodyCount)
{
    ColourSoftRows(
        island.contactIndices.size(), bodyCount,
        [&island](std::size_t i) { return IslandContactBodies(island, i); }, m_colouring);
}

void SoftContactLanes::Pack(std::span<const SoftContact> contacts, std::int32_t bodyCount,
                            TaskSystem* tasks)
{
    m_errorsKnown = false;
    m_groups.resize(static_cast<std::size_t>(m_groupsOfColour.Cut(m_colouring, tasks, bodyCount)));
    m_groupsOfColour.ForEachGroup([&](std::int32_t i) { PackGroup(i, contacts); });
}

void SoftContactLanes::PackGroup(std::int32_t i, std::span<const SoftContact> contacts)
{
    const auto [first, end] = m_groupsOfColour.RowsOf(i, m_colouring);
    const std::int32_t discardIndex = m_groupsOfColour.discardIndex;
    SoftContactGroup& g = m_groups[static_cast<std::size_t>(i)];
    std::construct_at(&g); // empty lanes: zero masses, no point, nothing to write
    for (int l = 0; l < kLanes; ++l)
    {
        g.source[l] = -1;
        g.storeA[l] = g.storeB[l] = discardIndex;
    }
    int filled = 0;
    for (; first + filled < end; ++filled)
    {
        const std::int32_t k = m_colouring.order[first + filled];
        PackLane(g, filled, k, contacts[k], discardIndex);
    }
    // Empty lanes read lane 0's bodies and change nothing (zero masses, no point).
    for (int l = filled; l < kLanes; ++l)
    {
        g.indexA[l] = g.indexA[0];
        g.indexB[l] = g.indexB[0];
    }
}

// The sweeps' closures hold their values, not references to them: the group functions are
// called, not inlined, so a value behind a reference is loaded again for every group.

void SoftContactLanes::WarmStart(const SoftStepContext& context)
{
    SoftContactGroup* groups = m_groups.data();
    Velocity* velocities = context.bodies->velocities.data();
    m_groupsOfColour.ForEachGroupByColour([groups, velocities](std::int32_t i, DiscardSlots discard)
                                          { WarmStartGroup(groups[i], velocities, discard); });
}

void SoftContactLanes::Solve(const SoftStepContext& context, bool useBias)
{
    SoftContactGroup* groups = m_groups.data();
    const SoftStepContext* at = &context;
    const bool friction = !useBias || context.frictionInSolve;
    const bool measure = !m_errorsKnown;
    m_groupsOfColour.ForEachGroupByColour(
        [groups, at, useBias, friction, measure](std::int32_t i, DiscardSlots discard)
        { SolveGroup(groups[i], *at, useBias, friction, measure, discard); });
    m_errorsKnown = true;
}

void SoftContactLanes::CorrectPositions(const SoftStepContext& context)
{
    SoftContactGroup* groups = m_groups.data();
    const SoftStepContext* at = &context;
    m_groupsOfColour.ForEachGroupByColour([groups, at](std::int32_t i, DiscardSlots discard)
                                          { CorrectGroup(groups[i], *at, discard); });
}

void SoftContactLanes::ScaleImpulses(Real factor)
{
    m_groupsOfColour.ForEachGroup(
        [&](std::int32_t i)
        {
            SoftContactGroup& g = m_groups[static_cast<std::size_t>(i)];
            for (int j = 0; j < 2; ++j)
            {
                g.normalImpulse[j] *= factor;
                g.tangentImpulse[j] *= factor;
            }
            if (g.anyRolling)
            {
                g.rollingImpulse *= factor;
            }
        });
}

void SoftContactLanes::SaveImpulses()
{
    m_saved.resize(m_groups.size());
    m_groupsOfColour.ForEachGroup(
        [&](std::int32_t i)
        {
            const SoftContactGroup& g = m_groups[static_cast<std::size_t>(i)];
            // Without rolling resistance the spin impulses stay 0 (RestoreImpulses skips them).
            m_saved[static_cast<std::size_t>(i)] = {{g.normalImpulse[0], g.normalImpulse[1]},
                                                    {g.tangentImpulse[0], g.tangentImpulse[1]},
                                                    g.anyRolling ? g.rollingImpulse : RealW{}};
        });
}

void SoftContactLanes::RestoreImpulses()
{
    m_groupsOfColour.ForEachGroup(
        [&](std::int32_t i)
        {
            SoftContactGroup& g = m_groups[static_cast<std::size_t>(i)];
            const SoftGroupImpulses& saved = m_saved[static_cast<std::size_t>(i)];
            for (int j = 0; j < 2; ++j)
            {
                g.normalImpulse[j] = saved.normal[j];
                g.tangentImpulse[j] = saved.tangent[j];
            }
            if (g.anyRolling)
            {
                g.rollingImpulse = saved.rolling;
            }
        });
}

void SoftContactLanes::Collect(std::span<SoftContact> contacts) const
{
    ForEachLaneImpulses([&](std::int32_t k, const SoftContactImpulses& impulses)
                        { SetImpulses(contacts[k], impulses); });
}

} // namespace meff::detail
