// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Joints one by one, each with its own rows (engine/src/joints/: InitVelocityConstraints,
// SolveVelocityConstraints, SolvePositionConstraints of each joint type): what the Box2D back
// end does with every joint, the colour back end with the joints its lanes do not take, and the
// soft step when it prepares a joint.
#pragma once

#include "joints/joint.h"
#include "model/solver_types.h"

#include <span>

namespace meff::detail
{

struct Body;
struct Joint;

/// What a joint needs of each of its bodies when a step begins (see JointBody), read from
/// the body the world holds.
JointBody JointBodyOf(const Body& body);

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
