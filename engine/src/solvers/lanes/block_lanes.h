// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// The two normal rows of a two-point manifold as one block, lane by lane: shared by the colour
// back end's contact lanes and the soft step's.
#pragma once

#include "solvers/lanes/lane_bodies.h"
#include "solvers/lanes/wide_real.h"

namespace meff::detail
{

/// New accumulated impulses of the two rows.
struct BlockImpulsesW
{
    RealW x1, x2;
};

/// The block solver's view of a group's two normal rows: K's k12, K⁻¹ and the rows' own effective
/// masses (SolveBlockLanes reads them by their names).
struct BlockRows
{
    RealW k12, inv11, inv12, inv22;
    RealW normalMass[2];
};

/// BlockRows from the rows' K = [k11 k12; k12 k22] and effective masses: K⁻¹ recomputed with the
/// preparation's operations (Mat22::GetInverse), so bit for bit what it would have kept. K is
/// symmetric, and so is its inverse (both off-diagonal entries are −k12/det).
[[gnu::always_inline]] inline BlockRows BlockRowsOf(RealW k11, RealW k12, RealW k22,
                                                    const RealW (&normalMass)[2])
{
    const RealW invDet = InverseDeterminant(k11, k12, k12, k22);
    return {k12, invDet * k22, -invDet * k12, invDet * k11, {normalMass[0], normalMass[1]}};
}

/// Solves vn = K·x + b as one LCP by total enumeration of its four cases in Box2D's order (as
/// ContactSolver's SolveNormalBlock), b = (vn − bias) − K·a being the rows' velocity error at
/// the old impulses a. A lane where no case holds keeps a. `g` holds K's k12, K⁻¹ (inv11,
/// inv12, inv22: K is symmetric, and so is K⁻¹) and each row's own effective mass
/// (normalMass[2], 1/kii).
[[gnu::always_inline]] inline BlockImpulsesW SolveBlockLanes(const BlockRows& g, RealW a1, RealW a2,
                                                             RealW b1, RealW b2)
{
    // Case 1: both in contact, x = −K⁻¹·b.
    const RealW x1 = -(g.inv11 * b1 + g.inv12 * b2);
    const RealW x2 = -(g.inv12 * b1 + g.inv22 * b2);
    const MaskW case1 = (x1 >= 0) & (x2 >= 0);
    // Case 2: point 1 only (x2 = 0, vn2 ≥ 0).
    const RealW y1 = -g.normalMass[0] * b1;
    const MaskW case2 = (y1 >= 0) & (g.k12 * y1 + b2 >= 0);
    // Case 3: point 2 only (x1 = 0, vn1 ≥ 0).
    const RealW z2 = -g.normalMass[1] * b2;
    const MaskW case3 = (z2 >= 0) & (g.k12 * z2 + b1 >= 0);
    // Case 4: both separating.
    const MaskW case4 = (b1 >= 0) & (b2 >= 0);

    // The first case that holds picks: the first impulse x1, y1, 0 (cases 3, 4) or a1 (none), the
    // second x2, 0 (case 2), z2, 0 (case 4) or a2; by masks, the same bits as a select per case.
    const MaskW first12 = case1 | case2;
    const MaskW none = ~(first12 | case3 | case4);
    const MaskW takeY1 = case2 & ~case1, takeZ2 = case3 & ~first12;
    return {Pick(case1, x1, takeY1, y1, none, a1), Pick(case1, x2, takeZ2, z2, none, a2)};
}

} // namespace meff::detail
