// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Determinism (the same inputs give bit-identical runs, checked by the state hash every step)
// and rollback (stepping on from a restored snapshot is bit-identical to the original run).
#include <catch2/catch.hpp>

#include "error_checks.h"
#include "world_fixtures.h"
#include "meff/world.h"

#include <cmath>
#include <vector>

using namespace meff;

namespace
{

World MakePile()
{
    return meff::test::MakePile(16, 5, Real(0.37), Real(0.3));
}

std::vector<std::uint64_t> Hashes(World& world, int steps)
{
    std::vector<std::uint64_t> hashes;
    for (int i = 0; i < steps; ++i)
    {
        world.Step(Real(1) / 60);
        hashes.push_back(world.GetStateHash());
    }
    return hashes;
}

} // namespace

TEST_CASE("the same scene run twice is bit-identical at every step", "[determinism]")
{
    World first = MakePile();
    World second = MakePile();
    const std::vector<std::uint64_t> a = Hashes(first, 300);
    const std::vector<std::uint64_t> b = Hashes(second, 300);
    CHECK(a == b);
    // The hash follows the state: it changes while the pile falls.
    CHECK(a.front() != a[100]);
}

TEST_CASE("the state hash sees a one-ulp difference", "[determinism]")
{
    World first = MakePile();
    World second = MakePile();
    first.Step(Real(1) / 60);
    second.Step(Real(1) / 60);
    REQUIRE(first.GetStateHash() == second.GetStateHash());
    const BodyId body = second.GetBodies()[3];
    const Vec2 v = second.GetLinearVelocity(body);
    second.SetLinearVelocity(body, {std::nextafter(v.x, Real(1)), v.y});
    CHECK(first.GetStateHash() != second.GetStateHash());
}

TEST_CASE("stepping on from a restored snapshot is bit-identical", "[determinism]")
{
    World world = MakePile();
    Hashes(world, 60); // mid-fall: contacts and warm-start impulses exist
    REQUIRE(world.GetTouchingContactCount() > 0);
    const WorldSnapshot snapshot = world.SaveSnapshot();
    const BodyId probe = world.GetBodies()[5];
    const std::vector<std::uint64_t> original = Hashes(world, 120);
    const Vec2 originalEnd = world.GetPosition(probe);

    world.RestoreSnapshot(snapshot);
    CHECK(world.GetStepCount() == 60);
    const std::vector<std::uint64_t> replay = Hashes(world, 120);
    CHECK(replay == original);
    CHECK(world.GetPosition(probe) == originalEnd);

    // A snapshot can be restored more than once, and into a world whose ids it shares.
    world.RestoreSnapshot(snapshot);
    CHECK(Hashes(world, 120) == original);
}

TEST_CASE("restoring an empty snapshot is refused", "[determinism]")
{
    World world = MakePile();
    MEFF_CHECK_ERROR(world.RestoreSnapshot(WorldSnapshot{}));
}

namespace
{

/// One of each of issue 19's shapes, joints and surface settings, apart from one another on a
/// static floor (top at y = 0): a ball with rolling resistance rolling down an open chain, a
/// rounded box on a conveyor, a pulley, a gear between two hinges (the first on a spring), a
/// box on a prismatic spring, a box slowed by a friction joint, and a capsule with rolling
/// resistance tumbling onto the floor.
struct Gadgets
{
    World world;
    BodyId floor{}, ballBody{}, capsuleBody{};
    ChainId chain{};
    ShapeId ball{}, belt{}, capsule{};
    JointId pulley{}, hinge1{}, hinge2{}, gear{}, slider{}, friction{};
    std::vector<JointId> joints;

    explicit Gadgets(SolverKind kind) : world(Def(kind))
    {
        floor = world.CreateBody({});
        world.CreateShape(floor, {}, MakeOffsetBox(40, 1, {0, -1}, 0));
        // Listed right to left, so the solid side is up; down to the right.
        const Vec2 terrain[] = {{-12, 0.2f}, {-14, 0.8f}, {-16, 1.6f}, {-18, 2.6f}};
        chain = world.CreateChain(floor, {}, Chain{.points = terrain});
        ballBody = world.CreateBody(
            {.type = BodyType::Dynamic, .position = {-17.5f, 2.8f}, .linearVelocity = {2, 0}});
        ball = world.CreateShape(ballBody, {.rollingResistance = 0.1f}, Circle{{0, 0}, 0.3f});

        const BodyId beltBody = world.CreateBody({.position = {-8, 0.5f}});
        belt = world.CreateShape(beltBody, {.tangentSpeed = 2}, MakeBox(2, 0.5f));
        Polygon rounded = MakeBox(0.3f, 0.2f);
        rounded.radius = 0.1f;
        world.CreateShape(world.CreateBody({.type = BodyType::Dynamic, .position = {-9, 1.5f}}), {},
                          rounded);

        const BodyId heavy = AddBox({0, 5}, 2);
        const BodyId light = AddBox({4, 5}, 1);
        pulley = world.CreateJoint(
            world.MakePulleyJointDef(heavy, light, {0, 10}, {4, 10}, {0, 5}, {4, 5}, 1));

        const BodyId wheel1 = AddWheel({8, 6}, 0.5f);
        const BodyId wheel2 = AddWheel({10, 6}, 1);
        hinge1 = world.CreateJoint(world.MakeRevoluteJointDef(floor, wheel1, {8, 6}));
        hinge2 = world.CreateJoint(world.MakeRevoluteJointDef(floor, wheel2, {10, 6}));
        world.SetJointSpring(hinge1,
                             {.enable = true, .hertz = 1, .dampingRatio = 0.1f, .target = 1});
        gear = world.CreateJoint(GearJointDef{hinge1, hinge2, 2, false});

        const BodyId bob = AddBox({14, 4}, 1);
        slider = world.CreateJoint(world.MakePrismaticJointDef(floor, bob, {14, 4}, {0, 1}));
        world.SetJointSpring(slider,
                             {.enable = true, .hertz = 2, .dampingRatio = 0.1f, .target = 0});

        const BodyId puck = AddBox({20, 0.5f}, 1);
        world.SetLinearVelocity(puck, {3, 0});
        world.SetAngularVelocity(puck, 2);
        FrictionJointDef rub = world.MakeFrictionJointDef(floor, puck, {20, 0.5f});
        rub.maxForce = 1;
        rub.maxTorque = 0.2f;
        friction = world.CreateJoint(rub);

        capsuleBody = world.CreateBody({.type = BodyType::Dynamic,
                                        .position = {25, 1.5f},
                                        .angle = 0.7f,
                                        .angularVelocity = 3});
        capsule = world.CreateShape(capsuleBody, {.rollingResistance = 0.2f},
                                    Capsule{{-0.4f, 0}, {0.4f, 0}, 0.3f});
        joints = {pulley, hinge1, hinge2, gear, slider, friction};
    }

    static WorldDef Def(SolverKind kind)
    {
        WorldDef def;
        def.solver.kind = kind;
        return def;
    }
    BodyId AddBox(Vec2 position, Real density)
    {
        const BodyId body = world.CreateBody({.type = BodyType::Dynamic, .position = position});
        world.CreateShape(body, {.density = density}, MakeBox(0.5f, 0.5f));
        return body;
    }
    BodyId AddWheel(Vec2 position, Real radius)
    {
        const BodyId body = world.CreateBody({.type = BodyType::Dynamic, .position = position});
        world.CreateShape(body, {}, Circle{{0, 0}, radius});
        return body;
    }
};

/// What a run shows step by step: the state hash, and every joint's reaction (its accumulated
/// impulses, which the hash leaves out), each bit for bit.
struct Trace
{
    std::vector<std::uint64_t> hashes;
    std::vector<Real> reactions;
    bool operator==(const Trace&) const = default;
};

Trace Record(Gadgets& g, int steps)
{
    Trace trace;
    for (int i = 0; i < steps; ++i)
    {
        g.world.Step(Real(1) / 60);
        trace.hashes.push_back(g.world.GetStateHash());
        for (const JointId joint : g.joints)
        {
            const JointReaction r = g.world.GetReaction(joint, 60);
            trace.reactions.insert(trace.reactions.end(), {r.force.x, r.force.y, r.torque});
        }
    }
    return trace;
}

} // namespace

TEST_CASE("Snapshots restore chains, capsules, pulley, gear and friction joints, springs, "
          "rolling resistance and tangent speed under every back end",
          "[determinism][snapshot]")
{
    const SolverKind kind = GENERATE(SolverKind::Box2D, SolverKind::Colour, SolverKind::SoftStep);
    CAPTURE(SolverKindName(kind));
    Gadgets g(kind);
    Record(g, 30); // everything moving: contacts, warm-start and rolling impulses exist
    const WorldSnapshot snapshot = g.world.SaveSnapshot();
    const JointSpring spring = g.world.GetJointSpring(g.slider);
    const Trace original = Record(g, 90);
    const Vec2 ballEnd = g.world.GetPosition(g.ballBody);

    // Not a vacuous comparison: the state moves, and every joint pulls at some step.
    CHECK(original.hashes.front() != original.hashes.back());
    for (std::size_t j = 0; j < g.joints.size(); ++j)
    {
        Real largest = 0;
        for (std::size_t k = 3 * j; k < original.reactions.size(); k += 3 * g.joints.size())
        {
            largest =
                Max(largest, std::abs(original.reactions[k]) + std::abs(original.reactions[k + 1]) +
                                 std::abs(original.reactions[k + 2]));
        }
        CAPTURE(j);
        CHECK(largest > 0);
    }

    // Take the features away or change them, then go back.
    g.world.DestroyChain(g.chain);
    g.world.DestroyJoint(g.hinge1); // destroys the gear first
    g.world.SetJointSpring(g.slider, {.enable = true, .hertz = 5, .dampingRatio = 1, .target = 2});
    g.world.DestroyBody(g.capsuleBody);
    REQUIRE_FALSE(g.world.IsValid(g.gear));
    g.world.RestoreSnapshot(snapshot);

    REQUIRE(g.world.IsValid(g.chain));
    CHECK(g.world.GetChainSegments(g.chain).size() == 3);
    REQUIRE(g.world.IsValid(g.gear));
    CHECK(g.world.GetJointType(g.gear) == JointType::Gear);
    CHECK(g.world.GetJointType(g.pulley) == JointType::Pulley);
    CHECK(g.world.GetJointType(g.friction) == JointType::Friction);
    const JointSpring restored = g.world.GetJointSpring(g.slider);
    CHECK(restored.enable == spring.enable);
    CHECK(restored.hertz == spring.hertz);
    CHECK(restored.dampingRatio == spring.dampingRatio);
    CHECK(restored.target == spring.target);
    REQUIRE(g.world.IsValid(g.capsule));
    CHECK(g.world.GetCapsule(g.capsule).radius == Real(0.3));
    CHECK(g.world.GetShapeDef(g.capsule).rollingResistance == Real(0.2));
    CHECK(g.world.GetShapeDef(g.belt).tangentSpeed == 2);

    const Trace replay = Record(g, 90);
    CHECK(replay.hashes == original.hashes);
    CHECK(replay.reactions == original.reactions);
    CHECK(g.world.GetPosition(g.ballBody) == ballEnd);
}
