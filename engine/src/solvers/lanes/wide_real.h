// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Four Reals side by side (eight in an AVX2 build, MEFF_AVX2), so that four (eight) independent
// constraints are solved by one instruction stream (SIMD). Written with GCC's vector extensions
// (also understood by Clang): SSE2 on x86-64, NEON on ARM, scalar code elsewhere; AVX2 when the
// build asks for it — no intrinsics, no extra dependency. Every lane
// does exactly the operations the scalar solver does, in the same order; only which
// constraints run together changes (see graph_colouring.h).
#pragma once

#include "meff/math.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <type_traits>

namespace meff::detail
{

// The lane count is fixed per build: MEFF_SIMD_LANES=8 comes with -mavx2 (engine/CMakeLists.txt,
// option MEFF_AVX2), and 4 is the default. The colouring does not depend on it, and lanes never
// share a body the solver moves, so both builds solve each constraint with the same operations
// (see docs/api-guide.md, "SIMD lanes", for where they can still differ).
#ifndef MEFF_SIMD_LANES
#define MEFF_SIMD_LANES 4
#endif
#if MEFF_SIMD_LANES != 4 && MEFF_SIMD_LANES != 8
#error "MEFF_SIMD_LANES must be 4 or 8"
#endif
#if MEFF_SIMD_LANES == 8 && (defined(__x86_64__) || defined(__i386__)) && !defined(__AVX2__)
#error "eight lanes need AVX2: build with -DMEFF_AVX2=ON (it adds -mavx2)"
#endif
inline constexpr int kLanes = MEFF_SIMD_LANES;

using RealW = Real __attribute__((vector_size(kLanes * sizeof(Real))));
/// Four Reals: one body's state (solver_types.h) and half of an eight-lane vector.
using Real4 = Real __attribute__((vector_size(4 * sizeof(Real))));
/// A lane mask: all bits set in the lanes where a comparison holds.
using MaskW = decltype(RealW{} < RealW{});

/// Whether x is +0 bit for bit: a target or speed the sweeps may skip, since subtracting +0
/// changes no bit.
inline bool IsPositiveZero(Real x)
{
    return x == 0 && !std::signbit(x);
}

inline RealW Splat(Real x)
{
    return RealW{} + x;
}
inline RealW Select(MaskW m, RealW ifTrue, RealW ifFalse)
{
    return m ? ifTrue : ifFalse;
}
/// x where mx is set, y where my is set, z where mz is set and +0 where none is, the masks being
/// disjoint: each lane's bits are one operand's, as from selects, by three ands and two ors.
inline RealW Pick(MaskW mx, RealW x, MaskW my, RealW y, MaskW mz, RealW z)
{
    return std::bit_cast<RealW>((mx & std::bit_cast<MaskW>(x)) | (my & std::bit_cast<MaskW>(y)) |
                                (mz & std::bit_cast<MaskW>(z)));
}
inline RealW MinW(RealW a, RealW b)
{
    return a < b ? a : b;
}
inline RealW MaxW(RealW a, RealW b)
{
    return a > b ? a : b;
}
// Lane reductions by shuffles (a butterfly), not a loop over the lanes: the loop went through
// memory and cost more than the arithmetic it guarded. Eight lanes first fold their upper half
// onto the lower one, then reduce four as the default build does.
using Mask4 = decltype(Real4{} < Real4{});

inline Mask4 OrHalves(MaskW m)
{
#if MEFF_SIMD_LANES == 8
    return __builtin_shufflevector(m, m, 0, 1, 2, 3) | __builtin_shufflevector(m, m, 4, 5, 6, 7);
#else
    return m;
#endif
}

inline Mask4 AndHalves(MaskW m)
{
#if MEFF_SIMD_LANES == 8
    return __builtin_shufflevector(m, m, 0, 1, 2, 3) & __builtin_shufflevector(m, m, 4, 5, 6, 7);
#else
    return m;
#endif
}

inline bool AnyLane(MaskW m)
{
    const Mask4 quad = OrHalves(m);
    const Mask4 pairs = quad | __builtin_shufflevector(quad, quad, 2, 3, 0, 1);
    return (pairs | __builtin_shufflevector(pairs, pairs, 1, 0, 3, 2))[0] != 0;
}

inline bool AllLanes(MaskW m)
{
    const Mask4 quad = AndHalves(m);
    const Mask4 pairs = quad & __builtin_shufflevector(quad, quad, 2, 3, 0, 1);
    return (pairs & __builtin_shufflevector(pairs, pairs, 1, 0, 3, 2))[0] != 0;
}

struct Vec2W
{
    RealW x, y;
};

inline Vec2W operator+(Vec2W a, Vec2W b)
{
    return {a.x + b.x, a.y + b.y};
}
inline Vec2W operator-(Vec2W a, Vec2W b)
{
    return {a.x - b.x, a.y - b.y};
}
inline Vec2W operator*(RealW s, Vec2W a)
{
    return {s * a.x, s * a.y};
}
inline RealW Dot(Vec2W a, Vec2W b)
{
    return a.x * b.x + a.y * b.y;
}
/// a × b (the z of the 3D cross product).
inline RealW Cross(Vec2W a, Vec2W b)
{
    return a.x * b.y - a.y * b.x;
}
/// w × r for an angular velocity w: (−w·r.y, w·r.x).
inline Vec2W Cross(RealW w, Vec2W r)
{
    return {-w * r.y, w * r.x};
}
inline Vec2W Select(MaskW m, Vec2W ifTrue, Vec2W ifFalse)
{
    return {m ? ifTrue.x : ifFalse.x, m ? ifTrue.y : ifFalse.y};
}

/// Each lane's vector scaled to unit length, as Vec2::Normalize: left as it is where its length
/// is below kEpsilon. The square root is taken lane by lane (std::sqrt, correctly rounded).
inline Vec2W NormalizeW(Vec2W v)
{
    const RealW lengthSquared = v.x * v.x + v.y * v.y;
    RealW length{};
    for (int l = 0; l < kLanes; ++l)
    {
        length[l] = std::sqrt(lengthSquared[l]);
    }
    const MaskW normalizable = length >= kEpsilon;
    const RealW invLength = Splat(1) / Select(normalizable, length, Splat(1));
    return Select(normalizable, invLength * v, v);
}

/// A rotation per lane: sine and cosine of each lane's angle.
struct RotW
{
    RealW s, c;
};

/// q·v: each lane's vector rotated by its rotation.
inline Vec2W Mul(RotW q, Vec2W v)
{
    return {q.c * v.x - q.s * v.y, q.s * v.x + q.c * v.y};
}

/// SinCosW's exact fallback, lane by lane through the standard library.
[[gnu::noinline, gnu::cold]] inline RotW SinCosLanes(RealW angle)
{
    RotW q{};
    for (int l = 0; l < kLanes; ++l)
    {
        q.s[l] = std::sin(angle[l]);
        q.c[l] = std::cos(angle[l]);
    }
    return q;
}

/// SinCosW's constants, each in every lane (wide_real.cpp): read from memory, they are the
/// arithmetic's operands, where GCC 12 broadcast each from a scalar first (two SSE2 instructions
/// per use).
struct SinCosConstantsW
{
    RealW reducible, minusReducible; ///< ±6000: the reduction's exact range (rad)
    RealW twoOverPi;                 ///< 2/π
    RealW roundingShift;             ///< 1.5·2²³
    RealW halfPi1, halfPi2, halfPi3; ///< π/2 in three parts (Cody and Waite)
    RealW sin1, sin2, sin3;          ///< P's coefficients
    RealW cos1, cos2, cos3, cos4;    ///< −1/2 and Q's coefficients
    RealW one;                       ///< 1
};
extern const SinCosConstantsW kSinCosW;

/// The lanes whose angle SinCosW reduces itself (|angle| ≤ 6000 rad; NaN: false).
[[gnu::always_inline]] inline MaskW SinCosReducible(RealW angle)
{
    return (angle <= kSinCosW.reducible) & (angle >= kSinCosW.minusReducible);
}

/// SinCosW's reduction and polynomials, for angles that are SinCosReducible in every lane (float
/// builds).
[[gnu::always_inline]] inline RotW SinCosReduced(RealW angle)
{
    const SinCosConstantsW& k0 = kSinCosW;
    using IntW = decltype(RealW{} < RealW{});
    // Adding and subtracting 1.5·2²³ rounds a float to the nearest integer (|x| < 2²²).
    const RealW k = (angle * k0.twoOverPi + k0.roundingShift) - k0.roundingShift;
    const RealW r = ((angle - k * k0.halfPi1) - k * k0.halfPi2) - k * k0.halfPi3;
    const RealW r2 = r * r;
    const RealW sinR = r + r * r2 * (k0.sin1 + r2 * (k0.sin2 + r2 * k0.sin3));
    const RealW cosR = k0.one + r2 * (k0.cos1 + r2 * (k0.cos2 + r2 * (k0.cos3 + r2 * k0.cos4)));

    // a = k·π/2 + r: quadrant k mod 4 swaps sine and cosine and sets their signs (negating is
    // flipping the sign bit: bit 1 of the quadrant shifted there, and xor).
    using Bits = std::conditional_t<sizeof(Real) == 4, std::uint32_t, std::uint64_t>;
    using BitsW = Bits __attribute__((vector_size(kLanes * sizeof(Real))));
    const IntW quadrant = __builtin_convertvector(k, IntW) & 3;
    const IntW swap = (quadrant & 1) != 0;
    const RealW s = swap ? cosR : sinR;
    const RealW c = swap ? sinR : cosR;
    constexpr int kToSignBit = int(sizeof(Real)) * 8 - 2;
    const auto sSign = std::bit_cast<BitsW>(quadrant & 2) << kToSignBit;
    const auto cSign = std::bit_cast<BitsW>((quadrant + 1) & 2) << kToSignBit;
    return {std::bit_cast<RealW>(std::bit_cast<BitsW>(s) ^ sSign),
            std::bit_cast<RealW>(std::bit_cast<BitsW>(c) ^ cSign)};
}

/// Sine and cosine of every lane's angle at once, each within about an ulp of std::sin/std::cos.
/// The angle is reduced by the nearest multiple k of π/2, r = a − k·π/2 with |r| ≤ π/4, π/2 split
/// into three floats (Cody and Waite) whose leading two have so few bits that k·C1 and k·C2 are
/// exact for |k| < 4096; sin r ≈ r + r³·P(r²) and cos r ≈ 1 − r²/2 + r⁴·Q(r²), P and Q of degree
/// 2, fitted by weighted least squares on 400 Chebyshev nodes of [0, π/4] (near-minimax): in
/// float arithmetic, as evaluated here, both stay within 6.5e-8 (about half an ulp of 1) of the
/// true values over [−π/4, π/4], two terms fewer than Taylor series of the same accuracy. Lanes
/// beyond 6000 rad (k too large for exact products) or non-finite, and double builds, use the
/// standard library. The constants are kSinCosW's (wide_real.cpp).
[[gnu::always_inline]] inline RotW SinCosW(RealW angle)
{
    if (!std::is_same_v<Real, float> || !AllLanes(SinCosReducible(angle)))
    {
        return SinCosLanes(angle);
    }
    return SinCosReduced(angle);
}

/// SinCosW of two bodies' angles, their ranges tested at once (the same results).
[[gnu::always_inline]] inline void SinCosW(RealW angleA, RealW angleB, RotW& qA, RotW& qB)
{
    if (!std::is_same_v<Real, float> ||
        !AllLanes(SinCosReducible(angleA) & SinCosReducible(angleB)))
    {
        qA = SinCosW(angleA);
        qB = SinCosW(angleB);
        return;
    }
    qA = SinCosReduced(angleA);
    qB = SinCosReduced(angleB);
}

} // namespace meff::detail
