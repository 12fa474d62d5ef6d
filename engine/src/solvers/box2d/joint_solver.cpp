// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
#include "solvers/box2d/joint_solver.h"

#include "joints/joint.h"
#include "joints/joint_slot.h"
#include "model/body.h"

namespace meff::detail
{

void JointSolver::Prepare(std::span<const std::int32_t> jointIndices, std::span<JointSlot> joints,
                          std::span<const Body> bodies, SolverData& data)
{
    m_joints.clear();
    for (const std::int32_t j : jointIndices)
    {
        Joint& joint = joints[j].joint;
        PrepareSequentialJoint(joint, bodies, data);
        m_joints.push_back(&joint);
    }
}

void JointSolver::SolveVelocities(SolverData& data)
{
    SolveSequentialVelocities(m_joints, data);
}

bool JointSolver::SolvePositions(SolverData& data)
{
    return SolveSequentialPositions(m_joints, data);
}

} // namespace meff::detail
