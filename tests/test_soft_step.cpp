// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The soft-step back end (SolverKind::SoftStep, engine/src/solvers/soft_step/) against analytic
// answers — a soft spring's frequency and decay, a pinned rod's first step, a pendulum's energy
// over 1000 s, each joint's constraint — and the world's promises under it: determinism,
// snapshots, sleep, continuous collision and events.
#include "analytic_support.h"

#include "meff/world.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

using namespace meff;
using namespace meff::analytic;

namespace
{

World MakeSoftWorld(Vec2 gravity = {0, -10})
{
    WorldDef def;
    def.gravity = gravity;
    def.solver.kind = SolverKind::SoftStep;
    def.allowSleep = false; // resting bodies are read step after step (their contact reports)
    return World{def};
}

} // namespace

TEST_CASE("Soft step: a soft distance joint oscillates as the damped spring of its hertz and "
          "damping ratio",
          "[soft_step][analytic]")
{
    // A 2 kg ball on a spring to a fixed point, no gravity, stretched 0.5 m and released: x(t)
    // = L + A·e^(−ζωt)·cos(ω_d·t) with ω = 2π·f, ω_d = ω·√(1 − ζ²).
    const double f = 1, zeta = 0.1, L = 2, A = 0.5;
    World world = MakeSoftWorld({0, 0});
    const BodyId anchor = AddAnchor(world, {0, 0});
    const BodyId ball = AddBall(world, {Real(L + A), 0}, {0, 0}, Real(0.2), Material(15.9f, 0));
    DistanceJointDef def = world.MakeDistanceJointDef(anchor, ball, {0, 0}, {Real(L + A), 0});
    def.length = Real(L);
    def.minLength = 0; // a spring, not a rod
    def.maxLength = kMaxReal;
    def.hertz = Real(f);
    def.dampingRatio = Real(zeta);
    world.CreateJoint(def);

    // Upward zero crossings of x − L (period) and the maxima of x − L (decay).
    std::vector<double> crossings, peaks;
    double previous = A, beforePrevious = A;
    const double dt = kDt;
    for (int i = 1; i <= 600; ++i)
    {
        world.Step(kDt);
        const double x = world.GetPosition(ball).x - L;
        if (previous < 0 && x >= 0)
        {
            crossings.push_back((i - 1 + previous / (previous - x)) * dt);
        }
        if (previous > beforePrevious && previous >= x && previous > 0)
        {
            peaks.push_back(previous);
        }
        beforePrevious = previous;
        previous = x;
    }
    REQUIRE(crossings.size() >= 5);
    REQUIRE(peaks.size() >= 4);
    const double omega = 2 * kPiD * f;
    const double periodExact = 2 * kPiD / (omega * std::sqrt(1 - zeta * zeta));
    const double period = (crossings.back() - crossings.front()) / double(crossings.size() - 1);
    // The implicit spring over sub-steps h = dt/4 shifts the frequency by O((hω)²) ≈ 7e-4 and
    // peaks are read at frame times (dt/T = 1.7 %, which the averaged crossings do not see):
    // 2 % as the issue asks.
    CHECK(period == Approx(periodExact).epsilon(0.02));
    // Decay per period e^(−ζ·ω·T_d); sampling a peak at frame times lowers it by at most
    // 1 − cos(ω·dt/2) ≈ 0.14 % of the amplitude: 5 % as the issue asks.
    const double decay = std::pow(peaks.back() / peaks.front(), 1.0 / double(peaks.size() - 1));
    CHECK(decay == Approx(std::exp(-zeta * omega * periodExact)).epsilon(0.05));
}

TEST_CASE("Soft step: a rod pinned at one end starts with alpha = 3g/(2L) and the pin carries "
          "the seed's m_eff * g",
          "[soft_step][analytic][pendulum]")
{
    World world = MakeSoftWorld();
    const Real L = 2, hx = L / 2, hy = Real(0.02);
    const BodyId ground = AddAnchor(world, {0, 0});
    const BodyId rod = AddBox(world, BodyType::Dynamic, {hx, 0}, 0, hx, hy, Material(5, 0));
    const JointId pin = world.CreateJoint(world.MakeRevoluteJointDef(ground, rod, {0, 0}));
    const double g = 10, m = world.GetMass(rod), Ic = world.GetRotationalInertia(rod);
    world.Step(kDt);

    // As for the Box2D back end (test_pendulum.cpp): I_pin = Ic + m·hx², α = m·g·hx/I_pin,
    // and the pin's force F = g·m_eff with the seed's m_eff = 1/(1/m + hx²/Ic).
    const double alpha = m * g * hx / (Ic + m * hx * hx);
    const double force = g / (1 / m + double(hx) * hx / Ic);
    // Within the step the rod turns by α·dt²/2 ≈ 1e-3 rad, which changes α by cos θ − 1 ≈ 5e-7
    // and adds a centripetal pull ω²·hx ≈ 2e-3·g; the soft point row also feeds back the
    // anchors' drift over the step, of order (h·ω_joint)² of the 1e-3 rad turn: 0.5 % holds
    // all of it.
    CHECK(-world.GetAngularVelocity(rod) / kDt == Approx(alpha).epsilon(0.005));
    CHECK(-world.GetAngularVelocity(rod) / kDt == Approx(3 * g / (2 * L)).epsilon(0.005));
    // The stored impulse is the last sub-step's, h = dt/4: the pin force near t = dt − h/2,
    // when the rod has turned θ = α·t²/2 and spins at ω = α·t. The centre's acceleration is
    // then α·hx along the rod's normal plus ω²·hx towards the pin, and F = m·(a_c − g).
    const double t = kDt - kDt / 8.0, theta = alpha * t * t / 2, omega = alpha * t;
    const double ax = -alpha * hx * std::sin(theta) - omega * omega * hx * std::cos(theta);
    const double ay = -alpha * hx * std::cos(theta) + omega * omega * hx * std::sin(theta);
    const JointReaction reaction = world.GetReaction(pin, 1 / kDt);
    // The sub-step's impulse averages the force over h, whose change over h is below 1e-3 of
    // it; the soft row's drift feedback as above: 0.5 % of the force.
    CHECK(reaction.force.x == Approx(m * ax).margin(0.005 * force));
    CHECK(reaction.force.y == Approx(m * (ay + g)).epsilon(0.005));
    CHECK(reaction.force.y == Approx(force).epsilon(0.005));
}

TEST_CASE("Soft step: a frictionless pendulum keeps its energy within 1 % over 1000 s",
          "[soft_step][analytic][pendulum]")
{
    World world = MakeSoftWorld();
    const BodyId ground = AddAnchor(world, {0, 5});
    const BodyId rod = AddBox(world, BodyType::Dynamic, {1, 5}, 0, 1, Real(0.05), Material(1, 0));
    world.CreateJoint(world.MakeRevoluteJointDef(ground, rod, {0, 5}));
    const double m = world.GetMass(rod), g = 10;
    const auto energy = [&]
    {
        return KineticEnergy(world, std::vector<BodyId>{rod}) +
               m * g * double(world.GetWorldCenter(rod).y);
    };
    const double e0 = energy();
    const double swing = m * g * 1; // the drop of the centre from release to the bottom
    double worst = 0;
    for (int i = 0; i < 60000; ++i)
    {
        world.Step(kDt);
        if (i % 60 == 59)
        {
            worst = std::max(worst, std::abs(energy() - e0) / swing);
        }
    }
    INFO("largest energy change over 1000 s, as a fraction of the swing: " << worst);
    CHECK(worst < 0.01);
}

TEST_CASE("Soft step: every joint type holds its constraint under gravity", "[soft_step][joint]")
{
    World world = MakeSoftWorld();
    const BodyId ground = AddAnchor(world, {0, 0});
    const ShapeDef material = Material(1, Real(0.3));
    const auto box = [&](Vec2 p)
    { return AddBox(world, BodyType::Dynamic, p, 0, Real(0.5), Real(0.25), material); };

    const BodyId pinned = box({1, 0});
    const JointId revolute = world.CreateJoint(world.MakeRevoluteJointDef(ground, pinned, {0, 0}));
    const BodyId roped = box({4, 0});
    const JointId rod =
        world.CreateJoint(world.MakeDistanceJointDef(ground, roped, {3, 2}, {4, 0}));
    const BodyId slider = box({7, 0});
    PrismaticJointDef slide = world.MakePrismaticJointDef(ground, slider, {7, 0}, {1, 1});
    slide.enableLimit = true;
    slide.lowerTranslation = -1;
    slide.upperTranslation = 1;
    const JointId prismatic = world.CreateJoint(slide);
    const BodyId welded = box({10, 0});
    const JointId weld = world.CreateJoint(world.MakeWeldJointDef(ground, welded, {9.5f, 0}));
    const BodyId wheel = AddBall(world, {13, 0}, {0, 0}, Real(0.3), material);
    WheelJointDef hub = world.MakeWheelJointDef(ground, wheel, {13, 0}, {0, 1});
    hub.hertz = 4;
    hub.dampingRatio = Real(0.7);
    const JointId wheelJoint = world.CreateJoint(hub);
    const BodyId carried = box({16, 0});
    MotorJointDef follow = world.MakeMotorJointDef(ground, carried);
    follow.maxForce = 1000;
    follow.maxTorque = 1000;
    const JointId motor = world.CreateJoint(follow);
    const BodyId dragged = box({19, 0});
    const JointId mouse =
        world.CreateJoint(MouseJointDef{.bodyA = ground,
                                        .bodyB = dragged,
                                        .target = {19, 0},
                                        .maxForce = 1000 * world.GetMass(dragged)});
    const double wheelMass = world.GetMass(wheel);

    for (int i = 0; i < 180; ++i)
    {
        world.Step(kDt);
    }
    const auto gap = [&](JointId j) { return Distance(world.GetAnchorA(j), world.GetAnchorB(j)); };
    // Rigid rows are held to a small fraction of linear slop (5 mm) once settled: the soft
    // joint rows settle at their load over (2π·60 Hz)² — 0.1 mm for these 0.125 kg boxes.
    CHECK(gap(revolute) < 1e-3);
    CHECK(std::abs(Distance(world.GetAnchorA(rod), world.GetAnchorB(rod)) - std::sqrt(5.0f)) <
          1e-3);
    // The prismatic keeps its angle and its axis, and stops at its lower limit −1 m along
    // (1, 1)/√2 (the box slides down the diagonal).
    const Vec2 slid = world.GetPosition(slider) - Vec2{7, 0};
    CHECK(std::abs(world.GetAngle(slider)) < 1e-3);
    CHECK(std::abs(slid.x - slid.y) < 1e-3);
    CHECK(world.GetJointTranslation(prismatic) == Approx(-1).margin(0.01));
    CHECK(gap(weld) < 1e-3);
    CHECK(std::abs(world.GetAngle(welded)) < 1e-3);
    // The wheel hangs on its spring, sagging m·g/k = g/(2π·4 Hz)² = 15.8 mm; its side row holds.
    const double k = wheelMass * std::pow(2 * kPiD * 4, 2);
    CHECK(13 - world.GetPosition(wheel).x == Approx(0).margin(1e-3));
    CHECK(-world.GetPosition(wheel).y == Approx(wheelMass * 10 / k).epsilon(0.05));
    (void)wheelJoint;
    // The motor joint holds the box at its offset (none) against gravity, within its
    // correction's lag of g·dt²-order; the mouse spring holds its box within m·g/k of the
    // target (k from the default 5 Hz: 10 mm).
    CHECK(Distance(world.GetPosition(carried), {16, 0}) < 0.01);
    (void)motor;
    CHECK(Distance(world.GetPosition(dragged), {19, 0}) < 0.02);
    (void)mouse;
}

namespace
{

/// A pile of boxes on the ground and a short chain: every contact kind and a joint.
World MakePile(bool allowSleep)
{
    WorldDef def;
    def.solver.kind = SolverKind::SoftStep;
    def.allowSleep = allowSleep;
    World world{def};
    const BodyId ground = world.CreateBody(BodyDef{});
    world.CreateShape(ground, ShapeDef{}, Segment{{-20, 0}, {20, 0}});
    for (int i = 0; i < 12; ++i)
    {
        AddBox(world, BodyType::Dynamic, {Real(i % 4) * Real(1.1) - 2, Real(0.6) + Real(i / 4)},
               Real(0.1) * Real(i % 3), Real(0.5), Real(0.5), Material(1, Real(0.6)));
    }
    BodyId previous = AddAnchor(world, {6, 5});
    for (int i = 0; i < 5; ++i)
    {
        const BodyId link = AddBox(world, BodyType::Dynamic, {Real(6.5) + Real(i), 5}, 0, Real(0.5),
                                   Real(0.1), Material(1, Real(0.6)));
        world.CreateJoint(world.MakeRevoluteJointDef(previous, link, {Real(6) + Real(i), 5}));
        previous = link;
    }
    return world;
}

} // namespace

TEST_CASE("Soft step: the same world steps to the same state, and a snapshot replays bit for "
          "bit",
          "[soft_step][determinism]")
{
    World a = MakePile(false), b = MakePile(false);
    WorldSnapshot snapshot;
    std::vector<std::uint64_t> hashes;
    for (int i = 0; i < 240; ++i)
    {
        a.Step(kDt);
        b.Step(kDt);
        REQUIRE(a.GetStateHash() == b.GetStateHash());
        if (i == 119)
        {
            snapshot = a.SaveSnapshot();
        }
        if (i >= 120)
        {
            hashes.push_back(a.GetStateHash());
        }
    }
    a.RestoreSnapshot(snapshot);
    for (const std::uint64_t hash : hashes)
    {
        a.Step(kDt);
        REQUIRE(a.GetStateHash() == hash);
    }
}

TEST_CASE("Soft step: a resting stack falls asleep, a hit wakes it, and a bullet does not tunnel",
          "[soft_step][sleeping][continuous]")
{
    WorldDef def;
    def.solver.kind = SolverKind::SoftStep;
    def.allowSleep = true;
    World world{def};
    const BodyId ground = world.CreateBody(BodyDef{});
    world.CreateShape(ground, ShapeDef{}, Segment{{-20, 0}, {20, 0}});
    std::vector<BodyId> stack;
    for (int i = 0; i < 3; ++i)
    {
        // Placed at their resting distance: 1 m boxes, 0.015 m apart (skins less slop).
        stack.push_back(AddBox(world, BodyType::Dynamic, {0, Real(0.515) + Real(1.015) * Real(i)},
                               0, Real(0.5), Real(0.5), Material(1, Real(0.6))));
    }
    // Box2D's rule: 0.5 s below 0.01 m/s and 2°/s; the stack is at rest from the start.
    for (int i = 0; i < 120; ++i)
    {
        world.Step(kDt);
    }
    for (const BodyId box : stack)
    {
        CHECK_FALSE(world.IsAwake(box));
    }
    AddBall(world, {-8, 0.5f}, {20, 0}, Real(0.2), Material(1, Real(0.6)));
    for (int i = 0; i < 60; ++i)
    {
        world.Step(kDt);
    }
    CHECK(world.IsAwake(stack[0]));

    // A 0.1 m ball at 300 m/s against a 0.1 m thick wall: 5 m per step, so only continuous
    // collision stops it.
    World shot = MakeSoftWorld({0, 0});
    AddBox(shot, BodyType::Static, {10, 0}, 0, Real(0.05), 5, Material(0, 0));
    BodyDef bulletDef;
    bulletDef.type = BodyType::Dynamic;
    bulletDef.position = {0, 0};
    bulletDef.linearVelocity = {300, 0};
    bulletDef.bullet = true;
    const BodyId bullet = shot.CreateBody(bulletDef);
    shot.CreateShape(bullet, Material(1, 0), Circle{{0, 0}, Real(0.05)});
    for (int i = 0; i < 10; ++i)
    {
        shot.Step(kDt);
    }
    CHECK(shot.GetPosition(bullet).x < 10);
}

TEST_CASE("Soft step: a resting box's reports carry m*g*dt per step, and a landing raises "
          "begin and hit events",
          "[soft_step][events]")
{
    World world = MakeSoftWorld();
    const BodyId ground = world.CreateBody(BodyDef{});
    ShapeDef groundDef;
    groundDef.enableHitEvents = true;
    world.CreateShape(ground, groundDef, Segment{{-5, 0}, {5, 0}});
    const BodyId box =
        AddBox(world, BodyType::Dynamic, {0, 2}, 0, Real(0.5), Real(0.5), Material(2, Real(0.6)));
    bool began = false, hit = false;
    for (int i = 0; i < 240; ++i)
    {
        world.Step(kDt);
        began = began || !world.GetContactBeginEvents().empty();
        hit = hit || !world.GetContactHitEvents().empty();
    }
    CHECK(began);
    CHECK(hit); // it lands at √(2·g·1.5 m) ≈ 5.5 m/s, above the 1 m/s threshold
    double impulse = 0;
    for (const ContactPointReport& report : world.GetContactReports())
    {
        impulse += report.normalImpulse;
    }
    // At rest the ground carries the box's weight: the step's total impulse is m·g·dt, up to
    // the settling left after 4 s (the box is still within 1e-3 m/s of rest).
    const double weight = world.GetMass(box) * 10 * double(kDt);
    CHECK(impulse == Approx(weight).epsilon(0.01));
}

TEST_CASE("Soft step: a motor at its largest torque or force gives the body exactly that for the "
          "whole step, half kicks included",
          "[soft_step][analytic][motor]")
{
    // A motor asked for a speed it cannot reach pushes with its largest torque T (or force F)
    // all the time, so from rest ω(t) = T·t/I and v(t) = F·t/m. The soft step's velocity
    // Verlet opens and closes each step with half a sub-step's kick; a motor bounded by a whole
    // sub-step's impulse there gave 5 sub-steps' impulse per 4-sub-step step: 25 % too fast.
    World world = MakeSoftWorld({0, 0});
    const BodyId ground = AddAnchor(world, {0, 0});
    const Real T = 3, F = 4;
    const BodyId disk = AddBall(world, {0, 0}, {0, 0}, Real(0.5), Material(2, 0));
    RevoluteJointDef hinge = world.MakeRevoluteJointDef(ground, disk, {0, 0});
    hinge.enableMotor = true;
    hinge.motorSpeed = 1000;
    hinge.maxMotorTorque = T;
    world.CreateJoint(hinge);

    const BodyId slider =
        AddBox(world, BodyType::Dynamic, {0, 5}, 0, Real(0.5), Real(0.25), Material(3, 0));
    PrismaticJointDef rail = world.MakePrismaticJointDef(ground, slider, {0, 5}, {1, 0});
    rail.enableMotor = true;
    rail.motorSpeed = 1000;
    rail.maxMotorForce = F;
    world.CreateJoint(rail);

    const BodyId wheel = AddBall(world, {0, 10}, {0, 0}, Real(0.4), Material(1, 0));
    WheelJointDef axle = world.MakeWheelJointDef(ground, wheel, {0, 10}, {0, 1});
    axle.enableMotor = true;
    axle.motorSpeed = -1000;
    axle.maxMotorTorque = T;
    world.CreateJoint(axle);

    const int steps = 60;
    for (int i = 0; i < steps; ++i)
    {
        world.Step(kDt);
    }
    const double t = steps * double(kDt);
    // Float sums of 60 × 4 equal impulses and the rows' effective masses (the seed's 1/I and
    // 1/m, one row each): a few ulps per sub-step, far inside 1e-4. The buggy bound is 25 % off.
    CHECK(world.GetAngularVelocity(disk) ==
          Approx(T * t / world.GetRotationalInertia(disk)).epsilon(1e-4));
    CHECK(world.GetLinearVelocity(slider).x == Approx(F * t / world.GetMass(slider)).epsilon(1e-4));
    CHECK(world.GetAngularVelocity(wheel) ==
          Approx(-T * t / world.GetRotationalInertia(wheel)).epsilon(1e-4));
}
