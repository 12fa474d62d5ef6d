// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// AddPair's rules (contact_manager.cpp), shared with the batched pair finding
// (pair_batches.cpp): which pairs the broad phase finds get a contact.
#pragma once

#include "dynamics/world_state.h"

#include <algorithm>
#include <cstdint>

namespace meff::detail
{

/// The filter's bits (Box2D 2.4.1's b2ContactFilter::ShouldCollide).
inline bool FiltersAllow(const Filter& a, const Filter& b)
{
    if (a.groupIndex == b.groupIndex && a.groupIndex != 0)
    {
        return a.groupIndex > 0;
    }
    return (a.maskBits & b.categoryBits) != 0 && (a.categoryBits & b.maskBits) != 0;
}

/// The same key for (a, b) and (b, a); never 0 (PairSet's empty mark), since a ≠ b.
inline std::uint64_t ShapePairKey(std::int32_t a, std::int32_t b)
{
    const auto low = static_cast<std::uint32_t>(std::min(a, b));
    const auto high = static_cast<std::uint32_t>(std::max(a, b));
    return (std::uint64_t{high} << 32) | low;
}

/// At least one body dynamic, and no joint between them that forbids collision.
inline bool BodiesShouldCollide(const WorldState& world, std::int32_t a, std::int32_t b)
{
    const Body& bodyA = world.bodies[a];
    const Body& bodyB = world.bodies[b];
    if (bodyA.type != BodyType::Dynamic && bodyB.type != BodyType::Dynamic)
    {
        return false;
    }
    for (std::int32_t key = bodyB.jointList; key != kNullIndex;)
    {
        const JointSlot& joint = world.joints[EdgeOwner(key)];
        const Edge& edge = joint.edges[EdgeSide(key)];
        if (edge.other == a && !joint.joint.collideConnected)
        {
            return false;
        }
        key = edge.next;
    }
    return true;
}

/// AddPair's refusals that only read the world: the same body, the filter's bits, the bodies
/// (no dynamic one, or a joint that forbids collision) and an existing contact. As none of them
/// writes anything, their order is free (Box2D 2.4.1 walks the contact list, then the joint
/// list, then the filter), and the batched pair finding asks them on the threads.
[[gnu::always_inline]] inline bool BuiltInRulesRefuse(const WorldState& world,
                                                      std::int32_t shapeIndexA,
                                                      std::int32_t shapeIndexB)
{
    // Does a contact between these two shapes exist already? Asked first: it needs only the
    // shapes' indices, and most pairs a moved proxy finds are its standing contacts (a crowd
    // that moves together), which the other rules would have read two shapes and two bodies
    // to pass. Box2D 2.4.1 walks body B's contact list, a cache miss per edge and a thousand
    // edges for a container full of boxes; the set answers the same question in one look-up.
    if (world.contactPairs.Contains(ShapePairKey(shapeIndexA, shapeIndexB)))
    {
        return true;
    }
    const Shape& first = world.shapes[shapeIndexA];
    const Shape& second = world.shapes[shapeIndexB];
    const std::int32_t bodyA = first.body;
    const std::int32_t bodyB = second.body;
    if (bodyA == bodyB)
    {
        return true;
    }
    // The filter, already in hand, goes before the joint list, since pairs of shapes that
    // never collide (a net's or a ragdoll's) are found again every step their boxes move, and
    // the list's walk misses the cache.
    return !FiltersAllow(first.def.filter, second.def.filter) ||
           !BodiesShouldCollide(world, bodyB, bodyA);
}

/// The rest of AddPair, for a pair the built-in rules let through: the user's filter, which may
/// count or log its calls, so asked exactly when Box2D asks its b2ContactFilter (after the
/// built-in rules, before the shape types are looked at: Box2D asks about two segments too,
/// then makes no contact), then the contact.
void CreateContact(WorldState& world, std::int32_t shapeIndexA, std::int32_t shapeIndexB);
/// CreateContact for the kept pairs of the first `batches` of the batched pair finding
/// (WorldState::scratch.pairBatches) that have no contact yet, without the user's filter, in
/// three passes whose contacts, slots, serial numbers and lists are CreateContact's one pair
/// after another (contact_manager.cpp).
void MakeContacts(WorldState& world, int batches);

/// FindNewContacts for the colour and soft-step back ends (pair_batches.cpp).
void FindNewContactsInBatches(WorldState& world);

} // namespace meff::detail
