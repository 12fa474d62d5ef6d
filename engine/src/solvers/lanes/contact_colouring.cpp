// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
#include "solvers/lanes/contact_colouring.h"

namespace meff::detail
{

void ColourContacts(const IslandContacts& island, std::size_t bodyCount, ConstraintColouring& out)
{
    ColourConstraints(
        island.contactIndices.size(), bodyCount,
        [&island](std::size_t i) { return IslandContactBodies(island, i); }, out);
}

} // namespace meff::detail
