// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// The broad phase's tree grown in place and built again (TreeUpdate::EnlargeAndRebuild), for the
// back ends that need not reproduce Box2D 2.4.1's tree.
//
// Re-inserting a moved leaf (Box2D 2.4.1) costs a removal, a descent by the perimeter heuristic
// and rotations on the way up, for each of the thousands of proxies that leave their fat boxes
// every step when a crowd moves (spinner, washer, the tumbler), and a tree grown leaf by leaf in
// the order bodies happen to move is looser than one built over all of them at once: queries
// visit more nodes. Here a moved leaf only grows its ancestors' boxes, and once per step, before
// the pairs are looked for, the grown part — every internal node above a moved leaf — is built
// again top down over its leaves and the untouched subtrees below it, splitting each set at the
// middle of its box centres' extent along the longer axis. Each split depends only on the set
// of units it splits (not on their order), so the tree, and with it the pairs' order, is the same
// for any standard library. With a task system the top splits are made on the calling thread and
// the subtrees below them built on the threads: every subtree's internal nodes are the freed
// nodes the serial build would give it (taken off the free list in its order before the build),
// so the tree, node ids included, is the same for any thread count.
#include "collision/broad_phase.h"

#include "tasks/parallel_ranges.h"

#include <algorithm>
#include <atomic>
#include <cmath>

namespace meff::detail
{

namespace
{

/// Splits deeper than this are made at the median instead of the middle of the extent: a
/// middle split of clustered centres can peel off one unit at a time, and the median bounds the
/// rest of the build's depth by log2 of the units.
constexpr int kMaxMiddleSplitDepth = 32;

/// The fewest units a thread is handed a subtree of: a unit costs a few dozen instructions per
/// level, so a subtree of fewer costs less than handing it to another thread.
constexpr int kMinUnitsPerBuildTask = 256;

/// Levels split on the calling thread before the threads take the subtrees below: enough for
/// two subtrees per thread, each level costing one pass over the units on this thread.
int TopLevels(const TaskSystem* tasks)
{
    int levels = 0;
    while ((1 << levels) < 2 * WorkerCount(tasks))
    {
        ++levels;
    }
    return levels;
}

} // namespace

void DynamicTree::EnlargeAncestors(std::int32_t leaf)
{
    const AABB box = m_nodes[leaf].aabb;
    std::int32_t index = m_links[leaf].parentOrNext;
    while (index != kNullProxy)
    {
        Node& node = m_nodes[index];
        if (node.enlarged && node.aabb.Contains(box))
        {
            // Marked by an earlier leaf this step: its ancestors are marked and hold its box.
            break;
        }
        node.aabb = Combine(node.aabb, box);
        node.enlarged = true;
        index = m_links[index].parentOrNext;
    }
    m_grown = true;
}

void DynamicTree::SetFatBoxForRebuild(std::int32_t proxyId, const AABB& fat)
{
    m_nodes[proxyId].aabb = fat;
    m_nodes[proxyId].moved = true;
    // A marked node's ancestors are all marked, or being marked by the thread that marked it
    // (EnlargeAncestors too marks up to the root or to a marked node), so the walk stops at one.
    for (std::int32_t index = m_links[proxyId].parentOrNext; index != kNullProxy;
         index = m_links[index].parentOrNext)
    {
        const std::atomic_ref<bool> enlarged(m_nodes[index].enlarged);
        if (enlarged.load(std::memory_order_relaxed))
        {
            break;
        }
        enlarged.store(true, std::memory_order_relaxed);
    }
}

void DynamicTree::RebuildGrown(TaskSystem* tasks)
{
    m_grown = false; // a box grew, so the tree has a leaf and a root

    // The units: leaves and internal nodes not marked (their subtrees are kept whole), found
    // from the root through the marked nodes, which the build reuses. The marked nodes form a
    // binary tree whose leaves are the units, so the build needs exactly the nodes marked: a
    // build that freed them in this walk's order and allocated its nodes afresh would take them
    // back off the free list last freed first, and leave the free list as it was. So they are
    // used in that order, without the free list: the tree, node ids included, is the same, and
    // the pool never grows (no Node reference is invalidated below).
    m_units.clear();
    m_unitStack.clear();
    m_buildIds.clear();
    m_unitStack.push_back(m_root);
    while (!m_unitStack.empty())
    {
        const std::int32_t index = m_unitStack.back();
        m_unitStack.pop_back();
        Node& node = m_nodes[index];
        if (node.IsLeaf() || !node.enlarged)
        {
            m_units.push_back({index, node.aabb.GetCenter()});
            continue;
        }
        m_unitStack.push_back(node.child2);
        m_unitStack.push_back(node.child1);
        node.enlarged = false;
        m_buildIds.push_back(index);
    }
    std::reverse(m_buildIds.begin(), m_buildIds.end());
    // Rebuild's stages. Read: m_units (the units and their boxes). Written: the marked nodes
    // (LinkNode sets all that AllocateNode would have reset, but for the fields an internal node
    // keeps as AllocateNode made it: no user data, not moved), the units' parent links, m_root.
    // Each subtree's nodes are known before it is built (BuildRange), wherever it is built.
    const int count = static_cast<int>(m_units.size());
    if (tasks == nullptr || WorkerCount(tasks) < 2 || count < 2 * kMinUnitsPerBuildTask)
    {
        m_root = BuildRange(0, count, 0, 0);
    }
    else
    {
        m_buildSplits.clear();
        m_buildTasks.clear();
        SplitTop(0, count, 0, 0, TopLevels(tasks));
        // Each task writes its own units' range, its own nodes and its units' parent links.
        ForEachIndex(tasks, static_cast<int>(m_buildTasks.size()), 1,
                     [this](int i)
                     {
                         const BuildTask& task = m_buildTasks[static_cast<std::size_t>(i)];
                         BuildRange(task.begin, task.end, task.depth, task.offset);
                     });
        // The top splits' nodes, children before parents (the list holds parents first).
        for (auto top = m_buildSplits.rbegin(); top != m_buildSplits.rend(); ++top)
        {
            LinkNode(RootOf(top->begin, top->end, top->offset),
                     RootOf(top->begin, top->split, top->offset),
                     RootOf(top->split, top->end, top->offset + top->split - top->begin - 1));
        }
        m_root = RootOf(0, count, 0);
    }
    m_links[m_root].parentOrNext = kNullProxy;
}

void DynamicTree::SplitTop(int begin, int end, int depth, int offset, int levels)
{
    if (levels == 0 || end - begin < 2 * kMinUnitsPerBuildTask)
    {
        m_buildTasks.push_back({begin, end, depth, offset});
        return;
    }
    const int split = SplitRange(begin, end, depth);
    m_buildSplits.push_back({begin, split, end, offset});
    SplitTop(begin, split, depth + 1, offset, levels - 1);
    SplitTop(split, end, depth + 1, offset + split - begin - 1, levels - 1);
}

int DynamicTree::CountEnlarged() const
{
    int count = 0;
    for (std::size_t i = 0; i < m_nodes.size(); ++i)
    {
        count += m_links[i].height > 0 && m_nodes[i].enlarged ? 1 : 0;
    }
    return count;
}

int DynamicTree::SplitRange(int begin, int end, int depth)
{
    const auto first = m_units.begin() + begin;
    const auto last = m_units.begin() + end;
    Vec2 lower = first->centre;
    Vec2 upper = first->centre;
    for (auto unit = first + 1; unit != last; ++unit)
    {
        lower = Min(lower, unit->centre);
        upper = Max(upper, unit->centre);
    }
    const Vec2 extent = upper - lower;
    const bool alongX = extent.x >= extent.y;
    const auto key = [alongX](const BuildUnit& unit)
    { return alongX ? unit.centre.x : unit.centre.y; };

    auto middle = last;
    if (depth < kMaxMiddleSplitDepth)
    {
        const Real split = Real(0.5) * (alongX ? lower.x + upper.x : lower.y + upper.y);
        middle = std::partition(first, last,
                                [&key, split](const BuildUnit& unit) { return key(unit) < split; });
    }
    if (middle == first || middle == last)
    {
        // Centres all alike along the axis (or too deep): half the units on each side. Ties
        // are broken by node id, so that each side is the same set of units whatever the
        // standard library's nth_element does with equal keys, and so is the tree. A box that
        // overflowed to infinity on both sides has a NaN centre: NaN sorts last, so the order
        // stays strict and weak (nth_element's precondition) whatever the boxes.
        middle = first + (end - begin) / 2;
        const auto before = [](Real x, Real y)
        { return x < y || (std::isnan(y) && !std::isnan(x)); };
        std::nth_element(first, middle, last,
                         [&key, &before](const BuildUnit& a, const BuildUnit& b) {
                             return before(key(a), key(b)) ||
                                    (!before(key(b), key(a)) && a.node < b.node);
                         });
    }

    return static_cast<int>(middle - m_units.begin());
}

std::int32_t DynamicTree::BuildRange(int begin, int end, int depth, int offset)
{
    if (end - begin == 1)
    {
        return m_units[static_cast<std::size_t>(begin)].node;
    }
    const int split = SplitRange(begin, end, depth);
    const std::int32_t child1 = BuildRange(begin, split, depth + 1, offset);
    const std::int32_t child2 = BuildRange(split, end, depth + 1, offset + split - begin - 1);
    const std::int32_t index = RootOf(begin, end, offset);
    LinkNode(index, child1, child2);
    return index;
}

void DynamicTree::LinkNode(std::int32_t index, std::int32_t child1, std::int32_t child2)
{
    m_nodes[index].child1 = child1;
    m_nodes[index].child2 = child2;
    Refit(index);
    m_links[child1].parentOrNext = index;
    m_links[child2].parentOrNext = index;
}

} // namespace meff::detail
