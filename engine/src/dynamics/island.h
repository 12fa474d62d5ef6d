// Islands: groups of bodies linked by touching contacts and joints, found by a depth-first
// search in Box2D 2.4.1's order. Each island is solved on its own by the step stages.
//
// Islands exist for sleep (an island sleeps as a whole) and for Box2D's solver order. When
// neither is wanted (no sleep, solving by colour) and every moving body is awake, the whole
// world is one island, gathered by a walk through the arrays instead of the search's walk
// through each body's contact and joint lists (a cache miss per edge).
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
/// Fills `island` with every moving body, every static body that a contact or joint names,
/// every solid contact and every joint with a moving body (bodies in array order, contacts and
/// joints in reverse array order) when every moving body is awake; otherwise returns false
/// and leaves the search to BuildIsland. Sets the bodies' island flags as the search would
/// (static bodies unflagged), so needs no ResetIslandFlags; the contacts' and joints' flags
/// are left as they were (the searches reset them before use).
bool BuildWorldIsland(WorldState& world, Island& island);
/// Lets static bodies join later islands again.
void ReleaseStaticBodies(WorldState& world, const Island& island);

} // namespace meff::detail
