// Template definitions for broad_phase.h (included at its end).
#pragma once

#include "collision/broad_phase.h"

#include <algorithm>

namespace meff::detail
{

template <typename Callback>
void DynamicTree::Query(const AABB& aabb, Callback&& callback) const
{
    // Depth-first with an explicit stack, visiting child2 before child1 (child1 is pushed
    // first), as Box2D does. The stack is shared by nested queries (a callback may query this
    // tree again): each query only works above the depth it started at, and the guard trims
    // the stack back to that depth however the query ends.
    struct StackGuard
    {
        std::vector<std::int32_t>& stack;
        std::size_t base;
        ~StackGuard() { stack.resize(base); }
    };
    const StackGuard guard{m_stack, m_stack.size()};

    m_stack.push_back(m_root);
    while (m_stack.size() > guard.base)
    {
        const std::int32_t nodeId = m_stack.back();
        m_stack.pop_back();
        if (nodeId == kNullProxy)
        {
            continue;
        }

        const Node& node = m_nodes[nodeId];
        if (!TestOverlap(node.aabb, aabb))
        {
            continue;
        }
        if (node.IsLeaf())
        {
            if (!callback(nodeId))
            {
                return;
            }
        }
        else
        {
            m_stack.push_back(node.child1);
            m_stack.push_back(node.child2);
        }
    }
}

template <typename AddPair>
void BroadPhase::UpdatePairs(AddPair&& addPair)
{
    m_pairBuffer.clear();

    // Query the tree with the fat box of every proxy that moved, so that pairs that may touch
    // soon are not missed. When both proxies of a pair moved, only the query of the one with
    // the larger id records it; the pair is stored as (smaller id, larger id), in discovery
    // order (Box2D 2.4.1 neither sorts nor deduplicates this buffer).
    for (std::size_t i = 0; i < m_moveBuffer.size(); ++i)
    {
        const std::int32_t queryId = m_moveBuffer[i];
        if (queryId == kNullProxy)
        {
            continue;
        }

        const AABB fatBox = m_tree.GetFatAABB(queryId);
        m_tree.Query(
            fatBox,
            [this, queryId](std::int32_t proxyId)
            {
                if (proxyId == queryId)
                {
                    return true;
                }
                if (proxyId > queryId && m_tree.WasMoved(proxyId))
                {
                    return true;
                }
                m_pairBuffer.push_back({std::min(proxyId, queryId), std::max(proxyId, queryId)});
                return true;
            });
    }

    for (std::size_t i = 0; i < m_pairBuffer.size(); ++i)
    {
        const Pair pair = m_pairBuffer[i];
        addPair(m_tree.GetUserData(pair.proxyIdA), m_tree.GetUserData(pair.proxyIdB));
    }

    for (const std::int32_t proxyId : m_moveBuffer)
    {
        if (proxyId != kNullProxy)
        {
            m_tree.ClearMoved(proxyId);
        }
    }
    m_moveBuffer.clear();
}

} // namespace meff::detail
