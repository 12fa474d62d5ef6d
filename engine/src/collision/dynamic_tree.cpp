// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// The dynamic AABB tree of the broad phase.
//
// Node ids are what the rest of the engine calls proxy ids, and they decide the order in which
// contacts are created, so every step that hands out or recycles a node, and every step that
// reshapes the tree, reproduces Box2D 2.4.1's b2DynamicTree:
//  - the pool starts with 16 nodes and doubles; the fresh nodes are chained in increasing
//    order and a freed node goes to the head of the free list;
//  - a leaf is inserted next to the sibling chosen by the perimeter (surface area) heuristic,
//    then every ancestor is rebalanced by at most one rotation on the way back up;
//  - removing a leaf frees its parent before the ancestors are rebalanced.
// Floating-point expressions keep Box2D's operation order so that fat boxes and costs round
// identically. That is the tree of TreeUpdate::Reinsert (Box2D's back end); the other back ends
// grow it in place and build it again instead (tree_rebuild.cpp).
#include "collision/broad_phase.h"

#include <algorithm>

namespace meff::detail
{

namespace
{

constexpr std::int32_t kInitialNodeCapacity = 16;

} // namespace

DynamicTree::DynamicTree(FatBoxRule rule) : m_rule(rule)
{
    m_nodes.resize(kInitialNodeCapacity);
    m_links.resize(kInitialNodeCapacity);
    for (std::int32_t i = 0; i < kInitialNodeCapacity; ++i)
    {
        m_links[i].parentOrNext = i + 1 < kInitialNodeCapacity ? i + 1 : kNullProxy;
        m_links[i].height = -1;
    }
    m_freeList = 0;
}

std::int32_t DynamicTree::AllocateNode()
{
    if (m_freeList == kNullProxy)
    {
        // Every slot is in use: double the pool and chain the new slots in increasing order,
        // exactly as Box2D does, so that later ids match.
        const auto oldCapacity = static_cast<std::int32_t>(m_nodes.size());
        const std::int32_t newCapacity = 2 * oldCapacity;
        m_nodes.resize(static_cast<std::size_t>(newCapacity));
        m_links.resize(static_cast<std::size_t>(newCapacity));
        for (std::int32_t i = oldCapacity; i < newCapacity; ++i)
        {
            m_links[i].parentOrNext = i + 1 < newCapacity ? i + 1 : kNullProxy;
            m_links[i].height = -1;
        }
        m_freeList = oldCapacity;
    }

    const std::int32_t id = m_freeList;
    Node& node = m_nodes[id];
    NodeLinks& links = m_links[id];
    m_freeList = links.parentOrNext;
    links.parentOrNext = kNullProxy;
    node.child1 = kNullProxy;
    node.child2 = kNullProxy;
    links.height = 0;
    links.userData = -1;
    node.categoryBits = 0;
    node.maskBits = 0;
    node.bitsDecide = true;
    node.moved = false;
    node.enlarged = false;
    ++m_nodeCount;
    return id;
}

void DynamicTree::FreeNode(std::int32_t id)
{
    NodeLinks& links = m_links[id];
    links.parentOrNext = m_freeList;
    links.height = -1;
    m_freeList = id;
    --m_nodeCount;
}

std::int32_t DynamicTree::CreateProxy(const AABB& aabb, std::int32_t userData, ProxyLayers layers)
{
    // Insertion rotates subtrees, which would leave a grown box under one that is not marked,
    // where Rebuild would never reach it: the grown part is built first. Boxes grow only in
    // MoveProxy: in a step (each time followed by the pairs' search, which rebuilds) and in
    // SetTransform.
    Rebuild();
    const std::int32_t proxyId = AllocateNode();

    Node& node = m_nodes[proxyId];
    const Vec2 r(m_rule.margin, m_rule.margin);
    node.aabb.lowerBound = aabb.lowerBound - r;
    node.aabb.upperBound = aabb.upperBound + r;
    m_links[proxyId].userData = userData;
    m_links[proxyId].height = 0;
    node.categoryBits = layers.categoryBits;
    node.maskBits = layers.maskBits;
    node.bitsDecide = layers.bitsDecide;
    node.moved = true;

    InsertLeaf(proxyId);
    return proxyId;
}

void DynamicTree::DestroyProxy(std::int32_t proxyId)
{
    Rebuild(); // as in CreateProxy: removal rotates subtrees too
    RemoveLeaf(proxyId);
    FreeNode(proxyId);
}

bool DynamicTree::MoveProxy(std::int32_t proxyId, const AABB& aabb, Vec2 displacement)
{
    AABB fat;
    if (!NeedsNewBox(proxyId, aabb, displacement, fat))
    {
        return false;
    }
    SetFatBox(proxyId, fat);
    return true;
}

bool DynamicTree::NeedsNewBox(std::int32_t proxyId, const AABB& aabb, Vec2 displacement,
                              AABB& fat) const
{
    // The candidate fat box: the margin all round, then stretched along the predicted motion
    // (only on the side the shape is heading to).
    const Vec2 r(m_rule.margin, m_rule.margin);
    fat.lowerBound = aabb.lowerBound - r;
    fat.upperBound = aabb.upperBound + r;

    const Vec2 d = m_rule.displacementMultiplier * displacement;
    if (d.x < Real(0))
    {
        fat.lowerBound.x += d.x;
    }
    else
    {
        fat.upperBound.x += d.x;
    }
    if (d.y < Real(0))
    {
        fat.lowerBound.y += d.y;
    }
    else
    {
        fat.upperBound.y += d.y;
    }

    const AABB& current = m_nodes[proxyId].aabb;
    if (current.Contains(aabb))
    {
        // The shape is still inside its box. Keep the box unless it is oversized, i.e. it sticks
        // out of the candidate grown by four more margins (a fast body that came to rest).
        const Vec2 slack = Real(4) * r;
        AABB huge;
        huge.lowerBound = fat.lowerBound - slack;
        huge.upperBound = fat.upperBound + slack;
        if (huge.Contains(current))
        {
            return false;
        }
    }
    return true;
}

void DynamicTree::SetFatBox(std::int32_t proxyId, const AABB& fat)
{
    if (m_update == TreeUpdate::EnlargeAndRebuild)
    {
        m_nodes[proxyId].aabb = fat;
        EnlargeAncestors(proxyId);
    }
    else
    {
        RemoveLeaf(proxyId);
        m_nodes[proxyId].aabb = fat;
        InsertLeaf(proxyId);
    }
    m_nodes[proxyId].moved = true;
}

void DynamicTree::InsertLeaf(std::int32_t leaf)
{
    if (m_root == kNullProxy)
    {
        m_root = leaf;
        m_links[leaf].parentOrNext = kNullProxy;
        return;
    }

    // Walk down from the root towards the cheapest sibling. Creating a parent here costs twice
    // the combined perimeter; going down costs the growth of this node (paid by every ancestor
    // of the eventual parent) plus the child's own growth, or its full combined perimeter when
    // the child is a leaf.
    const AABB leafBox = m_nodes[leaf].aabb;
    std::int32_t index = m_root;
    while (!m_nodes[index].IsLeaf())
    {
        const Node& node = m_nodes[index];
        const std::int32_t child1 = node.child1;
        const std::int32_t child2 = node.child2;

        const Real perimeter = node.aabb.GetPerimeter();
        const Real combinedPerimeter = Combine(node.aabb, leafBox).GetPerimeter();

        const Real cost = Real(2) * combinedPerimeter;
        const Real inheritedCost = Real(2) * (combinedPerimeter - perimeter);

        auto descentCost = [&](std::int32_t child)
        {
            const Node& c = m_nodes[child];
            const Real grown = Combine(leafBox, c.aabb).GetPerimeter();
            if (c.IsLeaf())
            {
                return grown + inheritedCost;
            }
            return (grown - c.aabb.GetPerimeter()) + inheritedCost;
        };
        const Real cost1 = descentCost(child1);
        const Real cost2 = descentCost(child2);

        if (cost < cost1 && cost < cost2)
        {
            break;
        }
        // Ties go to child2.
        index = cost1 < cost2 ? child1 : child2;
    }

    const std::int32_t sibling = index;
    const std::int32_t oldParent = m_links[sibling].parentOrNext;
    // May grow the pool: no Node references are held across this call.
    const std::int32_t newParent = AllocateNode();
    {
        Node& parent = m_nodes[newParent];
        m_links[newParent].parentOrNext = oldParent;
        m_links[newParent].userData = -1;
        parent.aabb = Combine(leafBox, m_nodes[sibling].aabb);
        m_links[newParent].height = m_links[sibling].height + 1;
        parent.child1 = sibling;
        parent.child2 = leaf;
        UniteLayers(parent);
    }
    m_links[sibling].parentOrNext = newParent;
    m_links[leaf].parentOrNext = newParent;

    if (oldParent != kNullProxy)
    {
        Node& grand = m_nodes[oldParent];
        if (grand.child1 == sibling)
        {
            grand.child1 = newParent;
        }
        else
        {
            grand.child2 = newParent;
        }
    }
    else
    {
        m_root = newParent;
    }

    // Back up to the root: rebalance, then refresh height and box.
    index = m_links[leaf].parentOrNext;
    while (index != kNullProxy)
    {
        index = Balance(index);
        Refit(index);
        index = m_links[index].parentOrNext;
    }
}

void DynamicTree::RemoveLeaf(std::int32_t leaf)
{
    if (leaf == m_root)
    {
        m_root = kNullProxy;
        return;
    }

    const std::int32_t parent = m_links[leaf].parentOrNext;
    const std::int32_t grand = m_links[parent].parentOrNext;
    const std::int32_t sibling =
        m_nodes[parent].child1 == leaf ? m_nodes[parent].child2 : m_nodes[parent].child1;

    if (grand == kNullProxy)
    {
        m_root = sibling;
        m_links[sibling].parentOrNext = kNullProxy;
        FreeNode(parent);
        return;
    }

    // The sibling takes the parent's place, and the parent is freed before the walk up (this
    // fixes which id the next allocation gets).
    if (m_nodes[grand].child1 == parent)
    {
        m_nodes[grand].child1 = sibling;
    }
    else
    {
        m_nodes[grand].child2 = sibling;
    }
    m_links[sibling].parentOrNext = grand;
    FreeNode(parent);

    std::int32_t index = grand;
    while (index != kNullProxy)
    {
        index = Balance(index);
        Refit(index);
        index = m_links[index].parentOrNext;
    }
}

// When one child of `iA` is more than one level taller than the other, lifts that taller child
// (C) into A's place: A keeps its shorter child, C keeps the taller of its own two children and
// hands the shorter one to A. Returns the index now at the top of this subtree.
std::int32_t DynamicTree::Balance(std::int32_t iA)
{
    Node& a = m_nodes[iA];
    NodeLinks& aLinks = m_links[iA];
    if (a.IsLeaf() || aLinks.height < 2)
    {
        return iA;
    }

    const std::int32_t iB = a.child1;
    const std::int32_t iC = a.child2;
    const std::int32_t balance = m_links[iC].height - m_links[iB].height;

    // Lifts `iUp` (a child of A) above A. `upIsChild2` tells which slot of A it occupied; the
    // child of `up` left behind replaces it in that same slot.
    auto rotate = [&](std::int32_t iUp, std::int32_t iStay, bool upIsChild2)
    {
        Node& up = m_nodes[iUp];
        NodeLinks& upLinks = m_links[iUp];
        const std::int32_t iF = up.child1;
        const std::int32_t iG = up.child2;

        up.child1 = iA;
        upLinks.parentOrNext = aLinks.parentOrNext;
        aLinks.parentOrNext = iUp;

        if (upLinks.parentOrNext != kNullProxy)
        {
            Node& above = m_nodes[upLinks.parentOrNext];
            if (above.child1 == iA)
            {
                above.child1 = iUp;
            }
            else
            {
                above.child2 = iUp;
            }
        }
        else
        {
            m_root = iUp;
        }

        // The taller grandchild stays under `up`; ties keep G (up's child2).
        const bool keepF = m_links[iF].height > m_links[iG].height;
        const std::int32_t iKeep = keepF ? iF : iG;
        const std::int32_t iGive = keepF ? iG : iF;
        const Node& keep = m_nodes[iKeep];
        const Node& give = m_nodes[iGive];
        const Node& stay = m_nodes[iStay];

        up.child2 = iKeep;
        if (upIsChild2)
        {
            a.child2 = iGive;
        }
        else
        {
            a.child1 = iGive;
        }
        m_links[iGive].parentOrNext = iA;
        a.aabb = Combine(stay.aabb, give.aabb);
        up.aabb = Combine(a.aabb, keep.aabb);

        aLinks.height = 1 + std::max(m_links[iStay].height, m_links[iGive].height);
        upLinks.height = 1 + std::max(aLinks.height, m_links[iKeep].height);
        UniteLayers(a); // `up`'s are set by the caller's walk up, which refits it next
    };

    if (balance > 1)
    {
        rotate(iC, iB, true);
        return iC;
    }
    if (balance < -1)
    {
        rotate(iB, iC, false);
        return iB;
    }
    return iA;
}

void DynamicTree::UniteLayers(Node& node)
{
    const Node& c1 = m_nodes[node.child1];
    const Node& c2 = m_nodes[node.child2];
    node.categoryBits = c1.categoryBits | c2.categoryBits;
    node.maskBits = c1.maskBits | c2.maskBits;
}

void DynamicTree::Refit(std::int32_t index)
{
    Node& node = m_nodes[index];
    node.aabb = Combine(m_nodes[node.child1].aabb, m_nodes[node.child2].aabb);
    m_links[index].height = 1 + std::max(m_links[node.child1].height, m_links[node.child2].height);
    UniteLayers(node);
}

int DynamicTree::GetHeight() const
{
    if (m_root == kNullProxy)
    {
        return 0;
    }
    return m_links[m_root].height;
}

bool DynamicTree::Validate() const
{
    const auto capacity = static_cast<std::int32_t>(m_nodes.size());
    auto inRange = [capacity](std::int32_t i) { return 0 <= i && i < capacity; };

    // The free list: in range, marked free, no cycle.
    std::int32_t freeCount = 0;
    if (m_links.size() != m_nodes.size())
    {
        return false;
    }
    for (std::int32_t i = m_freeList; i != kNullProxy; i = m_links[i].parentOrNext)
    {
        if (!inRange(i) || m_links[i].height != -1 || freeCount > capacity)
        {
            return false;
        }
        ++freeCount;
    }
    if (m_nodeCount + freeCount != capacity)
    {
        return false;
    }

    if (m_root == kNullProxy)
    {
        return m_nodeCount == 0;
    }
    if (!inRange(m_root) || m_links[m_root].parentOrNext != kNullProxy)
    {
        return false;
    }

    // Every reachable node: links both ways, height and box consistent with the children.
    std::int32_t reached = 0;
    std::vector<std::int32_t> pending{m_root};
    while (!pending.empty())
    {
        const std::int32_t i = pending.back();
        pending.pop_back();
        ++reached;
        if (reached > m_nodeCount)
        {
            return false;
        }
        const Node& node = m_nodes[i];
        const NodeLinks& links = m_links[i];
        // Marks (TreeUpdate::EnlargeAndRebuild): only internal nodes, only while a box has
        // grown since the last Rebuild, and a marked node's parent is marked too (the root
        // aside), so that Rebuild's walk down the marked nodes reaches every one.
        if (node.enlarged &&
            (node.IsLeaf() || !m_grown ||
             (links.parentOrNext != kNullProxy && !m_nodes[links.parentOrNext].enlarged)))
        {
            return false;
        }
        if (node.IsLeaf())
        {
            if (node.child2 != kNullProxy || links.height != 0)
            {
                return false;
            }
            continue;
        }
        for (const std::int32_t child : {node.child1, node.child2})
        {
            if (!inRange(child) || m_links[child].parentOrNext != i || m_links[child].height < 0)
            {
                return false;
            }
            pending.push_back(child);
        }
        const Node& c1 = m_nodes[node.child1];
        const Node& c2 = m_nodes[node.child2];
        if (links.height != 1 + std::max(m_links[node.child1].height, m_links[node.child2].height))
        {
            return false;
        }
        // A box grown in place (TreeUpdate::EnlargeAndRebuild) need only hold its children's.
        const AABB box = Combine(c1.aabb, c2.aabb);
        const bool exact =
            box.lowerBound == node.aabb.lowerBound && box.upperBound == node.aabb.upperBound;
        if (!exact && !(node.enlarged && node.aabb.Contains(box)))
        {
            return false;
        }
        if (node.categoryBits != (c1.categoryBits | c2.categoryBits) ||
            node.maskBits != (c1.maskBits | c2.maskBits))
        {
            return false;
        }
    }
    return reached == m_nodeCount;
}

} // namespace meff::detail
