// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Weld, motor and mouse joints through the World API: what each joint is for (analytic checks),
// both solver modes (block and scalar rows), the runtime setters, and argument validation.
// Bit-for-bit agreement with Box2D is in test_joints_box2d_weld_motor_mouse.cpp.
#include "error_checks.h"
#include "joints/joint.h"
#include "meff/world.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <span>
#include <utility>
#include <vector>

using namespace meff;

namespace
{

constexpr Real kDt = Real(1) / Real(60);

World MakeWorld(bool blockJoints, Vec2 gravity = {0, -10})
{
    WorldDef def;
    def.gravity = gravity;
    def.solver.blockJoints = blockJoints;
    return World(def);
}

BodyId AddBox(World& world, Vec2 position, Real angle, Real halfWidth, Real halfHeight,
              Vec2 center = {0, 0})
{
    const BodyId body =
        world.CreateBody({.type = BodyType::Dynamic, .position = position, .angle = angle});
    world.CreateShape(body, ShapeDef{}, MakeOffsetBox(halfWidth, halfHeight, center, 0));
    return body;
}

/// B's pose in A's frame: where B's origin is and how far B is turned, seen from A.
struct RelativePose
{
    Vec2 position;
    Real angle = 0;
};

RelativePose PoseOfBInA(const World& world, BodyId a, BodyId b)
{
    return {world.GetLocalPoint(a, world.GetPosition(b)), world.GetAngle(b) - world.GetAngle(a)};
}

} // namespace

TEST_CASE("A rigidly welded pair falls and spins as one body", "[joints][weld]")
{
    const bool blockJoints = GENERATE(true, false);
    CAPTURE(blockJoints);
    World world = MakeWorld(blockJoints);
    // An L of two unequal boxes, welded at their shared corner, thrown spinning.
    const BodyId a = AddBox(world, {0, 10}, Real(0.2), 1, Real(0.25));
    const BodyId b = AddBox(world, {Real(1.2), Real(10.6)}, Real(0.2), Real(0.25), Real(0.6));
    const JointId weld = world.CreateJoint(world.MakeWeldJointDef(a, b, {1, Real(10.2)}));
    // A rigid motion: both turn at ω, and B's centre moves with vA + ω×(cB − cA).
    const Real omega = 3;
    const Vec2 vA(2, 5);
    world.SetLinearVelocity(a, vA);
    world.SetAngularVelocity(a, omega);
    world.SetLinearVelocity(b,
                            vA + Cross(omega, world.GetWorldCenter(b) - world.GetWorldCenter(a)));
    world.SetAngularVelocity(b, omega);

    const RelativePose start = PoseOfBInA(world, a, b);
    const Real ma = world.GetMass(a), mb = world.GetMass(b);
    const Vec2 comStart =
        (Real(1) / (ma + mb)) * (ma * world.GetWorldCenter(a) + mb * world.GetWorldCenter(b));
    const Vec2 momentumStart = ma * world.GetLinearVelocity(a) + mb * world.GetLinearVelocity(b);
    const Vec2 vStart = (Real(1) / (ma + mb)) * momentumStart;

    Real poseDrift = 0, angleDrift = 0, anchorGap = 0;
    const int steps = 180;
    for (int i = 0; i < steps; ++i)
    {
        world.Step(kDt);
        const RelativePose pose = PoseOfBInA(world, a, b);
        poseDrift = std::max(poseDrift, Distance(pose.position, start.position));
        angleDrift = std::max(angleDrift, std::abs(pose.angle - start.angle));
        anchorGap = std::max(anchorGap, Distance(world.GetAnchorA(weld), world.GetAnchorB(weld)));
    }
    // The velocity rows remove relative motion each step; the position pass then pulls the
    // remaining drift (from rotating lever arms) back until it is within the slops: the two
    // anchors stay within linearSlop (0.005 m) of each other and the relative angle within
    // angularSlop (2°) of its start.
    const Tolerances tol;
    CHECK(anchorGap <= tol.linearSlop);
    CHECK(angleDrift <= tol.angularSlop);
    // B's origin, 0.45 m from the anchor, also moves with the angle error: up to the anchor gap
    // + 0.45 m · angle error. Measured: gap 0.83 mm and 2.5 mrad (1.1 mm at B's origin) with
    // the scalar rows, 2e-6 with the block solver, so the origin too stays within linearSlop.
    CHECK(poseDrift <= tol.linearSlop);
    // The pair still spins as one: no relative turning (the velocity rows remove it each
    // step, to float rounding of a 3 rad/s rate and the scalar rows' residual, far below
    // 1e-3 rad/s). Its rate only decays: the rows act at the lever arms of the step's start, so
    // each step bleeds a little rotational energy ((ωh)² order: ~11% over 3 s at 3 rad/s);
    // a weld never adds rotation.
    CHECK(world.GetAngularVelocity(b) == Approx(world.GetAngularVelocity(a)).margin(1e-3));
    CHECK(world.GetAngularVelocity(a) <= omega);
    CHECK(world.GetAngularVelocity(a) >= Real(0.8) * omega);

    // Joint impulses are equal and opposite, and the position pass moves the centres by
    // −mA⁻¹P and +mB⁻¹P: the centre of mass follows the free fall of one body, which the
    // semi-implicit Euler step integrates as c0 + v0·t + g·h²·n(n+1)/2. Float rounding of
    // ~10 m coordinates over 180 steps stays below 1e-4 m; 1e-3 m leaves room.
    const Vec2 com =
        (Real(1) / (ma + mb)) * (ma * world.GetWorldCenter(a) + mb * world.GetWorldCenter(b));
    const Real t = kDt * Real(steps);
    const Real fall = Real(-10) * kDt * kDt * Real(steps) * Real(steps + 1) / 2;
    CHECK(com.x == Approx(comStart.x + vStart.x * t).margin(1e-3));
    CHECK(com.y == Approx(comStart.y + vStart.y * t + fall).margin(1e-3));
}

TEST_CASE("A weld holds a cantilever's weight and moment", "[joints][weld]")
{
    const bool blockJoints = GENERATE(true, false);
    CAPTURE(blockJoints);
    World world = MakeWorld(blockJoints);
    const BodyId wall = world.CreateBody({});
    const BodyId beam = AddBox(world, {1, 5}, 0, 1, Real(0.1)); // 0.4 kg, centre 1 m out
    const JointId weld = world.CreateJoint(world.MakeWeldJointDef(wall, beam, {0, 5}));
    for (int i = 0; i < 120; ++i)
    {
        world.Step(kDt);
    }
    // At rest the weld carries the weight m·g = 4 N up and its moment m·g·1 m = 4 N·m. The
    // residual motion of a settling rigid joint is far below 1% of either.
    const JointReaction r = world.GetReaction(weld, 1 / kDt);
    CHECK(r.force.x == Approx(0).margin(0.04));
    CHECK(r.force.y == Approx(4).epsilon(0.01));
    CHECK(r.torque == Approx(4).epsilon(0.01));
    // And it sags by no more than the position pass allows.
    CHECK(std::abs(world.GetAngle(beam)) <= world.GetTolerances().angularSlop);
}

TEST_CASE("A soft weld is a torsional spring at its frequency", "[joints][weld]")
{
    const bool blockJoints = GENERATE(true, false);
    CAPTURE(blockJoints);
    World world = MakeWorld(blockJoints, {0, 0});
    const BodyId ground = world.CreateBody({});
    // The box's origin is at the weld so that b2AngularStiffness's inertia (about the origin)
    // is the inertia about the weld, and the spring's frequency is the body's.
    const BodyId arm = AddBox(world, {0, 0}, 0, 1, Real(0.1), {1, 0});
    WeldJointDef def = world.MakeWeldJointDef(ground, arm, {0, 0});
    const Real hertz = 1;
    def.hertz = hertz;
    def.dampingRatio = 0;
    world.CreateJoint(def);
    // Turning about the weld at 0.5 rad/s: the centre, 1 m out, moves at 0.5 m/s.
    world.SetAngularVelocity(arm, Real(0.5));
    world.SetLinearVelocity(arm, {0, Real(0.5)});

    // The period from the angle's upward zero crossings over several cycles.
    std::vector<Real> upCrossings;
    Real previous = world.GetAngle(arm);
    Real amplitude = 0;
    for (int i = 0; i < 600; ++i)
    {
        world.Step(kDt);
        const Real angle = world.GetAngle(arm);
        amplitude = std::max(amplitude, std::abs(angle));
        if (previous < 0 && angle >= 0)
        {
            upCrossings.push_back(Real(i + 1) * kDt - angle / (angle - previous) * kDt);
        }
        previous = angle;
    }
    REQUIRE(upCrossings.size() >= 5);
    const Real period = (upCrossings.back() - upCrossings.front()) / Real(upCrossings.size() - 1);
    // Implicit Euler lengthens the period by about (ωh)²/2 ≈ 0.5% at 1 Hz and 60 Hz; the
    // point row's coupling adds a little. 2% separates "the spring's frequency" from any
    // other (a mis-sized inertia, as about the centre here, would be off by a factor of 2).
    CHECK(period == Approx(1 / hertz).epsilon(0.02));
    // Undamped, the amplitude would be ω0/ω = 0.5/(2π) ≈ 0.080 rad. The soft row is implicit
    // Euler, which shrinks an oscillation by 1/√(1 + (ωh)²) per step: ≈ 8% over the 15 steps
    // to the first peak at 1 Hz and 60 Hz. So the amplitude lies between 90% and 100% of it.
    const Real ideal = Real(0.5) / (2 * kPi * hertz);
    CHECK(amplitude <= ideal);
    CHECK(amplitude >= Real(0.9) * ideal);
}

TEST_CASE("A mouse joint is a damped spring towards its target", "[joints][mouse]")
{
    const bool blockJoints = GENERATE(true, false);
    CAPTURE(blockJoints);
    World world = MakeWorld(blockJoints, {0, 0});
    const BodyId ground = world.CreateBody({});
    // Grabbed at its centre, the body only translates: a point mass on a spring.
    const BodyId ball = world.CreateBody({.type = BodyType::Dynamic});
    world.CreateShape(ball, ShapeDef{}, Circle{{0, 0}, Real(0.5)});
    MouseJointDef def;
    def.bodyA = ground;
    def.bodyB = ball;
    def.target = {0, 0};
    def.maxForce = 1000 * world.GetMass(ball); // never reached
    const Real hertz = GENERATE(Real(1), Real(2));
    const Real dampingRatio = GENERATE(Real(0.1), Real(1));
    CAPTURE(hertz, dampingRatio);
    def.hertz = hertz;
    def.dampingRatio = dampingRatio;
    const JointId mouse = world.CreateJoint(def);
    world.SetMouseTarget(mouse, {1, 0});
    CHECK(world.GetMouseTarget(mouse) == Vec2(1, 0));
    CHECK(world.GetAnchorA(mouse) == Vec2(1, 0));

    Real maxX = 0;
    std::vector<Real> peaks; // times of the local maxima of x
    Real x0 = 0, x1 = 0;
    for (int i = 0; i < 600; ++i)
    {
        world.Step(kDt);
        const Real x = world.GetPosition(ball).x;
        maxX = std::max(maxX, x);
        if (i >= 2 && x1 > x0 && x1 >= x)
        {
            peaks.push_back(Real(i) * kDt);
        }
        x0 = x1;
        x1 = x;
    }
    // Settled on the target (to float precision after 10 s of a damped spring).
    CHECK(world.GetPosition(ball).x == Approx(1).margin(1e-3));
    CHECK(world.GetPosition(ball).y == Approx(0).margin(1e-6));
    if (dampingRatio >= 1)
    {
        // Critically damped: reaches without overshoot. Implicit Euler only adds damping.
        CHECK(maxX <= 1);
    }
    else
    {
        // Underdamped: overshoots by at most e^(−πζ/√(1−ζ²)) ≈ 0.73 (implicit Euler's
        // damping lowers it; at 2 Hz and 60 Hz by a few tenths).
        const Real bound =
            std::exp(-kPi * dampingRatio / std::sqrt(1 - dampingRatio * dampingRatio));
        CHECK(maxX - 1 > Real(0.3));
        CHECK(maxX - 1 <= bound);
        // Successive peaks one damped period apart: 1/(f·√(1−ζ²)). Implicit Euler's period
        // error is ~(ωh)²/2 (0.5% at 1 Hz, 2% at 2 Hz); peaks are found to the step (1.7%
        // of a 1 s period, 3.3% of 0.5 s), so 5% is the bound for one period.
        REQUIRE(peaks.size() >= 2);
        const Real period = peaks[1] - peaks[0];
        CHECK(period ==
              Approx(1 / (hertz * std::sqrt(1 - dampingRatio * dampingRatio))).epsilon(0.05));
    }
}

TEST_CASE("A mouse joint's force is capped at maxForce", "[joints][mouse]")
{
    const bool blockJoints = GENERATE(true, false);
    CAPTURE(blockJoints);
    World world = MakeWorld(blockJoints, {0, 0});
    const BodyId ground = world.CreateBody({});
    const BodyId box = AddBox(world, {0, 0}, 0, Real(0.5), Real(0.5)); // 1 kg
    MouseJointDef def;
    def.bodyA = ground;
    def.bodyB = box;
    def.maxForce = 3;
    def.hertz = 5;
    def.dampingRatio = Real(0.7);
    const JointId mouse = world.CreateJoint(def);
    world.SetMouseTarget(mouse, {10, 5});
    Vec2 vPrevious = world.GetLinearVelocity(box);
    for (int i = 0; i < 60; ++i)
    {
        world.Step(kDt);
        const Vec2 v = world.GetLinearVelocity(box);
        // Δv ≤ F·h/m per step; float rounding of the clamp (Normalize then scale) ≤ 1e-6.
        CHECK(Distance(v, vPrevious) <= 3 * kDt / world.GetMass(box) * Real(1 + 1e-5));
        // The cap binds far from the target: the reaction is maxForce, pointing at it.
        const JointReaction r = world.GetReaction(mouse, 1 / kDt);
        CHECK(r.force.Length() == Approx(3).epsilon(1e-5));
        vPrevious = v;
    }
}

TEST_CASE("A motor joint drives body B to its offset from body A", "[joints][motor]")
{
    const bool blockJoints = GENERATE(true, false);
    CAPTURE(blockJoints);
    World world = MakeWorld(blockJoints);
    const BodyId base = world.CreateBody({.position = {1, 2}, .angle = Real(0.5)});
    const BodyId platform = AddBox(world, {4, 1}, 0, 1, Real(0.1)); // 0.4 kg
    MotorJointDef def = world.MakeMotorJointDef(base, platform);
    // Initialize's offsets hold the present pose.
    CHECK(def.linearOffset.x == Approx(world.GetLocalPoint(base, {4, 1}).x));
    CHECK(def.angularOffset == Real(-0.5));
    def.linearOffset = {0, 2};
    def.angularOffset = Real(0.3);
    def.maxForce = 50;
    def.maxTorque = 10;
    const JointId motor = world.CreateJoint(def);
    CHECK(world.GetAnchorA(motor) == world.GetPosition(base));
    CHECK(world.GetAnchorB(motor) == world.GetPosition(platform));

    for (int i = 0; i < 300; ++i)
    {
        world.Step(kDt);
    }
    // Unclamped, the rows make Cdot = v + (β/h)·e vanish, so each step the error shrinks to
    // (1 − β)·e = 0.7·e while the accumulated impulse carries the weight: after 300 steps only
    // the iterations' residual is left. 1 mm (and 1 mrad) is far above it and far below the
    // 2 m and 0.8 rad the joint had to move.
    const RelativePose pose = PoseOfBInA(world, base, platform);
    CHECK(pose.position.x == Approx(0).margin(1e-3));
    CHECK(pose.position.y == Approx(2).margin(1e-3));
    CHECK(pose.angle == Approx(0.3).margin(1e-3));
    const JointReaction r = world.GetReaction(motor, 1 / kDt);
    // Holds the weight, 0.4 kg · 10 m/s²: with the error decayed (0.7^300) the step's impulse is
    // m·g·h, read back as impulse/h; relative 1e-4 allows float round-off of that (measured: 4
    // exactly).
    CHECK(r.force.y == Approx(4).epsilon(1e-4));

    // The target moves (a game moving the platform): it follows.
    world.SetMotorJointOffsets(motor, {1, 3}, Real(-0.2));
    for (int i = 0; i < 300; ++i)
    {
        world.Step(kDt);
    }
    const RelativePose moved = PoseOfBInA(world, base, platform);
    CHECK(moved.position.x == Approx(1).margin(1e-3));
    CHECK(moved.position.y == Approx(3).margin(1e-3));
    CHECK(moved.angle == Approx(-0.2).margin(1e-3));
}

TEST_CASE("A motor joint's force and torque are capped", "[joints][motor]")
{
    const bool blockJoints = GENERATE(true, false);
    CAPTURE(blockJoints);
    World world = MakeWorld(blockJoints, {0, 0});
    const BodyId base = world.CreateBody({});
    const BodyId box = AddBox(world, {0, 0}, 0, Real(0.5), Real(0.5));
    MotorJointDef def = world.MakeMotorJointDef(base, box);
    def.linearOffset = {100, 0};
    def.angularOffset = 100;
    def.maxForce = 2;
    def.maxTorque = Real(0.5);
    const JointId motor = world.CreateJoint(def);
    for (int i = 0; i < 30; ++i)
    {
        world.Step(kDt);
        // Far from its target, the motor pushes with exactly its limits (the disc clamp
        // rescales to h·maxForce up to float rounding).
        const JointReaction r = world.GetReaction(motor, 1 / kDt);
        CHECK(r.force.Length() == Approx(2).epsilon(1e-5));
        CHECK(r.torque == Approx(0.5).epsilon(1e-5));
    }
}

TEST_CASE("Weld, motor and mouse joints reject bad arguments", "[joints][make]")
{
    using detail::MakeJoint;
    const Real nan = std::numeric_limits<Real>::quiet_NaN();
    const Real inf = std::numeric_limits<Real>::infinity();

    SECTION("weld")
    {
        WeldJointDef def;
        def.localAnchorA = {nan, 0};
        MEFF_CHECK_ERROR_WITH(MakeJoint(def, 0, 1, 1, 1),
                              Catch::Contains("WeldJointDef::localAnchorA"));
        def.localAnchorA = {0, 0};
        def.referenceAngle = inf;
        MEFF_CHECK_ERROR_WITH(MakeJoint(def, 0, 1, 1, 1), Catch::Contains("referenceAngle"));
        def.referenceAngle = 0;
        def.hertz = -1;
        MEFF_CHECK_ERROR(MakeJoint(def, 0, 1, 1, 1));
        MEFF_CHECK_ERROR_WITH(
            MakeJoint(def, 0, 1, 1, 1),
            Catch::Contains("WeldJointDef::hertz: must be finite and >= 0, got -1"));
        def.hertz = 1;
        def.dampingRatio = nan;
        MEFF_CHECK_ERROR_WITH(MakeJoint(def, 0, 1, 1, 1), Catch::Contains("dampingRatio"));
    }
    SECTION("motor")
    {
        MotorJointDef def;
        def.linearOffset = {0, inf};
        MEFF_CHECK_ERROR_WITH(MakeJoint(def, 0, 1), Catch::Contains("MotorJointDef::linearOffset"));
        def.linearOffset = {0, 0};
        def.angularOffset = nan;
        MEFF_CHECK_ERROR_WITH(MakeJoint(def, 0, 1), Catch::Contains("angularOffset"));
        def.angularOffset = 0;
        def.maxForce = -2;
        MEFF_CHECK_ERROR_WITH(
            MakeJoint(def, 0, 1),
            Catch::Contains("MotorJointDef::maxForce: must be finite and >= 0, got -2"));
        def.maxForce = 1;
        def.maxTorque = -1;
        MEFF_CHECK_ERROR_WITH(
            MakeJoint(def, 0, 1),
            Catch::Contains("MotorJointDef::maxTorque: must be finite and >= 0, got -1"));
        def.maxTorque = 1;
        def.correctionFactor = Real(1.5);
        MEFF_CHECK_ERROR_WITH(
            MakeJoint(def, 0, 1),
            Catch::Contains("MotorJointDef::correctionFactor: must be at most 1, got 1.5"));
        def.correctionFactor = Real(-0.1);
        MEFF_CHECK_ERROR_WITH(MakeJoint(def, 0, 1), Catch::Contains("correctionFactor"));
        def.correctionFactor = 1; // the ends of [0, 1] are allowed
        MEFF_CHECK_NO_ERROR(MakeJoint(def, 0, 1));
    }
    SECTION("mouse")
    {
        MouseJointDef def;
        const Transform xf;
        def.target = {nan, 0};
        MEFF_CHECK_ERROR_WITH(MakeJoint(def, 0, 1, 0, 1, xf, true),
                              Catch::Contains("MouseJointDef::target"));
        def.target = {0, 0};
        def.maxForce = -1;
        MEFF_CHECK_ERROR_WITH(MakeJoint(def, 0, 1, 0, 1, xf, true), Catch::Contains("maxForce"));
        def.maxForce = 1;
        def.hertz = inf;
        MEFF_CHECK_ERROR_WITH(MakeJoint(def, 0, 1, 0, 1, xf, true), Catch::Contains("hertz"));
        def.hertz = 5;
        MEFF_CHECK_ERROR_WITH(MakeJoint(def, 0, 1, 0, 1, xf, false),
                              Catch::Contains("MouseJointDef::bodyB: must be a dynamic body"));
    }
    SECTION("world")
    {
        World world;
        const BodyId ground = world.CreateBody({});
        const BodyId box = AddBox(world, {0, 0}, 0, 1, 1);
        MouseJointDef mouseDef;
        mouseDef.bodyA = box;
        mouseDef.bodyB = ground; // static: nothing to drag
        MEFF_CHECK_ERROR(world.CreateJoint(mouseDef));
        CHECK(world.GetJoints().empty());

        const JointId weld = world.CreateJoint(world.MakeWeldJointDef(ground, box, {0, 0}));
        MEFF_CHECK_ERROR_WITH(world.SetMouseTarget(weld, {1, 1}),
                              Catch::Contains("not a mouse joint"));
        MEFF_CHECK_ERROR_WITH(world.SetMotorJointOffsets(weld, {1, 1}, 0),
                              Catch::Contains("not a motor joint"));
        MEFF_CHECK_ERROR(world.MakeWeldJointDef(ground, box, {nan, 0}));

        const JointId motor = world.CreateJoint(world.MakeMotorJointDef(ground, box));
        MEFF_CHECK_ERROR(world.SetMotorJointOffsets(motor, {inf, 0}, 0));
        MEFF_CHECK_ERROR(world.SetMotorJointOffsets(motor, {0, 0}, nan));
        mouseDef.bodyA = ground;
        mouseDef.bodyB = box;
        const JointId mouse = world.CreateJoint(mouseDef);
        MEFF_CHECK_ERROR(world.SetMouseTarget(mouse, {0, nan}));
        CHECK(world.GetJointType(weld) == JointType::Weld);
        CHECK(world.GetJointType(motor) == JointType::Motor);
        CHECK(world.GetJointType(mouse) == JointType::Mouse);
    }
}

TEST_CASE("Snapshots keep a moved mouse target", "[joints][mouse][snapshot]")
{
    World world = MakeWorld(true);
    const BodyId ground = world.CreateBody({});
    const BodyId box = AddBox(world, {0, 0}, 0, Real(0.5), Real(0.5));
    MouseJointDef def;
    def.bodyA = ground;
    def.bodyB = box;
    def.target = {Real(0.2), Real(0.3)};
    def.maxForce = 100;
    const JointId mouse = world.CreateJoint(def);
    world.SetMouseTarget(mouse, {2, 1});
    for (int i = 0; i < 10; ++i)
    {
        world.Step(kDt);
    }
    const WorldSnapshot saved = world.SaveSnapshot();
    std::vector<std::uint64_t> first;
    world.SetMouseTarget(mouse, {-1, 2});
    for (int i = 0; i < 30; ++i)
    {
        world.Step(kDt);
        first.push_back(world.GetStateHash());
    }
    world.RestoreSnapshot(saved);
    CHECK(world.GetMouseTarget(mouse) == Vec2(2, 1)); // the target is part of the state
    world.SetMouseTarget(mouse, {-1, 2});
    for (int i = 0; i < 30; ++i)
    {
        world.Step(kDt);
        CHECK(world.GetStateHash() == first[std::size_t(i)]);
    }
}

namespace
{

/// Records the points and segments a world draws.
class PointRecorder final : public DebugDraw
{
  public:
    std::vector<Vec2> points;
    std::vector<std::pair<Vec2, Vec2>> segments;

    void DrawPolygon(std::span<const Vec2>, const DrawColor&) override {}
    void DrawSolidPolygon(std::span<const Vec2>, const DrawColor&) override {}
    void DrawCircle(Vec2, Real, const DrawColor&) override {}
    void DrawSolidCircle(Vec2, Real, Vec2, const DrawColor&) override {}
    void DrawSegment(Vec2 p1, Vec2 p2, const DrawColor&) override { segments.push_back({p1, p2}); }
    void DrawTransform(const Transform&) override {}
    void DrawPoint(Vec2 p, Real, const DrawColor&) override { points.push_back(p); }
};

} // namespace

TEST_CASE("A mouse joint draws its target and the grabbed point", "[joints][mouse][draw]")
{
    World world = MakeWorld(true);
    const BodyId ground = world.CreateBody({.position = {50, 50}});
    const BodyId box = AddBox(world, {0, 0}, 0, Real(0.5), Real(0.5));
    MouseJointDef def;
    def.bodyA = ground;
    def.bodyB = box;
    def.target = {Real(0.25), 0};
    def.maxForce = 10;
    const JointId mouse = world.CreateJoint(def);
    world.SetMouseTarget(mouse, {3, 4});

    PointRecorder draw;
    DrawFlags flags;
    flags.shapes = false;
    world.Draw(draw, flags);
    // As b2Joint::Draw: the target, the grabbed point, the line between; nothing reaches to
    // the ground body's origin (50, 50), which takes no part.
    REQUIRE(draw.points.size() == 2);
    CHECK(draw.points[0] == Vec2(3, 4));
    CHECK(draw.points[1] == Vec2(Real(0.25), 0));
    REQUIRE(draw.segments.size() == 1);
    CHECK(draw.segments[0].first == Vec2(3, 4));
    CHECK(draw.segments[0].second == Vec2(Real(0.25), 0));
}
