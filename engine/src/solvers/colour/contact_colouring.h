// The graph colouring (graph_colouring.h) of an island's contacts.
#pragma once

#include "solvers/box2d/contact_constraint.h"
#include "solvers/colour/graph_colouring.h"

#include <cstddef>

namespace meff::detail
{

/// Colours the island's contacts in island order (ColourConstraints); `bodyCount` is the
/// island's body count. The colouring's indices are positions in island.contactIndices.
void ColourContacts(const IslandContacts& island, std::size_t bodyCount, ConstraintColouring& out);

} // namespace meff::detail
