// The graph colouring (graph_coloring.h) of an island's contacts.
#pragma once

#include "dynamics/contact_constraint.h"
#include "dynamics/graph_coloring.h"

#include <cstddef>

namespace meff::detail
{

/// Colours the island's contacts in island order (ColorConstraints); `bodyCount` is the
/// island's body count. The colouring's indices are positions in island.contactIndices.
void ColorContacts(const IslandContacts& island, std::size_t bodyCount, ConstraintColoring& out);

} // namespace meff::detail
