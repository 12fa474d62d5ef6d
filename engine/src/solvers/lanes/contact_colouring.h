// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The graph colouring (graph_colouring.h) of an island's contacts.
#pragma once

#include "model/body.h"
#include "model/contact.h"
#include "solvers/lanes/graph_colouring.h"
#include "solvers/shared/contact_constraint.h"

#include <cstddef>

namespace meff::detail
{

/// The bodies of the island's contact i (a position in island.contactIndices) as a colouring
/// sees them: their solver indices, and whether the solver moves them.
inline ConstraintBodies IslandContactBodies(const IslandContacts& island, std::size_t i)
{
    const Contact& contact = island.contacts[island.contactIndices[i]];
    const Body& bodyA = island.bodies[contact.bodyA];
    const Body& bodyB = island.bodies[contact.bodyB];
    return {bodyA.islandIndex, bodyB.islandIndex, SolverMoves(bodyA.invMass, bodyA.invI),
            SolverMoves(bodyB.invMass, bodyB.invI)};
}

/// Colours the island's contacts in island order (ColourConstraints); `bodyCount` is the
/// island's body count. The colouring's indices are positions in island.contactIndices.
void ColourContacts(const IslandContacts& island, std::size_t bodyCount, ConstraintColouring& out);

} // namespace meff::detail
