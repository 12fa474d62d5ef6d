// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
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
/// `displacementMultiplier` times the step's displacement on the side the shape is heading to.
/// A larger box is kept longer as its shape moves (fewer tree updates and pair searches) but
/// overlaps more boxes (more candidate pairs, each one a contact the narrow phase walks every
/// step). Box2D 2.4.1: a 0.1 m margin and a fourfold stretch.
struct FatBoxRule
{
    Real margin = Real(0.1);         ///< m
    Real displacementMultiplier = 4; ///< Box2D's b2_aabbMultiplier; 0: no stretch
    friend bool operator==(const FatBoxRule&, const FatBoxRule&) = default;
};

/// How the broad phase's tree follows a proxy whose shape left its fat box.
enum class TreeUpdate
{
    /// Box2D 2.4.1's: the leaf is removed and inserted again by the perimeter heuristic, with
    /// rotations on the way up: the tree, and so the pairs' order, are Box2D's.
    Reinsert,
    /// The leaf takes its new box in place and its ancestors grow to hold it (a walk up, no
    /// search); before the next pairs are found, the grown part of the tree is built again top
    /// down, the untouched subtrees kept whole (DynamicTree::Rebuild). Cheaper where many
    /// proxies move each step, and a built tree is tighter than one grown leaf by leaf.
    EnlargeAndRebuild,
};

/// Which pose a moved shape's box covers (SynchronizeShapes).
enum class ShapeBoxes
{
    /// Box2D 2.4.1's: the whole motion over the step, from the step's start pose to its end.
    Swept,
    /// The swept box when continuous collision is on (its time of impact needs the pairs of
    /// shapes that crossed during the step, which only the sweep finds); the end pose alone when
    /// it is off, as Box2D v3: every pair touching at the end is still found, and a crowd of fast
    /// bodies is not paired along its paths (spinner by colour: 61,152 contacts → 22,872).
    SweptForContinuous,
};

/// A back end's choices for the collision stages.
struct CollisionPolicy
{
    FatBoxRule fatBoxes;
    ShapeBoxes shapeBoxes = ShapeBoxes::Swept;
    TreeUpdate treeUpdate = TreeUpdate::Reinsert;
    /// A touching manifold is kept as it is, not computed again, while neither shape has moved
    /// by more than this (m) relative to the other since it was computed (Collide's recycling);
    /// 0: every touching manifold is computed every step, as Box2D 2.4.1 does.
    Real recycleDistance = 0;
    /// Whether the shared stages — the pair search (in batches), the narrow phase, the boxes'
    /// synchronization and continuous collision's first search — may use the world's threads
    /// (WorldState::StageTasks). false: they run on the stepping thread, the new pairs added in
    /// the broad phase's order, as Box2D 2.4.1 does.
    bool threadedStages = false;
    friend bool operator==(const CollisionPolicy&, const CollisionPolicy&) = default;
};

} // namespace meff::detail
