// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Template definitions for broad_phase.h (included at its end).
#pragma once

#include "collision/broad_phase.h"

#include <algorithm>
#include <cmath>

namespace meff::detail
{

template <typename Callback>
void DynamicTree::Walk(const AABB& aabb, const ProxyLayers* layers, Callback&& callback) const
{
    // Depth-first with an explicit stack, visiting child2 before child1 (child1 is pushed
    // first), as Box2D does. The box is copied: the callback may change what `aabb` names.
    // A node is tested before it is pushed rather than after it is popped: the same nodes are
    // visited in the same order (the tree does not change during the walk), but the ones that
    // fail cost no trip through the stack, and the two children, side by side in one cache line
    // or two, are read together.
    const AABB box = aabb;
    const auto enters = [this, &box, layers](std::int32_t nodeId)
    {
        const Node& node = m_nodes[nodeId];
        return TestOverlap(node.aabb, box) &&
               (layers == nullptr || LayersMeet(node.categoryBits, node.maskBits, *layers));
    };
    if (m_root == kNullProxy || !enters(m_root))
    {
        return;
    }
    TreeWalkStack stack;
    stack.Push(m_root);
    while (!stack.Empty())
    {
        const std::int32_t nodeId = stack.Pop();
        const Node& node = m_nodes[nodeId];
        if (node.IsLeaf())
        {
            if (!callback(nodeId))
            {
                return;
            }
            continue;
        }
        const std::int32_t child1 = node.child1;
        const std::int32_t child2 = node.child2;
        if (enters(child1))
        {
            stack.Push(child1);
        }
        if (enters(child2))
        {
            stack.Push(child2);
        }
    }
}

template <typename Callback>
void DynamicTree::RayCast(const RayCastInput& input, Callback&& callback) const
{
    BoxCast(input, Vec2(0, 0), callback);
}

template <typename Callback>
void DynamicTree::BoxCast(const RayCastInput& input, Vec2 halfExtents, Callback&& callback) const
{
    const Vec2 p1 = input.p1;
    const Vec2 p2 = input.p2;
    Vec2 r = p2 - p1;
    r.Normalize();

    // v is perpendicular to the ray. The segment p1 → t misses a box of centre c and
    // half-extents h when |v·(p1 − c)| > |v|·h: its line passes outside the box (van den
    // Bergen, Collision Detection in Interactive 3D Environments, p. 80). The other axes of
    // the test are the box of the segment, checked first.
    const Vec2 v = Cross(Real(1), r);
    const Vec2 absV = Abs(v);

    Real maxFraction = input.maxFraction;
    auto segmentBox = [&p1, &p2](Real fraction)
    {
        const Vec2 t = p1 + fraction * (p2 - p1);
        return AABB{Min(p1, t), Max(p1, t)};
    };
    AABB segmentAABB = segmentBox(maxFraction);

    // The same explicit stack and visiting order as Query (child2 first); see there.
    TreeWalkStack stack;
    stack.Push(m_root);
    while (!stack.Empty())
    {
        const std::int32_t nodeId = stack.Pop();
        if (nodeId == kNullProxy)
        {
            continue;
        }

        const Node& node = m_nodes[nodeId];
        // Minkowski sum with the moving box. With zero extents x − 0 and x + 0 equal x (only a
        // −0 upper bound turns +0, which no overlap test can tell), so a ray cast rounds as
        // Box2D's.
        const AABB box{node.aabb.lowerBound - halfExtents, node.aabb.upperBound + halfExtents};
        if (!TestOverlap(box, segmentAABB))
        {
            continue;
        }

        const Vec2 c = box.GetCenter();
        const Vec2 h = box.GetExtents();
        const Real separation = std::abs(Dot(v, p1 - c)) - Dot(absV, h);
        if (separation > Real(0))
        {
            continue;
        }

        if (node.IsLeaf())
        {
            const RayCastInput subInput{input.p1, input.p2, maxFraction};
            const Real value = callback(subInput, nodeId);
            if (value == Real(0))
            {
                return; // the caller has what it wants
            }
            if (value > Real(0))
            {
                maxFraction = value;
                segmentAABB = segmentBox(maxFraction);
            }
        }
        else
        {
            stack.Push(node.child1);
            stack.Push(node.child2);
        }
    }
}

template <typename AddPair>
void BroadPhase::UpdatePairs(AddPair&& addPair)
{
    m_pairBuffer.clear();
    m_tree.Rebuild(); // TreeUpdate::EnlargeAndRebuild: the queries walk a built tree

    // Query the tree with the fat box of every proxy that moved, so that pairs that may touch
    // soon are not missed (FindPairs: the same queries). When both proxies of a pair moved,
    // only the query of the one with the larger id records it; the pair is stored as (smaller
    // id, larger id), in discovery order (Box2D 2.4.1 neither sorts nor deduplicates this
    // buffer).
    FindPairs(0, static_cast<int>(m_moveBuffer.size()), m_pairBuffer);

    for (std::size_t i = 0; i < m_pairBuffer.size(); ++i)
    {
        const Pair pair = m_pairBuffer[i];
        addPair(m_tree.GetUserData(pair.proxyIdA), m_tree.GetUserData(pair.proxyIdB));
    }
    ClearMoveBuffer();
}

} // namespace meff::detail
