// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// The colour back end (SolverKind::Colour): Box2D 2.4.1's island step (shared/island_step.h)
// with contacts and plain revolute joints solved colour by colour in SIMD lanes. Without sleep
// and with every moving body awake the whole world is one island, gathered from the arrays
// (BuildWorldIsland); otherwise islands are searched as Box2D's back end does.
#pragma once

#include "solvers/colour/colour_contact_solver.h"
#include "solvers/colour/colour_joint_solver.h"
#include "solvers/shared/island.h"
#include "solvers/solver.h"

namespace meff::detail
{

class ColourSolver final : public Solver
{
  public:
    void Step(SolverWorld& world, const StepContext& step) override;
    CollisionPolicy Collision(const Tolerances& tolerances) const override
    {
        return ThroughputCollision(tolerances);
    }

  private:
    Island m_island;
    ColourContactSolver m_contacts;
    ColourJointSolver m_joints;
};

} // namespace meff::detail
