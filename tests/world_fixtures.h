// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Small worlds shared by tests.
#pragma once

#include "meff/world.h"

#include <cmath>

namespace meff::test
{

/// `count` boxes and circles (alternating) dropped in `columns` columns `spacing` apart onto a
/// segment into a pile: contacts come and go and warm starting matters while it settles.
inline World MakePile(int count, int columns, Real spacing, Real circleRestitution)
{
    World world;
    const BodyId ground = world.CreateBody({});
    world.CreateShape(ground, ShapeDef{}, Segment{{-20, 0}, {20, 0}});
    for (int i = 0; i < count; ++i)
    {
        const BodyId body = world.CreateBody(
            {.type = BodyType::Dynamic, .position = {spacing * Real(i % columns), Real(1 + i)}});
        if (i % 2 == 0)
        {
            world.CreateShape(body, ShapeDef{}, MakeBox(Real(0.4), Real(0.3)));
        }
        else
        {
            world.CreateShape(body, ShapeDef{.restitution = circleRestitution},
                              Circle{{0, 0}, Real(0.35)});
        }
    }
    return world;
}

/// A 10 × 10 grid of pinwheels in zero gravity, 3 m apart: each a dynamic bar (a 2 m × 0.2 m box
/// and a circle of radius 0.15 at its middle, the same body's pair) hinged at its middle to a
/// static hub body and, when `spinning`, turned by its motor at 3 rad/s, every other one the
/// other way. Four static dots of radius 0.1 stand 3 cm beyond each bar's reach, at 0°, 90°,
/// 180° and 270°: in every pinwheel's fat boxes (Box2D's 10 cm margin, the colour rule's 5 cm)
/// but never touching it. The dots of even pinwheels are on the hub body (the hinge refuses
/// their pairs), those of odd ones on another static body (contacts made and destroyed as the
/// bar passes). The bars, turning in step, leave their fat boxes together every few steps: a
/// hundred moved proxies, four batches of the colour and soft-step pair finding, whose pairs
/// come and go in a cycle of a quarter turn.
inline World MakePinwheels(SolverKind kind, bool spinning,
                           Real aabbMargin = Tolerances{}.aabbMargin)
{
    World world(WorldDef{
        .gravity = {0, 0}, .solver = {.kind = kind}, .tolerances = {.aabbMargin = aabbMargin}});
    const BodyId hubs = world.CreateBody({});
    const BodyId posts = world.CreateBody({});
    const Real reach = std::sqrt(Real(1.01)); // the bar's corner: hypot(1, 0.1)
    const Real dot = reach + Real(0.03) + Real(0.1);
    for (int i = 0; i < 100; ++i)
    {
        const Vec2 centre{Real(3) * Real(i % 10), Real(3) * Real(i / 10)};
        const BodyId bar = world.CreateBody({.type = BodyType::Dynamic, .position = centre});
        world.CreateShape(bar, ShapeDef{}, MakeBox(Real(1), Real(0.1)));
        world.CreateShape(bar, ShapeDef{}, Circle{{0, 0}, Real(0.15)});
        RevoluteJointDef hinge = world.MakeRevoluteJointDef(hubs, bar, centre);
        hinge.enableMotor = spinning;
        hinge.motorSpeed = i % 2 == 0 ? Real(3) : Real(-3);
        hinge.maxMotorTorque = Real(1e4);
        world.CreateJoint(hinge);
        const BodyId dots = i % 2 == 0 ? hubs : posts;
        for (const Vec2 at : {Vec2{dot, 0}, Vec2{0, dot}, Vec2{-dot, 0}, Vec2{0, -dot}})
        {
            world.CreateShape(dots, ShapeDef{}, Circle{centre + at, Real(0.1)});
        }
    }
    return world;
}

} // namespace meff::test
