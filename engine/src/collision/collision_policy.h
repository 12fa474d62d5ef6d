// What a solver back end asks of the shared collision stages (Solver::Collision): how the
// broad phase fattens boxes and whether the narrow phase may keep a touching manifold. The
// stages are the same code for every back end; each back end picks its settings here, so Box2D's
// keeps Box2D 2.4.1's behaviour bit for bit while the others trade exactness for speed.
#pragma once

#include "meff/math.h"

namespace meff::detail
{

/// How a proxy's fat box is made from its shape's box (its back end chooses:
/// Solver::Collision): the box grown by `margin` on every side, then stretched by
/// `displacementMultiplier` times the step's displacement on the side the shape is heading to —
/// with `stretchLimit` > 0, by at most that fraction of the shape's extent (the half-diagonal of
/// its own box) in x and in y. A larger box is kept longer as its shape moves (fewer
/// re-insertions and pair searches) but overlaps more boxes (more candidate pairs, each one a
/// contact the narrow phase updates every step). Box2D 2.4.1: a 0.1 m margin and a fourfold,
/// unlimited stretch.
struct FatBoxRule
{
    Real margin = Real(0.1);         ///< m
    Real displacementMultiplier = 4; ///< Box2D's b2_aabbMultiplier
    Real stretchLimit = 0;           ///< of the extent; 0: no limit
    friend bool operator==(const FatBoxRule&, const FatBoxRule&) = default;
};

/// A back end's choices for the collision stages.
struct CollisionPolicy
{
    FatBoxRule fatBoxes;
    /// A touching manifold is kept as it is, not computed again, while neither shape has moved
    /// by more than this (m) relative to the other since it was computed (Collide's recycling);
    /// 0: every touching manifold is computed every step, as Box2D 2.4.1 does.
    Real recycleDistance = 0;
    friend bool operator==(const CollisionPolicy&, const CollisionPolicy&) = default;
};

} // namespace meff::detail
