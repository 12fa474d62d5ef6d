#include "solvers/colour/contact_colouring.h"

#include "dynamics/body.h"
#include "dynamics/contact.h"

namespace meff::detail
{

void ColourContacts(const IslandContacts& island, std::size_t bodyCount, ConstraintColouring& out)
{
    ColourConstraints(
        island.contactIndices.size(), bodyCount,
        [&](std::size_t i)
        {
            const Contact& contact = island.contacts[island.contactIndices[i]];
            const Body& bodyA = island.bodies[contact.bodyA];
            const Body& bodyB = island.bodies[contact.bodyB];
            return ConstraintBodies{bodyA.islandIndex, bodyB.islandIndex,
                                    SolverMoves(bodyA.invMass, bodyA.invI),
                                    SolverMoves(bodyB.invMass, bodyB.invI)};
        },
        out);
}

} // namespace meff::detail
