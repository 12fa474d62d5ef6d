#include "dynamics/contact_coloring.h"

#include "dynamics/contact_constraint.h"

#include <algorithm>

namespace meff::detail
{

bool MovesBodyA(const ContactVelocityConstraint& vc)
{
    return SolverMoves(vc.invMassA, vc.invIA);
}

bool MovesBodyB(const ContactVelocityConstraint& vc)
{
    return SolverMoves(vc.invMassB, vc.invIB);
}

void ColorContacts(std::span<const ContactVelocityConstraint> constraints, ConstraintColoring& out)
{
    std::int32_t bodyCount = 0;
    for (const ContactVelocityConstraint& vc : constraints)
    {
        bodyCount = std::max({bodyCount, vc.indexA + 1, vc.indexB + 1});
    }
    ColorConstraints(
        constraints.size(), static_cast<std::size_t>(bodyCount),
        [&](std::size_t i)
        {
            const ContactVelocityConstraint& vc = constraints[i];
            return ConstraintBodies{vc.indexA, vc.indexB, MovesBodyA(vc), MovesBodyB(vc)};
        },
        out);
}

} // namespace meff::detail
