// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
#include "joint_frame.h"

namespace meff::scene_detail
{

namespace
{

/// The local form, where the scene gives it, replaces what the world form computed.
void ApplyLocalForm(const SceneJoint& joint, JointFrame& frame)
{
    if (joint.localAnchors)
    {
        frame.localAnchorA = ToEngine(joint.localAnchorA);
        frame.localAnchorB = ToEngine(joint.localAnchorB);
    }
    if (joint.localAxisA)
    {
        frame.localAxisA = ToEngine(*joint.localAxisA);
    }
    if (joint.referenceAngle)
    {
        frame.referenceAngle = Real(*joint.referenceAngle);
    }
}

template <typename Def>
void TakeAnchors(const Def& def, JointFrame& frame)
{
    frame.localAnchorA = def.localAnchorA;
    frame.localAnchorB = def.localAnchorB;
}

} // namespace

JointFrame ComputeJointFrame(const World& world, BodyId a, BodyId b, const SceneJoint& joint)
{
    JointFrame frame;
    const Vec2 anchor = ToEngine(joint.anchor);
    switch (joint.type)
    {
    case JointType::Revolute:
    {
        const RevoluteJointDef def = world.MakeRevoluteJointDef(a, b, anchor);
        TakeAnchors(def, frame);
        frame.referenceAngle = def.referenceAngle;
        break;
    }
    case JointType::Prismatic:
    {
        const PrismaticJointDef def =
            world.MakePrismaticJointDef(a, b, anchor, ToEngine(joint.axis));
        TakeAnchors(def, frame);
        frame.localAxisA = def.localAxisA;
        frame.referenceAngle = def.referenceAngle;
        break;
    }
    case JointType::Wheel:
    {
        const WheelJointDef def = world.MakeWheelJointDef(a, b, anchor, ToEngine(joint.axis));
        TakeAnchors(def, frame);
        frame.localAxisA = def.localAxisA;
        break;
    }
    case JointType::Weld:
    {
        const WeldJointDef def = world.MakeWeldJointDef(a, b, anchor);
        TakeAnchors(def, frame);
        frame.referenceAngle = def.referenceAngle;
        break;
    }
    case JointType::Distance:
        TakeAnchors(
            world.MakeDistanceJointDef(a, b, ToEngine(joint.anchorA), ToEngine(joint.anchorB)),
            frame);
        break;
    case JointType::Friction:
        TakeAnchors(world.MakeFrictionJointDef(a, b, anchor), frame);
        break;
    case JointType::Pulley:
        TakeAnchors(world.MakePulleyJointDef(a, b, ToEngine(joint.groundAnchorA),
                                             ToEngine(joint.groundAnchorB), ToEngine(joint.anchorA),
                                             ToEngine(joint.anchorB), Real(joint.ratio)),
                    frame);
        break;
    case JointType::Motor:
    {
        const MotorJointDef def = world.MakeMotorJointDef(a, b);
        frame.linearOffset = joint.linearOffset ? ToEngine(*joint.linearOffset) : def.linearOffset;
        frame.angularOffset = joint.angularOffset ? Real(*joint.angularOffset) : def.angularOffset;
        break;
    }
    default:
        break;
    }
    ApplyLocalForm(joint, frame);
    return frame;
}

} // namespace meff::scene_detail
