#include "dynamics/joint_solver.h"

#include "dynamics/body.h"
#include "dynamics/world_state.h"
#include "joints/joint.h"

namespace meff::detail
{

namespace
{

/// A revolute joint whose only rows are the point block: what the SIMD lanes solve.
RevoluteJoint* LaneRevolute(Joint& joint, const SolverSettings& solver)
{
    auto* revolute = std::get_if<RevoluteJoint>(&joint.data);
    if (revolute == nullptr || revolute->enableLimit || revolute->enableMotor ||
        !solver.blockJoints)
    {
        return nullptr;
    }
    return revolute;
}

} // namespace

void JointSolver::Prepare(std::span<const std::int32_t> jointIndices, std::span<JointSlot> joints,
                          std::span<const Body> bodies, SolverData& data)
{
    m_colored = data.step.solver.graphColoring;
    m_sequential.clear();
    m_candidates.clear();
    m_candidateRevolutes.clear();
    m_candidateBodies.clear();
    const auto info = [&](std::int32_t bodyIndex)
    {
        const Body& body = bodies[bodyIndex];
        return JointBody{body.islandIndex, body.sweep.localCenter, body.invMass, body.invI};
    };
    for (const std::int32_t j : jointIndices)
    {
        Joint& joint = joints[j].joint;
        RevoluteJoint* revolute = m_colored ? LaneRevolute(joint, data.step.solver) : nullptr;
        if (revolute != nullptr)
        {
            // The lanes prepare the rest, four joints at a time.
            const JointBody a = info(joint.bodyA), b = info(joint.bodyB);
            StoreJointBodies(*revolute, a, b);
            m_candidates.push_back(&joint);
            m_candidateRevolutes.push_back(revolute);
            m_candidateBodies.push_back({a.solverIndex, b.solverIndex,
                                         SolverMoves(a.invMass, a.invI),
                                         SolverMoves(b.invMass, b.invI)});
        }
        else
        {
            InitJointVelocityConstraints(joint, info(joint.bodyA), info(joint.bodyB), data);
            m_sequential.push_back(&joint);
        }
    }
    // An island without lane joints (most islands of a contact scene) skips the colouring.
    m_colored = m_colored && !m_candidates.empty();
    if (m_colored)
    {
        m_coloredSolver.Prepare(m_candidateRevolutes, m_candidateBodies, data);
        for (const std::int32_t i : m_coloredSolver.Overflow())
        {
            Joint& joint = *m_candidates[i];
            InitJointVelocityConstraints(joint, info(joint.bodyA), info(joint.bodyB), data);
            m_sequential.push_back(&joint);
        }
    }
}

void JointSolver::SolveVelocities(SolverData& data)
{
    if (m_colored)
    {
        m_coloredSolver.SolveVelocities(data.velocities);
    }
    for (Joint* joint : m_sequential)
    {
        SolveJointVelocityConstraints(*joint, data);
    }
}

void JointSolver::StoreImpulses() const
{
    if (m_colored)
    {
        m_coloredSolver.StoreImpulses();
    }
}

bool JointSolver::SolvePositions(SolverData& data)
{
    bool okay = true;
    if (m_colored)
    {
        okay = m_coloredSolver.SolvePositions(data.positions, data.step.tolerances);
    }
    for (Joint* joint : m_sequential)
    {
        const bool jointOkay = SolveJointPositionConstraints(*joint, data);
        okay = okay && jointOkay;
    }
    return okay;
}

} // namespace meff::detail
