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

#include <cmath>
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

/// The normal rows' Softness while solving, per lane: SoftStepContext::staticContact where a
/// lane's contact is against a body the solver does not move, SoftStepContext::contact elsewhere
/// (as SoftContactSolver's preparation picks it).
struct SoftnessW
{
    RealW biasScale, massScale, impulseScale;
};

SoftnessW SoftnessOf(const SoftContactHeader& h, const SoftStepContext& context)
{
    const MaskW fixed = LanesOf(~(h.storesA & h.storesB) & 0xFFU);
    const Softness& s = context.staticContact;
    const Softness& m = context.contact;
    return {Select(fixed, Splat(s.biasScale), Splat(m.biasScale)),
            Select(fixed, Splat(s.massScale), Splat(m.massScale)),
            Select(fixed, Splat(s.impulseScale), Splat(m.impulseScale))};
}

/// OneSidedTarget per lane for a normal row at error C (`softness` only read with `pushOut`).
[[gnu::always_inline]] inline TargetW NormalTarget(const SoftnessW& softness, RealW C, bool pushOut,
                                                   Real invH, Real maxPush)
{
    const MaskW apart = C > 0;
    const RealW speculative = MinW(C, Splat(Real(1e9))) * invH;
    if (!pushOut)
    {
        return {Select(apart, speculative, Splat(0)), Splat(1), Splat(0)};
    }
    const RealW push = MaxW(softness.biasScale * C, Splat(-maxPush));
    return {Select(apart, speculative, push), Select(apart, Splat(1), softness.massScale),
            Select(apart, Splat(0), softness.impulseScale)};
}

/// Applies impulse λ along n at point j's levers (ApplyRowImpulse).
[[gnu::always_inline]] inline void ApplyRow(const LaneMasses& m, Vec2W n, RealW aA, RealW aB,
                                            RealW lambda, BodyStateW& a, BodyStateW& b)
{
    ApplyRowImpulseOf(n, aA, aB, lambda, m.invMassA, m.invIA, m.invMassB, m.invIB, a.linear,
                      a.angular, b.linear, b.angular);
}

/// J·v of the row along n through point j's levers.
[[gnu::always_inline]] inline RealW RowVelocityW(Vec2W n, RealW aA, RealW aB, const BodyStateW& a,
                                                 const BodyStateW& b)
{
    return RowVelocityOf(n, aA, aB, a.linear, a.angular, b.linear, b.angular);
}

/// The normal rows one by one (SolveRow, accumulated impulse ≥ 0).
[[gnu::always_inline]] inline void SolveNormalRows(SoftContactGroup& g, const LaneMasses& m,
                                                   const TargetW (&t)[2], BodyStateW& a,
                                                   BodyStateW& b)
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
        ApplyRow(m, g.normal, aA, aB, applied, a, b);
        g.totalNormalImpulse[j] += applied;
    }
}

/// The two normal rows as one block (SolveTwoPointBlock's cases in its order); a lane where no
/// case holds keeps its impulses.
[[gnu::always_inline]] inline void SolveNormalBlock(SoftContactGroup& g, const LaneMasses& m,
                                                    const TargetW (&t)[2], BodyStateW& a,
                                                    BodyStateW& b)
{
    const RealW aA1 = Cross(g.rA[0], g.normal), aB1 = Cross(g.rB[0], g.normal);
    const RealW aA2 = Cross(g.rA[1], g.normal), aB2 = Cross(g.rB[1], g.normal);
    const RealW a1 = g.normalImpulse[0], a2 = g.normalImpulse[1];
    const RealW v1 = RowVelocityW(g.normal, aA1, aB1, a, b) + t[0].bias;
    const RealW v2 = RowVelocityW(g.normal, aA2, aB2, a, b) + t[1].bias;
    // K and K⁻¹ as the preparation's SoftContact::K and invK (PrepareContact, BlockRowsOf).
    const RealW k11 = LinearInverseMass(aA1, aB1, m.invMassA, m.invIA, m.invMassB, m.invIB);
    const RealW k22 = LinearInverseMass(aA2, aB2, m.invMassA, m.invIA, m.invMassB, m.invIB);
    const RealW k12 = RowCoupling(aA1, aB1, aA2, aB2, m.invMassA, m.invIA, m.invMassB, m.invIB);
    const RealW b1 = v1 - (k11 * a1 + k12 * a2);
    const RealW b2 = v2 - (k12 * a1 + k22 * a2);
    const auto [new1, new2] =
        SolveBlockLanes(BlockRowsOf(k11, k12, k22, g.normalMass), a1, a2, b1, b2);
    const RealW applied1 = new1 - a1, applied2 = new2 - a2;
    ApplyRow(m, g.normal, aA1, aB1, applied1, a, b);
    ApplyRow(m, g.normal, aA2, aB2, applied2, a, b);
    g.normalImpulse[0] = new1;
    g.normalImpulse[1] = new2;
    g.totalNormalImpulse[0] += applied1;
    g.totalNormalImpulse[1] += applied2;
}

/// Friction of both points (rigid, driven to the conveyor's speed, |λt| ≤ μ·λn), in the lanes
/// with μ > 0. `tangentSpeed` null: +0 in every lane, whose negation −0 is the bias.
[[gnu::always_inline]] inline void SolveFriction(SoftContactGroup& g, const LaneMasses& m,
                                                 MaskW hasFriction, const RealW* tangentSpeed,
                                                 BodyStateW& a, BodyStateW& b)
{
    const Vec2W tangent{g.normal.y, -g.normal.x};
    const RealW bias = tangentSpeed != nullptr ? -*tangentSpeed : Splat(-Real(0));
    for (int j = 0; j < 2; ++j)
    {
        const RealW aA = Cross(g.rA[j], tangent), aB = Cross(g.rB[j], tangent);
        const RealW maxFriction = g.friction * g.normalImpulse[j];
        const RealW impulse = SoftImpulseOf(g.tangentMass[j], RowVelocityW(tangent, aA, aB, a, b),
                                            bias, Splat(1), Splat(0), g.tangentImpulse[j]);
        const RealW next = ClampW(g.tangentImpulse[j] + impulse, -maxFriction, maxFriction);
        const RealW applied = Select(hasFriction, next - g.tangentImpulse[j], Splat(0));
        g.tangentImpulse[j] = Select(hasFriction, next, g.tangentImpulse[j]);
        ApplyRow(m, tangent, aA, aB, applied, a, b);
        g.totalTangentImpulse[j] += applied;
    }
}

/// The spin rows of rolling resistance, their impulses totalled over the step.
void SolveRolling(SoftContactGroup& g, SoftContactExtras& e, const LaneMasses& m, BodyStateW& a,
                  BodyStateW& b)
{
    RollingRows rows{e.rollingResistance, e.rollingMass, e.rollingImpulse,
                     g.normalImpulse,     m.invIA,       m.invIB};
    SolveRollingLanes(rows, a, b, [&](int l, Real lambda) { e.totalRollingImpulse[l] += lambda; });
}

/// The inverse masses and inertias of a group's bodies (SoftBodies::masses).
[[gnu::always_inline]] inline LaneMasses GroupMasses(const SoftContactHeader& h,
                                                     const BodyMass* masses)
{
    return MassesOf(GatherBodyMass(masses, h.indexA), GatherBodyMass(masses, h.indexB));
}

/// What a sweep reads besides the groups: the bodies, and the side array of the groups' extras.
struct SweepBodies
{
    Velocity* velocities;
    const BodyMass* masses;
    SoftContactExtras* extras;
};

void WarmStartGroup(const SoftContactHeader& h, SoftContactGroup& g, SoftContactExtras& e,
                    const SweepBodies& bodies, DiscardSlots discard)
{
    const LaneMasses m = GroupMasses(h, bodies.masses);
    BodyStateW a = Gather(bodies.velocities, h.indexA);
    BodyStateW b = Gather(bodies.velocities, h.indexB);
    const Vec2W tangent{g.normal.y, -g.normal.x};
    for (int j = 0; j < 2; ++j)
    {
        const Vec2W P = g.normalImpulse[j] * g.normal + g.tangentImpulse[j] * tangent;
        ApplyImpulseW(m, a, b, g.rA[j], g.rB[j], P);
        g.totalNormalImpulse[j] += g.normalImpulse[j];
        g.totalTangentImpulse[j] += g.tangentImpulse[j];
    }
    // Without rolling resistance every lane's spin impulse is 0 and would change nothing.
    if ((h.extras & SoftContactHeader::kRolling) != 0)
    {
        a.angular = a.angular - m.invIA * e.rollingImpulse;
        b.angular = b.angular + m.invIB * e.rollingImpulse;
        e.totalRollingImpulse += e.rollingImpulse;
    }
    ScatterStores(bodies.velocities, h.indexA, h.storesA, discard.own, a);
    ScatterStores(bodies.velocities, h.indexB, h.storesB, discard.own, b);
}

/// Each point's C at the bodies' poses now, into g.error.
void MeasureErrors(const SoftContactHeader& h, SoftContactGroup& g, const SoftStepContext& context)
{
    const SoftDelta* deltas = context.bodies->deltas.data();
    const DeltaW dA = GatherDeltas(deltas, h.indexA);
    const DeltaW dB = GatherDeltas(deltas, h.indexB);
    const RealW slop = Splat(context.rowSlop);
    for (int j = 0; j < 2; ++j)
    {
        g.error[j] = SeparationOf(g.baseSeparation[j], g.normal, dA.dp, dA.dq, dB.dp, dB.dq,
                                  g.rA[j], g.rB[j], slop);
    }
}

/// One sweep of the group; `measure`: the bodies moved since g.error was measured.
void SolveGroup(const SoftContactHeader& h, SoftContactGroup& g, SoftContactExtras& e,
                const SoftStepContext& context, bool useBias, bool friction, bool measure,
                DiscardSlots discard)
{
    Velocity* velocities = context.bodies->velocities.data();
    const LaneMasses m = GroupMasses(h, context.bodies->masses.data());
    BodyStateW a = Gather(velocities, h.indexA);
    BodyStateW b = Gather(velocities, h.indexB);
    if (measure)
    {
        MeasureErrors(h, g, context);
    }
    // Rigid contacts leave the overlap to CorrectPositions; soft ones push it out here.
    const bool pushOut = useBias && context.contactModel == SoftContactModel::Soft;
    const SoftnessW softness = pushOut ? SoftnessOf(h, context) : SoftnessW{};
    TargetW targets[2];
    for (int j = 0; j < 2; ++j)
    {
        targets[j] = NormalTarget(softness, g.error[j], pushOut, context.invH, context.maxPushOut);
    }
    // The block only where both rows are rigid now (always for rigid contacts).
    MaskW block = LanesOf(h.block);
    if (pushOut)
    {
        for (const TargetW& t : targets)
        {
            block = block & (t.massScale == 1) & (t.impulseScale == 0);
        }
    }
    if (!AnyLane(block))
    {
        SolveNormalRows(g, m, targets, a, b);
    }
    else if (!AnyLane(LanesOf(h.valid) & ~block))
    {
        SolveNormalBlock(g, m, targets, a, b);
    }
    else
    {
        // Mixed: each lane takes the velocities and impulses of its own kind of solve.
        BodyStateW aRows = a, bRows = b;
        SoftContactGroup rows = g;
        SolveNormalRows(rows, m, targets, aRows, bRows);
        SolveNormalBlock(g, m, targets, a, b);
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
        const bool tangentSpeed = (h.extras & SoftContactHeader::kTangentSpeed) != 0;
        SolveFriction(g, m, LanesOf(h.hasFriction), tangentSpeed ? &e.tangentSpeed : nullptr, a, b);
        if ((h.extras & SoftContactHeader::kRolling) != 0)
        {
            SolveRolling(g, e, m, a, b);
        }
    }
    ScatterStores(velocities, h.indexA, h.storesA, discard.own, a);
    ScatterStores(velocities, h.indexB, h.storesB, discard.own, b);
}

void CorrectGroup(const SoftContactHeader& h, const SoftContactGroup& g,
                  const SoftStepContext& context, DiscardSlots discard)
{
    SoftDelta* deltas = context.bodies->deltas.data();
    DeltaW dA = GatherDeltas(deltas, h.indexA);
    DeltaW dB = GatherDeltas(deltas, h.indexB);
    const LaneMasses m = GroupMasses(h, context.bodies->masses.data());
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
        const MaskW move = LanesOf(h.hasPoint[j]) & (C != 0);
        if (!AnyLane(move))
        {
            continue;
        }
        moved = true;
        const Vec2W rA = Mul(dA.dq, g.rA[j]);
        const Vec2W rB = Mul(dB.dq, g.rB[j]);
        const RealW aA = Cross(rA, g.normal), aB = Cross(rB, g.normal);
        const RealW k = LinearInverseMass(aA, aB, m.invMassA, m.invIA, m.invMassB, m.invIB);
        const RealW lambda = -C * RowMassW(k);
        const Vec2W P = lambda * g.normal;
        const DeltaW nextA{dA.dp - m.invMassA * P,
                           MulRot(SmallRotationW(-m.invIA * lambda * aA), dA.dq)};
        const DeltaW nextB{dB.dp + m.invMassB * P,
                           MulRot(SmallRotationW(m.invIB * lambda * aB), dB.dq)};
        dA = {Select(move, nextA.dp, dA.dp),
              {Select(move, nextA.dq.s, dA.dq.s), Select(move, nextA.dq.c, dA.dq.c)}};
        dB = {Select(move, nextB.dp, dB.dp),
              {Select(move, nextB.dq.s, dB.dq.s), Select(move, nextB.dq.c, dB.dq.c)}};
    }
    if (moved)
    {
        ScatterDeltaStores(deltas, h.indexA, h.storesA, discard.own, dA);
        ScatterDeltaStores(deltas, h.indexB, h.storesB, discard.own, dB);
    }
}

/// What of contact c lives in its group's extras (SoftContactHeader::extras).
std::uint8_t ExtrasOf(const SoftContact& c)
{
    return static_cast<std::uint8_t>(
        (IsPositiveZero(c.tangentSpeed) ? 0 : SoftContactHeader::kTangentSpeed) |
        (c.rollingResistance > 0 ? SoftContactHeader::kRolling : 0));
}

/// Lane l of a group from contact c (prepared by SoftContactSolver): its bits in the header, its
/// rows, and what few contacts need in the group's extras.
void PackLane(SoftContactHeader& h, SoftContactGroup& g, SoftContactExtras& e, int l,
              const SoftContact& c)
{
    const auto bit = static_cast<std::uint8_t>(1U << l);
    h.indexA[l] = c.indexA;
    h.indexB[l] = c.indexB;
    h.storesA |= SolverMoves(c.mA, c.iA) ? bit : 0;
    h.storesB |= SolverMoves(c.mB, c.iB) ? bit : 0;
    h.valid |= bit;
    h.hasFriction |= c.friction > 0 ? bit : 0;
    g.friction[l] = c.friction;
    const std::uint8_t extras = ExtrasOf(c);
    h.extras |= extras;
    if ((extras & SoftContactHeader::kTangentSpeed) != 0)
    {
        e.tangentSpeed[l] = c.tangentSpeed;
    }
    if ((extras & SoftContactHeader::kRolling) != 0)
    {
        e.rollingResistance[l] = c.rollingResistance;
        e.rollingMass[l] = c.rollingMass;
        e.rollingImpulse[l] = c.rollingImpulse;
        e.totalRollingImpulse[l] = c.totalRollingImpulse;
    }
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
        h.hasPoint[j] |= bit;
    }
    h.block |= c.block ? bit : 0;
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
    const auto groups =
        static_cast<std::size_t>(m_groupsOfColour.Cut(m_colouring, tasks, bodyCount));
    m_headers.resize(groups);
    m_groups.resize(groups);
    m_extras.resize(groups);
    m_groupsOfColour.ForEachGroup([&](std::int32_t i) { PackGroup(i, contacts); });
}

void SoftContactLanes::PackGroup(std::int32_t i, std::span<const SoftContact> contacts)
{
    const auto [first, end] = m_groupsOfColour.RowsOf(i, m_colouring);
    const auto at = static_cast<std::size_t>(i);
    SoftContactHeader& h = m_headers[at];
    SoftContactGroup& g = m_groups[at];
    SoftContactExtras& e = m_extras[at];
    // Empty lanes: no rows, nothing to write.
    std::construct_at(&h);
    std::construct_at(&g);
    int filled = 0;
    for (; first + filled < end; ++filled)
    {
        const SoftContact& c = contacts[m_colouring.order[first + filled]];
        // The extras are cleared only for a group that has some, before its first lane's.
        if (h.extras == 0 && ExtrasOf(c) != 0)
        {
            std::construct_at(&e);
        }
        PackLane(h, g, e, filled, c);
    }
    // Empty lanes read lane 0's bodies and change nothing (no rows), writing the discard slot.
    for (int l = filled; l < kLanes; ++l)
    {
        h.indexA[l] = h.indexA[0];
        h.indexB[l] = h.indexB[0];
    }
}

// The sweeps' closures hold their values, not references to them: the group functions are
// called, not inlined, so a value behind a reference is loaded again for every group.

void SoftContactLanes::WarmStart(const SoftStepContext& context)
{
    const SoftContactHeader* headers = m_headers.data();
    SoftContactGroup* groups = m_groups.data();
    const SweepBodies bodies{context.bodies->velocities.data(), context.bodies->masses.data(),
                             m_extras.data()};
    m_groupsOfColour.ForEachGroupByColour(
        [headers, groups, bodies](std::int32_t i, DiscardSlots discard)
        { WarmStartGroup(headers[i], groups[i], bodies.extras[i], bodies, discard); });
}

void SoftContactLanes::Solve(const SoftStepContext& context, bool useBias)
{
    const SoftContactHeader* headers = m_headers.data();
    SoftContactGroup* groups = m_groups.data();
    SoftContactExtras* extras = m_extras.data();
    const SoftStepContext* at = &context;
    const bool friction = !useBias || context.frictionInSolve;
    const bool measure = !m_errorsKnown;
    m_groupsOfColour.ForEachGroupByColour(
        [headers, groups, extras, at, useBias, friction, measure](std::int32_t i,
                                                                  DiscardSlots discard) {
            SolveGroup(headers[i], groups[i], extras[i], *at, useBias, friction, measure, discard);
        });
    m_errorsKnown = true;
}

void SoftContactLanes::CorrectPositions(const SoftStepContext& context)
{
    const SoftContactHeader* headers = m_headers.data();
    const SoftContactGroup* groups = m_groups.data();
    const SoftStepContext* at = &context;
    m_groupsOfColour.ForEachGroupByColour(
        [headers, groups, at](std::int32_t i, DiscardSlots discard)
        { CorrectGroup(headers[i], groups[i], *at, discard); });
}

void SoftContactLanes::ScaleImpulses(Real factor)
{
    m_groupsOfColour.ForEachGroup(
        [&](std::int32_t i)
        {
            const auto at = static_cast<std::size_t>(i);
            SoftContactGroup& g = m_groups[at];
            for (int j = 0; j < 2; ++j)
            {
                g.normalImpulse[j] *= factor;
                g.tangentImpulse[j] *= factor;
            }
            if ((m_headers[at].extras & SoftContactHeader::kRolling) != 0)
            {
                m_extras[at].rollingImpulse *= factor;
            }
        });
}

void SoftContactLanes::SaveImpulses()
{
    m_saved.resize(m_groups.size());
    m_groupsOfColour.ForEachGroup(
        [&](std::int32_t i)
        {
            const auto at = static_cast<std::size_t>(i);
            const SoftContactGroup& g = m_groups[at];
            // Without rolling resistance the spin impulses stay 0 (RestoreImpulses skips them).
            const bool rolling = (m_headers[at].extras & SoftContactHeader::kRolling) != 0;
            m_saved[at] = {{g.normalImpulse[0], g.normalImpulse[1]},
                           {g.tangentImpulse[0], g.tangentImpulse[1]},
                           rolling ? m_extras[at].rollingImpulse : RealW{}};
        });
}

void SoftContactLanes::RestoreImpulses()
{
    m_groupsOfColour.ForEachGroup(
        [&](std::int32_t i)
        {
            const auto at = static_cast<std::size_t>(i);
            SoftContactGroup& g = m_groups[at];
            const SoftGroupImpulses& saved = m_saved[at];
            for (int j = 0; j < 2; ++j)
            {
                g.normalImpulse[j] = saved.normal[j];
                g.tangentImpulse[j] = saved.tangent[j];
            }
            if ((m_headers[at].extras & SoftContactHeader::kRolling) != 0)
            {
                m_extras[at].rollingImpulse = saved.rolling;
            }
        });
}

void SoftContactLanes::Collect(std::span<SoftContact> contacts) const
{
    ForEachLaneImpulses([&](std::int32_t k, const SoftContactImpulses& impulses)
                        { SetImpulses(contacts[k], impulses); });
}

} // namespace meff::detail
