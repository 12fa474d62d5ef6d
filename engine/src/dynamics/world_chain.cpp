// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Chains (Box2D 2.4.1's b2ChainShape): a chain is made of ChainSegment shapes, one per link,
// each with its neighbours as ghost vertices. Box2D keeps a chain as one fixture with one
// broad-phase proxy per child; here each child is a shape with one proxy. The proxies are
// created, moved and destroyed in the children's order, and the body's shape list holds them
// together in that order where Box2D holds the chain fixture, so the broad phase, and so the
// contacts and the solver, see exactly what Box2D's do.
#include "core/report_error.h"
#include "dynamics/step_stages.h"
#include "dynamics/world_state.h"
#include "meff/validity.h"
#include "meff/world.h"

#include <algorithm>
#include <string>
#include <vector>

namespace meff
{

using namespace detail;

namespace
{

/// Reports the refusal of a chain; no segments.
std::vector<ChainSegment> RefuseChain(const std::string& message)
{
    ReportError(InvalidArgument("World::CreateChain: " + message));
    return {};
}

/// The chain's segments with their ghosts, as b2ChainShape::CreateChain/CreateLoop and
/// GetChildEdge make them. Refuses (reported, no segments) what Box2D asserts (and a loop's
/// closing link, which Box2D does not check).
std::vector<ChainSegment> MakeSegments(const Chain& chain, Real linearSlop)
{
    const std::size_t minimum = chain.loop ? 3 : 2;
    if (chain.points.size() < minimum)
    {
        return RefuseChain(std::string(chain.loop ? "a loop" : "an open chain") +
                           " needs at least " + std::to_string(minimum) + " points, got " +
                           std::to_string(chain.points.size()));
    }
    if (chain.loop && (chain.prev || chain.next))
    {
        return RefuseChain(
            "a loop takes its ghost vertices from its own points: prev and next must be "
            "unset");
    }
    // The vertices along the chain; a loop comes back to its first point.
    std::vector<Vec2> v(chain.points.begin(), chain.points.end());
    if (chain.loop)
    {
        v.push_back(v.front());
    }
    for (std::size_t i = 0; i < v.size(); ++i)
    {
        if (!v[i].IsValid())
        {
            return RefuseChain("points[" + std::to_string(i) + "]: must be finite, got " +
                               NumberText(v[i]));
        }
        if (i > 0 && DistanceSquared(v[i - 1], v[i]) <= linearSlop * linearSlop)
        {
            return RefuseChain("points " + std::to_string(i - 1) + " and " +
                               std::to_string(i % chain.points.size()) +
                               " must be further apart than the linear slop, got " +
                               NumberText(v[i - 1]) + " and " + NumberText(v[i]));
        }
    }
    const std::size_t m = v.size();
    // An open chain without ghosts continues its end segments in straight lines.
    const Vec2 prev = chain.loop ? v[m - 2] : chain.prev.value_or(v[0] + (v[0] - v[1]));
    const Vec2 next = chain.loop ? v[1] : chain.next.value_or(v[m - 1] + (v[m - 1] - v[m - 2]));
    // A ghost on its end point would give the end no direction to meet.
    if (!prev.IsValid() || !next.IsValid() ||
        DistanceSquared(prev, v[0]) <= linearSlop * linearSlop ||
        DistanceSquared(next, v[m - 1]) <= linearSlop * linearSlop)
    {
        return RefuseChain(
            "prev and next: must be finite and further than the linear slop from the first "
            "and last points, got " +
            NumberText(prev) + " and " + NumberText(next));
    }
    std::vector<ChainSegment> segments(m - 1);
    for (std::size_t i = 0; i + 1 < m; ++i)
    {
        segments[i].ghost1 = i > 0 ? v[i - 1] : prev;
        segments[i].segment.point1 = v[i];
        segments[i].segment.point2 = v[i + 1];
        segments[i].ghost2 = i + 2 < m ? v[i + 2] : next;
    }
    return segments;
}

/// The live chain `id` names; nullptr (reported) for a null or stale id.
template <typename State> // WorldState or const WorldState
auto* ResolveChain(State& world, ChainId id)
{
    return world.chains.Resolve(id, "chain");
}

} // namespace

ChainId World::CreateChain(BodyId body, const ShapeDef& def, const Chain& chain)
{
    WorldState& world = State();
    const std::vector<ChainSegment> segments = MakeSegments(chain, world.tolerances.linearSlop);
    if (segments.empty())
    {
        return {}; // refused (reported)
    }

    // Every check CreateShape makes (body, definition) fails on the first segment, before
    // anything is made, so a refused chain leaves the world as it was.
    std::vector<ShapeId> ids;
    ids.reserve(segments.size());
    for (const ChainSegment& segment : segments)
    {
        const ShapeId id = CreateShape(body, def, segment);
        if (id.IsNull())
        {
            return {}; // refused (reported) on the first segment: nothing was made
        }
        ids.push_back(id);
    }

    const ChainId chainId = world.chains.Allocate();
    const std::int32_t index = chainId.index;
    ChainSlot& slot = world.chains[index];
    slot.body = body.index;
    slot.segments = ids;
    slot.loop = chain.loop;
    for (const ShapeId id : ids)
    {
        world.shapes[id.index].chain = index;
    }

    // Each CreateShape put its segment first in the body's list; turn the run around so the
    // list holds the chain in order, as Box2D's fixture list holds the one chain fixture whose
    // children it visits in order.
    Body& owner = world.bodies[body.index];
    const auto count = static_cast<std::ptrdiff_t>(ids.size());
    std::reverse(owner.shapes.begin(), owner.shapes.begin() + count);
    std::reverse(owner.shapeIds.begin(), owner.shapeIds.begin() + count);
    return chainId;
}

void World::DestroyChain(ChainId id)
{
    WorldState& world = State();
    if (!RequireNotWalked(world, "World::DestroyChain"))
    {
        return;
    }
    ChainSlot* const found = ResolveChain(world, id);
    if (found == nullptr)
    {
        return;
    }
    ChainSlot& chain = *found;
    BuildContactReports(world); // the last step's reports still name these shapes
    Body& body = world.bodies[chain.body];
    const auto ofChain = [&](std::int32_t shape) { return world.shapes[shape].chain == id.index; };

    // As b2Body::DestroyFixture: the contacts first, walking the body's list once, then the
    // proxies in the children's order.
    for (std::int32_t key = body.contactList; key != kNullIndex;)
    {
        const std::int32_t c = EdgeOwner(key);
        const Contact& contact = world.contacts[c];
        key = contact.edges[EdgeSide(key)].next;
        if (ofChain(contact.shapeA) || ofChain(contact.shapeB))
        {
            // meff wakes what a destroyed shape touched (see DestroyShape).
            if (contact.IsTouching() && !contact.IsSensor())
            {
                WakeBody(world, contact.bodyA);
                WakeBody(world, contact.bodyB);
            }
            DestroyContact(world, c);
        }
    }
    for (const ShapeId segment : chain.segments)
    {
        Shape& shape = world.shapes[segment.index];
        world.broadPhase.DestroyProxy(shape.proxyId);
        world.shapes.Free(segment.index);
    }
    std::erase_if(body.shapes, ofChain);
    std::erase_if(body.shapeIds, [&](ShapeId s) { return ofChain(s.index); });
    chain.segments.clear();
    world.chains.Free(id.index);
}

bool World::IsValid(ChainId id) const
{
    return State().chains.IsValid(id);
}

std::span<const ShapeId> World::GetChainSegments(ChainId id) const
{
    const ChainSlot* const chain = ResolveChain(State(), id);
    return chain != nullptr ? std::span<const ShapeId>(chain->segments)
                            : std::span<const ShapeId>();
}

bool World::IsChainLoop(ChainId id) const
{
    const auto* const chain = ResolveChain(State(), id);
    return chain != nullptr && chain->loop;
}

ChainId World::GetChain(ShapeId id) const
{
    if (GetBody(id).IsNull())
    {
        return {}; // a stale or null shape id (reported)
    }
    const std::int32_t chain = State().shapes[id.index].chain;
    return chain < 0 ? ChainId{} : ChainId{chain, State().chains[chain].generation};
}

} // namespace meff
