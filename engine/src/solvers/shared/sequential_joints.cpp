// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
#include "solvers/shared/sequential_joints.h"

#include "joints/joint.h"
#include "model/body.h"

namespace meff::detail
{

JointBody JointBodyOf(const Body& body)
{
    return JointBody{body.islandIndex, body.sweep.localCenter, body.invMass, body.invI};
}

void StoreOtherJointBodies(Joint& joint, std::span<const Body> bodies)
{
    if (auto* gear = std::get_if<GearJoint>(&joint.data))
    {
        StoreGearBodies(*gear, JointBodyOf(bodies[gear->bodyC]), JointBodyOf(bodies[gear->bodyD]));
    }
}

void PrepareSequentialJoint(Joint& joint, std::span<const Body> bodies, SolverData& data)
{
    StoreOtherJointBodies(joint, bodies);
    InitJointVelocityConstraints(joint, JointBodyOf(bodies[joint.bodyA]),
                                 JointBodyOf(bodies[joint.bodyB]), data);
}

void SolveSequentialVelocities(std::span<Joint* const> joints, SolverData& data)
{
    for (Joint* joint : joints)
    {
        SolveJointVelocityConstraints(*joint, data);
    }
}

bool SolveSequentialPositions(std::span<Joint* const> joints, SolverData& data)
{
    bool okay = true;
    for (Joint* joint : joints)
    {
        const bool jointOkay = SolveJointPositionConstraints(*joint, data);
        okay = okay && jointOkay;
    }
    return okay;
}

} // namespace meff::detail
