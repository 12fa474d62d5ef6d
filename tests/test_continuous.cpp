// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Continuous collision (WorldDef::continuous, the SolveContinuous stage).
//
// Documented behaviour: with continuous on, a fast body does not pass through static geometry
// thinner than its step, and a bullet does not pass through dynamic bodies; with it off, both
// tunnel. Lockstep golden tests run the same scenes in meff and in Box2D 2.4.1's b2World with
// continuous physics on and require bit-identical bodies and contact reports (PostSolve,
// including the time-of-impact sub-steps) at every step.
#include "meff/world.h"

#include <box2d/box2d.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <vector>

using namespace meff;

namespace
{

constexpr Real kDt = Real(1) / Real(60);

World MakeWorld(bool continuous, Vec2 gravity = {0, 0})
{
    WorldDef def;
    def.gravity = gravity;
    def.continuous = continuous;
    return World{def};
}

ShapeDef Material(Real density, Real friction, Real restitution = 0)
{
    ShapeDef def;
    def.density = density;
    def.friction = friction;
    def.restitution = restitution;
    return def;
}

/// A static wall at x = 0: a two-sided segment, or a box 2·halfThickness wide.
void AddWall(World& world, bool segment, Real halfThickness = Real(0.05))
{
    const BodyId wall = world.CreateBody(BodyDef{});
    if (segment)
    {
        world.CreateShape(wall, Material(0, Real(0.6)), Segment{{0, -5}, {0, 5}});
    }
    else
    {
        world.CreateShape(wall, Material(0, Real(0.6)), MakeBox(halfThickness, 5));
    }
}

BodyId AddBall(World& world, Vec2 position, Vec2 velocity, Real radius, bool bullet = false)
{
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.position = position;
    def.linearVelocity = velocity;
    def.bullet = bullet;
    const BodyId ball = world.CreateBody(def);
    world.CreateShape(ball, Material(1, Real(0.6)), Circle{{0, 0}, radius});
    return ball;
}

} // namespace

TEST_CASE("Continuous on: a small fast ball does not tunnel through a thin static wall",
          "[continuous]")
{
    const bool segment = GENERATE(true, false);
    const Real speed = GENERATE(Real(100), Real(1000));
    INFO((segment ? "segment" : "thin box") << " wall, ball at " << speed << " m/s");
    const Real radius = Real(0.05);

    for (const bool continuous : {true, false})
    {
        World world = MakeWorld(continuous);
        AddWall(world, segment);
        // Placed so that no step ends with the ball touching the wall: the discrete solver
        // alone never sees the impact.
        const BodyId ball = AddBall(world, {Real(-5.3), 0}, {speed, 0}, radius);
        Real maxX = -kMaxReal;
        for (int step = 0; step < 60; ++step)
        {
            world.Step(kDt);
            maxX = Max(maxX, world.GetPosition(ball).x);
        }
        const Real wallFace = segment ? Real(0) : Real(-0.05);
        INFO("continuous " << continuous << ": furthest x " << maxX);
        if (continuous)
        {
            // Stopped at the wall: its surface at most a skin and a few slops past the face.
            CHECK(maxX < wallFace - radius + Real(0.03));
            CHECK(world.GetPosition(ball).x < 0);
        }
        else
        {
            // Documented: without continuous collision the ball passes straight through.
            CHECK(world.GetPosition(ball).x > 10);
        }
    }
}

TEST_CASE("Continuous collision is on by default, as in Box2D, and can be switched", "[continuous]")
{
    World world{WorldDef{}};
    CHECK(world.GetContinuous());
    world.SetContinuous(false);
    CHECK_FALSE(world.GetContinuous());
}

TEST_CASE("A bullet does not tunnel through a thin dynamic box; a non-bullet does",
          "[continuous][bullet]")
{
    for (const bool bullet : {true, false})
    {
        World world = MakeWorld(true);
        BodyDef boxDef;
        boxDef.type = BodyType::Dynamic;
        const BodyId box = world.CreateBody(boxDef);
        world.CreateShape(box, Material(1, Real(0.6)), MakeBox(Real(0.05), 1));
        const BodyId ball = AddBall(world, {Real(-5.3), 0}, {100, 0}, Real(0.05), bullet);
        bool passed = false;
        for (int step = 0; step < 30; ++step)
        {
            world.Step(kDt);
            passed = passed || world.GetPosition(ball).x > world.GetPosition(box).x;
        }
        INFO("bullet " << bullet << ": ball x " << world.GetPosition(ball).x << ", box x "
                       << world.GetPosition(box).x);
        if (bullet)
        {
            CHECK_FALSE(passed);
            CHECK(world.GetLinearVelocity(box).x > 1); // the hit pushed the box
        }
        else
        {
            // Two ordinary dynamic bodies are left to the discrete solver: it tunnels.
            CHECK(passed);
            CHECK(world.GetLinearVelocity(box).x == 0);
        }
    }
}

TEST_CASE("Continuous off leaves the discrete step untouched", "[continuous]")
{
    // Slow bodies never trigger an impact, so the result with continuous on and off is the
    // same to the bit; the off world is the discrete engine alone.
    World on = MakeWorld(true, {0, -10});
    World off = MakeWorld(false, {0, -10});
    std::vector<BodyId> onBoxes, offBoxes;
    for (World* world : {&on, &off})
    {
        const BodyId ground = world->CreateBody(BodyDef{});
        world->CreateShape(ground, Material(0, Real(0.6)), MakeOffsetBox(10, 1, {0, -1}, 0));
        for (int i = 0; i < 5; ++i)
        {
            BodyDef def;
            def.type = BodyType::Dynamic;
            // Each box starts 0.1 m above its resting height (gap 2·skin − slop) and drops.
            def.position = {Real(i) * Real(0.1), Real(0.615) + Real(i) * Real(1.1)};
            const BodyId box = world->CreateBody(def);
            world->CreateShape(box, Material(1, Real(0.6)), MakeBox(Real(0.5), Real(0.5)));
            (world == &on ? onBoxes : offBoxes).push_back(box);
        }
    }
    for (int step = 0; step < 120; ++step)
    {
        on.Step(kDt);
        off.Step(kDt);
        for (std::size_t i = 0; i < onBoxes.size(); ++i)
        {
            REQUIRE(on.GetPosition(onBoxes[i]) == off.GetPosition(offBoxes[i]));
            REQUIRE(on.GetAngle(onBoxes[i]) == off.GetAngle(offBoxes[i]));
        }
        REQUIRE(on.GetContactReports().size() == off.GetContactReports().size());
    }
}

#ifndef MEFF_DOUBLE

namespace
{

enum class Kind
{
    Circle,
    Box,
    Segment,
};

/// One body of a lockstep scene, built the same way in both engines.
struct BodySpec
{
    BodyType type = BodyType::Dynamic;
    Vec2 position;
    Real angle = 0;
    Vec2 velocity;
    Real angularVelocity = 0;
    bool bullet = false;
    Kind kind = Kind::Box;
    Real a = Real(0.5), b = Real(0.5); ///< radius, or half-extents, or segment half-length
    Real restitution = 0;
    bool awake = true;
};

class PostSolveRecorder : public b2ContactListener
{
  public:
    void PostSolve(b2Contact* contact, const b2ContactImpulse* impulse) override
    {
        // The world manifold at the transforms the solver left: meff's reports are built at
        // the same, later (when read, or before a time-of-impact event changes them).
        b2WorldManifold manifold;
        contact->GetWorldManifold(&manifold);
        for (int i = 0; i < impulse->count; ++i)
        {
            normalImpulses.push_back(impulse->normalImpulses[i]);
            tangentImpulses.push_back(impulse->tangentImpulses[i]);
            points.push_back(manifold.points[i]);
            normals.push_back(manifold.normal);
            separations.push_back(manifold.separations[i]);
            featureKeys.push_back(contact->GetManifold()->points[i].id.key);
        }
    }
    void Clear()
    {
        normalImpulses.clear();
        tangentImpulses.clear();
        points.clear();
        normals.clear();
        separations.clear();
        featureKeys.clear();
    }
    std::vector<float> normalImpulses, tangentImpulses, separations;
    std::vector<b2Vec2> points, normals;
    std::vector<std::uint32_t> featureKeys;
};

b2BodyType ToB2(BodyType type)
{
    switch (type)
    {
    case BodyType::Static:
        return b2_staticBody;
    case BodyType::Kinematic:
        return b2_kinematicBody;
    case BodyType::Dynamic:
        return b2_dynamicBody;
    }
    return b2_staticBody;
}

struct Lockstep
{
    World meff = MakeWorld(true, {0, -10});
    b2World box2d{b2Vec2(0, -10)};
    PostSolveRecorder recorder;
    std::vector<BodyId> meffBodies;
    std::vector<b2Body*> box2dBodies;

    explicit Lockstep(const std::vector<BodySpec>& specs, bool allowSleep = false)
    {
        meff.SetAllowSleeping(allowSleep);
        box2d.SetAllowSleeping(allowSleep);
        box2d.SetContinuousPhysics(true);
        box2d.SetContactListener(&recorder);
        for (const BodySpec& spec : specs)
        {
            BodyDef def;
            def.type = spec.type;
            def.position = spec.position;
            def.angle = spec.angle;
            def.linearVelocity = spec.velocity;
            def.angularVelocity = spec.angularVelocity;
            def.bullet = spec.bullet;
            def.awake = spec.awake;
            const BodyId id = meff.CreateBody(def);
            meffBodies.push_back(id);

            b2BodyDef bdef;
            bdef.type = ToB2(spec.type);
            bdef.position.Set(spec.position.x, spec.position.y);
            bdef.angle = spec.angle;
            bdef.linearVelocity.Set(spec.velocity.x, spec.velocity.y);
            bdef.angularVelocity = spec.angularVelocity;
            bdef.bullet = spec.bullet;
            bdef.awake = spec.awake;
            b2Body* body = box2d.CreateBody(&bdef);
            box2dBodies.push_back(body);

            const Real density = spec.type == BodyType::Dynamic ? Real(1) : Real(0);
            b2FixtureDef fdef;
            fdef.density = density;
            fdef.friction = Real(0.6);
            fdef.restitution = spec.restitution;
            fdef.restitutionThreshold = 1;
            const ShapeDef sdef = Material(density, Real(0.6), spec.restitution);
            switch (spec.kind)
            {
            case Kind::Circle:
            {
                meff.CreateShape(id, sdef, Circle{{0, 0}, spec.a});
                b2CircleShape circle;
                circle.m_radius = spec.a;
                fdef.shape = &circle;
                body->CreateFixture(&fdef);
                break;
            }
            case Kind::Box:
            {
                meff.CreateShape(id, sdef, MakeBox(spec.a, spec.b));
                b2PolygonShape box;
                box.SetAsBox(spec.a, spec.b);
                fdef.shape = &box;
                body->CreateFixture(&fdef);
                break;
            }
            case Kind::Segment:
            {
                meff.CreateShape(id, sdef, Segment{{-spec.a, 0}, {spec.a, 0}});
                b2EdgeShape edge;
                edge.SetTwoSided(b2Vec2(-spec.a, 0), b2Vec2(spec.a, 0));
                fdef.shape = &edge;
                body->CreateFixture(&fdef);
                break;
            }
            }
        }
    }

    /// Steps both engines `steps` times, requiring identical state; returns the number of
    /// contact reports beyond the discrete solver's (time-of-impact sub-step reports).
    void Run(int steps)
    {
        for (int step = 0; step < steps; ++step)
        {
            recorder.Clear();
            meff.Step(kDt);
            box2d.Step(kDt, 8, 3);
            INFO("step " << step);
            for (std::size_t i = 0; i < meffBodies.size(); ++i)
            {
                INFO("body " << i);
                const b2Body* body = box2dBodies[i];
                const Vec2 p = meff.GetPosition(meffBodies[i]);
                const Vec2 v = meff.GetLinearVelocity(meffBodies[i]);
                REQUIRE(p.x == body->GetPosition().x);
                REQUIRE(p.y == body->GetPosition().y);
                REQUIRE(meff.GetAngle(meffBodies[i]) == body->GetAngle());
                REQUIRE(v.x == body->GetLinearVelocity().x);
                REQUIRE(v.y == body->GetLinearVelocity().y);
                REQUIRE(meff.GetAngularVelocity(meffBodies[i]) == body->GetAngularVelocity());
                REQUIRE(meff.IsAwake(meffBodies[i]) == body->IsAwake());
            }
            const auto reports = meff.GetContactReports();
            REQUIRE(reports.size() == recorder.normalImpulses.size());
            for (std::size_t i = 0; i < reports.size(); ++i)
            {
                REQUIRE(reports[i].normalImpulse == recorder.normalImpulses[i]);
                REQUIRE(reports[i].tangentImpulse == recorder.tangentImpulses[i]);
                REQUIRE(reports[i].point.x == recorder.points[i].x);
                REQUIRE(reports[i].point.y == recorder.points[i].y);
                REQUIRE(reports[i].normal.x == recorder.normals[i].x);
                REQUIRE(reports[i].normal.y == recorder.normals[i].y);
                REQUIRE(reports[i].separation == recorder.separations[i]);
                REQUIRE(reports[i].featureKey == recorder.featureKeys[i]);
            }
            REQUIRE(meff.GetContactCount() == box2d.GetContactCount());
            // A contact point reported again within one step comes from a time-of-impact
            // sub-step (the discrete solver reports each once).
            for (std::size_t i = 0; i < reports.size(); ++i)
            {
                for (std::size_t j = 0; j < i; ++j)
                {
                    if (reports[j].shapeA == reports[i].shapeA &&
                        reports[j].shapeB == reports[i].shapeB &&
                        reports[j].pointIndex == reports[i].pointIndex)
                    {
                        ++repeatedReports;
                        break;
                    }
                }
            }
        }
    }

    std::size_t repeatedReports = 0;
};

} // namespace

TEST_CASE("Lockstep with Box2D 2.4.1, continuous on: fast bodies onto static ground",
          "[continuous][box2d][lockstep]")
{
    std::vector<BodySpec> specs;
    // Ground: a thin box and a segment shelf.
    specs.push_back({BodyType::Static, {0, 0}, 0, {}, 0, false, Kind::Box, 20, Real(0.05)});
    specs.push_back({BodyType::Static, {8, 6}, Real(0.3), {}, 0, false, Kind::Segment, 3});
    // Fast falling and thrown bodies: circles, boxes, spinning, one bouncing.
    specs.push_back({BodyType::Dynamic, {-6, 8}, 0, {0, -90}, 0, false, Kind::Circle, 0.1f});
    specs.push_back(
        {BodyType::Dynamic, {-3, 10}, 0.4f, {20, -110}, 15, false, Kind::Box, 0.2f, 0.1f});
    specs.push_back({BodyType::Dynamic, {0, 4}, 0, {0, -120}, 0, false, Kind::Box, 0.5f, 0.5f});
    specs.push_back(
        {BodyType::Dynamic, {3, 12}, 1.0f, {-10, -100}, -20, false, Kind::Box, 0.3f, 0.05f});
    specs.push_back(
        {BodyType::Dynamic, {8, 14}, 0, {1, -80}, 0, false, Kind::Circle, 0.2f, 0, Real(0.8)});
    specs.push_back({BodyType::Dynamic, {5, 3}, 0, {0, -200}, 0, false, Kind::Circle, 0.05f});
    // A slow box resting near the impacts (a neighbour of the time-of-impact islands).
    specs.push_back({BodyType::Dynamic, {-6, Real(0.55)}, 0, {}, 0, false, Kind::Box, 0.5f, 0.5f});

    Lockstep lockstep(specs);
    lockstep.Run(120);
    // Time-of-impact events happened (and agreed with Box2D's, reports included).
    CHECK(lockstep.repeatedReports > 0);
}

TEST_CASE("Lockstep with Box2D 2.4.1, continuous on: bullets and a kinematic body",
          "[continuous][box2d][lockstep][bullet]")
{
    std::vector<BodySpec> specs;
    specs.push_back({BodyType::Static, {0, 0}, 0, {}, 0, false, Kind::Box, 20, Real(0.5)});
    // A stack of thin boxes the bullets fly into.
    for (int i = 0; i < 4; ++i)
    {
        specs.push_back({BodyType::Dynamic,
                         {2, Real(0.5) + Real(1.01) + Real(i) * Real(1.015)},
                         0,
                         {},
                         0,
                         false,
                         Kind::Box,
                         Real(0.1),
                         Real(0.5)});
    }
    specs.push_back(
        {BodyType::Dynamic, {-6, 1.3f}, 0, {110, 0}, 0, true, Kind::Circle, 0.08f, 0, 0.3f});
    specs.push_back(
        {BodyType::Dynamic, {-8, 3.4f}, 0.2f, {115, -5}, 3, true, Kind::Box, 0.1f, 0.05f});
    // A kinematic paddle moving fast, and a body thrown at it.
    specs.push_back(
        {BodyType::Kinematic, {-10, 6}, 0, {30, 0}, 1, false, Kind::Box, Real(0.1), Real(1)});
    specs.push_back({BodyType::Dynamic, {4, 6}, 0, {-100, 0}, 0, false, Kind::Circle, 0.1f});

    Lockstep lockstep(specs);
    lockstep.Run(90);
    CHECK(lockstep.repeatedReports > 0);
    // The low bullet hit the bottom thin box (rather than tunnelling) and knocked it away.
    CHECK(lockstep.meff.GetPosition(lockstep.meffBodies[1]).x > 3);
}

TEST_CASE("Lockstep with Box2D 2.4.1, continuous on: a bullet strikes a box on a kinematic "
          "platform that carries another",
          "[continuous][box2d][lockstep][bullet]")
{
    // The bullet's event takes the platform (a kinematic neighbour of the box it strikes) into
    // its island and moves it back to the impact. The platform's report with the other box,
    // solved before, must still be the one at the transforms the discrete solver left (Box2D's
    // PostSolve): the reports an event could change are built before it.
    std::vector<BodySpec> specs;
    specs.push_back({BodyType::Kinematic,
                     {0, 2},
                     0,
                     {Real(0.37), Real(0.13)},
                     Real(0.05),
                     false,
                     Kind::Box,
                     3,
                     Real(0.2)});
    specs.push_back({BodyType::Dynamic, {-1, Real(2.7)}, 0, {}, 0, false, Kind::Box, 0.5f, 0.5f});
    specs.push_back({BodyType::Dynamic, {1.5f, Real(2.7)}, 0, {}, 0, false, Kind::Box, 0.5f, 0.5f});
    for (int i = 0; i < 3; ++i)
    {
        specs.push_back({BodyType::Dynamic,
                         {Real(-14 - 7 * i), Real(2.8) + Real(0.1) * Real(i)},
                         0,
                         {120, 0},
                         0,
                         true,
                         Kind::Circle,
                         0.08f});
    }
    Lockstep lockstep(specs);
    lockstep.Run(30);
    CHECK(lockstep.repeatedReports > 0);
    // The bullet struck the first box rather than passing through it: it is still short of the
    // second box, and the first was knocked along the platform faster than the platform moves.
    CHECK(lockstep.meff.GetPosition(lockstep.meffBodies[3]).x < Real(0.5));
    CHECK(lockstep.meff.GetLinearVelocity(lockstep.meffBodies[1]).x > Real(0.5));
}

TEST_CASE("Lockstep with Box2D 2.4.1, continuous on: a bullet wakes a sleeping kinematic "
          "platform whose contact with a sleeping box then has an impact",
          "[continuous][box2d][lockstep][bullet]")
{
    // The platform and the box on it start asleep, their polygons 0.003 m apart (their skins
    // overlapping): their contact is never updated while both sleep. The bullet's event wakes
    // the platform; Box2D's walk then sweeps the platform and the box and finds them already
    // within the impact distance (closer than the target separation, not overlapping), an
    // event at once. The impact queue lists a kinematic body's contacts after an event only
    // when the event woke it, which is this case.
    std::vector<BodySpec> specs;
    BodySpec platform{BodyType::Kinematic, {0, 0}, 0, {}, 0, false, Kind::Box, 2, Real(0.2)};
    platform.awake = false;
    specs.push_back(platform);
    BodySpec box{BodyType::Dynamic, {0, Real(0.703)}, 0, {}, 0, false, Kind::Box, 0.5f, 0.5f};
    box.awake = false;
    specs.push_back(box);
    // Low on the platform's face: the bullet's box never reaches the box's (no contact between
    // them, which would list the box's contacts after the bullet's event anyway).
    specs.push_back(
        {BodyType::Dynamic, {-10, Real(-0.12)}, 0, {100, 0}, 0, true, Kind::Circle, 0.05f});
    Lockstep lockstep(specs, true);
    lockstep.Run(20);
    CHECK(lockstep.meff.IsAwake(lockstep.meffBodies[0]));
    CHECK(lockstep.meff.IsAwake(lockstep.meffBodies[1]));
}

#endif // MEFF_DOUBLE
