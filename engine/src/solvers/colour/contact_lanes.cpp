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

/// The friction rows of both points (as SolveVelocityConstraint: |λt| ≤ μ·λn, vt driven to
/// the conveyor's speed; a group whose lanes all have tangentSpeed +0 skips subtracting it,
/// which would change no bit).
[[gnu::always_inline]] inline void SolveFriction(ContactVelocityGroup& g, const LaneMasses& m,
                                                 const RealW* tangentSpeed, BodyStateW& a,
                                                 BodyStateW& b)
{
    const Vec2W tangent{g.normal.y, -g.normal.x};
    for (int j = 0; j < 2; ++j)
    {
        RealW vt = Dot(RelativeVelocity(a, b, g.rA[j], g.rB[j]), tangent);
        if (tangentSpeed != nullptr)
        {
            vt = vt - *tangentSpeed;
        }
        const RealW maxFriction = g.friction * g.normalImpulse[j];
        const RealW newImpulse =
            MaxW(-maxFriction, MinW(g.tangentImpulse[j] + g.tangentMass[j] * (-vt), maxFriction));
        const RealW lambda = newImpulse - g.tangentImpulse[j];
        g.tangentImpulse[j] = newImpulse;
        ApplyImpulseW(m, a, b, g.rA[j], g.rB[j], lambda * tangent);
    }
}

void SolveRolling(ContactVelocityGroup& g, ContactGroupExtras& e, const LaneMasses& m,
                  BodyStateW& a, BodyStateW& b)
{
    RollingRows rows{e.rollingResistance, e.rollingMass, e.rollingImpulse,
                     g.normalImpulse,     m.invIA,       m.invIB};
    SolveRollingLanes(rows, a, b, [](int, Real) {});
}

/// vn − bias, or vn where the group has no restitution (bias +0 in every lane).
[[gnu::always_inline]] inline RealW LessBias(RealW vn, const RealW* velocityBias, int j)
{
    return velocityBias != nullptr ? vn - velocityBias[j] : vn;
}

/// The lanes of RowMass(k) whose bit is set in `rows`, 0 in the others: a normal row's mass as
/// the preparation computed it (its k is K's diagonal entry; 0 where the row is not solved).
[[gnu::always_inline]] inline RealW NormalMass(RealW k, unsigned rows)
{
    // Where every lane solves the row (most groups), selecting changes nothing.
    return rows == kEveryLane ? RowMass(k) : Select(LanesOf(rows), RowMass(k), Splat(0));
}

/// The normal rows one by one: λ = −(vn − bias)/k, accumulated impulse ≥ 0 (in `impulse`, the
/// group's or a copy of them).
[[gnu::always_inline]] inline void SolveNormalRows(const ContactGroupHeader& h,
                                                   const ContactVelocityGroup& g,
                                                   RealW (&impulse)[2], const LaneMasses& m,
                                                   const RealW* velocityBias, BodyStateW& a,
                                                   BodyStateW& b)
{
    const RealW normalMass[2] = {NormalMass(g.k11, h.hasPoint[0]), NormalMass(g.k22, h.solvesTwo)};
    for (int j = 0; j < 2; ++j)
    {
        const RealW vn = Dot(RelativeVelocity(a, b, g.rA[j], g.rB[j]), g.normal);
        const RealW lambda = -normalMass[j] * LessBias(vn, velocityBias, j);
        const RealW newImpulse = MaxW(impulse[j] + lambda, Splat(0));
        const RealW applied = newImpulse - impulse[j];
        impulse[j] = newImpulse;
        ApplyImpulseW(m, a, b, g.rA[j], g.rB[j], applied * g.normal);
    }
}

/// Makes the compiler forget the values it has loaded from memory (it emits no instruction): the
/// group's rows read after it are read again where used, as the arithmetic's memory operands,
/// instead of kept from before in registers (SSE2 has sixteen) and spilled to the stack.
[[gnu::always_inline]] inline void ForgetLoads()
{
    asm volatile("" ::: "memory");
}

/// The block lanes' BlockRows from K alone. There the preparation's condition test left
/// det K > 0 (k11² < kMaxConditionNumber·det) and so k11, k22 > 0 (sums of non-negative terms
/// whose product exceeds k12²): K⁻¹ = adj K / det and the rows' masses 1/kii are what
/// InverseDeterminant and RowMass give, the preparation's bit for bit, without their tests for
/// zero. The other lanes' are not taken.
[[gnu::always_inline]] inline BlockRows BlockLaneRows(const ContactVelocityGroup& g)
{
    const RealW one = Splat(1);
    const RealW invDet = one / (g.k11 * g.k22 - g.k12 * g.k12);
    return {g.k12, invDet * g.k22, -invDet * g.k12, invDet * g.k11, {one / g.k11, one / g.k22}};
}

/// The two normal rows as one LCP, vn = K·x + b, by total enumeration of its four cases in
/// Box2D's order (as ContactSolver's SolveNormalBlock); a lane where none holds keeps its
/// impulses. `block` holds the lanes that take the block's answer (bit l: lane l). Inlined:
/// called, it passed the bodies' states through memory.
[[gnu::always_inline]] inline void SolveNormalBlock(ContactVelocityGroup& g, unsigned block,
                                                    const LaneMasses& m, const RealW* velocityBias,
                                                    BodyStateW& a, BodyStateW& b)
{
    const RealW a1 = g.normalImpulse[0], a2 = g.normalImpulse[1];
    const RealW vn1 = Dot(RelativeVelocity(a, b, g.rA[0], g.rB[0]), g.normal);
    const RealW vn2 = Dot(RelativeVelocity(a, b, g.rA[1], g.rB[1]), g.normal);
    const RealW b1 = LessBias(vn1, velocityBias, 0) - (g.k11 * a1 + g.k12 * a2);
    const RealW b2 = LessBias(vn2, velocityBias, 1) - (g.k12 * a1 + g.k22 * a2);
    ForgetLoads();
    const auto [block1, block2] = SolveBlockLanes(BlockLaneRows(g), a1, a2, b1, b2);
    // Only the block lanes take the block's answer (every lane in most groups).
    const bool everyLane = block == kEveryLane;
    const RealW new1 = everyLane ? block1 : Select(LanesOf(block), block1, a1);
    const RealW new2 = everyLane ? block2 : Select(LanesOf(block), block2, a2);

    const Vec2W P1 = (new1 - a1) * g.normal;
    const Vec2W P2 = (new2 - a2) * g.normal;
    a.linear = a.linear - m.invMassA * (P1 + P2);
    a.angular = a.angular - m.invIA * (Cross(g.rA[0], P1) + Cross(g.rA[1], P2));
    b.linear = b.linear + m.invMassB * (P1 + P2);
    b.angular = b.angular + m.invIB * (Cross(g.rB[0], P1) + Cross(g.rB[1], P2));
    g.normalImpulse[0] = new1;
    g.normalImpulse[1] = new2;
}

/// The normal rows of a group with both kinds of lanes: each lane takes the velocities and
/// impulses of its own kind of solve. Not inlined: inlined, its copies of the bodies' states had
/// the sweep keep more on the stack in every group, the others (nearly all) included.
[[gnu::noinline]] void SolveMixedNormals(const ContactGroupHeader& h, ContactVelocityGroup& g,
                                         const LaneMasses& m, const RealW* velocityBias,
                                         BodyStateW& a, BodyStateW& b)
{
    const MaskW block = LanesOf(h.block);
    BodyStateW aRows = a, bRows = b;
    RealW rows[2] = {g.normalImpulse[0], g.normalImpulse[1]};
    SolveNormalRows(h, g, rows, m, velocityBias, aRows, bRows);
    SolveNormalBlock(g, h.block, m, velocityBias, a, b);
    a.linear = Select(block, a.linear, aRows.linear);
    a.angular = Select(block, a.angular, aRows.angular);
    b.linear = Select(block, b.linear, bRows.linear);
    b.angular = Select(block, b.angular, bRows.angular);
    for (int j = 0; j < 2; ++j)
    {
        g.normalImpulse[j] = Select(block, g.normalImpulse[j], rows[j]);
    }
}

void SolveVelocityGroup(const ContactGroupHeader& h, ContactVelocityGroup& g,
                        ContactGroupExtras* extras, const BodyMass* bodies, Velocity* velocities,
                        DiscardSlots discard)
{
    const LaneMasses m =
        MassesOf(GatherBodyMass(bodies, h.indexA), GatherBodyMass(bodies, h.indexB));
    BodyStateW a = Gather(velocities, h.indexA);
    BodyStateW b = Gather(velocities, h.indexB);
    const bool tangentSpeed = (h.extras & ContactGroupHeader::kTangentSpeed) != 0;
    SolveFriction(g, m, tangentSpeed ? &extras->tangentSpeed : nullptr, a, b);
    if ((h.extras & ContactGroupHeader::kRolling) != 0)
    {
        SolveRolling(g, *extras, m, a, b);
    }
    const RealW* velocityBias =
        (h.extras & ContactGroupHeader::kRestitution) != 0 ? extras->velocityBias : nullptr;
    const bool anyBlock = h.block != 0;
    const bool anyScalar = (h.valid & ~h.block) != 0;
    if (!anyBlock)
    {
        SolveNormalRows(h, g, g.normalImpulse, m, velocityBias, a, b);
    }
    else if (!anyScalar)
    {
        SolveNormalBlock(g, h.block, m, velocityBias, a, b);
    }
    else
    {
        SolveMixedNormals(h, g, m, velocityBias, a, b);
    }
    ScatterStores(velocities, h.indexA, h.storesA, discard.own, a);
    ScatterStores(velocities, h.indexB, h.storesB, discard.own, b);
}

/// Which manifold types a position group's lanes hold (ContactGroupHeader::circles, faceB): a
/// Select whose mask is false in every lane gives its second operand bit for bit, so where the
/// header says no lane is of a type, SolvePositionGroup skips that type's selects.
enum class GroupManifolds
{
    FaceA, ///< FaceA only (most of a pyramid's groups)
    Faces, ///< FaceA and FaceB, no circles
    Any,
};

/// The position sweep's tolerances in every lane, made once a sweep (read from memory, they are
/// the arithmetic's operands instead of broadcasts in every group).
struct PositionTolerancesW
{
    RealW baumgarte;                ///< Tolerances::baumgarte
    RealW linearSlop;               ///< Tolerances::linearSlop (m)
    RealW minusMaxLinearCorrection; ///< −Tolerances::maxLinearCorrection (m)
};

/// One sweep over a group's points (as SolvePositionConstraint); returns each lane's smallest
/// separation.
template <GroupManifolds kKind>
RealW SolvePositionGroup(const ContactGroupHeader& h, const ContactPositionGroup& g,
                         const BodyMass* bodies, Position* positions,
                         const PositionTolerancesW& tol, DiscardSlots discard)
{
    const BodyMassW A = GatherBodyMass(bodies, h.indexA);
    const BodyMassW B = GatherBodyMass(bodies, h.indexB);
    BodyStateW a = Gather(positions, h.indexA);
    BodyStateW b = Gather(positions, h.indexB);
    const MaskW circles = LanesOf(h.circles), faceB = LanesOf(h.faceB);
    RealW minSeparation = Splat(0);
    for (int j = 0; j < 2; ++j)
    {
        if (h.hasPoint[j] == 0)
        {
            break;
        }
        // Where every lane has the point (most groups), selecting by hasPoint changes nothing.
        const bool everyLane = h.hasPoint[j] == kEveryLane;
        const MaskW hasPoint = LanesOf(h.hasPoint[j]);
        TransformW xfA, xfB;
        TransformsFromCenter(a, A.localCenter, b, B.localCenter, xfA, xfB);
        // FaceA and circles: A holds the reference face (or centre); FaceB: B does.
        TransformW reference = xfA, incident = xfB;
        if constexpr (kKind != GroupManifolds::FaceA)
        {
            reference = Select(faceB, xfB, xfA);
            incident = Select(faceB, xfA, xfB);
        }
        const Vec2W planePoint = Mul(reference, g.localPoint);
        const Vec2W clipPoint = Mul(incident, g.localPoints[j]);
        const Vec2W d = clipPoint - planePoint;

        // Circles: the normal joins the two centres (left as is when they coincide, as
        // Vec2::Normalize); faces: the reference face's normal.
        Vec2W normal = Mul(reference.q, g.localNormal);
        Vec2W point = clipPoint;
        if constexpr (kKind == GroupManifolds::Any)
        {
            const Vec2W centreNormal = h.circles != 0 ? NormalizeW(d) : d;
            normal = Select(circles, centreNormal, normal);
            point = Select(circles, Splat(Real(0.5)) * (planePoint + clipPoint), clipPoint);
        }
        const RealW separation = Dot(d, normal) - g.radiusA - g.radiusB;
        if constexpr (kKind != GroupManifolds::FaceA)
        {
            normal = Select(faceB, Vec2W{-normal.x, -normal.y}, normal);
        }

        const Vec2W rA = point - a.linear;
        const Vec2W rB = point - b.linear;
        minSeparation = everyLane
                            ? MinW(minSeparation, separation)
                            : Select(hasPoint, MinW(minSeparation, separation), minSeparation);

        // Baumgarte-scaled correction leaving linearSlop of overlap, at most
        // maxLinearCorrection; scalar effective mass k = Σ1/m + (r×n)²/I along the normal.
        const RealW C =
            MinW(MaxW(tol.baumgarte * (separation + tol.linearSlop), tol.minusMaxLinearCorrection),
                 Splat(0));
        const RealW rnA = Cross(rA, normal), rnB = Cross(rB, normal);
        const RealW K = A.invMass + B.invMass + A.invI * rnA * rnA + B.invI * rnB * rnB;
        const MaskW solvable = everyLane ? (K > 0) : (hasPoint & (K > 0));
        const RealW impulse = Select(solvable, -C / Select(solvable, K, Splat(1)), Splat(0));
        ApplyImpulseW(MassesOf(A, B), a, b, rA, rB, impulse * normal);
    }
    ScatterStores(positions, h.indexA, h.storesA, discard.own, a);
    ScatterStores(positions, h.indexB, h.storesB, discard.own, b);
    return minSeparation;
}

/// SolvePositionGroup for the manifold types the group's header names.
RealW SolvePositionGroupOfKind(const ContactGroupHeader& h, const ContactPositionGroup& g,
                               const BodyMass* bodies, Position* positions,
                               const PositionTolerancesW& tol, DiscardSlots discard)
{
    if (h.circles != 0)
    {
        return SolvePositionGroup<GroupManifolds::Any>(h, g, bodies, positions, tol, discard);
    }
    if (h.faceB != 0)
    {
        return SolvePositionGroup<GroupManifolds::Faces>(h, g, bodies, positions, tol, discard);
    }
    return SolvePositionGroup<GroupManifolds::FaceA>(h, g, bodies, positions, tol, discard);
}

} // namespace

void ContactLanes::SolveVelocities(SolverData& data)
{
    for (int c = 0; c < GroupColourCount(); ++c)
    {
        ForEachGroupOfColour(c, data,
                             [&](std::int32_t i, DiscardSlots discard)
                             {
                                 SolveVelocityGroup(m_headers[i], m_velocityGroups[i], &m_extras[i],
                                                    m_bodies.data(), data.velocities, discard);
                             });
    }
}

void ContactLanes::CollectResults(std::span<SolvedContact> solved, TaskSystem* tasks) const
{
    // Each group writes only its own contacts' SolvedContact: any thread may take any group.
    ForEachGroupWithColour(m_groupStarts, tasks, kMinGroupsPerTask,
                           [&](std::int32_t i, int c)
                           {
                               const GroupRows rows = GroupRowsOf(m_groupStarts, m_colouring, i, c);
                               const std::int32_t first = rows.first, end = rows.end;
                               const ContactVelocityGroup& group = m_velocityGroups[i];
                               const bool rolling =
                                   (m_headers[i].extras & ContactGroupHeader::kRolling) != 0;
                               for (int l = 0; l < kLanes && first + l < end; ++l)
                               {
                                   SolvedContact& s = solved[m_colouring.order[first + l]];
                                   s.rollingImpulse =
                                       rolling ? m_extras[i].rollingImpulse[l] : Real(0);
                                   for (int j = 0; j < s.pointCount; ++j)
                                   {
                                       s.normalImpulse[j] = group.normalImpulse[j][l];
                                       s.tangentImpulse[j] = group.tangentImpulse[j][l];
                                   }
                               }
                           });
}

Real ContactLanes::SolvePositions(SolverData& data)
{
    const Tolerances& tolerances = data.step.tolerances;
    const PositionTolerancesW tol{Splat(tolerances.baumgarte), Splat(tolerances.linearSlop),
                                  Splat(-tolerances.maxLinearCorrection)};
    for (int c = 0; c < GroupColourCount(); ++c)
    {
        ForEachGroupOfColour(c, data,
                             [&](std::int32_t i, DiscardSlots discard)
                             {
                                 m_groupMinSeparation[i] = SolvePositionGroupOfKind(
                                     m_headers[i], m_positionGroups[i], m_bodies.data(),
                                     data.positions, tol, discard);
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
