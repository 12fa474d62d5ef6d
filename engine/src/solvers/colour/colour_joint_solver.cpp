// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
#include "solvers/colour/colour_joint_solver.h"

#include "joints/joint.h"
#include "joints/joint_slot.h"
#include "model/body.h"
#include "solvers/shared/sequential_joints.h"
#include "tasks/parallel_ranges.h"

namespace meff::detail
{

namespace
{

/// A revolute joint whose only rows are the point block: what the SIMD lanes solve. A limit,
/// a motor or a spring sends the joint to the scalar path (RevoluteJoint's own rows).
RevoluteJoint* LaneRevolute(Joint& joint, const SolverSettings& solver)
{
    auto* revolute = std::get_if<RevoluteJoint>(&joint.data);
    if (revolute == nullptr || revolute->enableLimit || revolute->enableMotor ||
        revolute->enableSpring || !solver.blockJoints)
    {
        return nullptr;
    }
    return revolute;
}

} // namespace

void ColourJointSolver::Prepare(std::span<const std::int32_t> jointIndices,
                                std::span<JointSlot> joints, std::span<const Body> bodies,
                                SolverData& data)
{
    // Which joints the lanes take, and their bodies, on the threads: each joint writes only
    // itself and its own slots.
    const std::size_t count = jointIndices.size();
    m_tasks = data.tasks;
    m_laneOf.resize(count);
    m_bodiesOf.resize(count);
    ForEachIndex(data.tasks, static_cast<int>(count), kMinLaneJointPicksPerTask,
                 [&](int i)
                 {
                     const auto k = static_cast<std::size_t>(i);
                     Joint& joint = joints[jointIndices[k]].joint;
                     RevoluteJoint* revolute = LaneRevolute(joint, data.step.solver);
                     m_laneOf[k] = revolute;
                     if (revolute != nullptr)
                     {
                         // The lanes prepare the rest, kLanes joints at a time.
                         const JointBody a = JointBodyOf(bodies[joint.bodyA]);
                         const JointBody b = JointBodyOf(bodies[joint.bodyB]);
                         StoreJointBodies(*revolute, a, b);
                         m_bodiesOf[k] = {a.solverIndex, b.solverIndex,
                                          SolverMoves(a.invMass, a.invI),
                                          SolverMoves(b.invMass, b.invI)};
                     }
                 });
    // The lane joints listed for the colouring in island order, on the threads.
    m_candidates.resize(count);
    m_candidateRevolutes.resize(count);
    m_candidateBodies.resize(count);
    const auto laneJoints = static_cast<std::size_t>(StableCompact(
        data.tasks, static_cast<int>(count), m_pieceCounts,
        [&](int k) { return m_laneOf[static_cast<std::size_t>(k)] != nullptr; },
        [&](int k, std::int32_t position)
        {
            const auto i = static_cast<std::size_t>(position);
            const auto j = static_cast<std::size_t>(k);
            m_candidates[i] = &joints[jointIndices[j]].joint;
            m_candidateRevolutes[i] = m_laneOf[j];
            m_candidateBodies[i] = m_bodiesOf[j];
        }));
    m_candidates.resize(laneJoints);
    m_candidateRevolutes.resize(laneJoints);
    m_candidateBodies.resize(laneJoints);
    // Then in island order on this thread: the other joints prepared one by one (their warm
    // start moves the bodies).
    m_sequential.clear();
    for (std::size_t k = 0; k < count && m_sequential.size() < count - laneJoints; ++k)
    {
        if (m_laneOf[k] == nullptr)
        {
            Joint& joint = joints[jointIndices[k]].joint;
            PrepareSequentialJoint(joint, bodies, data);
            m_sequential.push_back(&joint);
        }
    }
    // An island without lane joints (most islands of a contact scene) skips the colouring.
    m_lanesInUse = !m_candidates.empty();
    if (m_lanesInUse)
    {
        m_lanes.Prepare(m_candidateRevolutes, m_candidateBodies, data);
        for (const std::int32_t i : m_lanes.Overflow())
        {
            Joint& joint = *m_candidates[i];
            PrepareSequentialJoint(joint, bodies, data);
            m_sequential.push_back(&joint);
        }
    }
}

void ColourJointSolver::SolveVelocities(SolverData& data)
{
    if (m_lanesInUse)
    {
        m_lanes.SolveVelocities(data);
    }
    SolveSequentialVelocities(m_sequential, data);
}

void ColourJointSolver::StoreImpulses()
{
    if (m_lanesInUse)
    {
        m_lanes.StoreImpulses(m_tasks);
    }
}

bool ColourJointSolver::SolvePositions(SolverData& data)
{
    bool okay = true;
    if (m_lanesInUse)
    {
        okay = m_lanes.SolvePositions(data);
    }
    const bool sequentialOkay = SolveSequentialPositions(m_sequential, data);
    return okay && sequentialOkay;
}

} // namespace meff::detail
