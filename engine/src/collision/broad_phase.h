// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// The broad phase: a dynamic AABB tree of fattened shape boxes plus a buffer of moved proxies,
// reporting the new overlapping pairs each step.
//
// It follows Box2D 2.4.1's b2BroadPhase/b2DynamicTree algorithms (node pool and free list,
// surface-area insertion heuristic, AVL-style rotations, fat AABBs extended by the margin and
// by 4x the displacement, moved flags, pair order) so that contacts are created in the same
// order as in Box2D and the solver sweeps them in the same order — for Box2D's back end; the
// others choose their own fat boxes and tree update (collision_policy.h).
#pragma once

#include "collision/collision_policy.h"
#include "meff/math.h"
#include "meff/ray_cast.h"

#include <cstdint>
#include <vector>

namespace meff
{
class TaskSystem;
}

namespace meff::detail
{

inline constexpr std::int32_t kNullProxy = -1;

/// A proxy's collision layers: its shape's Filter category and mask bits. The tree keeps them
/// so that a query can skip every subtree none of whose proxies could pair with it: each
/// internal node holds the union (bitwise or) of its leaves' bits, and a proxy A pairs with B
/// only if A's category meets B's mask and B's category meets A's.
struct ProxyLayers
{
    std::uint16_t categoryBits = 0xFFFF;
    std::uint16_t maskBits = 0xFFFF;
    /// Whether the bits alone decide this proxy's pairs. False for a shape in a positive
    /// collision group, which pairs with its group whatever the bits: its queries skip nothing.
    bool bitsDecide = true;
};

/// True when some proxy under a node with these (union) layers may pair with `query`'s.
inline bool LayersMeet(std::uint16_t categoryBits, std::uint16_t maskBits, ProxyLayers query)
{
    return (categoryBits & query.maskBits) != 0 && (maskBits & query.categoryBits) != 0;
}

class DynamicTree
{
  public:
    explicit DynamicTree(FatBoxRule rule);
    /// Box2D 2.4.1's rule with this margin.
    explicit DynamicTree(Real aabbMargin) : DynamicTree(FatBoxRule{aabbMargin}) {}

    /// Inserts a leaf with the box fattened by the margin; returns its proxy id.
    std::int32_t CreateProxy(const AABB& aabb, std::int32_t userData, ProxyLayers layers = {});
    void DestroyProxy(std::int32_t proxyId);
    /// Gives the leaf a new fat box when `aabb` leaves it (or it is far too large), re-inserting
    /// the leaf or growing its ancestors (TreeUpdate); returns true when it did.
    bool MoveProxy(std::int32_t proxyId, const AABB& aabb, Vec2 displacement);
    /// MoveProxy's test, which reads only the leaf (so leaves may be tested on several threads
    /// at once while nothing changes the tree): true, with the new fat box in `fat`, when the
    /// leaf needs one (SetFatBox).
    bool NeedsNewBox(std::int32_t proxyId, const AABB& aabb, Vec2 displacement, AABB& fat) const;
    /// MoveProxy's update, given NeedsNewBox's fat box.
    void SetFatBox(std::int32_t proxyId, const AABB& fat);
    /// SetFatBox for TreeUpdate::EnlargeAndRebuild, safe on several threads at once for distinct
    /// leaves while nothing else changes the tree: the leaf takes the fat box and is flagged as
    /// moved, and its ancestors are marked for Rebuild without growing their boxes, which stay
    /// stale until Rebuild builds every marked node afresh: Rebuild must come before anything
    /// reads the tree's internal boxes (the step's pair search rebuilds first). Rebuild's tree is
    /// SetFatBox's: it depends only on the set of marked nodes, every ancestor of a moved leaf.
    /// Then NoteGrown, on one thread.
    void SetFatBoxForRebuild(std::int32_t proxyId, const AABB& fat);
    /// After SetFatBoxForRebuild: the tree awaits Rebuild.
    void NoteGrown() { m_grown = true; }
    /// The rule for the boxes made from now on; boxes already made are kept until their shape
    /// leaves them (or they are far too large for the new rule).
    void SetFatBoxRule(FatBoxRule rule) { m_rule = rule; }
    const FatBoxRule& GetFatBoxRule() const { return m_rule; }
    /// How MoveProxy updates the tree from now on (TreeUpdate). Boxes grown under the old
    /// update are built first, so that a re-insertion's rotations never meet one.
    void SetTreeUpdate(TreeUpdate update)
    {
        Rebuild();
        m_update = update;
    }
    /// TreeUpdate::EnlargeAndRebuild: builds again the part of the tree whose boxes grew since
    /// the last call (every internal node above a moved leaf), keeping the untouched subtrees
    /// whole; does nothing when no box grew. Node ids of leaves (proxy ids) are kept. With
    /// `tasks`, the subtrees below the top splits are built on its threads; the tree, node ids
    /// included, is the same for any thread count.
    void Rebuild(TaskSystem* tasks = nullptr)
    {
        if (m_grown)
        {
            RebuildGrown(tasks);
        }
    }

    std::int32_t GetUserData(std::int32_t proxyId) const { return m_links[proxyId].userData; }
    const AABB& GetFatAABB(std::int32_t proxyId) const { return m_nodes[proxyId].aabb; }
    bool WasMoved(std::int32_t proxyId) const { return m_nodes[proxyId].moved; }
    ProxyLayers GetLayers(std::int32_t proxyId) const
    {
        const Node& node = m_nodes[proxyId];
        return {node.categoryBits, node.maskBits, node.bitsDecide};
    }
    void ClearMoved(std::int32_t proxyId) { m_nodes[proxyId].moved = false; }

    /// Calls callback(proxyId) -> bool for every leaf whose fat box overlaps `aabb`, until it
    /// returns false. Traversal order is Box2D's (stack, child1 pushed before child2).
    template <typename Callback>
    void Query(const AABB& aabb, Callback&& callback) const
    {
        Walk(aabb, nullptr, callback);
    }
    /// Query for the leaves whose layers meet `layers` (LayersMeet): the others are never
    /// reported, and subtrees with none are not entered. The order of the reported leaves is
    /// Query's.
    template <typename Callback>
    void Query(const AABB& aabb, ProxyLayers layers, Callback&& callback) const
    {
        Walk(aabb, &layers, callback);
    }

    /// Calls callback(subInput, proxyId) -> Real for every leaf whose fat box the ray
    /// input.p1 → input.p2 (up to input.maxFraction) may cross, pruning as Box2D 2.4.1's
    /// b2DynamicTree::RayCast (the segment's box, then the segment's separating axis). The
    /// callback's return value: 0 ends the cast; > 0 clips the ray to that fraction (subInput
    /// carries the current clip); < 0 leaves the clip alone. The ray must have length > 0.
    template <typename Callback>
    void RayCast(const RayCastInput& input, Callback&& callback) const;

    /// RayCast for a moving box: the ray is the path of the box's centre and every fat box is
    /// grown by `halfExtents` (their Minkowski sum), so the leaves reported are those the
    /// moving box may touch. With zero halfExtents it is RayCast, rounding included.
    template <typename Callback>
    void BoxCast(const RayCastInput& input, Vec2 halfExtents, Callback&& callback) const;

    int GetHeight() const;
    /// Internal nodes whose boxes grew in place and await Rebuild; for tests.
    int CountEnlarged() const;
    /// Checks parent links, heights, boxes and layer unions of the whole tree; for tests.
    bool Validate() const;

    /// The part of a node that a walk (Query, RayCast, BoxCast) reads: 32 bytes (64 with
    /// MEFF_DOUBLE), aligned so that one never straddles two cache lines. The rest is in
    /// NodeLinks, at the same index.
    struct alignas(32) Node
    {
        AABB aabb;
        std::int32_t child1 = kNullProxy;
        std::int32_t child2 = kNullProxy;
        /// A leaf's ProxyLayers bits; an internal node's, the union of its leaves'.
        std::uint16_t categoryBits = 0;
        std::uint16_t maskBits = 0;
        bool bitsDecide = true; ///< leaves: ProxyLayers::bitsDecide
        bool moved = false;
        /// Internal nodes: the box may be larger than its children's union, grown in place
        /// for a moved leaf below (TreeUpdate::EnlargeAndRebuild); Rebuild builds it again.
        bool enlarged = false;
        bool IsLeaf() const { return child1 == kNullProxy; }
    };
    // A whole number of nodes per cache line (two with float, one with double).
    static_assert(64 % sizeof(Node) == 0);
    /// The part of a node that only the tree's updates and the proxies' owners read.
    struct NodeLinks
    {
        std::int32_t userData = -1;
        std::int32_t parentOrNext = kNullProxy; ///< parent, or next free node
        std::int32_t height = -1;               ///< leaf 0, free -1
    };

  private:
    /// Query's walk; with `layers`, it skips the nodes whose layers do not meet them.
    template <typename Callback>
    void Walk(const AABB& aabb, const ProxyLayers* layers, Callback&& callback) const;
    /// Sets an internal node's layers to the union of its two children's.
    void UniteLayers(Node& node);
    /// Sets an internal node's box, height and layers from its two children's.
    void Refit(std::int32_t index);
    std::int32_t AllocateNode();
    void FreeNode(std::int32_t node);
    void InsertLeaf(std::int32_t leaf);
    void RemoveLeaf(std::int32_t leaf);
    std::int32_t Balance(std::int32_t index);
    /// Grows the leaf's ancestors to hold its box, marking them enlarged.
    void EnlargeAncestors(std::int32_t leaf);
    void RebuildGrown(TaskSystem* tasks);
    /// A Rebuild unit: a leaf or a kept subtree, with its box's centre.
    struct BuildUnit
    {
        std::int32_t node;
        Vec2 centre;
    };
    /// A range of units whose subtree one thread builds (BuildRange's arguments).
    struct BuildTask
    {
        int begin, end, depth, offset;
    };
    /// A split made before the threads build the subtrees below it: its node is linked after.
    struct BuildSplit
    {
        int begin, split, end, offset;
    };
    /// Orders m_units[begin, end) (at least two) into the two sides of its split; returns the
    /// index of the second side's first unit.
    int SplitRange(int begin, int end, int depth);
    /// Builds a subtree over m_units[begin, end) whose internal nodes are m_buildIds[offset,
    /// offset + end − begin − 1), in the order of the serial build's allocations (children's
    /// nodes first, child1's before child2's, the root last); returns its root.
    std::int32_t BuildRange(int begin, int end, int depth, int offset);
    /// The root BuildRange(begin, end, ·, offset) returns, known before it runs.
    std::int32_t RootOf(int begin, int end, int offset) const
    {
        return end - begin == 1 ? m_units[static_cast<std::size_t>(begin)].node
                                : m_buildIds[static_cast<std::size_t>(offset + end - begin - 2)];
    }
    /// Makes node `index` the parent of child1 and child2 (box, height, layers, links).
    void LinkNode(std::int32_t index, std::int32_t child1, std::int32_t child2);
    /// Splits the top `levels` levels of m_units[begin, end) on this thread, listing the splits
    /// in m_buildSplits (parents first) and the ranges below them in m_buildTasks.
    void SplitTop(int begin, int end, int depth, int offset, int levels);

    /// The nodes, split in two arrays indexed alike (node id = proxy id): what the walks read,
    /// and the rest. Every change to the pool resizes both.
    std::vector<Node> m_nodes;
    std::vector<NodeLinks> m_links;
    std::int32_t m_root = kNullProxy;
    std::int32_t m_freeList = kNullProxy;
    std::int32_t m_nodeCount = 0;
    FatBoxRule m_rule;
    TreeUpdate m_update = TreeUpdate::Reinsert;
    bool m_grown = false;           ///< some box grew in place since the last Rebuild
    std::vector<BuildUnit> m_units; ///< Rebuild's scratch, kept for its capacity
    std::vector<std::int32_t> m_unitStack;
    std::vector<std::int32_t> m_buildIds; ///< the marked nodes, in the serial build's order
    std::vector<BuildSplit> m_buildSplits;
    std::vector<BuildTask> m_buildTasks;
};

/// The explicit stack of one walk of a tree (Query, RayCast, BoxCast), local to the walk so that
/// a callback may start another and the compiler can keep it out of memory it must reload: 256
/// node ids in place — an AVL-balanced tree needs its height plus one, under 60 for any tree
/// that fits in memory; a rebuilt one (TreeUpdate::EnlargeAndRebuild), whose kept subtrees add
/// their heights, may need more — and the heap beyond, last in first out across both.
class TreeWalkStack
{
  public:
    bool Empty() const { return m_count == 0 && m_spill.empty(); }
    void Push(std::int32_t id)
    {
        if (m_count < kInPlace) [[likely]]
        {
            m_inPlace[m_count++] = id;
            return;
        }
        m_spill.push_back(id);
    }
    std::int32_t Pop()
    {
        if (!m_spill.empty()) [[unlikely]]
        {
            const std::int32_t id = m_spill.back();
            m_spill.pop_back();
            return id;
        }
        return m_inPlace[--m_count];
    }

  private:
    static constexpr int kInPlace = 256;
    std::int32_t m_inPlace[kInPlace];
    int m_count = 0;
    std::vector<std::int32_t> m_spill;
};

class BroadPhase
{
  public:
    explicit BroadPhase(FatBoxRule rule) : m_tree(rule) {}
    /// Box2D 2.4.1's rule with this margin.
    explicit BroadPhase(Real aabbMargin) : m_tree(FatBoxRule{aabbMargin}) {}

    std::int32_t CreateProxy(const AABB& aabb, std::int32_t userData, ProxyLayers layers = {});
    void DestroyProxy(std::int32_t proxyId);
    void MoveProxy(std::int32_t proxyId, const AABB& aabb, Vec2 displacement);
    /// MoveProxy in two halves (DynamicTree::NeedsNewBox, SetFatBox): the test, which may run
    /// on several threads at once while nothing changes the tree, then the move.
    bool NeedsNewBox(std::int32_t proxyId, const AABB& aabb, Vec2 displacement, AABB& fat) const
    {
        return m_tree.NeedsNewBox(proxyId, aabb, displacement, fat);
    }
    void SetFatBox(std::int32_t proxyId, const AABB& fat)
    {
        m_tree.SetFatBox(proxyId, fat);
        BufferMove(proxyId);
    }
    /// SetFatBox in two halves for TreeUpdate::EnlargeAndRebuild: the tree's
    /// (DynamicTree::SetFatBoxForRebuild), on several threads at once for distinct proxies, then
    /// the move buffer's (BufferRebuiltMove), on one thread, in the order of the moves.
    void SetFatBoxForRebuild(std::int32_t proxyId, const AABB& fat)
    {
        m_tree.SetFatBoxForRebuild(proxyId, fat);
    }
    /// SetFatBoxForRebuild's second half.
    void BufferRebuiltMove(std::int32_t proxyId)
    {
        m_tree.NoteGrown();
        BufferMove(proxyId);
    }
    void SetFatBoxRule(FatBoxRule rule) { m_tree.SetFatBoxRule(rule); }
    const FatBoxRule& GetFatBoxRule() const { return m_tree.GetFatBoxRule(); }
    void SetTreeUpdate(TreeUpdate update) { m_tree.SetTreeUpdate(update); }
    /// DynamicTree::Rebuild; before the pairs are looked for, so the queries walk a built tree.
    void RebuildTree(TaskSystem* tasks = nullptr) { m_tree.Rebuild(tasks); }
    /// Makes the proxy report its pairs again at the next UpdatePairs.
    void TouchProxy(std::int32_t proxyId);

    const AABB& GetFatAABB(std::int32_t proxyId) const { return m_tree.GetFatAABB(proxyId); }
    std::int32_t GetUserData(std::int32_t proxyId) const { return m_tree.GetUserData(proxyId); }
    bool TestOverlap(std::int32_t proxyIdA, std::int32_t proxyIdB) const;
    int GetProxyCount() const { return m_proxyCount; }
    const DynamicTree& GetTree() const { return m_tree; }

    /// Calls addPair(userDataA, userDataB) for each new overlapping pair involving a moved
    /// proxy, in Box2D 2.4.1's order (A has the smaller proxy id), then clears the move buffer.
    /// A pair whose layers do not meet is left out when the querying proxy lets the bits
    /// decide: then neither proxy is in the other's positive group, so the filter refuses the
    /// pair whatever else it is. The pairs the filter lets through, and their order, are
    /// Box2D's. Filters are fixed at shape creation; a filter setter would have to update the
    /// leaf's layers and refit its ancestors' unions.
    template <typename AddPair>
    void UpdatePairs(AddPair&& addPair);

    /// A pair of proxies found by a moved proxy's query, A the smaller id.
    struct Pair
    {
        std::int32_t proxyIdA;
        std::int32_t proxyIdB;
    };
    /// UpdatePairs in batches: how many move-buffer entries there are to query.
    int GetMoveCount() const { return static_cast<int>(m_moveBuffer.size()); }
    /// Appends to `pairs` the pairs that the queries of move-buffer entries [begin, end) find,
    /// in UpdatePairs' order, so that the ranges' pairs, put end to end in entry order, are
    /// UpdatePairs' pairs. Reads only the tree: ranges may be queried on several threads at
    /// once, as long as nothing changes it meanwhile.
    void FindPairs(int begin, int end, std::vector<Pair>& pairs) const;
    /// What UpdatePairs does after the pairs are added: the moved proxies are not moved any
    /// more and the move buffer is emptied.
    void ClearMoveBuffer();

    template <typename Callback>
    void Query(const AABB& aabb, Callback&& callback) const
    {
        m_tree.Query(aabb, callback);
    }
    template <typename Callback>
    void Query(const AABB& aabb, ProxyLayers layers, Callback&& callback) const
    {
        m_tree.Query(aabb, layers, callback);
    }
    template <typename Callback>
    void RayCast(const RayCastInput& input, Callback&& callback) const
    {
        m_tree.RayCast(input, callback);
    }
    template <typename Callback>
    void BoxCast(const RayCastInput& input, Vec2 halfExtents, Callback&& callback) const
    {
        m_tree.BoxCast(input, halfExtents, callback);
    }

  private:
    void BufferMove(std::int32_t proxyId);
    void UnBufferMove(std::int32_t proxyId);

    DynamicTree m_tree;
    int m_proxyCount = 0;
    std::vector<std::int32_t> m_moveBuffer;
    std::vector<Pair> m_pairBuffer;
};

} // namespace meff::detail

#include "collision/broad_phase_inl.h"
