// The joint rows of an island in Box2D 2.4.1's order: every joint one by one, in island order,
// with its own rows (engine/src/joints/: InitVelocityConstraints, SolveVelocityConstraints,
// SolvePositionConstraints of each joint type).
#pragma once

#include "dynamics/solver_types.h"
#include "joints/joint.h"
#include "solvers/box2d/island_step.h"

#include <cstdint>
#include <span>
#include <vector>

namespace meff::detail
{

struct Body;
struct Joint;
struct JointSlot;

/// What a joint needs of each of its bodies when a step begins (see JointBody), read from
/// the body the world holds.
JointBody JointBodyOf(const Body& body);

class JointSolver final : public JointStage
{
  public:
    void Prepare(std::span<const std::int32_t> jointIndices, std::span<JointSlot> joints,
                 std::span<const Body> bodies, SolverData& data) override;
    void SolveVelocities(SolverData& data) override;
    void StoreImpulses() override {} ///< the joints accumulate in place
    bool SolvePositions(SolverData& data) override;

  private:
    std::vector<Joint*> m_joints; ///< the island's joints, in island order
};

/// Stores what a joint's rows need of bodies beyond its own two (a gear's: the bodies its two
/// joints are anchored on), before the joint is prepared; nothing for other joints.
void StoreOtherJointBodies(Joint& joint, std::span<const Body> bodies);
/// Prepares one joint in island order (InitJointVelocityConstraints with its bodies).
void PrepareSequentialJoint(Joint& joint, std::span<const Body> bodies, SolverData& data);
/// One velocity sweep, and one position sweep (true when all are within tolerance), of joints
/// solved one by one.
void SolveSequentialVelocities(std::span<Joint* const> joints, SolverData& data);
bool SolveSequentialPositions(std::span<Joint* const> joints, SolverData& data);

} // namespace meff::detail
