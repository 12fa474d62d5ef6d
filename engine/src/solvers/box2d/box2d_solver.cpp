#include "solvers/box2d/box2d_solver.h"

namespace meff::detail
{

void Box2DSolver::Step(SolverWorld& world, const StepContext& step)
{
    ForEachAwakeIsland(world, m_island,
                       [&](Island& island)
                       { SolveIsland(world, island, step, m_contacts, m_joints); });
}

} // namespace meff::detail
