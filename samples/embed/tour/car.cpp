// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Tour stop: a car on wheel joints. Each wheel joint lets its wheel spin freely and slide along
// the chassis's vertical axis against a spring (the suspension); the rear one also has a motor.
// The car settles on its springs, then drives over a bump.
#include "tour.h"

#include <algorithm>
#include <cmath>

namespace meff::tour
{

namespace
{

constexpr Real kStep = Real(1) / 60;
constexpr Real kHertz = 4;           // suspension frequency (Hz)
constexpr Real kDampingRatio = 0.7f; // a little under critical: one soft rebound
constexpr Real kWheelRadius = 0.4f;  // m

/// The joint's translation: how far the wheel centre sits above its rest point on the chassis
/// along the suspension axis (m), i.e. how much the chassis's weight compresses the spring.
Real SuspensionTravel(const World& world, JointId joint, Vec2 axis)
{
    return Dot(world.GetAnchorB(joint) - world.GetAnchorA(joint), axis);
}

} // namespace

CarResult RunCar(std::FILE* log)
{
    World world(WorldDef{});
    const Vec2 gravity = world.GetGravity();

    // Flat ground with one low bump 12 m ahead.
    const BodyId ground = world.CreateBody(BodyDef{});
    world.CreateShape(ground, ShapeDef{}, Segment{{-20, 0}, {80, 0}});
    const Vec2 bump[] = {{10, 0}, {12, Real(0.25)}, {14, 0}};
    world.CreateShape(ground, ShapeDef{}, MakePolygon(bump));

    // Chassis 2.5 m × 0.5 m; wheels 1 m either side of its centre, so each spring carries half
    // of its weight.
    BodyDef chassisDef;
    chassisDef.type = BodyType::Dynamic;
    chassisDef.position = {0, 1};
    const BodyId chassis = world.CreateBody(chassisDef);
    world.CreateShape(chassis, ShapeDef{}, MakeBox(Real(1.25), Real(0.25)));

    const Vec2 axis{0, 1};
    JointId wheels[2];
    for (int i = 0; i < 2; ++i)
    {
        BodyDef wheelDef;
        wheelDef.type = BodyType::Dynamic;
        wheelDef.position = {i == 0 ? Real(-1) : Real(1), Real(0.4)};
        const BodyId wheel = world.CreateBody(wheelDef);
        ShapeDef tyre;
        tyre.friction = Real(0.9);
        world.CreateShape(wheel, tyre, Circle{{0, 0}, kWheelRadius});

        WheelJointDef joint = world.MakeWheelJointDef(chassis, wheel, wheelDef.position, axis);
        joint.hertz = kHertz;
        joint.dampingRatio = kDampingRatio;
        joint.enableMotor = i == 0; // rear-wheel drive
        joint.maxMotorTorque = 20;
        joint.motorSpeed = 0;
        wheels[i] = world.CreateJoint(joint);
    }

    // Settle on the springs for two seconds.
    for (int step = 0; step < 120; ++step)
    {
        world.Step(kStep);
    }
    CarResult result;
    result.restSag = Real(0.5) * (SuspensionTravel(world, wheels[0], axis) +
                                  SuspensionTravel(world, wheels[1], axis));
    // Static deflection of a spring: x = F/k with F = half the chassis's weight and k the
    // stiffness the joint derives from its hertz, k = m·(2πf)², where m is the reduced mass of
    // chassis and wheel (both dynamic, as Box2D's b2LinearStiffness).
    const Real chassisMass = world.GetMass(chassis);
    const Real wheelMass = world.GetMass(world.GetBodyB(wheels[0]));
    const Real reduced = chassisMass * wheelMass / (chassisMass + wheelMass);
    const Real omega = 2 * kPi * kHertz;
    result.expectedSag = Real(0.5) * chassisMass * -gravity.y / (reduced * omega * omega);

    // Drive: the motor turns the rear wheel clockwise (negative ω) to go right.
    const Real startX = world.GetPosition(chassis).x;
    world.SetJointMotorSpeed(wheels[0], -15);
    result.lowestChassisY = world.GetPosition(chassis).y;
    for (int step = 0; step < 240; ++step)
    {
        world.Step(kStep);
        result.lowestChassisY = std::min(result.lowestChassisY, world.GetPosition(chassis).y);
        result.largestTilt = std::max(result.largestTilt, std::abs(world.GetAngle(chassis)));
    }
    result.distance = world.GetPosition(chassis).x - startX;

    if (log != nullptr)
    {
        std::fprintf(log,
                     "car: settled %.4f m on its springs (m·g/k = %.4f m), then drove %.2f m over "
                     "the bump, tilting at most %.2f rad\n",
                     double(result.restSag), double(result.expectedSag), double(result.distance),
                     double(result.largestTilt));
    }
    return result;
}

} // namespace meff::tour
