// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Sleeping (WorldDef::allowSleep): Box2D 2.4.1's rules.
//
// Documented behaviour: an island whose every body has rested within the sleep tolerances for
// Tolerances::timeToSleep falls asleep together, at the same step as in Box2D; a body with
// allowSleep = false keeps its island awake; a sleeping body does not move at all; each wake
// rule of the World API wakes the body; snapshots and the state hash carry the sleep state.
// Golden tests run the same worlds in Box2D 2.4.1's b2World and require the same step of
// falling asleep and bit-identical bodies.
#include "meff/scene.h"
#include "meff/validation.h"
#include "meff/world.h"

#include <box2d/box2d.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <vector>

using namespace meff;

namespace
{

constexpr Real kDt = Real(1) / Real(60);
constexpr int kVelocityIterations = 8;
constexpr int kPositionIterations = 3;

ShapeDef Material()
{
    ShapeDef def;
    def.density = 1;
    def.friction = Real(0.6);
    return def;
}

/// The same world built in meff and in Box2D 2.4.1, body for body, in the same order.
struct Twin
{
    World meff;
    b2World box2d{b2Vec2(0, -10)};
    std::vector<BodyId> meffBodies;
    std::vector<b2Body*> box2dBodies;

    explicit Twin(bool allowSleep = true) : meff(MakeDef(allowSleep))
    {
        box2d.SetAllowSleeping(allowSleep);
        box2d.SetContinuousPhysics(true);
    }

    static WorldDef MakeDef(bool allowSleep)
    {
        WorldDef def;
        def.allowSleep = allowSleep;
        return def;
    }

    /// A static segment from (-half, 0) to (half, 0) at x = centerX.
    std::size_t AddGround(Real centerX = 0, Real half = 20)
    {
        const BodyId id = meff.CreateBody(BodyDef{.position = {centerX, 0}});
        meff.CreateShape(id, Material(), Segment{{-half, 0}, {half, 0}});
        b2BodyDef def;
        def.position.Set(centerX, 0);
        b2Body* body = box2d.CreateBody(&def);
        b2EdgeShape edge;
        edge.SetTwoSided(b2Vec2(-half, 0), b2Vec2(half, 0));
        b2FixtureDef fixture;
        fixture.shape = &edge;
        fixture.density = 1;
        fixture.friction = Real(0.6);
        body->CreateFixture(&fixture);
        return Add(id, body);
    }

    std::size_t AddBox(Vec2 position, Real half, bool allowSleep = true, Vec2 velocity = {})
    {
        const BodyId id = meff.CreateBody(BodyDef{.type = BodyType::Dynamic,
                                                  .position = position,
                                                  .linearVelocity = velocity,
                                                  .allowSleep = allowSleep});
        meff.CreateShape(id, Material(), MakeBox(half, half));
        b2BodyDef def;
        def.type = b2_dynamicBody;
        def.position.Set(position.x, position.y);
        def.linearVelocity.Set(velocity.x, velocity.y);
        def.allowSleep = allowSleep;
        b2Body* body = box2d.CreateBody(&def);
        b2PolygonShape box;
        box.SetAsBox(half, half);
        b2FixtureDef fixture;
        fixture.shape = &box;
        fixture.density = 1;
        fixture.friction = Real(0.6);
        body->CreateFixture(&fixture);
        return Add(id, body);
    }

    std::size_t Add(BodyId id, b2Body* body)
    {
        meffBodies.push_back(id);
        box2dBodies.push_back(body);
        return meffBodies.size() - 1;
    }

    void Step()
    {
        meff.Step(kDt);
        box2d.Step(kDt, kVelocityIterations, kPositionIterations);
    }

    /// Positions, angles, velocities and awake flags equal bit for bit.
    void RequireIdentical(int step) const
    {
        for (std::size_t i = 0; i < meffBodies.size(); ++i)
        {
            INFO("step " << step << ", body " << i);
            const b2Body* b = box2dBodies[i];
            const BodyId m = meffBodies[i];
            REQUIRE(meff.IsAwake(m) == b->IsAwake());
            REQUIRE(meff.GetPosition(m).x == b->GetPosition().x);
            REQUIRE(meff.GetPosition(m).y == b->GetPosition().y);
            REQUIRE(meff.GetAngle(m) == b->GetAngle());
            REQUIRE(meff.GetLinearVelocity(m).x == b->GetLinearVelocity().x);
            REQUIRE(meff.GetLinearVelocity(m).y == b->GetLinearVelocity().y);
            REQUIRE(meff.GetAngularVelocity(m) == b->GetAngularVelocity());
        }
    }
};

/// A 1 m box resting on a ground segment, stepped until it sleeps. Returns the box.
BodyId RestingBox(World& world, Vec2 position = {0, Real(0.52)})
{
    const BodyId ground = world.CreateBody({});
    world.CreateShape(ground, Material(), Segment{{-20, 0}, {20, 0}});
    const BodyId box = world.CreateBody({.type = BodyType::Dynamic, .position = position});
    world.CreateShape(box, Material(), MakeBox(Real(0.5), Real(0.5)));
    for (int i = 0; i < 600 && world.IsAwake(box); ++i)
    {
        world.Step(kDt);
    }
    REQUIRE_FALSE(world.IsAwake(box));
    return box;
}

World SleepyWorld()
{
    WorldDef def;
    def.allowSleep = true;
    return World{def};
}

/// Whether the body moves faster than the sleep tolerances, as the island's sleep test reads
/// its velocity after the step (squared speeds against squared tolerances): such a step
/// restarts the body's rest time.
bool MovingTooFastToSleep(const World& world, BodyId body)
{
    const Tolerances tol;
    const Vec2 v = world.GetLinearVelocity(body);
    const Real w = world.GetAngularVelocity(body);
    return w * w > tol.angularSleepTolerance * tol.angularSleepTolerance ||
           Dot(v, v) > tol.linearSleepTolerance * tol.linearSleepTolerance;
}

/// The float sum of 30 steps of 1/60 s is 0.50000018 >= timeToSleep (0.5 s), and of 29 steps
/// 0.48333353 < 0.5: a body sleeps at the earliest 30 steps after the last step it moved.
constexpr int kStepsToSleep = 30;

std::vector<unsigned char> Bytes(const Transform& xf)
{
    std::vector<unsigned char> bytes(sizeof(Transform));
    std::memcpy(bytes.data(), &xf, sizeof(Transform));
    return bytes;
}

} // namespace

TEST_CASE("Islands fall asleep together at the same step as Box2D 2.4.1", "[sleeping][box2d]")
{
    Twin twin;
    twin.AddGround();
    // Island 1: a stack of two boxes dropped a little.
    const std::size_t low = twin.AddBox({0, Real(0.6)}, Real(0.5));
    const std::size_t high = twin.AddBox({0, Real(1.7)}, Real(0.5));
    // Island 2: a box sliding to rest.
    const std::size_t slider = twin.AddBox({5, Real(0.52)}, Real(0.5), true, {2, 0});
    // Island 3: a small box dropped from higher up, which takes longer to come to rest.
    const std::size_t faller = twin.AddBox({-5, 3}, Real(0.25));

    std::vector<int> sleptAtMeff(twin.meffBodies.size(), -1);
    std::vector<int> sleptAtBox2D(twin.meffBodies.size(), -1);
    std::vector<int> lastMoving(twin.meffBodies.size(), 0);
    for (int step = 1; step <= 600; ++step)
    {
        twin.Step();
        twin.RequireIdentical(step);
        for (std::size_t i = 1; i < twin.meffBodies.size(); ++i)
        {
            if (MovingTooFastToSleep(twin.meff, twin.meffBodies[i]))
            {
                lastMoving[i] = step;
            }
            if (sleptAtMeff[i] < 0 && !twin.meff.IsAwake(twin.meffBodies[i]))
            {
                sleptAtMeff[i] = step;
            }
            if (sleptAtBox2D[i] < 0 && !twin.box2dBodies[i]->IsAwake())
            {
                sleptAtBox2D[i] = step;
            }
        }
    }
    for (std::size_t i = 1; i < sleptAtMeff.size(); ++i)
    {
        INFO("body " << i);
        CHECK(sleptAtMeff[i] == sleptAtBox2D[i]);
        // Every body rests at least timeToSleep (0.5 s = 30 steps) before it may sleep, counted
        // from the last step it moved; each was dropped or pushed, so it moved at step 1 at
        // least, and sleeps after step 30.
        CHECK(lastMoving[i] >= 1);
        CHECK(sleptAtMeff[i] >= lastMoving[i] + kStepsToSleep);
    }
    // The stack (one island: its later box counts) and the slider sleep exactly 30 steps after
    // they stopped moving. The faller, which lands hard, sleeps one step later than that (so
    // does Box2D's, checked above), so for it only the lower bound is asserted.
    CHECK(sleptAtMeff[low] == std::max(lastMoving[low], lastMoving[high]) + kStepsToSleep);
    CHECK(sleptAtMeff[slider] == lastMoving[slider] + kStepsToSleep);
    // The stack sleeps as one island: both boxes at the same step.
    CHECK(sleptAtMeff[low] == sleptAtMeff[high]);
    // Separate islands sleep on their own clocks.
    CHECK(sleptAtMeff[slider] != sleptAtMeff[low]);
    CHECK(sleptAtMeff[faller] != sleptAtMeff[low]);
}

TEST_CASE("A contact that begins restarts both bodies' rest time, as b2Contact::Update",
          "[sleeping][box2d]")
{
    Twin twin;
    twin.AddGround();
    const std::size_t box = twin.AddBox({0, Real(0.52)}, Real(0.5));
    int step = 0;
    for (; step < 20; ++step)
    {
        twin.Step();
    }
    // A static post put down touching the resting box: the island is unchanged (static bodies
    // do not join it), so only the contact's wake can restart the box's rest time.
    const BodyId post = twin.meff.CreateBody(BodyDef{.position = {Real(0.75), Real(0.52)}});
    twin.meff.CreateShape(post, Material(), MakeBox(Real(0.25), Real(0.25)));
    b2BodyDef postDef;
    postDef.position.Set(Real(0.75), Real(0.52));
    b2Body* box2dPost = twin.box2d.CreateBody(&postDef);
    b2PolygonShape postShape;
    postShape.SetAsBox(Real(0.25), Real(0.25));
    b2FixtureDef postFixture;
    postFixture.shape = &postShape;
    postFixture.density = 1;
    postFixture.friction = Real(0.6);
    box2dPost->CreateFixture(&postFixture);
    twin.Add(post, box2dPost);

    int sleptAt = -1;
    for (; step < 200 && sleptAt < 0; ++step)
    {
        twin.Step();
        twin.RequireIdentical(step + 1);
        if (!twin.meff.IsAwake(twin.meffBodies[box]))
        {
            sleptAt = step + 1;
        }
    }
    // The contact begins in step 21 (the post's shape is paired at its start), restarting the
    // rest time, which then gains 1/60 s per step from step 21 on and reaches timeToSleep in
    // step 50. Without the restart the box, resting since its first steps, would sleep sooner.
    CHECK(sleptAt == 50);
}

TEST_CASE("A body with allowSleep false keeps its whole island awake", "[sleeping][box2d]")
{
    Twin twin;
    twin.AddGround();
    // Left stack: the bottom box may not sleep, so neither may the box resting on it.
    const std::size_t stubborn = twin.AddBox({-3, Real(0.52)}, Real(0.5), false);
    const std::size_t rider = twin.AddBox({-3, Real(1.54)}, Real(0.5));
    // Right stack: the same, both allowed: it sleeps.
    const std::size_t lower = twin.AddBox({3, Real(0.52)}, Real(0.5));
    const std::size_t upper = twin.AddBox({3, Real(1.54)}, Real(0.5));
    for (int step = 1; step <= 300; ++step)
    {
        twin.Step();
        twin.RequireIdentical(step);
    }
    CHECK(twin.meff.IsAwake(twin.meffBodies[stubborn]));
    CHECK(twin.meff.IsAwake(twin.meffBodies[rider]));
    CHECK_FALSE(twin.meff.IsAwake(twin.meffBodies[lower]));
    CHECK_FALSE(twin.meff.IsAwake(twin.meffBodies[upper]));
    CHECK_FALSE(twin.meff.IsSleepingAllowed(twin.meffBodies[stubborn]));
}

TEST_CASE("Without allowSleep nothing sleeps, as Box2D with sleeping off", "[sleeping][box2d]")
{
    Twin twin(false);
    twin.AddGround();
    const std::size_t box = twin.AddBox({0, Real(0.52)}, Real(0.5));
    for (int step = 1; step <= 200; ++step)
    {
        twin.Step();
        twin.RequireIdentical(step);
    }
    CHECK(twin.meff.IsAwake(twin.meffBodies[box]));
}

TEST_CASE("Sleeping bodies do not move, bit for bit, and report no contacts", "[sleeping]")
{
    World world = SleepyWorld();
    const BodyId box = RestingBox(world);
    const std::vector<unsigned char> before = Bytes(world.GetTransform(box));
    const Vec2 center = world.GetWorldCenter(box);
    for (int i = 0; i < 300; ++i)
    {
        world.Step(kDt);
        REQUIRE(Bytes(world.GetTransform(box)) == before);
        REQUIRE(world.GetWorldCenter(box).x == center.x);
        REQUIRE(world.GetWorldCenter(box).y == center.y);
        REQUIRE(world.GetLinearVelocity(box).x == 0);
        REQUIRE(world.GetLinearVelocity(box).y == 0);
        REQUIRE(world.GetAngularVelocity(box) == 0);
        REQUIRE(world.GetContactReports().empty());
        REQUIRE_FALSE(world.IsAwake(box));
    }
    // The contact with the ground persists (touching) while asleep, so waking resumes at once.
    CHECK(world.GetTouchingContactCount() == 1);
}

TEST_CASE("Wake rules of the World API", "[sleeping]")
{
    World world = SleepyWorld();
    const BodyId box = RestingBox(world);
    const Vec2 start = world.GetPosition(box);

    SECTION("SetLinearVelocity: non-zero wakes, zero does not")
    {
        world.SetLinearVelocity(box, {0, 0});
        CHECK_FALSE(world.IsAwake(box));
        world.SetLinearVelocity(box, {1, 0});
        CHECK(world.IsAwake(box));
        world.Step(kDt);
        CHECK(world.GetPosition(box).x > start.x);
    }
    SECTION("SetAngularVelocity: non-zero wakes, zero does not")
    {
        world.SetAngularVelocity(box, 0);
        CHECK_FALSE(world.IsAwake(box));
        world.SetAngularVelocity(box, 1);
        CHECK(world.IsAwake(box));
    }
    SECTION("ApplyForce wakes and the force acts")
    {
        world.ApplyForce(box, {100, 0}, world.GetWorldCenter(box));
        CHECK(world.IsAwake(box));
        world.Step(kDt);
        CHECK(world.GetLinearVelocity(box).x > 0);
    }
    SECTION("ApplyForceToCenter with wake = false leaves the body asleep and ignores the force")
    {
        // 100 N up as well as sideways: more than the 1 kg box's weight, so it lifts off and
        // neither the ground nor friction acts on it once awake.
        const Vec2 force(100, 100);
        world.ApplyForceToCenter(box, force, false);
        CHECK_FALSE(world.IsAwake(box));
        world.Step(kDt);
        CHECK_FALSE(world.IsAwake(box));
        CHECK(world.GetPosition(box).x == start.x);
        world.ApplyForceToCenter(box, force);
        CHECK(world.IsAwake(box));
        world.Step(kDt);
        // One step of the force given awake, none of the one given asleep (which would double
        // it): v = h·F/m (+ g·h upwards). Relative 1e-5: the contact's warm start applies the
        // resting impulse (m·g·h ≈ 0.17 N·s) and the solver takes it back as the box separates,
        // leaving float round-off of a few ulps (1e-7 m/s each) on speeds of 1.5 m/s.
        const Real m = world.GetMass(box);
        REQUIRE(m == Approx(1));
        CHECK(world.GetLinearVelocity(box).x == Approx(kDt * force.x / m).epsilon(1e-5));
        CHECK(world.GetLinearVelocity(box).y == Approx(kDt * (force.y / m - 10)).epsilon(1e-5));
    }
    SECTION("ApplyTorque wakes")
    {
        world.ApplyTorque(box, 50);
        CHECK(world.IsAwake(box));
    }
    SECTION("ApplyLinearImpulse wakes and changes the velocity at once")
    {
        world.ApplyLinearImpulse(box, {0, 5}, world.GetWorldCenter(box));
        CHECK(world.IsAwake(box));
        CHECK(world.GetLinearVelocity(box).y > 0);
    }
    SECTION("ApplyAngularImpulse wakes; with wake = false it is ignored")
    {
        world.ApplyAngularImpulse(box, 1, false);
        CHECK_FALSE(world.IsAwake(box));
        CHECK(world.GetAngularVelocity(box) == 0);
        world.ApplyAngularImpulse(box, 1);
        CHECK(world.IsAwake(box));
        CHECK(world.GetAngularVelocity(box) > 0);
    }
    SECTION("SetTransform wakes the moved body (a departure from Box2D 2.4.1)")
    {
        world.SetTransform(box, {0, 5}, 0);
        CHECK(world.IsAwake(box));
        world.Step(kDt);
        CHECK(world.GetPosition(box).y < 5); // it falls instead of hanging in the air
    }
    SECTION("Creating and destroying a joint wakes both bodies")
    {
        const BodyId other =
            world.CreateBody({.type = BodyType::Dynamic, .position = {3, Real(0.52)}});
        world.CreateShape(other, Material(), MakeBox(Real(0.5), Real(0.5)));
        world.SetAwake(other, false);
        const JointId joint =
            world.CreateJoint(world.MakeDistanceJointDef(box, other, start, {3, Real(0.52)}));
        CHECK(world.IsAwake(box));
        CHECK(world.IsAwake(other));
        world.SetAwake(box, false);
        world.SetAwake(other, false);
        world.DestroyJoint(joint);
        CHECK(world.IsAwake(box));
        CHECK(world.IsAwake(other));
    }
    SECTION("A contact that begins with a moving body wakes the sleeper")
    {
        const BodyId ball = world.CreateBody(
            {.type = BodyType::Dynamic, .position = {-3, Real(0.5)}, .linearVelocity = {6, 0}});
        world.CreateShape(ball, Material(), Circle{{0, 0}, Real(0.3)});
        bool woke = false;
        for (int i = 0; i < 120 && !woke; ++i)
        {
            world.Step(kDt);
            woke = world.IsAwake(box);
            if (woke)
            {
                // Woken in the very step the contact began.
                bool began = false;
                for (const ContactEvent& event : world.GetContactBeginEvents())
                {
                    began = began || world.GetBody(event.shapeA) == ball ||
                            world.GetBody(event.shapeB) == ball;
                }
                CHECK(began);
            }
        }
        CHECK(woke);
    }
    SECTION("Destroying the ground wakes what rested on it (as Box2D 2.4.1's b2Contact::Destroy)")
    {
        const BodyId ground = world.GetBodies()[0];
        world.DestroyBody(ground);
        CHECK(world.IsAwake(box));
        world.Step(kDt);
        CHECK(world.GetPosition(box).y < start.y);
    }
    SECTION("Destroying the ground's shape wakes what rested on it")
    {
        const BodyId ground = world.GetBodies()[0];
        world.DestroyShape(world.GetShapes(ground)[0]);
        CHECK(world.IsAwake(box));
    }
    SECTION("SetSleepingAllowed(false) wakes and keeps the body awake")
    {
        world.SetSleepingAllowed(box, false);
        CHECK(world.IsAwake(box));
        for (int i = 0; i < 120; ++i)
        {
            world.Step(kDt);
        }
        CHECK(world.IsAwake(box));
    }
    SECTION("Turning sleeping off wakes every body; turning it on again lets them sleep")
    {
        world.SetAllowSleeping(false);
        CHECK_FALSE(world.GetAllowSleeping());
        CHECK(world.IsAwake(box));
        for (int i = 0; i < 120; ++i)
        {
            world.Step(kDt);
        }
        CHECK(world.IsAwake(box));
        world.SetAllowSleeping(true);
        for (int i = 0; i < 120; ++i)
        {
            world.Step(kDt);
        }
        CHECK_FALSE(world.IsAwake(box));
    }
}

TEST_CASE("Destroying what a sleeper rests on wakes it, as in Box2D 2.4.1", "[sleeping][box2d]")
{
    // Box2D 2.4.1 wakes both bodies of a contact with manifold points when the contact is
    // destroyed (b2Contact::Destroy), whether its body or only its fixture goes.
    Twin twin;
    const std::size_t ground = twin.AddGround();
    const std::size_t box = twin.AddBox({0, Real(0.52)}, Real(0.5));
    int step = 0;
    while (step < 600 && twin.meff.IsAwake(twin.meffBodies[box]))
    {
        twin.Step();
        twin.RequireIdentical(++step);
    }
    REQUIRE_FALSE(twin.meff.IsAwake(twin.meffBodies[box]));
    REQUIRE_FALSE(twin.box2dBodies[box]->IsAwake());

    SECTION("DestroyBody(ground)")
    {
        twin.meff.DestroyBody(twin.meffBodies[ground]);
        twin.box2d.DestroyBody(twin.box2dBodies[ground]);
    }
    SECTION("DestroyShape / DestroyFixture of the ground's only shape")
    {
        twin.meff.DestroyShape(twin.meff.GetShapes(twin.meffBodies[ground])[0]);
        twin.box2dBodies[ground]->DestroyFixture(twin.box2dBodies[ground]->GetFixtureList());
    }
    CHECK(twin.box2dBodies[box]->IsAwake());
    CHECK(twin.meff.IsAwake(twin.meffBodies[box]));
    // Then both fall alike, bit for bit (the ground, if destroyed, is left out of the compare).
    twin.meffBodies.erase(twin.meffBodies.begin() + static_cast<std::ptrdiff_t>(ground));
    twin.box2dBodies.erase(twin.box2dBodies.begin() + static_cast<std::ptrdiff_t>(ground));
    for (int i = 0; i < 30; ++i)
    {
        twin.Step();
        twin.RequireIdentical(++step);
    }
    CHECK(twin.meff.GetPosition(twin.meffBodies[0]).y < Real(0));
}

TEST_CASE("SetAwake(false) zeroes velocity and force; static bodies are never awake", "[sleeping]")
{
    World world = SleepyWorld();
    const BodyId ground = world.CreateBody({});
    const BodyId box =
        world.CreateBody({.type = BodyType::Dynamic, .position = {0, 5}, .linearVelocity = {1, 2}});
    world.CreateShape(box, Material(), MakeBox(Real(0.5), Real(0.5)));
    world.ApplyForceToCenter(box, {0, 1000});
    world.SetAwake(box, false);
    CHECK_FALSE(world.IsAwake(box));
    CHECK(world.GetLinearVelocity(box).x == 0);
    CHECK(world.GetLinearVelocity(box).y == 0);
    world.SetAwake(box, true);
    world.Step(kDt);
    // Only gravity acted: the force was cleared when it was put to sleep. Relative 1e-6: one
    // kick h·(1/m)·(m·g) is a few float roundings (6e-8 each) from −g·h, while the kept 1000 N
    // force would add +16.7 m/s.
    CHECK(world.GetLinearVelocity(box).y == Approx(-10 * kDt).epsilon(1e-6));

    CHECK_FALSE(world.IsAwake(ground));
    world.SetAwake(ground, true);
    CHECK_FALSE(world.IsAwake(ground));

    const BodyId sleeper =
        world.CreateBody({.type = BodyType::Dynamic, .position = {5, 5}, .awake = false});
    world.CreateShape(sleeper, Material(), MakeBox(Real(0.5), Real(0.5)));
    world.Step(kDt);
    CHECK_FALSE(world.IsAwake(sleeper));
    CHECK(world.GetPosition(sleeper).y == 5); // BodyDef::awake = false: starts asleep in the air
}

TEST_CASE("Wake calls agree with Box2D 2.4.1 where it defines them", "[sleeping][box2d]")
{
    Twin twin;
    twin.AddGround();
    const std::size_t a = twin.AddBox({0, Real(0.52)}, Real(0.5));
    const std::size_t b = twin.AddBox({3, Real(0.52)}, Real(0.5));
    const std::size_t c = twin.AddBox({6, Real(0.52)}, Real(0.5));
    int step = 0;
    const auto run = [&](int steps)
    {
        for (int i = 0; i < steps; ++i)
        {
            twin.Step();
            twin.RequireIdentical(++step);
        }
    };
    run(120);
    REQUIRE_FALSE(twin.meff.IsAwake(twin.meffBodies[a]));

    twin.meff.ApplyLinearImpulse(twin.meffBodies[a], {1, 2}, {0, 1});
    twin.box2dBodies[a]->ApplyLinearImpulse(b2Vec2(1, 2), b2Vec2(0, 1), true);
    twin.meff.ApplyTorque(twin.meffBodies[b], 30);
    twin.box2dBodies[b]->ApplyTorque(30, true);
    twin.meff.SetAngularVelocity(twin.meffBodies[c], 2);
    twin.box2dBodies[c]->SetAngularVelocity(2);
    twin.RequireIdentical(step);
    run(200);

    // Joints in Box2D 2.4.1 wake on destruction only; wake both engines' bodies by hand first
    // so that the comparison covers DestroyJoint's wake alone.
    b2DistanceJointDef box2dDef;
    box2dDef.Initialize(twin.box2dBodies[a], twin.box2dBodies[b],
                        twin.box2dBodies[a]->GetPosition(), twin.box2dBodies[b]->GetPosition());
    b2Joint* box2dJoint = twin.box2d.CreateJoint(&box2dDef);
    const JointId meffJoint = twin.meff.CreateJoint(twin.meff.MakeDistanceJointDef(
        twin.meffBodies[a], twin.meffBodies[b], twin.meff.GetPosition(twin.meffBodies[a]),
        twin.meff.GetPosition(twin.meffBodies[b])));
    CHECK_FALSE(twin.box2dBodies[a]->IsAwake()); // Box2D: creating a joint does not wake
    twin.box2dBodies[a]->SetAwake(true);
    twin.box2dBodies[b]->SetAwake(true);
    run(200);
    REQUIRE_FALSE(twin.meff.IsAwake(twin.meffBodies[a]));
    twin.box2d.DestroyJoint(box2dJoint);
    twin.meff.DestroyJoint(meffJoint);
    twin.RequireIdentical(step);
    CHECK(twin.meff.IsAwake(twin.meffBodies[a]));
    run(100);
}

TEST_CASE("Continuous collision wakes a sleeping body a bullet hits, as Box2D 2.4.1",
          "[sleeping][box2d][continuous]")
{
    Twin twin;
    twin.AddGround();
    const std::size_t box = twin.AddBox({0, Real(0.52)}, Real(0.5));
    int step = 0;
    const auto run = [&](int steps)
    {
        for (int i = 0; i < steps; ++i)
        {
            twin.Step();
            twin.RequireIdentical(++step);
        }
    };
    run(60);
    REQUIRE_FALSE(twin.meff.IsAwake(twin.meffBodies[box]));

    // A bullet fast enough to cross the box in one step (1.5 m per step): only the
    // time-of-impact pass sees the hit, and it must wake the box in both engines alike.
    const Vec2 start{-3, Real(0.6)};
    const Vec2 velocity{90, 0};
    const BodyId ball = twin.meff.CreateBody(BodyDef{
        .type = BodyType::Dynamic, .position = start, .linearVelocity = velocity, .bullet = true});
    twin.meff.CreateShape(ball, Material(), Circle{{0, 0}, Real(0.1)});
    b2BodyDef def;
    def.type = b2_dynamicBody;
    def.position.Set(start.x, start.y);
    def.linearVelocity.Set(velocity.x, velocity.y);
    def.bullet = true;
    b2Body* box2dBall = twin.box2d.CreateBody(&def);
    b2CircleShape circle;
    circle.m_radius = Real(0.1);
    b2FixtureDef fixture;
    fixture.shape = &circle;
    fixture.density = 1;
    fixture.friction = Real(0.6);
    box2dBall->CreateFixture(&fixture);
    twin.Add(ball, box2dBall);

    bool woke = false;
    for (int i = 0; i < 10 && !woke; ++i)
    {
        run(1);
        woke = twin.meff.IsAwake(twin.meffBodies[box]);
    }
    CHECK(woke);
    CHECK(twin.meff.GetPosition(ball).x < 0); // stopped or bounced, not tunnelled through
    run(60);
}

TEST_CASE("Snapshots and the state hash carry the sleep state", "[sleeping][determinism]")
{
    World world = SleepyWorld();
    const BodyId ground = world.CreateBody({});
    world.CreateShape(ground, Material(), Segment{{-20, 0}, {20, 0}});
    std::vector<BodyId> boxes;
    for (int i = 0; i < 6; ++i)
    {
        const BodyId box = world.CreateBody(
            {.type = BodyType::Dynamic, .position = {Real(i % 3) * 2, Real(0.6 + 1.2 * i)}});
        world.CreateShape(box, Material(), MakeBox(Real(0.5), Real(0.5)));
        boxes.push_back(box);
    }
    // Save mid-way: some rest timers running, nothing asleep yet or some asleep.
    for (int i = 0; i < 100; ++i)
    {
        world.Step(kDt);
    }
    const WorldSnapshot snapshot = world.SaveSnapshot();
    std::vector<std::uint64_t> hashes;
    std::vector<bool> awake;
    for (int i = 0; i < 300; ++i)
    {
        world.Step(kDt);
        hashes.push_back(world.GetStateHash());
        for (const BodyId box : boxes)
        {
            awake.push_back(world.IsAwake(box));
        }
    }
    // The run must include falling asleep, or the test proves nothing about sleep.
    REQUIRE_FALSE(world.IsAwake(boxes[0]));

    world.RestoreSnapshot(snapshot);
    std::size_t k = 0;
    for (int i = 0; i < 300; ++i)
    {
        world.Step(kDt);
        REQUIRE(world.GetStateHash() == hashes[static_cast<std::size_t>(i)]);
        for (const BodyId box : boxes)
        {
            REQUIRE(world.IsAwake(box) == awake[k++]);
        }
    }

    // The awake flag alone changes the hash: a body at rest with no rest time put to sleep.
    World still = SleepyWorld();
    const BodyId body = still.CreateBody({.type = BodyType::Dynamic});
    const std::uint64_t awakeHash = still.GetStateHash();
    still.SetAwake(body, false);
    CHECK(still.GetStateHash() != awakeHash);
}

TEST_CASE("Sleep tolerances: defaults are Box2D's, the linear one scales with length units",
          "[sleeping]")
{
    const Tolerances defaults;
    CHECK(defaults.timeToSleep == b2_timeToSleep);
    CHECK(defaults.linearSleepTolerance == b2_linearSleepTolerance);
    CHECK(defaults.angularSleepTolerance == b2_angularSleepTolerance);
    const Tolerances pixels = TolerancesForLengthUnits(32);
    CHECK(pixels.linearSleepTolerance == defaults.linearSleepTolerance * 32);
    CHECK(pixels.angularSleepTolerance == defaults.angularSleepTolerance);
    CHECK(pixels.timeToSleep == defaults.timeToSleep);

    WorldDef def;
    def.tolerances.timeToSleep = -1;
    CHECK_THROWS_AS(World{def}, InvalidArgument);
}

TEST_CASE("Sleeping scenes: the pile sleeps, the late ball wakes the stack", "[sleeping][scene]")
{
    const std::filesystem::path scenes =
        std::filesystem::path(MEFF_SOURCE_DIR) / "samples" / "scenes";

    SECTION("sleeping_pile")
    {
        const Scene scene = LoadScene((scenes / "sleeping_pile.json").string());
        REQUIRE(scene.world.allowSleep);
        BuiltScene built = BuildWorld(scene);
        int asleepAt = -1;
        int lastMoving = 0;
        for (int frame = 1; frame <= scene.world.frames; ++frame)
        {
            built.world.Step(Real(scene.world.dt));
            bool allAsleep = true;
            for (std::size_t i = 1; i < built.bodies.size(); ++i)
            {
                allAsleep = allAsleep && !built.world.IsAwake(built.bodies[i]);
                if (MovingTooFastToSleep(built.world, built.bodies[i]))
                {
                    lastMoving = frame;
                }
            }
            if (allAsleep && asleepAt < 0)
            {
                asleepAt = frame;
            }
        }
        // The boxes are dropped, so they move at frame 1 at least, and the pile rests at least
        // timeToSleep (30 frames of the file's 1/60 s) after its last moving box stopped.
        REQUIRE(scene.world.dt == Approx(1.0 / 60));
        CHECK(lastMoving >= 1);
        CHECK(asleepAt >= lastMoving + kStepsToSleep);
        CHECK(asleepAt > 30);
        // It sleeps well before the run ends, so the file's frames cover sleeping for a while.
        CHECK(asleepAt < scene.world.frames - 60);
    }
    SECTION("sleeping_wake")
    {
        const Scene scene = LoadScene((scenes / "sleeping_wake.json").string());
        BuiltScene built = BuildWorld(scene);
        const BodyId top = built.bodyByName.at("stack2");
        const BodyId loner = built.bodyByName.at("loner");
        // The frames at which each body's awake flag changed, in order.
        std::vector<int> topChanges;
        std::vector<int> lonerChanges;
        bool topAwake = true;
        bool lonerAwake = true;
        for (int frame = 1; frame <= scene.world.frames; ++frame)
        {
            built.world.Step(Real(scene.world.dt));
            if (built.world.IsAwake(top) != topAwake)
            {
                topAwake = !topAwake;
                topChanges.push_back(frame);
            }
            if (built.world.IsAwake(loner) != lonerAwake)
            {
                lonerAwake = !lonerAwake;
                lonerChanges.push_back(frame);
            }
        }
        // Both islands sleep early, each on its own; the ball (about 2.7 s of free fall) wakes
        // the stack first, rolls on and wakes the lone box later; both sleep again by the end.
        REQUIRE(topChanges.size() == 3);
        REQUIRE(lonerChanges.size() == 3);
        CHECK(topChanges[0] < 60);
        CHECK(lonerChanges[0] < 60);
        CHECK(topChanges[1] > 150);
        CHECK(lonerChanges[1] > topChanges[1]);
        CHECK(topChanges[2] < scene.world.frames);
        CHECK(lonerChanges[2] < scene.world.frames);
        for (const BodyId body : built.bodies)
        {
            CHECK_FALSE(built.world.IsAwake(body));
        }
    }
}

TEST_CASE("Lockstep comparison fails on an awake flag that differs", "[sleeping][validation]")
{
    validation::FrameSample meff;
    meff.bodies.push_back({0, 0, 0, 0, 0, 0, true});
    validation::FrameSample box2d = meff;
    const validation::Tolerances tolerances;
    CHECK_FALSE(validation::CompareFrames(meff, box2d, 1.0 / 60, tolerances).Exceeds());
    box2d.bodies[0].awake = false;
    const validation::FrameErrors errors =
        validation::CompareFrames(meff, box2d, 1.0 / 60, tolerances);
    CHECK(errors.awakeMismatches == 1);
    REQUIRE(errors.exceeded.size() == 1);
    CHECK(errors.exceeded[0] == "awake");
}
