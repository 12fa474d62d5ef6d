// The lanes' view of their bodies: four bodies' velocities or positions gathered from the
// island's arrays into SIMD lanes, updated there, and scattered back. Shared by the contact and
// joint solvers that work by colour (graph_colouring.h).
#pragma once

#include "dynamics/solver_types.h"
#include "solvers/colour/graph_colouring.h"
#include "solvers/lanes/wide_real.h"

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace meff::detail
{

/// One body state of four lanes: a velocity (v, w) or a position (c, a).
struct BodyStateW
{
    Vec2W linear;  ///< v (m/s) or c (m)
    RealW angular; ///< w (rad/s) or a (rad)
};

/// The four Reals of a Position (c.x, c.y, a, padding) or Velocity (v.x, v.y, w, padding):
/// solver_types.h aligns both to one RealW so that a body's state is one vector load.
template <typename State>
constexpr bool kStateIsOneVector = sizeof(State) == sizeof(RealW) &&
                                   alignof(State) == sizeof(RealW);
static_assert(kStateIsOneVector<Position> && kStateIsOneVector<Velocity>);
static_assert(offsetof(Position, a) == 2 * sizeof(Real) &&
              offsetof(Velocity, w) == 2 * sizeof(Real));

/// Reads the lanes' bodies from the island's positions or velocities: four vector loads and a
/// 4×4 transpose (rows are bodies, columns become x, y and angle).
template <typename State>
[[gnu::always_inline]] inline BodyStateW Gather(const State* states,
                                                const std::int32_t (&index)[kLanes])
{
    static_assert(kLanes == 4, "the transpose is written for four lanes");
    RealW r0, r1, r2, r3;
    std::memcpy(&r0, &states[index[0]], sizeof(RealW));
    std::memcpy(&r1, &states[index[1]], sizeof(RealW));
    std::memcpy(&r2, &states[index[2]], sizeof(RealW));
    std::memcpy(&r3, &states[index[3]], sizeof(RealW));
    const RealW xy01 = __builtin_shufflevector(r0, r1, 0, 4, 1, 5);
    const RealW xy23 = __builtin_shufflevector(r2, r3, 0, 4, 1, 5);
    const RealW a01 = __builtin_shufflevector(r0, r1, 2, 6, 3, 7);
    const RealW a23 = __builtin_shufflevector(r2, r3, 2, 6, 3, 7);
    return {{__builtin_shufflevector(xy01, xy23, 0, 1, 4, 5),
             __builtin_shufflevector(xy01, xy23, 2, 3, 6, 7)},
            __builtin_shufflevector(a01, a23, 0, 1, 4, 5)};
}

/// Writes the lanes' bodies back: the transpose of Gather and four vector stores. `store[l]`
/// is the lane's body, or SolverData::discardIndex where the lane must not change its body (a
/// static or kinematic body, which lanes of one colour may share, or an empty lane).
template <typename State>
[[gnu::always_inline]] inline void Scatter(State* states, const std::int32_t (&store)[kLanes],
                                           const BodyStateW& in)
{
    const RealW zero{};
    const RealW xy01 = __builtin_shufflevector(in.linear.x, in.linear.y, 0, 4, 1, 5);
    const RealW xy23 = __builtin_shufflevector(in.linear.x, in.linear.y, 2, 6, 3, 7);
    const RealW a01 = __builtin_shufflevector(in.angular, zero, 0, 4, 1, 5);
    const RealW a23 = __builtin_shufflevector(in.angular, zero, 2, 6, 3, 7);
    const RealW r0 = __builtin_shufflevector(xy01, a01, 0, 1, 4, 5);
    const RealW r1 = __builtin_shufflevector(xy01, a01, 2, 3, 6, 7);
    const RealW r2 = __builtin_shufflevector(xy23, a23, 0, 1, 4, 5);
    const RealW r3 = __builtin_shufflevector(xy23, a23, 2, 3, 6, 7);
    std::memcpy(static_cast<void*>(&states[store[0]]), &r0, sizeof(RealW));
    std::memcpy(static_cast<void*>(&states[store[1]]), &r1, sizeof(RealW));
    std::memcpy(static_cast<void*>(&states[store[2]]), &r2, sizeof(RealW));
    std::memcpy(static_cast<void*>(&states[store[3]]), &r3, sizeof(RealW));
}

/// The discard slots of a thread solving groups (SolverData::discardIndex): the one the groups
/// were packed with, and the worker's own.
struct DiscardSlots
{
    std::int32_t packed; ///< SolverData::discardIndex
    std::int32_t own;    ///< discardIndex + worker
};

/// Scatter for a worker of the world's TaskSystem: lanes packed to write the discard slot write
/// the worker's own slot instead, so that the groups of one colour, solved on several threads
/// at once, never write the same memory (for worker 0 the slots are the same).
template <typename State>
[[gnu::always_inline]] inline void ScatterFromWorker(State* states,
                                                     const std::int32_t (&store)[kLanes],
                                                     DiscardSlots discard, const BodyStateW& in)
{
    std::int32_t to[kLanes];
    for (int l = 0; l < kLanes; ++l)
    {
        to[l] = store[l] == discard.packed ? discard.own : store[l];
    }
    Scatter(states, to, in);
}

/// Fills lane l's bodies from a prepared constraint: the solver indices to read, where to write
/// (the body, or the discard slot where the lane must not move it), and the inverse masses
/// (1/kg) and inertias (1/(kg·m²)). Group and constraint name these members alike.
template <typename Group, typename Constraint>
void PackLaneBodies(Group& g, int l, const Constraint& c, std::int32_t discardIndex)
{
    g.indexA[l] = c.indexA;
    g.indexB[l] = c.indexB;
    g.storeA[l] = SolverMoves(c.invMassA, c.invIA) ? c.indexA : discardIndex;
    g.storeB[l] = SolverMoves(c.invMassB, c.invIB) ? c.indexB : discardIndex;
    g.invMassA[l] = c.invMassA;
    g.invMassB[l] = c.invMassB;
    g.invIA[l] = c.invIA;
    g.invIB[l] = c.invIB;
}

/// The two bodies' inverse masses (1/kg) and inverse inertias (1/(kg·m²)) of four lanes.
struct LaneMasses
{
    RealW invMassA, invIA, invMassB, invIB;
};

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

/// The body transform from a position state (centre of mass, angle) and the local centre:
/// p = c − q·localCenter.
[[gnu::always_inline]] inline TransformW TransformFromCenter(const BodyStateW& position,
                                                             Vec2W localCenter)
{
    const RotW q = SinCosW(position.angular);
    return {q, position.linear - Mul(q, localCenter)};
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

/// 1/det of the lanes' 2×2 matrix [k11 k12; k21 k22], 0 where it is singular (as
/// Mat22::GetInverse and Mat22::Solve).
[[gnu::always_inline]] inline RealW InverseDeterminant(RealW k11, RealW k12, RealW k21, RealW k22)
{
    const RealW det = k11 * k22 - k12 * k21;
    const MaskW invertible = det != 0;
    return Select(invertible, Splat(1) / Select(invertible, det, Splat(1)), Splat(0));
}

} // namespace meff::detail
