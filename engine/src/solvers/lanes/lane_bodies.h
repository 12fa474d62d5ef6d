// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The lanes' view of their bodies: four (AVX2: eight) bodies' velocities or positions gathered from
// the island's arrays into SIMD lanes, updated there, and scattered back. Shared by the contact and
// joint solvers that work by colour (graph_colouring.h).
#pragma once

#include "model/solver_types.h"
#include "solvers/lanes/graph_colouring.h"
#include "solvers/lanes/wide_real.h"

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace meff::detail
{

/// One body state per lane: a velocity (v, w) or a position (c, a).
struct BodyStateW
{
    Vec2W linear;  ///< v (m/s) or c (m)
    RealW angular; ///< w (rad/s) or a (rad)
};

/// The four Reals of a Position (c.x, c.y, a, padding) or Velocity (v.x, v.y, w, padding):
/// solver_types.h aligns both to one Real4 so that a body's state is one vector load.
template <typename State>
constexpr bool kStateIsOneVector = sizeof(State) == sizeof(Real4) &&
                                   alignof(State) == sizeof(Real4);
static_assert(kStateIsOneVector<Position> && kStateIsOneVector<Velocity>);
static_assert(offsetof(Position, a) == 2 * sizeof(Real) &&
              offsetof(Velocity, w) == 2 * sizeof(Real));

/// Four bodies' states by component: x, y and angle, one lane per body.
struct BodyState4
{
    Real4 x, y, a;
};

/// Reads four items of four Reals each (a body's state, its constants, its motion) by index: four
/// vector loads and a 4×4 transpose, out[c] holding the four items' component c.
template <typename Item>
[[gnu::always_inline]] inline void Transpose4(const Item* items, const std::int32_t* index,
                                              Real4 (&out)[4])
{
    static_assert(sizeof(Item) == sizeof(Real4));
    Real4 r0, r1, r2, r3;
    std::memcpy(&r0, &items[index[0]], sizeof(Real4));
    std::memcpy(&r1, &items[index[1]], sizeof(Real4));
    std::memcpy(&r2, &items[index[2]], sizeof(Real4));
    std::memcpy(&r3, &items[index[3]], sizeof(Real4));
    const Real4 lo01 = __builtin_shufflevector(r0, r1, 0, 4, 1, 5);
    const Real4 lo23 = __builtin_shufflevector(r2, r3, 0, 4, 1, 5);
    const Real4 hi01 = __builtin_shufflevector(r0, r1, 2, 6, 3, 7);
    const Real4 hi23 = __builtin_shufflevector(r2, r3, 2, 6, 3, 7);
    out[0] = __builtin_shufflevector(lo01, lo23, 0, 1, 4, 5);
    out[1] = __builtin_shufflevector(lo01, lo23, 2, 3, 6, 7);
    out[2] = __builtin_shufflevector(hi01, hi23, 0, 1, 4, 5);
    out[3] = __builtin_shufflevector(hi01, hi23, 2, 3, 6, 7);
}

/// Reads four bodies: Transpose4's x, y and angle (rows are bodies, columns become x, y and
/// angle; the padding's column is dropped).
template <typename State>
[[gnu::always_inline]] inline BodyState4 Gather4(const State* states, const std::int32_t* index)
{
    Real4 columns[4];
    Transpose4(states, index, columns);
    return {columns[0], columns[1], columns[2]};
}

/// Writes four items of four Reals each by index: Transpose4's inverse (in[c] holds the four
/// items' component c) and four vector stores.
template <typename Item>
[[gnu::always_inline]] inline void Untranspose4(Item* items, const std::int32_t* store,
                                                const Real4 (&in)[4])
{
    static_assert(sizeof(Item) == sizeof(Real4));
    const Real4 lo01 = __builtin_shufflevector(in[0], in[1], 0, 4, 1, 5);
    const Real4 lo23 = __builtin_shufflevector(in[0], in[1], 2, 6, 3, 7);
    const Real4 hi01 = __builtin_shufflevector(in[2], in[3], 0, 4, 1, 5);
    const Real4 hi23 = __builtin_shufflevector(in[2], in[3], 2, 6, 3, 7);
    const Real4 r[4] = {__builtin_shufflevector(lo01, hi01, 0, 1, 4, 5),
                        __builtin_shufflevector(lo01, hi01, 2, 3, 6, 7),
                        __builtin_shufflevector(lo23, hi23, 0, 1, 4, 5),
                        __builtin_shufflevector(lo23, hi23, 2, 3, 6, 7)};
    // Unrolled: GCC 12 at -O2 kept the loop, storing the rows to the stack to reload them.
#pragma GCC unroll 4
    for (int i = 0; i < 4; ++i)
    {
        std::memcpy(static_cast<void*>(&items[store[i]]), &r[i], sizeof(Real4));
    }
}

/// Writes four bodies: Untranspose4 of x, y and angle, the padding's column zero.
template <typename State>
[[gnu::always_inline]] inline void Scatter4(State* states, const std::int32_t* store,
                                            const BodyState4& in)
{
    Untranspose4(states, store, {in.x, in.y, in.a, Real4{}});
}

#if MEFF_SIMD_LANES == 8
/// Lanes 0–3 from `low`, 4–7 from `high`.
[[gnu::always_inline]] inline RealW Join(Real4 low, Real4 high)
{
    return __builtin_shufflevector(low, high, 0, 1, 2, 3, 4, 5, 6, 7);
}
[[gnu::always_inline]] inline Real4 LowHalf(RealW v)
{
    return __builtin_shufflevector(v, v, 0, 1, 2, 3);
}
[[gnu::always_inline]] inline Real4 HighHalf(RealW v)
{
    return __builtin_shufflevector(v, v, 4, 5, 6, 7);
}
#endif

/// Reads the lanes' items of four Reals each (Transpose4, four at a time): out[c] holds component
/// c of each lane's item.
template <typename Item>
[[gnu::always_inline]] inline void GatherComponents(const Item* items,
                                                    const std::int32_t (&index)[kLanes],
                                                    RealW (&out)[4])
{
#if MEFF_SIMD_LANES == 8
    Real4 low[4], high[4];
    Transpose4(items, index, low);
    Transpose4(items, index + 4, high);
    for (int c = 0; c < 4; ++c)
    {
        out[c] = Join(low[c], high[c]);
    }
#else
    Transpose4(items, index, out);
#endif
}

/// Reads the lanes' bodies from the island's positions or velocities, four at a time (Gather4).
template <typename State>
[[gnu::always_inline]] inline BodyStateW Gather(const State* states,
                                                const std::int32_t (&index)[kLanes])
{
#if MEFF_SIMD_LANES == 8
    const BodyState4 low = Gather4(states, index);
    const BodyState4 high = Gather4(states, index + 4);
    return {{Join(low.x, high.x), Join(low.y, high.y)}, Join(low.a, high.a)};
#else
    const BodyState4 all = Gather4(states, index);
    return {{all.x, all.y}, all.a};
#endif
}

/// Writes the lanes' bodies back, four at a time (Scatter4). `store[l]` is the lane's body, or
/// SolverData::discardIndex where the lane must not change its body (a static or kinematic
/// body, which lanes of one colour may share, or an empty lane).
template <typename State>
[[gnu::always_inline]] inline void Scatter(State* states, const std::int32_t (&store)[kLanes],
                                           const BodyStateW& in)
{
#if MEFF_SIMD_LANES == 8
    Scatter4(states, store, {LowHalf(in.linear.x), LowHalf(in.linear.y), LowHalf(in.angular)});
    Scatter4(states, store + 4,
             {HighHalf(in.linear.x), HighHalf(in.linear.y), HighHalf(in.angular)});
#else
    Scatter4(states, store, {in.linear.x, in.linear.y, in.angular});
#endif
}

/// The discard slots of a thread solving groups (SolverData::discardIndex): the one the groups
/// were packed with, and the worker's own.
struct DiscardSlots
{
    std::int32_t packed; ///< SolverData::discardIndex
    std::int32_t own;    ///< discardIndex + worker
};

/// Calls write(stores) with the stores of a worker of the world's TaskSystem: lanes packed to
/// write the discard slot write the worker's own slot instead, so that the groups of one colour,
/// solved on several threads at once, never write the same memory. For worker 0 (and without
/// threads) the slots are the same, and the packed stores are passed as they are.
template <typename Write>
[[gnu::always_inline]] inline void WithWorkerStores(const std::int32_t (&store)[kLanes],
                                                    DiscardSlots discard, Write&& write)
{
    if (discard.own == discard.packed)
    {
        write(store);
        return;
    }
    std::int32_t to[kLanes];
    for (int l = 0; l < kLanes; ++l)
    {
        to[l] = store[l] == discard.packed ? discard.own : store[l];
    }
    write(to);
}

/// Scatter for a worker of the world's TaskSystem (WithWorkerStores).
template <typename State>
[[gnu::always_inline]] inline void ScatterFromWorker(State* states,
                                                     const std::int32_t (&store)[kLanes],
                                                     DiscardSlots discard, const BodyStateW& in)
{
    WithWorkerStores(store, discard,
                     [&](const std::int32_t(&to)[kLanes]) { Scatter(states, to, in); });
}

/// A body's constants as the lanes read them, one Real4 per solver index: gathered by a group's
/// body indices (GatherBodyMass) instead of kept in every row that names the body.
struct alignas(4 * sizeof(Real)) BodyMass
{
    Real invMass = 0; ///< 1/kg, 0 for a static or kinematic body
    Real invI = 0;    ///< 1/(kg·m²)
    Vec2 localCenter; ///< centre of mass in the body's frame (m)
};
static_assert(sizeof(BodyMass) == sizeof(Real4));

/// kLanes bodies' constants, one lane per body.
struct BodyMassW
{
    RealW invMass, invI;
    Vec2W localCenter;
};

/// The lanes' bodies' constants (GatherComponents).
[[gnu::always_inline]] inline BodyMassW GatherBodyMass(const BodyMass* bodies,
                                                       const std::int32_t (&index)[kLanes])
{
    RealW columns[4];
    GatherComponents(bodies, index, columns);
    return {columns[0], columns[1], {columns[2], columns[3]}};
}

/// The two bodies' inverse masses (1/kg) and inverse inertias (1/(kg·m²)) per lane.
struct LaneMasses
{
    RealW invMassA, invIA, invMassB, invIB;
};

/// The inverse masses and inertias of a group's bodies A and B (GatherBodyMass of each).
[[gnu::always_inline]] inline LaneMasses MassesOf(const BodyMassW& A, const BodyMassW& B)
{
    return {A.invMass, A.invI, B.invMass, B.invI};
}

/// Every lane's bit (bit l: lane l).
inline constexpr unsigned kEveryLane = (1U << kLanes) - 1;

/// The lanes whose bit is set in `bits` (bit l: lane l), as a mask.
[[gnu::always_inline]] inline MaskW LanesOf(unsigned bits)
{
#if MEFF_SIMD_LANES == 8
    const MaskW laneBit{1, 2, 4, 8, 16, 32, 64, 128};
#else
    const MaskW laneBit{1, 2, 4, 8};
#endif
    return ((MaskW{} + static_cast<int>(bits)) & laneBit) != 0;
}

/// The bits of a mask's lanes (LanesOf's inverse).
inline unsigned BitsOf(MaskW m)
{
    unsigned bits = 0;
    for (int l = 0; l < kLanes; ++l)
    {
        bits |= m[l] != 0 ? 1U << l : 0U;
    }
    return bits;
}

/// kLanes solver body indices, one per lane.
using IndexW = std::int32_t __attribute__((vector_size(kLanes * sizeof(std::int32_t))));

/// Where a worker of the world's TaskSystem writes each lane's body: body index[l] where bit l of
/// `stores` is set and the worker's discard slot `discard` (DiscardSlots::own) elsewhere (static
/// or kinematic bodies, empty lanes).
[[gnu::always_inline]] inline void StoresOf(const std::int32_t (&index)[kLanes], unsigned stores,
                                            std::int32_t discard, std::int32_t (&to)[kLanes])
{
#if MEFF_SIMD_LANES == 8
    const IndexW laneBit{1, 2, 4, 8, 16, 32, 64, 128};
#else
    const IndexW laneBit{1, 2, 4, 8};
#endif
    IndexW bodies;
    std::memcpy(&bodies, index, sizeof(IndexW));
    const IndexW writes = ((IndexW{} + static_cast<std::int32_t>(stores)) & laneBit) != 0;
    const IndexW where = (bodies & writes) | ((IndexW{} + discard) & ~writes);
    std::memcpy(to, &where, sizeof(IndexW));
}

/// Scatter for a worker of the world's TaskSystem, to StoresOf's bodies.
template <typename State>
[[gnu::always_inline]] inline void ScatterStores(State* states, const std::int32_t (&index)[kLanes],
                                                 unsigned stores, std::int32_t discard,
                                                 const BodyStateW& in)
{
    // Every lane writes its body (most groups): the indices as they are, without StoresOf.
    if ((stores & kEveryLane) == kEveryLane)
    {
        Scatter(states, index, in);
        return;
    }
    std::int32_t to[kLanes];
    StoresOf(index, stores, discard, to);
    Scatter(states, to, in);
}

/// Fills lane l's bodies: the solver indices to read, where to write (the body, or the discard
/// slot where the lane must not move it), and the inverse masses (1/kg) and inertias
/// (1/(kg·m²)).
template <typename Group>
void PackLaneBodies(Group& g, int l, std::int32_t indexA, std::int32_t indexB, Real invMassA,
                    Real invIA, Real invMassB, Real invIB, std::int32_t discardIndex)
{
    g.indexA[l] = indexA;
    g.indexB[l] = indexB;
    g.storeA[l] = SolverMoves(invMassA, invIA) ? indexA : discardIndex;
    g.storeB[l] = SolverMoves(invMassB, invIB) ? indexB : discardIndex;
    g.invMassA[l] = invMassA;
    g.invMassB[l] = invMassB;
    g.invIA[l] = invIA;
    g.invIB[l] = invIB;
}

/// The same from a prepared constraint whose members are named as the group's.
template <typename Group, typename Constraint>
void PackLaneBodies(Group& g, int l, const Constraint& c, std::int32_t discardIndex)
{
    PackLaneBodies(g, l, c.indexA, c.indexB, c.invMassA, c.invIA, c.invMassB, c.invIB,
                   discardIndex);
}

/// Applies impulse P at lever arms rA, rB: −P to A, +P to B (velocities), or the same
/// pseudo-impulse to positions.
[[gnu::always_inline]] inline void ApplyImpulseW(const LaneMasses& m, BodyStateW& a, BodyStateW& b,
                                                 Vec2W rA, Vec2W rB, Vec2W P)
{
    a.linear = a.linear - m.invMassA * P;
    a.angular = a.angular - m.invIA * Cross(rA, P);
    b.linear = b.linear + m.invMassB * P;
    b.angular = b.angular + m.invIB * Cross(rB, P);
}

/// Velocity of B's point rB relative to A's point rA: vB + ωB×rB − vA − ωA×rA, per lane.
[[gnu::always_inline]] inline Vec2W RelativeVelocity(const BodyStateW& a, const BodyStateW& b,
                                                     Vec2W rA, Vec2W rB)
{
    return b.linear + Cross(b.angular, rB) - a.linear - Cross(a.angular, rA);
}

/// One body's transform per lane.
struct TransformW
{
    RotW q;
    Vec2W p;
};

/// The body transforms of both bodies of the lanes from their position states (centre of mass,
/// angle) and local centres: p = c − q·localCenter, the angles' ranges tested at once (SinCosW of
/// two angles).
[[gnu::always_inline]] inline void TransformsFromCenter(const BodyStateW& a, Vec2W localCenterA,
                                                        const BodyStateW& b, Vec2W localCenterB,
                                                        TransformW& xfA, TransformW& xfB)
{
    SinCosW(a.angular, b.angular, xfA.q, xfB.q);
    xfA.p = a.linear - Mul(xfA.q, localCenterA);
    xfB.p = b.linear - Mul(xfB.q, localCenterB);
}

[[gnu::always_inline]] inline Vec2W Mul(const TransformW& xf, Vec2W v)
{
    return Mul(xf.q, v) + xf.p;
}

inline TransformW Select(MaskW m, const TransformW& ifTrue, const TransformW& ifFalse)
{
    return {{Select(m, ifTrue.q.s, ifFalse.q.s), Select(m, ifTrue.q.c, ifFalse.q.c)},
            Select(m, ifTrue.p, ifFalse.p)};
}

/// 1/k of a row, 0 for a row no body can move along (k ≤ 0).
[[gnu::always_inline]] inline RealW RowMass(RealW k)
{
    const MaskW positive = k > 0;
    return Select(positive, Splat(1) / Select(positive, k, Splat(1)), Splat(0));
}

/// 1/det of the lanes' 2×2 matrix [k11 k12; k21 k22], 0 where it is singular (as
/// Mat22::GetInverse and Mat22::Solve).
[[gnu::always_inline]] inline RealW InverseDeterminant(RealW k11, RealW k12, RealW k21, RealW k22)
{
    const RealW det = k11 * k22 - k12 * k21;
    const MaskW invertible = det != 0;
    return Select(invertible, Splat(1) / Select(invertible, det, Splat(1)), Splat(0));
}

} // namespace meff::detail
