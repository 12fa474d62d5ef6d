// Islands: groups of bodies linked by touching contacts and joints, found by a depth-first
// search in Box2D 2.4.1's order. Each island is solved on its own by the step stages.
#pragma once

#include "dynamics/solver_types.h"

#include <cstdint>
#include <vector>

namespace meff::detail
{

struct WorldState;

struct Island
{
    std::vector<std::int32_t> bodies;   ///< world body indices, solver order
    std::vector<std::int32_t> contacts; ///< world contact indices, solver order
    std::vector<std::int32_t> joints;   ///< world joint indices, solver order
    std::vector<Position> positions;    ///< by solver index
    std::vector<Velocity> velocities;   ///< by solver index
    std::vector<std::int32_t> stack;    ///< depth-first search scratch

    void Clear()
    {
        bodies.clear();
        contacts.clear();
        joints.clear();
    }
};

/// Clears every island flag before a step's islands are built.
void ResetIslandFlags(WorldState& world);
/// Fills `island` with the island grown from `seed` (a non-static body with no island yet).
void BuildIsland(WorldState& world, std::int32_t seed, Island& island);
/// Lets static bodies join later islands again.
void ReleaseStaticBodies(WorldState& world, const Island& island);

} // namespace meff::detail
