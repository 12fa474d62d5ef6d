// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Rows shared by the joints that hold body B's anchor on a line fixed in body A (prismatic and
// wheel, Box2D 2.4.1's point-to-line constraints). A row along a world direction n (the axis
// or its perpendicular), with d = pB − pA the anchor separation, has
//   C = n·d,   Cdot = n·(vB − vA) + sB·wB − sA·wA,   J = [−n  −sA  n  sB]
//   sA = (d + rA) × n,  sB = rB × n
// (A's term uses d + rA because n turns with A), and its scalar effective mass is the seed's
//   k = 1/mA + 1/mB + sA²/IA + sB²/IB.
// Every expression keeps Box2D's floating-point operation order (frame-by-frame validation).
#pragma once

#include "joints/joint.h"

namespace meff::detail
{

/// Cdot of a line row: n·(vB − vA) + sB·wB − sA·wA.
inline Real LineRowSpeed(Vec2 n, Real sA, Real sB, Vec2 vA, Real wA, Vec2 vB, Real wB)
{
    return Dot(n, vB - vA) + sB * wB - sA * wA;
}

/// The two bodies' inverse masses, which a line row's impulse is divided by.
struct LineRowMasses
{
    Real mA = 0, mB = 0, iA = 0, iB = 0;
};

/// The inverse masses a joint stored for this step (every joint type has these members).
template <typename JointData>
LineRowMasses Masses(const JointData& joint)
{
    return {joint.invMassA, joint.invMassB, joint.invIA, joint.invIB};
}

/// A line row along n: its Jacobian's angular terms and its seed k (not yet inverted).
struct LineRow
{
    Real sA = 0, sB = 0; ///< (d + rA) × n and rB × n
    Real k = 0;          ///< 1/mA + 1/mB + sA²/IA + sB²/IB
};

inline LineRow MakeLineRow(Vec2 n, Vec2 d, Vec2 rA, Vec2 rB, const LineRowMasses& m)
{
    LineRow row;
    row.sA = Cross(d + rA, n);
    row.sB = Cross(rB, n);
    row.k = m.mA + m.mB + m.iA * row.sA * row.sA + m.iB * row.sB * row.sB;
    return row;
}

/// Applies a line row's impulse λ: λ·n on B and −λ·n on A, with the angular parts λ·sB and
/// −λ·sA. A negative λ flips every term exactly (IEEE negation is exact).
inline void ApplyLineRowImpulse(Real impulse, Vec2 n, Real sA, Real sB, const LineRowMasses& m,
                                Vec2& vA, Real& wA, Vec2& vB, Real& wB)
{
    const Vec2 P = impulse * n;
    const Real LA = impulse * sA;
    const Real LB = impulse * sB;
    vA -= m.mA * P;
    wA -= m.iA * LA;
    vB += m.mB * P;
    wB += m.iB * LB;
}

/// What the translation limit rows along the axis need.
struct TranslationLimit
{
    Vec2 axis;
    Real sA = 0, sB = 0;
    Real axialMass = 0;   ///< 1/k of the axial row
    Real translation = 0; ///< axis·d at the step's start
    Real lower = 0, upper = 0;
};

/// The two one-sided limit rows along the axis, lower then upper, each with accumulated
/// impulse ≥ 0. The bias max(C, 0)/h is speculative: while the limit is C away, the row allows
/// just the speed that closes the gap this step; once violated it adds no bias and the position
/// pass removes the error. The upper row is written with C = upper − translation and the
/// reversed Cdot, so its impulse is also ≥ 0 when active and acts with flipped signs.
inline void SolveTranslationLimits(const TranslationLimit& limit, const LineRowMasses& m,
                                   Real invDt, Real& lowerImpulse, Real& upperImpulse, Vec2& vA,
                                   Real& wA, Vec2& vB, Real& wB)
{
    {
        const Real C = limit.translation - limit.lower;
        const Real Cdot = LineRowSpeed(limit.axis, limit.sA, limit.sB, vA, wA, vB, wB);
        Real impulse = -limit.axialMass * (Cdot + Max(C, Real(0)) * invDt);
        const Real oldImpulse = lowerImpulse;
        lowerImpulse = Max(lowerImpulse + impulse, Real(0));
        impulse = lowerImpulse - oldImpulse;
        ApplyLineRowImpulse(impulse, limit.axis, limit.sA, limit.sB, m, vA, wA, vB, wB);
    }
    {
        const Real C = limit.upper - limit.translation;
        const Real Cdot = Dot(limit.axis, vA - vB) + limit.sA * wA - limit.sB * wB;
        Real impulse = -limit.axialMass * (Cdot + Max(C, Real(0)) * invDt);
        const Real oldImpulse = upperImpulse;
        upperImpulse = Max(upperImpulse + impulse, Real(0));
        impulse = upperImpulse - oldImpulse;
        ApplyLineRowImpulse(-impulse, limit.axis, limit.sA, limit.sB, m, vA, wA, vB, wB);
    }
}

} // namespace meff::detail
