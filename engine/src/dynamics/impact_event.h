// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Who a time-of-impact event touches (continuous.cpp): the island it may take, and the bodies
// it may move, refresh the contacts of or wake. The contact reports of what was solved before
// the event are built for those bodies first; after it, the impact queue lists again the
// contacts of the dynamic ones, and of a kinematic one the event woke.
#pragma once

#include "dynamics/world_state.h"

#include <cstdint>

namespace meff::detail
{

/// Whether a time-of-impact event's island takes `contact` of its dynamic body `body`, whose
/// other side is `other` (b2World::SolveTOI): static, kinematic and bullet neighbours, and any
/// neighbour of a bullet; never a sensor.
inline bool ImpactIslandMayTake(const Body& body, const Body& other, const Contact& contact)
{
    return !contact.IsSensor() && (other.type != BodyType::Dynamic || body.bullet || other.bullet);
}

/// Visits each body an event on contactIndex may move, refresh the contacts of or wake: its
/// two bodies and, for a dynamic one, the neighbours its island may take (a body may be visited
/// twice). Static ones too: the event sets their transforms again, to the same pose.
template <typename Visit>
void ForEachImpactEventBody(const WorldState& world, std::int32_t contactIndex, Visit&& visit)
{
    const Contact& contact = world.contacts[contactIndex];
    for (const std::int32_t bodyIndex : {contact.bodyA, contact.bodyB})
    {
        visit(bodyIndex);
        const Body& body = world.bodies[bodyIndex];
        if (body.type != BodyType::Dynamic)
        {
            continue; // the island takes neighbours of dynamic bodies only
        }
        for (std::int32_t key = body.contactList; key != kNullIndex;)
        {
            const Contact& neighbour = world.contacts[EdgeOwner(key)];
            const Edge& edge = neighbour.edges[EdgeSide(key)];
            key = edge.next;
            if (ImpactIslandMayTake(body, world.bodies[edge.other], neighbour))
            {
                visit(edge.other);
            }
        }
    }
}

} // namespace meff::detail
