// The graph colouring (graph_coloring.h) of an island's prepared contact constraints.
#pragma once

#include "dynamics/graph_coloring.h"

#include <span>

namespace meff::detail
{

struct ContactVelocityConstraint;

/// True when the solver may change the body's velocity through this contact.
bool MovesBodyA(const ContactVelocityConstraint& vc);
bool MovesBodyB(const ContactVelocityConstraint& vc);

/// Colours the contacts in island order (ColorConstraints).
void ColorContacts(std::span<const ContactVelocityConstraint> constraints, ConstraintColoring& out);

} // namespace meff::detail
