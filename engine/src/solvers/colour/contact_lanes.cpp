// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
#include "solvers/colour/contact_lanes.h"

#include "solvers/lanes/block_lanes.h"

#include "solvers/lanes/lane_bodies.h"
#include "solvers/lanes/rolling_lanes.h"

#include <algorithm>

namespace meff::detail
{

namespace
{

/// Applies impulse P at lever arms rA, rB (−P to A, +P to B).
[[gnu::always_inline]] inline void ApplyImpulse(const ContactVelocityGroup& g, BodyStateW& a,
                                                BodyStateW& b, Vec2W rA, Vec2W rB, Vec2W P)
{
    ApplyImpulseW({g.invMassA, g.invIA, g.invMassB, g.invIB}, a, b, rA, rB, P);
}

/// The friction rows of both points (as SolveVelocityConstraint: |λt| ≤ μ·λn, vt driven to
/// the conveyor's speed).
[[gnu::always_inline]] inline void SolveFriction(ContactVelocityGroup& g, BodyStateW& a,
                                                 BodyStateW& b)
{
    const Vec2W tangent{g.normal.y, -g.normal.x};
    for (int j = 0; j < 2; ++j)
    {
        const RealW vt = Dot(RelativeVelocity(a, b, g.rA[j], g.rB[j]), tangent) - g.tangentSpeed;
        const RealW maxFriction = g.friction * g.normalImpulse[j];
        const RealW newImpulse =
            MaxW(-maxFriction, MinW(g.tangentImpulse[j] + g.tangentMass[j] * (-vt), maxFriction));
        const RealW lambda = newImpulse - g.tangentImpulse[j];
        g.tangentImpulse[j] = newImpulse;
        ApplyImpulse(g, a, b, g.rA[j], g.rB[j], lambda * tangent);
    }
}

void SolveRolling(ContactVelocityGroup& g, BodyStateW& a, BodyStateW& b)
{
    SolveRollingLanes(g, a, b, [](int, Real) {});
}

/// The normal rows one by one: λ = −(vn − bias)/k, accumulated impulse ≥ 0.
[[gnu::always_inline]] inline void SolveNormalRows(ContactVelocityGroup& g, BodyStateW& a,
                                                   BodyStateW& b)
{
    for (int j = 0; j < 2; ++j)
    {
        const RealW vn = Dot(RelativeVelocity(a, b, g.rA[j], g.rB[j]), g.normal);
        const RealW lambda = -g.normalMass[j] * (vn - g.velocityBias[j]);
        const RealW newImpulse = MaxW(g.normalImpulse[j] + lambda, Splat(0));
        const RealW applied = newImpulse - g.normalImpulse[j];
        g.normalImpulse[j] = newImpulse;
        ApplyImpulse(g, a, b, g.rA[j], g.rB[j], applied * g.normal);
    }
}

/// The two normal rows as one LCP, vn = K·x + b, by total enumeration of its four cases in
/// Box2D's order (as ContactSolver's SolveNormalBlock); a lane where none holds keeps its
/// impulses.
void SolveNormalBlock(ContactVelocityGroup& g, BodyStateW& a, BodyStateW& b)
{
    const RealW a1 = g.normalImpulse[0], a2 = g.normalImpulse[1];
    const RealW vn1 = Dot(RelativeVelocity(a, b, g.rA[0], g.rB[0]), g.normal);
    const RealW vn2 = Dot(RelativeVelocity(a, b, g.rA[1], g.rB[1]), g.normal);
    const RealW b1 = (vn1 - g.velocityBias[0]) - (g.k11 * a1 + g.k12 * a2);
    const RealW b2 = (vn2 - g.velocityBias[1]) - (g.k12 * a1 + g.k22 * a2);
    const auto [block1, block2] = SolveBlockLanes(g, a1, a2, b1, b2);
    // Only the block lanes take the block's answer.
    const RealW new1 = Select(g.block, block1, a1);
    const RealW new2 = Select(g.block, block2, a2);

    const Vec2W P1 = (new1 - a1) * g.normal;
    const Vec2W P2 = (new2 - a2) * g.normal;
    a.linear = a.linear - g.invMassA * (P1 + P2);
    a.angular = a.angular - g.invIA * (Cross(g.rA[0], P1) + Cross(g.rA[1], P2));
    b.linear = b.linear + g.invMassB * (P1 + P2);
    b.angular = b.angular + g.invIB * (Cross(g.rB[0], P1) + Cross(g.rB[1], P2));
    g.normalImpulse[0] = new1;
    g.normalImpulse[1] = new2;
}

void SolveVelocityGroup(ContactVelocityGroup& g, Velocity* velocities, DiscardSlots discard)
{
    BodyStateW a = Gather(velocities, g.indexA);
    BodyStateW b = Gather(velocities, g.indexB);
    SolveFriction(g, a, b);
    if (g.anyRolling)
    {
        SolveRolling(g, a, b);
    }
    if (!g.anyBlock)
    {
        SolveNormalRows(g, a, b);
    }
    else if (!g.anyScalar)
    {
        SolveNormalBlock(g, a, b);
    }
    else
    {
        // Mixed group: each lane takes the velocities and impulses of its own kind of solve.
        BodyStateW aRows = a, bRows = b;
        ContactVelocityGroup rows = g;
        SolveNormalRows(rows, aRows, bRows);
        SolveNormalBlock(g, a, b);
        a.linear = Select(g.block, a.linear, aRows.linear);
        a.angular = Select(g.block, a.angular, aRows.angular);
        b.linear = Select(g.block, b.linear, bRows.linear);
        b.angular = Select(g.block, b.angular, bRows.angular);
        for (int j = 0; j < 2; ++j)
        {
            g.normalImpulse[j] = Select(g.block, g.normalImpulse[j], rows.normalImpulse[j]);
        }
    }
    ScatterFromWorker(velocities, g.storeA, discard, a);
    ScatterFromWorker(velocities, g.storeB, discard, b);
}

/// One sweep over a group's points (as SolvePositionConstraint); returns each lane's smallest
/// separation.
RealW SolvePositionGroup(const ContactPositionGroup& g, Position* positions, const Tolerances& tol,
                         Real baumgarte, DiscardSlots discard)
{
    BodyStateW a = Gather(positions, g.indexA);
    BodyStateW b = Gather(positions, g.indexB);
    RealW minSeparation = Splat(0);
    for (int j = 0; j < 2; ++j)
    {
        if (!AnyLane(g.hasPoint[j]))
        {
            break;
        }
        const TransformW xfA = TransformFromCenter(a, g.localCenterA);
        const TransformW xfB = TransformFromCenter(b, g.localCenterB);
        // FaceA and circles: A holds the reference face (or centre); FaceB: B does.
        const TransformW reference = Select(g.faceB, xfB, xfA);
        const TransformW incident = Select(g.faceB, xfA, xfB);
        const Vec2W planePoint = Mul(reference, g.localPoint);
        const Vec2W clipPoint = Mul(incident, g.localPoints[j]);
        const Vec2W d = clipPoint - planePoint;

        // Circles: the normal joins the two centres (left as is when they coincide, as
        // Vec2::Normalize); faces: the reference face's normal.
        const Vec2W centreNormal = AnyLane(g.circles) ? NormalizeW(d) : d;
        Vec2W normal = Select(g.circles, centreNormal, Mul(reference.q, g.localNormal));
        const RealW separation = Dot(d, normal) - g.radiusA - g.radiusB;
        const Vec2W point =
            Select(g.circles, Splat(Real(0.5)) * (planePoint + clipPoint), clipPoint);
        normal = Select(g.faceB, Vec2W{-normal.x, -normal.y}, normal);

        const Vec2W rA = point - a.linear;
        const Vec2W rB = point - b.linear;
        minSeparation = Select(g.hasPoint[j], MinW(minSeparation, separation), minSeparation);

        // Baumgarte-scaled correction leaving linearSlop of overlap, at most
        // maxLinearCorrection; scalar effective mass k = Σ1/m + (r×n)²/I along the normal.
        const RealW C =
            MinW(MaxW(baumgarte * (separation + tol.linearSlop), Splat(-tol.maxLinearCorrection)),
                 Splat(0));
        const RealW rnA = Cross(rA, normal), rnB = Cross(rB, normal);
        const RealW K = g.invMassA + g.invMassB + g.invIA * rnA * rnA + g.invIB * rnB * rnB;
        const MaskW solvable = g.hasPoint[j] & (K > 0);
        const RealW impulse = Select(solvable, -C / Select(solvable, K, Splat(1)), Splat(0));
        ApplyImpulseW({g.invMassA, g.invIA, g.invMassB, g.invIB}, a, b, rA, rB, impulse * normal);
    }
    ScatterFromWorker(positions, g.storeA, discard, a);
    ScatterFromWorker(positions, g.storeB, discard, b);
    return minSeparation;
}

} // namespace

void ContactLanes::SolveVelocities(SolverData& data)
{
    for (int c = 0; c < GroupColourCount(); ++c)
    {
        ForEachGroupOfColour(c, data,
                             [&](std::int32_t i, DiscardSlots discard) {
                                 SolveVelocityGroup(m_velocityGroups[i], data.velocities, discard);
                             });
    }
}

void ContactLanes::CollectResults(std::span<SolvedContact> solved) const
{
    for (const ContactVelocityGroup& group : m_velocityGroups)
    {
        for (int l = 0; l < kLanes && group.source[l] >= 0; ++l)
        {
            SolvedContact& s = solved[group.source[l]];
            s.rollingImpulse = group.rollingImpulse[l];
            for (int j = 0; j < s.pointCount; ++j)
            {
                s.normalImpulse[j] = group.normalImpulse[j][l];
                s.tangentImpulse[j] = group.tangentImpulse[j][l];
            }
        }
    }
}

Real ContactLanes::SolvePositions(SolverData& data)
{
    const Tolerances& tol = data.step.tolerances;
    for (int c = 0; c < GroupColourCount(); ++c)
    {
        ForEachGroupOfColour(c, data,
                             [&](std::int32_t i, DiscardSlots discard)
                             {
                                 m_groupMinSeparation[i] =
                                     SolvePositionGroup(m_positionGroups[i], data.positions, tol,
                                                        tol.baumgarte, discard);
                             });
    }
    // In group order whatever the threads: the same minimum, NaN and signed zeros included.
    RealW minSeparationW = Splat(0);
    for (const RealW groupMin : m_groupMinSeparation)
    {
        minSeparationW = MinW(minSeparationW, groupMin);
    }
    Real minSeparation = 0;
    for (int l = 0; l < kLanes; ++l)
    {
        minSeparation = Min(minSeparation, minSeparationW[l]);
    }
    return minSeparation;
}

} // namespace meff::detail
