// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
#include "solvers/solver.h"

#include "solvers/box2d/box2d_solver.h"
#include "solvers/colour/colour_solver.h"
#include "solvers/soft_step/soft_step_solver.h"

namespace meff::detail
{

namespace
{

std::unique_ptr<Solver> MakeSolver(SolverKind kind)
{
    switch (kind)
    {
    case SolverKind::Box2D:
        return std::make_unique<Box2DSolver>();
    case SolverKind::Colour:
        return std::make_unique<ColourSolver>();
    case SolverKind::SoftStep:
        return std::make_unique<SoftStepSolver>();
    }
    return nullptr;
}

} // namespace

CollisionPolicy Box2DCollision(const Tolerances& tolerances)
{
    CollisionPolicy policy;
    policy.fatBoxes = {tolerances.aabbMargin, 4};
    policy.shapeBoxes = ShapeBoxes::Swept;
    policy.treeUpdate = TreeUpdate::Reinsert;
    policy.recycleDistance = 0;
    policy.threadedStages = false;
    return policy;
}

CollisionPolicy ThroughputCollision(const Tolerances& tolerances)
{
    CollisionPolicy policy;
    policy.fatBoxes = {Real(0.5) * tolerances.aabbMargin, 0};
    policy.shapeBoxes = ShapeBoxes::SweptForContinuous;
    policy.treeUpdate = TreeUpdate::EnlargeAndRebuild;
    policy.recycleDistance = tolerances.linearSlop;
    policy.threadedStages = true;
    return policy;
}

SolverSet::SolverSet() = default;
SolverSet::~SolverSet() = default;
SolverSet::SolverSet(const SolverSet&) {}
SolverSet& SolverSet::operator=(const SolverSet&)
{
    return *this;
}
SolverSet::SolverSet(SolverSet&&) noexcept = default;
SolverSet& SolverSet::operator=(SolverSet&&) noexcept = default;

Solver& SolverSet::For(SolverKind kind)
{
    std::unique_ptr<Solver>& solver = m_solvers[static_cast<int>(kind)];
    if (!solver)
    {
        solver = MakeSolver(kind);
    }
    return *solver;
}

} // namespace meff::detail
