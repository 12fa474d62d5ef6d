// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Prismatic and wheel joints through the World API: what they must do physically (motor force
// balance, spring frequency), that the scalar-row form converges, and that bad definitions and
// calls are refused. Their bit-for-bit agreement with Box2D is
// test_joints_box2d_prismatic_wheel.cpp.
#include "error_checks.h"
#include "meff/world.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace meff;

namespace
{

constexpr Real kDt = Real(1) / Real(60);

/// A world with a static ground body and one dynamic box of the given mass (1 m square).
struct Rig
{
    World world;
    BodyId ground;
    BodyId box;

    explicit Rig(Vec2 gravity, Real mass = 2, Vec2 position = {0, 0})
        : world(WorldDef{.gravity = gravity})
    {
        ground = world.CreateBody(BodyDef{});
        box = world.CreateBody(BodyDef{.type = BodyType::Dynamic, .position = position});
        world.CreateShape(box, ShapeDef{.density = mass}, MakeBox(0.5f, 0.5f));
    }
};

} // namespace

TEST_CASE("Prismatic motor: steady speed when strong enough, constant force when not",
          "[joints][prismatic]")
{
    const Real g = 10;
    Rig rig({0, -g});
    const Real m = rig.world.GetMass(rig.box);
    REQUIRE(m == Approx(2));
    // An oblique rail: the joint must also supply the weight's component across it.
    const Vec2 axis(0.6f, 0.8f);
    PrismaticJointDef def = rig.world.MakePrismaticJointDef(rig.ground, rig.box, {0, 0}, axis);
    def.enableMotor = true;
    def.motorSpeed = 1.5f;

    SECTION("strong motor: the box climbs at the motor speed, the joint carries its weight")
    {
        def.maxMotorForce = 100; // > m·g·0.8 = 16 N along the rail
        const JointId rail = rig.world.CreateJoint(def);
        for (int i = 0; i < 60; ++i)
        {
            rig.world.Step(kDt);
        }
        // Converged rows: the speed is the motor's to float round-off (8 iterations of a
        // single-body system whose rows are exact after the first sweep).
        CHECK(rig.world.GetJointSpeed(rail) == Approx(1.5).epsilon(1e-5));
        // Translation: 1 s at 1.5 m/s, less the first step's acceleration (less than a step).
        CHECK(rig.world.GetJointTranslation(rail) == Approx(1.5).margin(1.5 * kDt));
        // Force balance at steady speed: the reaction on the box is minus its weight
        // (motor along the rail plus the perpendicular row across it). Relative 1e-4: the
        // float sum of two rows' impulses over 1/dt.
        const JointReaction r = rig.world.GetReaction(rail, 1 / kDt);
        CHECK(r.force.x == Approx(0).margin(1e-4 * m * g));
        CHECK(r.force.y == Approx(m * g).epsilon(1e-4));
        CHECK(r.torque == Approx(0).margin(1e-4 * m * g));

        // A new motor speed takes over.
        rig.world.SetJointMotorSpeed(rail, -0.5f);
        for (int i = 0; i < 30; ++i)
        {
            rig.world.Step(kDt);
        }
        CHECK(rig.world.GetJointSpeed(rail) == Approx(-0.5).epsilon(1e-5));
    }

    SECTION("weak motor: it pushes with its maximum force and the box slides down")
    {
        const Real F = 6; // < m·g·0.8 = 16 N
        def.maxMotorForce = F;
        const JointId rail = rig.world.CreateJoint(def);
        const int steps = 60;
        for (int i = 0; i < steps; ++i)
        {
            rig.world.Step(kDt);
        }
        // Newton along the rail: m·a = F − m·g·0.8, so v = steps·h·(F/m − 0.8·g) = −5 m/s.
        // Relative 1e-4: float accumulation over 60 steps.
        const double expected = steps * double(kDt) * (F / m - 0.8 * g);
        CHECK(rig.world.GetJointSpeed(rail) == Approx(expected).epsilon(1e-4));
        // The motor's reaction along the rail is F, against the motion.
        const JointReaction r = rig.world.GetReaction(rail, 1 / kDt);
        CHECK(Dot(r.force, axis) == Approx(F).epsilon(1e-4));
    }
}

TEST_CASE("Prismatic limit stops the slide", "[joints][prismatic]")
{
    Rig rig({0, -10});
    PrismaticJointDef def = rig.world.MakePrismaticJointDef(rig.ground, rig.box, {0, 0}, {0, 3});
    def.enableLimit = true;
    def.lowerTranslation = -0.75f;
    def.upperTranslation = 1;
    const JointId rail = rig.world.CreateJoint(def);
    for (int i = 0; i < 120; ++i)
    {
        rig.world.Step(kDt);
    }
    // Resting on the lower limit: within the linear slop (the position pass leaves it).
    CHECK(rig.world.GetJointTranslation(rail) == Approx(-0.75).margin(0.005));
    // At rest on it: each step the limit row takes back gravity's kick g·h = 0.17 m/s along
    // the (vertical) rail; 1e-6 m/s is float round-off of that (measured: 0 exactly).
    CHECK(rig.world.GetJointSpeed(rail) == Approx(0).margin(1e-6));
    // The limit carries the weight.
    CHECK(rig.world.GetReaction(rail, 1 / kDt).force.y ==
          Approx(10 * rig.world.GetMass(rig.box)).epsilon(1e-4));
}

TEST_CASE("Wheel suspension oscillates at its frequency", "[joints][wheel]")
{
    // A heavy chassis (body A) on a spring whose other end is a static wheel (body B), without
    // gravity: LinearStiffness uses the chassis' mass alone, so the chassis should oscillate
    // along the axis at `hertz`. The anchor is the chassis' centre of mass, so nothing turns.
    World world(WorldDef{.gravity = {0, 0}});
    const BodyId chassis = world.CreateBody(BodyDef{.type = BodyType::Dynamic, .position = {0, 1}});
    world.CreateShape(chassis, ShapeDef{.density = 50}, MakeBox(1, 0.25f));
    const BodyId wheel = world.CreateBody(BodyDef{.position = {0, 1}});
    world.CreateShape(wheel, ShapeDef{}, Circle{{0, 0}, 0.4f});
    const Real hertz = 1;
    WheelJointDef def = world.MakeWheelJointDef(chassis, wheel, {0, 1}, {0, 1});
    def.hertz = hertz;
    const JointId spring = world.CreateJoint(def);
    world.SetLinearVelocity(chassis, {0, 0.5f});

    // Zero crossings of the translation (linearly interpolated between steps).
    std::vector<double> crossings;
    double previous = world.GetJointTranslation(spring);
    for (int i = 1; i <= 300 && crossings.size() < 7; ++i)
    {
        world.Step(kDt);
        const double x = world.GetJointTranslation(spring);
        CHECK(std::abs(world.GetAngle(chassis)) < 1e-6);
        if ((previous < 0) != (x < 0) && i > 1)
        {
            crossings.push_back((i - 1 + previous / (previous - x)) * double(kDt));
        }
        previous = x;
    }
    REQUIRE(crossings.size() == 7);
    const double period = (crossings[6] - crossings[0]) / 3;
    // The soft row is implicit Euler on the spring, x' = x + h·v', v' = v − h·ω²·x', whose
    // rotation per step is atan(ω·h) instead of ω·h: the discrete period is
    // 2π·h/atan(ω·h), 0.36 % longer than 1/hertz at 1 Hz and 60 Hz. Its zeros fall exactly on
    // steps of that rotation, so only the linear interpolation between samples errs, by far
    // less than 1e-3 of a period.
    const double omega = 2 * 3.14159265358979 * hertz;
    const double discrete = 2 * 3.14159265358979 * double(kDt) / std::atan(omega * double(kDt));
    CHECK(period == Approx(discrete).epsilon(1e-3));
    CHECK(period == Approx(1 / hertz).epsilon(0.005));
}

TEST_CASE("Prismatic scalar rows (blockJoints off) converge like the block", "[joints][prismatic]")
{
    // A box hanging off an oblique rail by a 1.5 m lever: the joint must hold both the line
    // and the angle against the weight's torque, which couples the two rows strongly. It
    // slides 2 m and hits the upper limit at about 2.4 m/s (step 47).
    struct Run
    {
        double peakLine = 0, peakAngle = 0; ///< worst over the run (m, rad)
        double lateLine = 0, lateAngle = 0; ///< worst over the last second
        double translation = 0;             ///< at the end (m)
    };
    auto run = [](bool blockJoints, int velocityIterations)
    {
        // Awake throughout: the last second's joint error is read from a box at rest.
        World world(WorldDef{.gravity = {0, -10}, .allowSleep = false});
        world.SetSolverSettings(
            SolverSettings{.velocityIterations = velocityIterations, .blockJoints = blockJoints});
        const BodyId ground = world.CreateBody(BodyDef{});
        const BodyId box = world.CreateBody(
            BodyDef{.type = BodyType::Dynamic, .position = {1.5f, 0}, .angle = 0.3f});
        world.CreateShape(box, ShapeDef{.density = 3}, MakeBox(0.5f, 0.25f));
        PrismaticJointDef def = world.MakePrismaticJointDef(ground, box, {0, 0}, {1, -1});
        def.enableLimit = true;
        def.lowerTranslation = -1;
        def.upperTranslation = 2;
        const JointId rail = world.CreateJoint(def);
        Run result;
        const Vec2 normal = (1 / std::sqrt(Real(2))) * Vec2(1, 1);
        for (int i = 0; i < 240; ++i)
        {
            world.Step(kDt);
            // Distance of B's anchor from the rail line, and the angle error.
            const Vec2 d = world.GetAnchorB(rail) - world.GetAnchorA(rail);
            const double line = std::abs(Dot(d, normal));
            const double angle = std::abs(world.GetAngle(box) - 0.3f);
            result.peakLine = std::max(result.peakLine, line);
            result.peakAngle = std::max(result.peakAngle, angle);
            if (i >= 180)
            {
                result.lateLine = std::max(result.lateLine, line);
                result.lateAngle = std::max(result.lateAngle, angle);
            }
        }
        result.translation = world.GetJointTranslation(rail);
        return result;
    };
    const Run block = run(true, 8);
    const Run scalar = run(false, 8);
    const Run scalarMore = run(false, 20);
    // The block solves the coupled rows exactly each iteration: only round-off stays (1e-5 m
    // is far above float round-off at these sizes and far below the slop).
    CHECK(block.peakLine < 1e-5);
    CHECK(block.peakAngle < 1e-5);
    // Gauss-Seidel on strongly coupled scalar rows converges more slowly: the impact on the
    // limit leaves a few centimetres and under 2° (Box2D's angular slop, 0.0349 rad) of error
    // with 8 iterations (measured 0.030 m, 0.030 rad) ...
    CHECK(scalar.peakLine < 0.05);
    CHECK(scalar.peakAngle < 0.0349);
    // ... less with more iterations (measured 0.011 m), so it converges towards the block's
    // answer ...
    CHECK(scalarMore.peakLine < 0.5 * scalar.peakLine);
    // ... and the next steps remove it: within 1e-4 m and 1e-4 rad a second later (measured
    // below 1e-5).
    CHECK(scalar.lateLine < 1e-4);
    CHECK(scalar.lateAngle < 1e-4);
    // Both rest on the upper limit, 2 m down the rail, within the linear slop.
    CHECK(block.translation == Approx(2).margin(0.005));
    CHECK(scalar.translation == Approx(2).margin(0.005));
}

TEST_CASE("Prismatic and wheel definitions are validated", "[joints][prismatic][wheel][errors]")
{
    Rig rig({0, -10});
    World& world = rig.world;

    PrismaticJointDef prismatic = world.MakePrismaticJointDef(rig.ground, rig.box, {0, 0}, {1, 0});
    prismatic.lowerTranslation = 2;
    prismatic.upperTranslation = 1;
    CHECK(meff::test::ErrorMessageOf([&] { world.CreateJoint(prismatic); }) ==
          "PrismaticJointDef::lowerTranslation: must not exceed upperTranslation (1), got 2");
    prismatic.upperTranslation = 3;
    prismatic.maxMotorForce = -1;
    CHECK(meff::test::ErrorMessageOf([&] { world.CreateJoint(prismatic); }) ==
          "PrismaticJointDef::maxMotorForce: must be finite and >= 0, got -1");
    prismatic.maxMotorForce = 1;
    prismatic.motorSpeed = std::nanf("");
    CHECK(meff::test::ErrorMessageOf([&] { world.CreateJoint(prismatic); }) ==
          "PrismaticJointDef::motorSpeed: must be finite, got nan");
    prismatic.motorSpeed = 0;
    prismatic.localAxisA = {0, 0};
    CHECK(meff::test::ErrorMessageOf([&] { world.CreateJoint(prismatic); }) ==
          "PrismaticJointDef::localAxisA: must have a direction (a length > 0), got (0, 0)");
    MEFF_CHECK_ERROR(world.MakePrismaticJointDef(rig.ground, rig.box, {0, 0}, {kMaxReal * 2, 0}));

    WheelJointDef wheel = world.MakeWheelJointDef(rig.ground, rig.box, {0, 0}, {0, 1});
    wheel.maxMotorTorque = -2;
    CHECK(meff::test::ErrorMessageOf([&] { world.CreateJoint(wheel); }) ==
          "WheelJointDef::maxMotorTorque: must be finite and >= 0, got -2");
    wheel.maxMotorTorque = 0;
    wheel.hertz = -1;
    CHECK(meff::test::ErrorMessageOf([&] { world.CreateJoint(wheel); }) ==
          "WheelJointDef::hertz: must be finite and >= 0, got -1");
    wheel.hertz = 1;
    wheel.lowerTranslation = 0.5f;
    CHECK(meff::test::ErrorMessageOf([&] { world.CreateJoint(wheel); }) ==
          "WheelJointDef::lowerTranslation: must not exceed upperTranslation (0), got 0.5");
    wheel.lowerTranslation = 0;
    wheel.localAxisA = {0, 0};
    MEFF_CHECK_ERROR(world.CreateJoint(wheel));
    wheel.localAxisA = {0, 1};
    wheel.bodyB = wheel.bodyA;
    MEFF_CHECK_ERROR(world.CreateJoint(wheel));
    // Nothing refused was created.
    CHECK(world.GetJoints().empty());
}

TEST_CASE("Joint motor speed, translation and speed calls check the joint type",
          "[joints][prismatic][wheel][errors]")
{
    Rig rig({0, -10});
    World& world = rig.world;
    const JointId rod =
        world.CreateJoint(world.MakeDistanceJointDef(rig.ground, rig.box, {0, 2}, {0, 0}));
    CHECK(meff::test::ErrorMessageOf([&] { world.SetJointMotorSpeed(rod, 1); }) ==
          "World::SetJointMotorSpeed: the joint has no motor (only revolute, prismatic and wheel "
          "joints do)");
    MEFF_CHECK_ERROR(world.GetJointTranslation(rod));
    MEFF_CHECK_ERROR(world.GetJointSpeed(rod));

    const JointId pin = world.CreateJoint(world.MakeRevoluteJointDef(rig.ground, rig.box, {0, 0}));
    MEFF_CHECK_ERROR(world.GetJointTranslation(pin));
    world.SetAngularVelocity(rig.box, 2);
    CHECK(world.GetJointSpeed(pin) == 2);
    MEFF_CHECK_ERROR(world.SetJointMotorSpeed(pin, std::nanf("")));

    const JointId wheel =
        world.CreateJoint(world.MakeWheelJointDef(rig.ground, rig.box, {0, 0}, {0, 1}));
    world.SetJointMotorSpeed(wheel, -3); // accepted
    world.DestroyJoint(wheel);
    MEFF_CHECK_ERROR(world.SetJointMotorSpeed(wheel, 1)); // stale id
}
