// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The spin rows of rolling resistance in SIMD lanes: shared by the colour back end's contact
// lanes and the soft step's.
#pragma once

#include "solvers/lanes/lane_bodies.h"
#include "solvers/shared/contact_constraint.h"

namespace meff::detail
{

/// A group's spin rows as SolveRollingLanes reads them (by their names): the rows, kept beside the
/// group's other rows (few groups have them), its normal impulses and its bodies' inverse
/// inertias.
struct RollingRows
{
    const RealW& rollingResistance;
    const RealW& rollingMass;
    RealW& rollingImpulse;
    const RealW (&normalImpulse)[2];
    RealW invIA, invIB;
};

/// Each lane's spin row (SolveRollingRow), lane by lane: contacts with rolling resistance are
/// rare, so the lanes without it (resistance 0) cost nothing else. `applied(lane, lambda)` is
/// told each impulse applied (the soft step totals them over its sub-steps).
template <typename Group, typename Applied>
[[gnu::always_inline]] inline void SolveRollingLanes(Group& g, BodyStateW& a, BodyStateW& b,
                                                     Applied&& applied)
{
    for (int l = 0; l < kLanes; ++l)
    {
        if (!(g.rollingResistance[l] > 0))
        {
            continue;
        }
        // A lane of a vector type is not an lvalue a reference may bind to (clang refuses it).
        Real accumulated = g.rollingImpulse[l];
        const Real lambda = SolveRollingRow(g.rollingMass[l], g.rollingResistance[l],
                                            g.normalImpulse[0][l] + g.normalImpulse[1][l],
                                            a.angular[l], b.angular[l], accumulated);
        g.rollingImpulse[l] = accumulated;
        a.angular[l] -= g.invIA[l] * lambda;
        b.angular[l] += g.invIB[l] * lambda;
        applied(l, lambda);
    }
}

} // namespace meff::detail
