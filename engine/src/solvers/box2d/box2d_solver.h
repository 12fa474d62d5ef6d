// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// The Box2D back end (SolverKind::Box2D): Box2D 2.4.1's b2World::Solve and b2Island::Solve,
// bit for bit — islands grown from awake bodies in world body list order, each solved by
// shared/island_step.h with its contacts (ContactSolver) and joints (JointSolver) in island order.
#pragma once

#include "solvers/box2d/joint_solver.h"
#include "solvers/shared/contact_solver.h"
#include "solvers/shared/island.h"
#include "solvers/solver.h"

namespace meff::detail
{

class Box2DSolver final : public Solver
{
  public:
    void Step(SolverWorld& world, const StepContext& step) override;
    CollisionPolicy Collision(const Tolerances& tolerances) const override
    {
        return Box2DCollision(tolerances);
    }

  private:
    Island m_island;
    ContactSolver m_contacts;
    JointSolver m_joints;
};

} // namespace meff::detail
