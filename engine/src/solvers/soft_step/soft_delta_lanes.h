// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// The soft step's body motions (SoftDelta: dp, dq since the step began) in SIMD lanes: kLanes
// bodies' deltas gathered from the island's array into lanes and scattered back, as
// lane_bodies.h does for velocities — shared by the soft step's contact and joint lanes.
#pragma once

#include "solvers/lanes/lane_bodies.h"
#include "solvers/soft_step/soft_bodies.h"

#include <cstdint>
#include <cstring>

namespace meff::detail
{

static_assert(sizeof(SoftDelta) == sizeof(Real4) && alignof(SoftDelta) == sizeof(Real4));

/// Each lane's body motion since the step began (SoftDelta).
struct DeltaW
{
    Vec2W dp;
    RotW dq;
};

/// Each lane's deltas (dp.x, dp.y, dq.s, dq.c: GatherComponents).
[[gnu::always_inline]] inline DeltaW GatherDeltas(const SoftDelta* deltas,
                                                  const std::int32_t (&index)[kLanes])
{
    RealW columns[4];
    GatherComponents(deltas, index, columns);
    return {{columns[0], columns[1]}, {columns[2], columns[3]}};
}

[[gnu::always_inline]] inline void ScatterDeltas(SoftDelta* deltas,
                                                 const std::int32_t (&store)[kLanes],
                                                 const DeltaW& d)
{
#if MEFF_SIMD_LANES == 8
    const Real4 low[4] = {LowHalf(d.dp.x), LowHalf(d.dp.y), LowHalf(d.dq.s), LowHalf(d.dq.c)};
    const Real4 high[4] = {HighHalf(d.dp.x), HighHalf(d.dp.y), HighHalf(d.dq.s), HighHalf(d.dq.c)};
    Untranspose4(deltas, store, low);
    Untranspose4(deltas, store + 4, high);
#else
    const Real4 all[4] = {d.dp.x, d.dp.y, d.dq.s, d.dq.c};
    Untranspose4(deltas, store, all);
#endif
}

/// ScatterDeltas for a worker of the world's TaskSystem, to StoresOf's bodies (as ScatterStores).
[[gnu::always_inline]] inline void ScatterDeltaStores(SoftDelta* deltas,
                                                      const std::int32_t (&index)[kLanes],
                                                      unsigned stores, std::int32_t discard,
                                                      const DeltaW& d)
{
    std::int32_t to[kLanes];
    StoresOf(index, stores, discard, to);
    ScatterDeltas(deltas, to, d);
}

/// SmallRotationW's lanes beyond kShortSeriesAngle: the longer series, and std::sin/std::cos
/// in lanes beyond 0.5 rad, lane by lane (SmallRotation's cases). Out of line: most turns
/// within a sub-step are short.
[[gnu::noinline]] inline RotW LongRotationW(RealW angle, RotW shortSeries, MaskW small,
                                            RealW magnitude)
{
    RotW full;
    SmallRotationSeries(angle, full.s, full.c);
    RotW q{Select(small, shortSeries.s, full.s), Select(small, shortSeries.c, full.c)};
    const MaskW large = magnitude > Real(0.5);
    if (AnyLane(large))
    {
        for (int l = 0; l < kLanes; ++l)
        {
            if (large[l] != 0)
            {
                const Rot r(angle[l]);
                q.s[l] = r.s;
                q.c[l] = r.c;
            }
        }
    }
    return q;
}

/// SmallRotation per lane, bit for bit: the short series inline (one call cost as much as the
/// series itself in the contacts' position pass), the other cases out of line.
[[gnu::always_inline]] inline RotW SmallRotationW(RealW angle)
{
    RotW q;
    ShortRotationSeries(angle, q.s, q.c);
    const RealW magnitude = MaxW(angle, -angle);
    const MaskW small = magnitude <= kShortSeriesAngle;
    if (AllLanes(small))
    {
        return q;
    }
    return LongRotationW(angle, q, small, magnitude);
}

/// q·r per lane, as Mul(Rot, Rot).
[[gnu::always_inline]] inline RotW MulRot(RotW q, RotW r)
{
    return {q.s * r.c + q.c * r.s, q.c * r.c - q.s * r.s};
}

} // namespace meff::detail
