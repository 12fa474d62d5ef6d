// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Working memory of the step's threaded collision stages (Collide, SynchronizeShapes,
// FindNewContacts), kept in the world from step to step so that a warmed-up world does not
// allocate for them. None of it is state: it is rewritten before it is read, every step, and is
// outside snapshots and the state hash.
#pragma once

#include "collision/broad_phase.h"
#include "meff/math.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace meff::detail
{

/// What Collide does with one contact, decided before any of it is done.
enum class CollideAction : std::uint8_t
{
    Pending, ///< threaded Collide: flagged for filtering, so filtered and decided in list order
    Asleep,  ///< both bodies inactive: nothing, unless an earlier contact wakes one
    Destroy, ///< filtered out or the fat boxes parted
    Keep,    ///< touching, and the manifold is kept (CollisionPolicy::recycleDistance); threaded
             ///< Collide: also a fresh manifold that left the touching state as it was
    Update,  ///< a fresh manifold (UpdateContact)
};

/// One contact of the threaded Collide, by contact index.
struct CollideWork
{
    CollideAction action; ///< decided on the threads
    bool touching;        ///< Update: the fresh manifold's touching state, written by the threads
};

/// A pair of shapes found by the batched pair finding (FindNewContacts), in AddPair's order.
struct ShapePair
{
    std::int32_t shapeA;
    std::int32_t shapeB;
};

/// A contact the batched pair finding makes: its slot and its shapes in manifold order.
struct NewContact
{
    std::int32_t index;
    std::int32_t shapeA;
    std::int32_t shapeB;
};

/// One batch of the batched pair finding (pair_batches.cpp).
struct PairBatch
{
    std::vector<BroadPhase::Pair> found; ///< its queries' pairs of proxies, in order
    std::vector<ShapePair> kept;         ///< those the built-in rules let through, as shapes
};

/// The capacity of the longest lists of the batches so far.
struct PairBatchCapacity
{
    std::size_t found = 0;
    std::size_t kept = 0;
};

struct StepScratch
{
    /// The threaded Collide's contacts, in contact-list order.
    std::vector<std::int32_t> collideOrder;
    /// The threaded Collide's decisions, by contact index (alive contacts only).
    std::vector<CollideWork> collideWork;
    /// The threaded SynchronizeShapes' moved bodies, in body-list order.
    std::vector<std::int32_t> movedBodies;
    /// Per moved body (movedBodies' order): whether a shape of it needs a new fat box.
    std::vector<std::uint8_t> newBoxes;
    /// Per shape index: whether it needs its new fat box.
    std::vector<std::uint8_t> shapeNewBox;
    /// The batched pair finding's batches of move-buffer entries (only the first ones in use;
    /// never shrunk, so that the lists keep their capacity).
    std::vector<PairBatch> pairBatches;
    /// The contacts the batched pair finding makes, in the order it makes them.
    std::vector<NewContact> newContacts;
    /// The capacity every batch's lists have (pair_batches.cpp: EqualizeCapacity).
    PairBatchCapacity pairBatchCapacity;
};

} // namespace meff::detail
