// The joint stages of an island's step: prepare (InitJointVelocityConstraints, warm start
// included), the velocity sweeps, and the position sweeps. By default every joint is solved
// one by one in island order, as Box2D 2.4.1 does. With SolverSettings::graphColoring, the
// revolute joints that have only their point rows go by colour in SIMD lanes
// (colored_joint_solver.h) and the others follow one by one in island order.
#pragma once

#include "dynamics/colored_joint_solver.h"
#include "dynamics/solver_types.h"

#include <cstdint>
#include <span>
#include <vector>

namespace meff::detail
{

struct Body;
struct Joint;
struct JointSlot;
struct RevoluteJoint;

class JointSolver
{
  public:
    /// Prepares the island's joints. Bodies' islandIndex must be set.
    void Prepare(std::span<const std::int32_t> jointIndices, std::span<JointSlot> joints,
                 std::span<const Body> bodies, SolverData& data);
    void SolveVelocities(SolverData& data);
    /// Copies impulses accumulated in lanes back into the joints (reactions, next warm start).
    void StoreImpulses() const;
    /// One non-linear Gauss-Seidel sweep; true when every joint is within tolerance.
    bool SolvePositions(SolverData& data);

  private:
    std::vector<Joint*> m_sequential; ///< solved one by one, in island order
    /// With colouring: the joints the lanes can take, as joints and as revolute joints.
    std::vector<Joint*> m_candidates;
    std::vector<RevoluteJoint*> m_candidateRevolutes;
    std::vector<ConstraintBodies> m_candidateBodies;
    bool m_colored = false;
    ColoredJointSolver m_coloredSolver;
};

} // namespace meff::detail
