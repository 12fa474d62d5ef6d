// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// The broad phase: proxies in a dynamic tree, plus the buffer of proxies whose pairs must be
// looked for at the next UpdatePairs (Box2D 2.4.1's b2BroadPhase).
#include "collision/broad_phase.h"

#include <algorithm>

namespace meff::detail
{

std::int32_t BroadPhase::CreateProxy(const AABB& aabb, std::int32_t userData, ProxyLayers layers)
{
    const std::int32_t proxyId = m_tree.CreateProxy(aabb, userData, layers);
    ++m_proxyCount;
    BufferMove(proxyId);
    return proxyId;
}

void BroadPhase::DestroyProxy(std::int32_t proxyId)
{
    UnBufferMove(proxyId);
    --m_proxyCount;
    m_tree.DestroyProxy(proxyId);
}

void BroadPhase::MoveProxy(std::int32_t proxyId, const AABB& aabb, Vec2 displacement)
{
    if (m_tree.MoveProxy(proxyId, aabb, displacement))
    {
        BufferMove(proxyId);
    }
}

void BroadPhase::TouchProxy(std::int32_t proxyId)
{
    BufferMove(proxyId);
}

bool BroadPhase::TestOverlap(std::int32_t proxyIdA, std::int32_t proxyIdB) const
{
    return meff::TestOverlap(m_tree.GetFatAABB(proxyIdA), m_tree.GetFatAABB(proxyIdB));
}

void BroadPhase::FindPairs(int begin, int end, std::vector<Pair>& pairs) const
{
    // The queries UpdatePairs describes, over move buffer entries [begin, end): UpdatePairs
    // runs them over the whole buffer, the batched pair finding over batches of it.
    for (int i = begin; i < end; ++i)
    {
        const std::int32_t queryId = m_moveBuffer[static_cast<std::size_t>(i)];
        if (queryId == kNullProxy)
        {
            continue;
        }

        const AABB fatBox = m_tree.GetFatAABB(queryId);
        const auto record = [this, queryId, &pairs](std::int32_t proxyId)
        {
            if (proxyId == queryId)
            {
                return true;
            }
            if (proxyId > queryId && m_tree.WasMoved(proxyId))
            {
                return true;
            }
            pairs.push_back({std::min(proxyId, queryId), std::max(proxyId, queryId)});
            return true;
        };
        // Leaving out pairs whose layers do not meet drops only pairs the filter refuses, so
        // the rest keep their order (a net whose links do not collide with each other then
        // costs no walk through its own part of the tree).
        const ProxyLayers layers = m_tree.GetLayers(queryId);
        if (layers.bitsDecide)
        {
            m_tree.Query(fatBox, layers, record);
        }
        else
        {
            m_tree.Query(fatBox, record);
        }
    }
}

void BroadPhase::ClearMoveBuffer()
{
    for (const std::int32_t proxyId : m_moveBuffer)
    {
        if (proxyId != kNullProxy)
        {
            m_tree.ClearMoved(proxyId);
        }
    }
    m_moveBuffer.clear();
}

// A proxy may be buffered more than once (moved then touched): its queries then run twice and
// report the same pairs twice, as in Box2D. The contact manager filters existing contacts.
void BroadPhase::BufferMove(std::int32_t proxyId)
{
    m_moveBuffer.push_back(proxyId);
}

// Entries are blanked rather than erased so that the order of the others is kept.
void BroadPhase::UnBufferMove(std::int32_t proxyId)
{
    for (std::int32_t& id : m_moveBuffer)
    {
        if (id == proxyId)
        {
            id = kNullProxy;
        }
    }
}

} // namespace meff::detail
