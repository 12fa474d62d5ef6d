// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Pair finding in batches, for the colour and soft-step back ends: the broad phase's queries
// for the moved proxies and the built-in rules of AddPair run on the world's threads, batch by
// batch, and the contacts are made afterwards in the batches' order (their slots and links on
// the stepping thread, their fields on the threads: MakeContacts), so that the pairs, their
// order and the user's filter's questions are UpdatePairs' for any thread count. Box2D's back end
// keeps UpdatePairs (contact_manager.cpp: FindNewContacts).
#include "dynamics/pair_rules.h"
#include "tasks/parallel_ranges.h"

#include <algorithm>
#include <vector>

namespace meff::detail
{

namespace
{

/// Move-buffer entries to a batch: a moved proxy's query and its pairs' rules cost one to a few
/// thousand instructions (spinner, smash), so a batch of 32 is tens of thousands, more than
/// handing it to another thread costs.
constexpr int kMovesPerBatch = 32;

/// One batch: the queries of its entries, then the pairs the built-in rules let through, as
/// shapes, in the queries' order. Writes only the batch's own lists.
void FindBatchPairs(const WorldState& world, int batch, int moves, PairBatch& lists)
{
    lists.found.clear();
    lists.kept.clear();
    world.broadPhase.FindPairs(batch * kMovesPerBatch,
                               std::min(moves, (batch + 1) * kMovesPerBatch), lists.found);
    for (const BroadPhase::Pair& pair : lists.found)
    {
        const std::int32_t shapeA = world.broadPhase.GetUserData(pair.proxyIdA);
        const std::int32_t shapeB = world.broadPhase.GetUserData(pair.proxyIdB);
        if (!BuiltInRulesRefuse(world, shapeA, shapeB))
        {
            lists.kept.push_back({shapeA, shapeB});
        }
    }
}

/// Keeps every batch's lists at least as long as the longest list so far: a list that grows is
/// one allocation, and each batch would otherwise reach its own largest size at its own time,
/// long after the world has warmed up (without this, large_pyramid on a pool allocated 5 times
/// in its 31st to 50th steps: tests/test_world_lifecycle.cpp). New batches get that capacity
/// before the threads run; after them, a list that grew past it raises it for all. On the
/// stepping thread; allocates only when a batch is new or some list grew past all the others.
void ReserveBatches(std::vector<PairBatch>& lists, int batches, const PairBatchCapacity& capacity)
{
    if (lists.size() < static_cast<std::size_t>(batches))
    {
        lists.resize(static_cast<std::size_t>(batches)); // never shrunk: the lists keep capacity
        for (PairBatch& batch : lists)
        {
            batch.found.reserve(capacity.found);
            batch.kept.reserve(capacity.kept);
        }
    }
}

/// After the threads: the used batches' longest lists raise every batch's (see ReserveBatches).
void EqualizeCapacity(std::vector<PairBatch>& lists, int batches, PairBatchCapacity& capacity)
{
    std::size_t found = capacity.found;
    std::size_t kept = capacity.kept;
    for (int b = 0; b < batches; ++b)
    {
        found = std::max(found, lists[static_cast<std::size_t>(b)].found.capacity());
        kept = std::max(kept, lists[static_cast<std::size_t>(b)].kept.capacity());
    }
    if (found == capacity.found && kept == capacity.kept)
    {
        return;
    }
    capacity = {found, kept};
    for (PairBatch& batch : lists)
    {
        batch.found.reserve(found);
        batch.kept.reserve(kept);
    }
}

} // namespace

/// The move buffer is cut into batches of kMovesPerBatch entries, fixed by the buffer alone,
/// whatever the threads. The batches' kept lists, put end to end in batch order, are
/// UpdatePairs' pairs in UpdatePairs' order less those AddPair refuses before the user's filter:
/// nothing changes the tree, the shapes, the bodies or the joints while the pairs are added,
/// and the only contacts made meanwhile are this pass's own, hence the existing-contact test
/// again in the serial pass (a proxy buffered twice, moved then touched, finds its pairs twice).
void FindNewContactsInBatches(WorldState& world)
{
    world.broadPhase.RebuildTree(world.Tasks());
    const int moves = world.broadPhase.GetMoveCount();
    const int batches = (moves + kMovesPerBatch - 1) / kMovesPerBatch;
    std::vector<PairBatch>& lists = world.scratch.pairBatches;
    ReserveBatches(lists, batches, world.scratch.pairBatchCapacity);
    const WorldState& read = world;
    ForEachIndex(world.Tasks(), batches, 1,
                 [&read, &lists, moves](int b)
                 { FindBatchPairs(read, b, moves, lists[static_cast<std::size_t>(b)]); });
    EqualizeCapacity(lists, batches, world.scratch.pairBatchCapacity);
    if (world.customFilter)
    {
        // The user's filter may look at the world between its questions: each contact is made
        // whole before the next question, as UpdatePairs makes them.
        for (int b = 0; b < batches; ++b)
        {
            for (const ShapePair& pair : lists[static_cast<std::size_t>(b)].kept)
            {
                if (!world.contactPairs.Contains(ShapePairKey(pair.shapeA, pair.shapeB)))
                {
                    CreateContact(world, pair.shapeA, pair.shapeB);
                }
            }
        }
    }
    else
    {
        MakeContacts(world, batches);
    }
    world.broadPhase.ClearMoveBuffer();
}

} // namespace meff::detail
