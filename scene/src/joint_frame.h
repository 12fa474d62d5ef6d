// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Where a scene joint attaches to its bodies, in each body's own frame, exactly as BuildWorld
// creates it: the world-point form goes through World::Make*JointDef (Box2D's Initialize
// arithmetic, in the engine's precision), the local form is taken as written. BuildWorld, the
// b2dJson exporter and importer share it, so that what they write is what the engine builds.
#pragma once

#include "engine_shapes.h"
#include "meff/scene.h"

namespace meff::scene_detail
{

struct JointFrame
{
    Vec2 localAnchorA{};     ///< m, body A's frame (revolute, prismatic, wheel, weld, distance,
                             ///< friction)
    Vec2 localAnchorB{};     ///< m, body B's frame
    Real referenceAngle = 0; ///< rad (revolute, prismatic, weld)
    Vec2 localAxisA{1, 0};   ///< body A's frame, as given (prismatic, wheel; not normalized)
    Vec2 linearOffset{};     ///< m, B's origin in A's frame (motor)
    Real angularOffset = 0;  ///< rad (motor)
};

/// `world` holds bodies a and b where the scene places them. Throws InvalidArgument for
/// non-finite anchors (as World::Make*JointDef).
JointFrame ComputeJointFrame(const World& world, BodyId a, BodyId b, const SceneJoint& joint);

} // namespace meff::scene_detail
