// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Soft constraints: a row whose position error C is to behave as a damped spring of natural
// frequency ω and damping ratio ζ over a sub-step h. With k the row's inverse effective mass
// (the seed's 1/m_eff = 1/mA + 1/mB + (rA×n)²/IA + (rB×n)²/IB), one update's impulse is
//
//   λ = −m_eff·(massScale·Cdot + biasScale·C) − impulseScale·λ_accumulated,
//
// and a rigid row is massScale = 1, biasScale = impulseScale = 0: λ = −m_eff·Cdot.
// docs/soft-step.md derives both forms below from m_eff·C'' = −k_s·C − c·C', k_s = m_eff·ω²,
// c = 2·m_eff·ζ·ω:
//  - MakeSoft, the implicit Euler step (Box2D v3's soft constraint), for the rigid rows made
//    soft while solving: a1 = 2ζ + hω, a2 = hω·a1, massScale = a2/(1 + a2), impulseScale =
//    1/(1 + a2), biasScale = hω²/(1 + a2). Unconditionally stable, but it damps an oscillation
//    on its own (its amplitude decays as if ζ were larger by hω/2).
//  - SpringSoftness, for a joint's own spring: the step whose oscillation decays exactly at
//    e^(−ζωh) per sub-step: massScale = 1 − e^(−2ζωh), impulseScale = e^(−2ζωh), biasScale =
//    hω²·e^(−2ζωh). Without damping it is the symplectic Euler spring, which keeps its energy.
#pragma once

#include "meff/math.h"

#include <cmath>

namespace meff::detail
{

struct Softness
{
    Real biasScale = 0;    ///< 1/s: velocity bias per metre (or radian) of error, × massScale
    Real massScale = 1;    ///< fraction of the effective mass the row uses
    Real impulseScale = 0; ///< fraction of the accumulated impulse the row takes back
    /// Joints: the largest velocity bias (m/s, or rad/s for an angle) with which a gap is
    /// closed by velocity; what lies beyond is closed by moving the bodies (BiasOf).
    Real maxBias = kMaxReal;
    /// The joints' position pass: the row's bias is the part of biasScale·C beyond maxBias.
    bool excess = false;
};

/// A rigid row: no bias, the whole effective mass, no impulse taken back.
inline constexpr Softness kRigid{0, 1, 0};

/// The implicit soft row of natural frequency `hertz` (Hz) and damping ratio `zeta` over a
/// sub-step `h` (s); hertz 0 is a row that does nothing.
inline Softness MakeSoft(Real hertz, Real zeta, Real h)
{
    if (hertz == 0)
    {
        return {0, 0, 0};
    }
    const Real omega = Real(2) * kPi * hertz;
    const Real a1 = Real(2) * zeta + h * omega;
    const Real a2 = h * omega * a1;
    const Real a3 = Real(1) / (Real(1) + a2);
    return {h * omega * omega * a3, a2 * a3, a3};
}

/// The soft row of a spring of stiffness `stiffness` and damping `damping` (per unit of the
/// row's error: N/m and N·s/m, or N·m/rad and N·m·s/rad) acting on a row of inverse effective
/// mass `k` (ω = √(stiffness·k), ζ = damping·k/(2ω)), decaying exactly as the spring does.
/// Stiffer than hω = 1 (the explicit step's accuracy ends well before its stability limit
/// hω = 2), the implicit MakeSoft takes over.
inline Softness SpringSoftness(Real stiffness, Real damping, Real k, Real h)
{
    if (k <= 0 || stiffness <= 0)
    {
        if (k <= 0 || damping <= 0)
        {
            return {0, 0, 0};
        }
        // A damper alone: its velocity decays as e^(−c·k·h) per sub-step.
        const Real decay = std::exp(-damping * k * h);
        return {0, Real(1) - decay, decay};
    }
    const Real omega = std::sqrt(stiffness * k);
    const Real zeta = damping * k / (Real(2) * omega);
    if (h * omega > 1)
    {
        return MakeSoft(omega / (Real(2) * kPi), zeta, h);
    }
    const Real decay = std::exp(Real(-2) * zeta * omega * h);
    return {h * omega * omega * decay, Real(1) - decay, decay};
}

/// The spring of Box2D v3's revolute and prismatic joints, given as a natural frequency
/// `hertz` (Hz) and damping ratio `zeta` on the row's own effective mass (so k_s·k = ω²,
/// ω = 2π·hertz): SpringSoftness's exactly damped step (docs/soft-step.md, "The exactly
/// damped spring": massScale = 1 − e^(−2ζωh), biasScale = hω²·e^(−2ζωh), impulseScale =
/// e^(−2ζωh)), and the implicit MakeSoft beyond hω = 1. hertz 0 is a row that does nothing.
inline Softness FrequencySpringSoftness(Real hertz, Real zeta, Real h)
{
    if (!(hertz > 0))
    {
        return {0, 0, 0};
    }
    const Real omega = Real(2) * kPi * hertz;
    if (h * omega > 1)
    {
        return MakeSoft(hertz, zeta, h);
    }
    const Real decay = std::exp(Real(-2) * zeta * omega * h);
    return {h * omega * omega * decay, Real(1) - decay, decay};
}

/// A row's velocity bias at error C: biasScale·C, at most maxBias in size; with `excess` (the
/// joints' position pass) the part of it beyond maxBias.
inline Real BiasOf(const Softness& soft, Real C)
{
    const Real bias = soft.biasScale * C;
    const Real bounded = Clamp(bias, -soft.maxBias, soft.maxBias);
    return soft.excess ? bias - bounded : bounded;
}

/// The same for a point's two rows: the bias vector's length is bounded.
inline Vec2 BiasOf(const Softness& soft, Vec2 C)
{
    const Vec2 bias = soft.biasScale * C;
    const Real length = bias.Length();
    const Vec2 bounded = length > soft.maxBias ? (soft.maxBias / length) * bias : bias;
    return soft.excess ? bias - bounded : bounded;
}

/// One soft update of a row's accumulated impulse (the form at the top of this file): error C,
/// velocity cdot = J·v now, `mass` = 1/k, `accumulated` the impulse so far.
inline Real SpringRowImpulse(const Softness& soft, Real mass, Real cdot, Real C, Real accumulated)
{
    return -mass * (soft.massScale * cdot + soft.biasScale * C) - soft.impulseScale * accumulated;
}

} // namespace meff::detail
