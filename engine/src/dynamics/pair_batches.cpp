// Pair finding in batches, for the colour and soft-step back ends: the broad phase's queries
// for the moved proxies and the built-in rules of AddPair run on the world's threads, batch by
// batch, and the contacts are made afterwards on the stepping thread in the batches' order, so
// that the pairs, their order and the user's filter's questions are UpdatePairs' for any thread
// count. Box2D's back end keeps UpdatePairs (contact_manager.cpp: FindNewContacts).
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

/// Gives every batch's lists the capacity of the largest: a list that grows is one allocation,
/// and each batch would otherwise reach its own largest size at its own time, long after the
/// world has warmed up (without this, large_pyramid on a pool allocated 5 times in its 31st to
/// 50th steps: tests/test_world_lifecycle.cpp). On the stepping
/// thread, after the batches; allocates only when some list grew past all the others.
void EqualizeCapacity(std::vector<PairBatch>& lists)
{
    std::size_t found = 0;
    std::size_t kept = 0;
    for (const PairBatch& batch : lists)
    {
        found = std::max(found, batch.found.capacity());
        kept = std::max(kept, batch.kept.capacity());
    }
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
    const int moves = world.broadPhase.GetMoveCount();
    const int batches = (moves + kMovesPerBatch - 1) / kMovesPerBatch;
    std::vector<PairBatch>& lists = world.scratch.pairBatches;
    if (lists.size() < static_cast<std::size_t>(batches))
    {
        lists.resize(static_cast<std::size_t>(batches)); // never shrunk: the lists keep capacity
    }
    const WorldState& read = world;
    ForRanges(world.tasks, batches, 1,
              [&read, &lists, moves](int begin, int end, int)
              {
                  for (int b = begin; b < end; ++b)
                  {
                      FindBatchPairs(read, b, moves, lists[static_cast<std::size_t>(b)]);
                  }
              });
    EqualizeCapacity(lists);
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
    world.broadPhase.ClearMoveBuffer();
}

} // namespace meff::detail
