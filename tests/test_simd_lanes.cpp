// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The colour back end's SIMD lanes (engine/src/solvers/lanes/): the lane reductions and the
// bodies' gather and scatter see every lane, with the build's lane count (four, or eight in a
// MEFF_AVX2 build), so that both builds are held to the same checks.
#include "solvers/lanes/lane_bodies.h"
#include "solvers/lanes/wide_real.h"

#include <catch2/catch.hpp>

#include <vector>

using namespace meff;
using meff::detail::kLanes;
using meff::detail::MaskW;
using meff::detail::RealW;

namespace
{

/// A mask with exactly the lanes whose bit is set in `bits`.
MaskW MaskOf(unsigned bits)
{
    RealW v{};
    for (int l = 0; l < kLanes; ++l)
    {
        v[l] = (bits >> l) & 1u ? 1 : 0;
    }
    return v > 0;
}

} // namespace

TEST_CASE("SIMD lanes: the build's lane count", "[colouring][lanes]")
{
    // MEFF_AVX2 builds eight lanes; the default (SSE2) four.
#if defined(__AVX2__) && MEFF_SIMD_LANES == 8
    CHECK(kLanes == 8);
#else
    CHECK(kLanes == 4);
#endif
    CHECK(sizeof(RealW) == kLanes * sizeof(Real));
}

TEST_CASE("SIMD lanes: AnyLane and AllLanes look at every lane", "[colouring][lanes]")
{
    // Every subset of the lanes (16 or 256 masks): any is true unless none is set, all only
    // when every lane is.
    const unsigned all = (1u << kLanes) - 1;
    for (unsigned bits = 0; bits <= all; ++bits)
    {
        CAPTURE(bits);
        CHECK(detail::AnyLane(MaskOf(bits)) == (bits != 0));
        CHECK(detail::AllLanes(MaskOf(bits)) == (bits == all));
    }
}

TEST_CASE("SIMD lanes: gather and scatter move each lane's own body", "[colouring][lanes]")
{
    // Bodies with distinct velocities (exact small integers); lane l reads body 3l+1 and
    // writes it back changed, and the discard slot (the last body) takes a lane that must not
    // move its body. Every other body stays as it was.
    const int bodyCount = 3 * kLanes + 2;
    const std::int32_t discard = bodyCount - 1;
    std::vector<detail::Velocity> velocities(bodyCount);
    for (int i = 0; i < bodyCount; ++i)
    {
        velocities[i].v = Vec2(Real(10 * i), Real(10 * i + 1));
        velocities[i].w = Real(10 * i + 2);
    }
    std::int32_t index[kLanes];
    std::int32_t store[kLanes];
    for (int l = 0; l < kLanes; ++l)
    {
        index[l] = 3 * l + 1;
        store[l] = l == 2 ? discard : index[l];
    }

    detail::BodyStateW state = detail::Gather(velocities.data(), index);
    for (int l = 0; l < kLanes; ++l)
    {
        CHECK(state.linear.x[l] == Real(10 * index[l]));
        CHECK(state.linear.y[l] == Real(10 * index[l] + 1));
        CHECK(state.angular[l] == Real(10 * index[l] + 2));
    }

    state.linear.x = state.linear.x + 1000;
    state.angular = state.angular + 1000;
    const std::vector<detail::Velocity> before = velocities;
    detail::Scatter(velocities.data(), store, state);
    for (int i = 0; i < discard; ++i)
    {
        CAPTURE(i);
        const bool stored = i % 3 == 1 && i / 3 < kLanes && i / 3 != 2;
        CHECK(velocities[i].v.x == before[i].v.x + (stored ? 1000 : 0));
        CHECK(velocities[i].v.y == before[i].v.y);
        CHECK(velocities[i].w == before[i].w + (stored ? 1000 : 0));
    }
}
