// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Game events: sensors (begin/end overlap events), contact hit events and the pre-solve
// callback.
//
// Oracles: Box2D 2.4.1 itself for sensors and pre-solve (the same world built in both engines
// through the scene mirror, a b2ContactListener recording BeginContact/EndContact and applying
// the same PreSolve rule; events and bodies must agree exactly, step by step), and free fall
// for the hit speed.
#include "meff/box2d_mirror.h"
#include "meff/scene.h"
#include "meff/world.h"

#include <box2d/box2d.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <string>
#include <unordered_map>
#include <vector>

using namespace meff;

namespace
{

constexpr Real kDt = Real(1) / Real(60);

std::string Describe(ShapeId a, ShapeId b)
{
    return std::to_string(a.index) + "/" + std::to_string(a.generation) + "-" +
           std::to_string(b.index) + "/" + std::to_string(b.generation);
}

std::vector<std::string> Describe(std::span<const SensorEvent> events)
{
    std::vector<std::string> out;
    for (const SensorEvent& e : events)
    {
        out.push_back(Describe(e.sensorShape, e.visitorShape));
    }
    return out;
}

std::vector<std::string> Describe(std::span<const ContactEvent> events)
{
    std::vector<std::string> out;
    for (const ContactEvent& e : events)
    {
        out.push_back(Describe(e.shapeA, e.shapeB));
    }
    return out;
}

/// A ball of radius r dropped on a ground segment from centre height y0, with hit events on.
struct DropWorld
{
    World world;
    BodyId ground, ball;
    ShapeId groundShape, ballShape;
};

DropWorld MakeDrop(Real y0, Real r, bool hitEvents, const WorldDef& def = {})
{
    DropWorld d{World{def}, {}, {}, {}, {}};
    d.ground = d.world.CreateBody({});
    d.groundShape = d.world.CreateShape(d.ground, ShapeDef{}, Segment{{-5, 0}, {5, 0}});
    d.ball = d.world.CreateBody({.type = BodyType::Dynamic, .position = {0, y0}});
    d.ballShape =
        d.world.CreateShape(d.ball, ShapeDef{.enableHitEvents = hitEvents}, Circle{{0, 0}, r});
    return d;
}

} // namespace

// ---------------------------------------------------------------------------------------------
// Sensors

TEST_CASE("A sensor detects a falling ball without touching it", "[events][sensor]")
{
    World world;
    const BodyId gate = world.CreateBody({});
    const ShapeId sensor =
        world.CreateShape(gate, ShapeDef{.isSensor = true}, MakeOffsetBox(2, Real(0.5), {0, 3}, 0));
    const BodyId ball = world.CreateBody({.type = BodyType::Dynamic, .position = {0, 5}});
    const ShapeId ballShape = world.CreateShape(ball, ShapeDef{}, Circle{{0, 0}, Real(0.25)});

    int beginStep = -1, endStep = -1;
    for (int step = 1; step <= 90; ++step)
    {
        world.Step(kDt);
        // Free fall through the gate: v = −g·t exactly as without it (semi-implicit Euler).
        // Relative 1e-5: v is a float sum of up to 90 kicks of g·h, each rounded to about an
        // ulp (6e-8 relative): at most ~90 · 6e-8 = 5.4e-6 (measured: under 1e-6), while one
        // kick too many or too few would be off by at least 1/90.
        REQUIRE(world.GetLinearVelocity(ball).y == Approx(-10 * step * kDt).epsilon(1e-5));
        REQUIRE(world.GetContactReports().empty());
        REQUIRE(world.GetContactBeginEvents().empty());
        for (const SensorEvent& e : world.GetSensorBeginEvents())
        {
            CHECK(e.sensorShape == sensor);
            CHECK(e.visitorShape == ballShape);
            CHECK(beginStep == -1);
            beginStep = step;
        }
        for (const SensorEvent& e : world.GetSensorEndEvents())
        {
            CHECK(e.sensorShape == sensor);
            CHECK(e.visitorShape == ballShape);
            CHECK(endStep == -1);
            endStep = step;
        }
    }
    // The overlap is found in the narrow phase at the start of the step after the ball's bottom
    // came within the box's 0.01 m skin of the gate's top (y = 3.5), and lost the step after
    // its top went further than the skin below the gate's bottom (y = 2.5). Positions after
    // n steps: y_n = 5 − g·dt²·n(n+1)/2.
    const auto firstStepBelow = [](Real y)
    {
        int n = 0;
        while (Real(5) - Real(10) * kDt * kDt * Real(n * (n + 1)) / 2 > y)
        {
            ++n;
        }
        return n;
    };
    CHECK(beginStep == firstStepBelow(Real(3.5) + Real(0.01) + Real(0.25)) + 1);
    CHECK(endStep == firstStepBelow(Real(2.5) - Real(0.01) - Real(0.25)) + 1);
}

TEST_CASE("A sensor's density counts towards its body's mass, as in Box2D", "[events][sensor]")
{
    World world;
    const BodyId body = world.CreateBody({.type = BodyType::Dynamic});
    world.CreateShape(body, ShapeDef{.density = 2}, MakeBox(1, 1));
    world.CreateShape(body, ShapeDef{.density = 1, .isSensor = true},
                      MakeOffsetBox(1, 1, {2, 0}, 0));
    // Two 2×2 boxes: 2·4 + 1·4 kg, centre of mass (0·8 + 2·4)/12 = 2/3 m along x.
    CHECK(world.GetMass(body) == Approx(12));
    CHECK(world.GetLocalCenter(body).x == Approx(Real(2) / 3));
}

TEST_CASE("Sensor contacts are not solved and are absent from contact events", "[events][sensor]")
{
    // A dynamic box carrying a sensor circle rests on the ground: the circle overlaps the ground
    // but only the box holds the body up.
    World world;
    const BodyId ground = world.CreateBody({});
    const ShapeId groundShape = world.CreateShape(ground, ShapeDef{}, Segment{{-5, 0}, {5, 0}});
    const BodyId body = world.CreateBody({.type = BodyType::Dynamic, .position = {0, Real(0.6)}});
    const ShapeId box = world.CreateShape(body, ShapeDef{}, MakeBox(Real(0.5), Real(0.5)));
    const ShapeId ring = world.CreateShape(body, ShapeDef{.isSensor = true}, Circle{{0, 0}, 1});
    std::vector<SensorEvent> sensorBegins;
    std::vector<ContactEvent> contactBegins;
    for (int i = 0; i < 60; ++i)
    {
        world.Step(kDt);
        for (const SensorEvent& e : world.GetSensorBeginEvents())
        {
            sensorBegins.push_back(e);
        }
        for (const ContactEvent& e : world.GetContactBeginEvents())
        {
            contactBegins.push_back(e);
        }
        for (const ContactPointReport& report : world.GetContactReports())
        {
            CHECK(report.shapeB == box); // never the sensor
        }
    }
    REQUIRE(sensorBegins.size() == 1);
    CHECK(sensorBegins[0].sensorShape == ring);
    CHECK(sensorBegins[0].visitorShape == groundShape);
    REQUIRE(contactBegins.size() == 1);
    CHECK(contactBegins[0].shapeA == groundShape);
    CHECK(contactBegins[0].shapeB == box);
    // Resting on the box: centre at half height + the two 0.01 m skins − slop above the ground
    // (± 1 mm: the position solver leaves the overlap within a slop, not exactly at it).
    CHECK(world.GetPosition(body).y == Approx(0.5 + 0.02 - 0.005).margin(1e-3));
}

TEST_CASE("Destroying a shape inside a sensor reports a sensor end event", "[events][sensor]")
{
    World world{WorldDef{.gravity = {0, 0}}};
    const BodyId gate = world.CreateBody({});
    world.CreateShape(gate, ShapeDef{.isSensor = true}, MakeBox(2, 2));
    const BodyId ball = world.CreateBody({.type = BodyType::Dynamic});
    const ShapeId ballShape = world.CreateShape(ball, ShapeDef{}, Circle{{0, 0}, Real(0.25)});
    world.Step(kDt); // new shapes: contacts are found before the narrow phase of step 1
    REQUIRE(world.GetSensorBeginEvents().size() == 1);
    world.DestroyShape(ballShape);
    REQUIRE(world.GetSensorEndEvents().size() == 1);
    CHECK(world.GetSensorEndEvents()[0].visitorShape == ballShape);
}

// ---------------------------------------------------------------------------------------------
// Hit events

TEST_CASE("A dropped ball hits the ground at sqrt(2·g·h)", "[events][hit]")
{
    const Real r = Real(0.25);
    const Real y0 = 5;
    DropWorld d = MakeDrop(y0, r, true);
    int events = 0;
    for (int step = 0; step < 120; ++step)
    {
        d.world.Step(kDt);
        for (const ContactHitEvent& e : d.world.GetContactHitEvents())
        {
            ++events;
            CHECK(e.shapeA == d.groundShape);
            CHECK(e.shapeB == d.ballShape);
            CHECK(e.normal.x == Approx(0).margin(1e-6));
            CHECK(e.normal.y == Approx(1));
            CHECK(e.point.x == Approx(0).margin(1e-6));
            CHECK(std::abs(e.point.y) < Real(0.02)); // on the ground, within skin + slop
            // The contact forms once the ball's bottom is within the segment's 0.01 m skin:
            // a fall of h = y0 − r − 0.01. Semi-implicit Euler falls g·dt²·n(n+1)/2 in n steps,
            // which is the exact fall at speed v_n + g·dt/2, and the contact is found after the
            // crossing step (up to one step late), so v_n ∈ v* ± g·dt/2; the solver then sees
            // this step's gravity added: approach = v_n + g·dt ∈ [v* + g·dt/2, v* + 3g·dt/2].
            const Real h = y0 - r - Real(0.01);
            const Real exact = std::sqrt(2 * 10 * h);
            const Real gdt = 10 * kDt;
            CHECK(e.approachSpeed >= exact + gdt / 2 - Real(1e-3));
            CHECK(e.approachSpeed <= exact + 3 * gdt / 2 + Real(1e-3));
        }
    }
    CHECK(events == 1); // inelastic: one hit, then it rests (slower than the threshold)
}

TEST_CASE("Slow contacts and contacts without the flag make no hit events", "[events][hit]")
{
    SECTION("approach below the threshold")
    {
        // Falls 0.02 m before touching: about sqrt(2·10·0.02) = 0.63 m/s + g·dt, below 1 m/s.
        DropWorld d = MakeDrop(Real(0.25 + 0.01 + 0.02), Real(0.25), true);
        for (int step = 0; step < 60; ++step)
        {
            d.world.Step(kDt);
            CHECK(d.world.GetContactHitEvents().empty());
        }
        // The same drop with a 0.5 m/s threshold hits: the check above can fail.
        WorldDef def;
        def.tolerances.hitEventThreshold = Real(0.5);
        DropWorld low = MakeDrop(Real(0.25 + 0.01 + 0.02), Real(0.25), true, def);
        int events = 0;
        for (int step = 0; step < 60; ++step)
        {
            low.world.Step(kDt);
            events += static_cast<int>(low.world.GetContactHitEvents().size());
        }
        CHECK(events == 1);
    }
    SECTION("flag off: no events, and the same motion bit for bit")
    {
        DropWorld on = MakeDrop(5, Real(0.25), true);
        DropWorld off = MakeDrop(5, Real(0.25), false);
        int eventsOn = 0;
        for (int step = 0; step < 120; ++step)
        {
            on.world.Step(kDt);
            off.world.Step(kDt);
            eventsOn += static_cast<int>(on.world.GetContactHitEvents().size());
            CHECK(off.world.GetContactHitEvents().empty());
            REQUIRE(on.world.GetStateHash() == off.world.GetStateHash());
        }
        CHECK(eventsOn == 1);
    }
}

TEST_CASE("A box landing flat gives one hit event, its fastest point", "[events][hit]")
{
    // A 1 × 0.5 m box spinning at 1 rad/s, timed to land on its long face nearly flat: after 44
    // steps its centre has fallen g·h²·44·45/2 = 2.75 m to y = 0.25 and its angle is
    // −0.73 + 44/60 ≈ 0.003 rad, so both bottom corners are within the skins of the ground at
    // the start of the 45th step and the spin makes them approach 1 m/s apart. Discrete
    // collision only, so the hit is found from the pose the test reads before the step (a
    // time-of-impact sub-step would find it at a pose in between).
    World world{WorldDef{.continuous = false}};
    const BodyId ground = world.CreateBody({});
    const ShapeId groundShape = world.CreateShape(ground, ShapeDef{}, Segment{{-5, 0}, {5, 0}});
    const BodyId box = world.CreateBody({.type = BodyType::Dynamic,
                                         .position = {0, 3},
                                         .angle = Real(-0.73),
                                         .angularVelocity = Real(1)});
    const Real halfW = Real(0.5), halfH = Real(0.25);
    const ShapeId boxShape =
        world.CreateShape(box, ShapeDef{.enableHitEvents = true}, MakeBox(halfW, halfH));
    int events = 0;
    for (int step = 0; step < 120; ++step)
    {
        // The state the step starts from: its collision finds the manifold at this pose, and
        // the solver measures approach speeds after gravity's kick, v + g·h (no damping).
        const Vec2 p = world.GetPosition(box);
        const Real angle = world.GetAngle(box);
        const Vec2 v = world.GetLinearVelocity(box) + kDt * Vec2(0, -10);
        const Real omega = world.GetAngularVelocity(box);
        world.Step(kDt);
        const auto hits = world.GetContactHitEvents();
        CHECK(hits.size() <= 1); // one contact: at most one event per step
        events += static_cast<int>(hits.size());
        for (const ContactHitEvent& hit : hits)
        {
            CHECK(hit.shapeA == groundShape);
            CHECK(hit.shapeB == boxShape);
            CHECK(hit.normal.x == 0);
            CHECK(hit.normal.y == 1);
            // The manifold's points are the box corners within the two skins (0.01 m each) of
            // the ground. Along the normal (0, 1) a corner at r from the centre approaches at
            // −(v_y + ω·r_x).
            const Real c = std::cos(angle), s = std::sin(angle);
            Real fastest = 0;
            Real slowest = std::numeric_limits<Real>::max();
            Vec2 fastestLocal;
            int touching = 0;
            for (const Vec2 local : {Vec2(-halfW, -halfH), Vec2(halfW, -halfH), Vec2(halfW, halfH),
                                     Vec2(-halfW, halfH)})
            {
                const Vec2 r(c * local.x - s * local.y, s * local.x + c * local.y);
                if (p.y + r.y <= Real(0.02))
                {
                    ++touching;
                    const Real speed = -(v.y + omega * r.x);
                    slowest = std::min(slowest, speed);
                    if (speed > fastest)
                    {
                        fastest = speed;
                        fastestLocal = local;
                    }
                }
            }
            REQUIRE(touching == 2);
            CHECK(fastest - slowest > Real(0.9)); // the corners clearly differ (ω · 1 m)
            // The same quantities as the solver's, in another order: float round-off of an
            // 8 m/s speed, a few ulps (5e-7 m/s each), far below the 1 m/s between the corners.
            CHECK(hit.approachSpeed == Approx(fastest).epsilon(1e-5));
            // Reported at that corner, where it is after the step (the event's point comes from
            // the manifold with the bodies' final poses; a normal along y keeps the corner's x,
            // so only round-off separates the two).
            CHECK(hit.point.x == Approx(world.GetWorldPoint(box, fastestLocal).x).margin(1e-6));
        }
    }
    CHECK(events == 1);
}

TEST_CASE("A hit found only by continuous collision is reported once", "[events][hit]")
{
    // A ball at 100 m/s (1.67 m a step) towards a two-sided wall: the discrete step never sees
    // it touch; the time-of-impact sub-step stops it at the wall and reports the hit.
    World world{WorldDef{.gravity = {0, 0}, .continuous = true}};
    const BodyId wall = world.CreateBody({});
    const ShapeId wallShape = world.CreateShape(wall, ShapeDef{}, Segment{{0, -5}, {0, 5}});
    const BodyId ball = world.CreateBody(
        {.type = BodyType::Dynamic, .position = {-2, 0}, .linearVelocity = {100, 0}});
    const ShapeId ballShape =
        world.CreateShape(ball, ShapeDef{.enableHitEvents = true}, Circle{{0, 0}, Real(0.1)});
    int events = 0;
    for (int step = 0; step < 10; ++step)
    {
        world.Step(kDt);
        for (const ContactHitEvent& e : world.GetContactHitEvents())
        {
            ++events;
            CHECK(e.shapeA == wallShape);
            CHECK(e.shapeB == ballShape);
            CHECK(e.normal.x == Approx(-1));
            // No gravity, nothing else touching: the approach is the launch speed (float
            // round-off of the relative velocity along the normal only).
            CHECK(e.approachSpeed == Approx(100).epsilon(1e-5));
        }
    }
    CHECK(events == 1);
    CHECK(world.GetPosition(ball).x < 0); // stopped at the wall, not through it
}

TEST_CASE("TolerancesForLengthUnits scales the hit threshold", "[events][hit]")
{
    CHECK(TolerancesForLengthUnits(32).hitEventThreshold == Approx(32));
    CHECK_THROWS_AS(World(WorldDef{.tolerances = {.hitEventThreshold = -1}}), InvalidArgument);
}

// ---------------------------------------------------------------------------------------------
// Pre-solve

namespace
{

constexpr Real kPlatformTop = Real(3.1);
constexpr Real kBoxHalf = Real(0.25);

/// The one-way rule (as Box2D v3's platformer sample): a platform contact counts only when its
/// normal, turned to point from the platform to the other shape, points up. A body coming from
/// below has the normal pointing down until its centre is past the platform's.
bool PlatformAllows(bool platformIsA, Vec2 normalAToB)
{
    const Real up = platformIsA ? normalAToB.y : -normalAToB.y;
    return up > Real(0.5);
}

/// A static platform (top at y = 3.1) and a box shot up through it from below.
struct PlatformWorld
{
    World world;
    BodyId platform, box;
    ShapeId platformShape;

    PlatformWorld()
    {
        const BodyId ground = world.CreateBody({});
        world.CreateShape(ground, ShapeDef{}, Segment{{-5, 0}, {5, 0}});
        platform = world.CreateBody({.position = {0, 3}});
        platformShape = world.CreateShape(platform, ShapeDef{}, MakeBox(2, Real(0.1)));
        box = world.CreateBody(
            {.type = BodyType::Dynamic, .position = {0, 1}, .linearVelocity = {0, 10}});
        world.CreateShape(box, ShapeDef{}, MakeBox(kBoxHalf, kBoxHalf));
        world.SetPreSolveCallback(
            [shape = platformShape](const PreSolveContact& c)
            {
                if (c.shapeA != shape && c.shapeB != shape)
                {
                    return true;
                }
                REQUIRE(c.manifold->pointCount > 0);
                return PlatformAllows(c.shapeA == shape, c.worldManifold.normal);
            });
    }
};

} // namespace

TEST_CASE("One-way platform: the box passes up through it and lands on top", "[events][presolve]")
{
    PlatformWorld p;
    bool passedAbove = false;
    bool touchedFromBelow = false;
    for (int step = 0; step < 240; ++step)
    {
        p.world.Step(kDt);
        const Real y = p.world.GetPosition(p.box).y;
        const Real vy = p.world.GetLinearVelocity(p.box).y;
        if (vy > 0 && p.world.GetTouchingContactCount() > 0 && y < Real(3))
        {
            touchedFromBelow = true; // overlapping the platform on the way up...
            // ...but a disabled contact is not solved, so it is not reported.
            CHECK(p.world.GetContactReports().empty());
        }
        passedAbove = passedAbove || (y - kBoxHalf > kPlatformTop && vy > 0);
    }
    CHECK(touchedFromBelow);
    CHECK(passedAbove);
    // At rest on top: centre at top + half size + the two polygons' skins − slop (± 1 mm, the
    // position solver's leftover overlap is within a slop, not exactly at it).
    CHECK(p.world.GetPosition(p.box).y ==
          Approx(kPlatformTop + kBoxHalf + 0.02 - 0.005).margin(1e-3));
    CHECK(std::abs(p.world.GetLinearVelocity(p.box).y) < Real(1e-3));
}

TEST_CASE("Without the pre-solve callback the platform stops the box from below",
          "[events][presolve]")
{
    PlatformWorld p;
    p.world.SetPreSolveCallback({});
    for (int step = 0; step < 240; ++step)
    {
        p.world.Step(kDt);
        CHECK(p.world.GetPosition(p.box).y < Real(3));
    }
}

TEST_CASE("The pre-solve callback survives RestoreSnapshot", "[events][presolve]")
{
    SECTION("saved with the one-way rule, restored with an accept-all callback")
    {
        PlatformWorld p;
        const WorldSnapshot start = p.world.SaveSnapshot();
        int calls = 0;
        p.world.SetPreSolveCallback(
            [&calls](const PreSolveContact&)
            {
                ++calls;
                return true;
            });
        p.world.RestoreSnapshot(start); // keeps the accept-all callback installed after the save
        for (int step = 0; step < 120; ++step)
        {
            p.world.Step(kDt);
            // Not the saved one-way rule: the platform stops the box from below.
            CHECK(p.world.GetPosition(p.box).y < Real(3));
        }
        // Not wiped either: the callback installed after the save still sees the contacts.
        CHECK(calls > 0);
    }
    SECTION("saved without a callback, restored with the one-way rule")
    {
        PlatformWorld p;
        const auto oneWay = [shape = p.platformShape](const PreSolveContact& c)
        {
            return (c.shapeA != shape && c.shapeB != shape) ||
                   PlatformAllows(c.shapeA == shape, c.worldManifold.normal);
        };
        p.world.SetPreSolveCallback({});
        const WorldSnapshot start = p.world.SaveSnapshot();
        p.world.SetPreSolveCallback(oneWay);
        p.world.RestoreSnapshot(start); // must not bring back the empty callback of the save
        bool passedAbove = false;
        for (int step = 0; step < 120; ++step)
        {
            p.world.Step(kDt);
            passedAbove = passedAbove || p.world.GetPosition(p.box).y - kBoxHalf > kPlatformTop;
        }
        CHECK(passedAbove); // the one-way rule let it up through the platform
    }
}

#ifndef MEFF_DOUBLE

// ---------------------------------------------------------------------------------------------
// Golden tests against Box2D 2.4.1

namespace
{

/// Records Box2D's BeginContact/EndContact as meff's events (sensor contacts apart) and
/// applies an optional PreSolve rule, as SetEnabled(false).
class Box2DEvents : public b2ContactListener
{
  public:
    std::unordered_map<const b2Fixture*, ShapeId> shapeOf;
    std::vector<SensorEvent> sensorBegins, sensorEnds;
    std::vector<ContactEvent> contactBegins, contactEnds;
    std::function<bool(b2Contact*)> preSolve;

    void Clear()
    {
        sensorBegins.clear();
        sensorEnds.clear();
        contactBegins.clear();
        contactEnds.clear();
    }
    void BeginContact(b2Contact* contact) override { Record(contact, sensorBegins, contactBegins); }
    void EndContact(b2Contact* contact) override { Record(contact, sensorEnds, contactEnds); }
    void PreSolve(b2Contact* contact, const b2Manifold*) override
    {
        if (preSolve && !preSolve(contact))
        {
            contact->SetEnabled(false);
        }
    }

  private:
    void Record(b2Contact* contact, std::vector<SensorEvent>& sensors,
                std::vector<ContactEvent>& contacts)
    {
        const b2Fixture* a = contact->GetFixtureA();
        const b2Fixture* b = contact->GetFixtureB();
        if (a->IsSensor() || b->IsSensor())
        {
            const bool sensorIsA = a->IsSensor();
            sensors.push_back({shapeOf.at(sensorIsA ? a : b), shapeOf.at(sensorIsA ? b : a)});
        }
        else
        {
            contacts.push_back({shapeOf.at(a), shapeOf.at(b)});
        }
    }
};

/// One scene in both engines, stepped in lockstep.
struct Lockstep
{
    explicit Lockstep(const std::string& json)
        : scene(ParseScene(json, "events.json")), meff(BuildWorld(scene)), box2d(scene)
    {
        // Box2D's fixture lists are newest first; the scene's shapes are in creation order.
        for (std::size_t i = 0; i < scene.bodies.size(); ++i)
        {
            std::vector<const b2Fixture*> fixtures;
            for (const b2Fixture* f = box2d.Body(i)->GetFixtureList(); f; f = f->GetNext())
            {
                fixtures.push_back(f);
            }
            std::reverse(fixtures.begin(), fixtures.end());
            for (std::size_t k = 0; k < fixtures.size(); ++k)
            {
                events.shapeOf[fixtures[k]] = meff.shapes[i][k];
            }
        }
        box2d.World().SetContactListener(&events);
    }
    ~Lockstep() { box2d.World().SetContactListener(nullptr); }

    void Step()
    {
        events.Clear();
        meff.world.Step(static_cast<Real>(scene.world.dt));
        box2d.Step();
    }

    /// Every body's position, angle and velocities agree bit for bit.
    void RequireSameBodies(int step) const
    {
        for (std::size_t i = 0; i < scene.bodies.size(); ++i)
        {
            const BodyId id = meff.bodies[i];
            const b2Body* b = box2d.Body(i);
            INFO("step " << step << ", body " << scene.bodies[i].name);
            REQUIRE(meff.world.GetPosition(id).x == b->GetPosition().x);
            REQUIRE(meff.world.GetPosition(id).y == b->GetPosition().y);
            REQUIRE(meff.world.GetAngle(id) == b->GetAngle());
            REQUIRE(meff.world.GetLinearVelocity(id).x == b->GetLinearVelocity().x);
            REQUIRE(meff.world.GetLinearVelocity(id).y == b->GetLinearVelocity().y);
            REQUIRE(meff.world.GetAngularVelocity(id) == b->GetAngularVelocity());
        }
    }

    Scene scene;
    BuiltScene meff;
    validation::Box2DMirror box2d;
    Box2DEvents events;
};

/// Sensors of every kind: a static gate, a kinematic sweeper, a sensor ring on a dynamic box,
/// a sensor-only dynamic body that falls through everything (sensor against sensor), and
/// balls, boxes and a polygon falling through them onto the ground.
std::string SensorScene(bool continuous)
{
    return R"({
  "meff_scene": 1,
  "world": { "frames": 240, "continuous": )" +
           std::string(continuous ? "true" : "false") + R"( },
  "bodies": [
    { "name": "ground", "type": "static",
      "shapes": [{ "type": "segment", "points": [[-10, 0], [10, 0]] }] },
    { "name": "gate", "type": "static",
      "shapes": [{ "type": "box", "half_width": 4, "half_height": 0.5, "center": [0, 3], "sensor": true }] },
    { "name": "sweeper", "type": "kinematic", "position": [-7, 1], "linear_velocity": [3, 0],
      "shapes": [{ "type": "circle", "radius": 1, "sensor": true }] },
    { "name": "carrier", "type": "dynamic", "position": [2, 6], "angle": 0.3,
      "shapes": [{ "type": "box", "half_width": 0.3, "half_height": 0.3 },
                 { "type": "circle", "radius": 0.8, "sensor": true, "density": 0.5 }] },
    { "name": "ghost", "type": "dynamic", "position": [-2, 8],
      "shapes": [{ "type": "box", "half_width": 0.4, "half_height": 0.2, "sensor": true }] },
    { "name": "ball0", "type": "dynamic", "position": [-3, 5], "linear_velocity": [1, 0],
      "shapes": [{ "type": "circle", "radius": 0.25, "restitution": 0.5 }] },
    { "name": "ball1", "type": "dynamic", "position": [-1, 7],
      "shapes": [{ "type": "circle", "radius": 0.3 }] },
    { "name": "ball2", "type": "dynamic", "position": [0.5, 9], "linear_velocity": [0, -20],
      "bullet": true, "shapes": [{ "type": "circle", "radius": 0.2 }] },
    { "name": "box0", "type": "dynamic", "position": [3.5, 5], "angle": 0.7,
      "shapes": [{ "type": "box", "half_width": 0.4, "half_height": 0.2 }] },
    { "name": "wedge", "type": "dynamic", "position": [-4.5, 6],
      "shapes": [{ "type": "polygon", "vertices": [[-0.4, -0.3], [0.5, -0.2], [0, 0.4]] }] }
  ]
})";
}

} // namespace

TEST_CASE("Sensor events and bodies agree with Box2D 2.4.1 step by step", "[events][sensor][box2d]")
{
    const bool continuous = GENERATE(false, true);
    INFO("continuous " << continuous);
    Lockstep run(SensorScene(continuous));
    for (std::size_t i = 0; i < run.scene.bodies.size(); ++i)
    {
        REQUIRE(run.meff.world.GetMass(run.meff.bodies[i]) == run.box2d.Body(i)->GetMass());
    }
    std::size_t sensorEvents = 0, contactEvents = 0;
    for (int step = 1; step <= run.scene.world.frames; ++step)
    {
        run.Step();
        INFO("step " << step);
        REQUIRE(Describe(run.meff.world.GetSensorBeginEvents()) ==
                Describe(run.events.sensorBegins));
        REQUIRE(Describe(run.meff.world.GetSensorEndEvents()) == Describe(run.events.sensorEnds));
        REQUIRE(Describe(run.meff.world.GetContactBeginEvents()) ==
                Describe(run.events.contactBegins));
        REQUIRE(Describe(run.meff.world.GetContactEndEvents()) == Describe(run.events.contactEnds));
        run.RequireSameBodies(step);
        sensorEvents += run.events.sensorBegins.size() + run.events.sensorEnds.size();
        contactEvents += run.events.contactBegins.size() + run.events.contactEnds.size();
    }
    // The scene exercises what it claims to: many sensor events, and ordinary contacts too.
    CHECK(sensorEvents >= 20);
    CHECK(contactEvents >= 5);
}

TEST_CASE("The sensor_gate sample's sensor events agree with Box2D 2.4.1",
          "[events][sensor][box2d]")
{
    std::ifstream file(std::string(MEFF_SOURCE_DIR) + "/samples/scenes/sensor_gate.json");
    REQUIRE(file);
    const std::string json((std::istreambuf_iterator<char>(file)),
                           std::istreambuf_iterator<char>());
    Lockstep run(json);
    std::size_t begins = 0, ends = 0;
    for (int step = 1; step <= run.scene.world.frames; ++step)
    {
        run.Step();
        INFO("step " << step);
        REQUIRE(Describe(run.meff.world.GetSensorBeginEvents()) ==
                Describe(run.events.sensorBegins));
        REQUIRE(Describe(run.meff.world.GetSensorEndEvents()) == Describe(run.events.sensorEnds));
        begins += run.events.sensorBegins.size();
        ends += run.events.sensorEnds.size();
    }
    CHECK(begins == 4); // every falling body enters the gate once...
    CHECK(ends == 4);   // ...and leaves it below
}

TEST_CASE("A one-way platform by pre-solve agrees with Box2D 2.4.1 bit for bit",
          "[events][presolve][box2d]")
{
    const bool continuous = GENERATE(false, true);
    INFO("continuous " << continuous);
    // Boxes and a ball shot up through a platform (the fast box is in it within a step, so with
    // continuous on the time-of-impact stage meets the refused contact too), then falling back
    // onto it; one misses the platform and lands on the ground. The capped box hits a bar just
    // above the platform while still inside it from below: with continuous on, that impact's
    // mini-island must leave out the refused platform contact; the box falls back to the ground.
    Lockstep run(R"({
  "meff_scene": 1,
  "world": { "frames": 300, "continuous": )" +
                 std::string(continuous ? "true" : "false") + R"( },
  "bodies": [
    { "name": "ground", "type": "static",
      "shapes": [{ "type": "segment", "points": [[-10, 0], [10, 0]] }] },
    { "name": "platform", "type": "static", "position": [0, 3],
      "shapes": [{ "type": "box", "half_width": 3, "half_height": 0.1 }] },
    { "name": "slow", "type": "dynamic", "position": [-1, 1], "linear_velocity": [0, 9],
      "shapes": [{ "type": "box", "half_width": 0.25, "half_height": 0.25 }] },
    { "name": "fast", "type": "dynamic", "position": [1, 2.5], "linear_velocity": [0.5, 12],
      "shapes": [{ "type": "box", "half_width": 0.25, "half_height": 0.25 }] },
    { "name": "ball", "type": "dynamic", "position": [2.2, 1], "linear_velocity": [-0.3, 11],
      "shapes": [{ "type": "circle", "radius": 0.25 }] },
    { "name": "miss", "type": "dynamic", "position": [5, 1], "linear_velocity": [0, 8],
      "shapes": [{ "type": "box", "half_width": 0.25, "half_height": 0.25 }] },
    { "name": "bar", "type": "static",
      "shapes": [{ "type": "segment", "points": [[-2.7, 3.2], [-1.5, 3.2]] }] },
    { "name": "capped", "type": "dynamic", "position": [-2.1, 2.4], "linear_velocity": [0, 30],
      "shapes": [{ "type": "box", "half_width": 0.25, "half_height": 0.25 }] }
  ]
})");
    const Real top = Real(3.1);
    const std::size_t platform = 1;
    // Both engines apply PlatformAllows to their own world manifold inside their own step.
    const BodyId platformId = run.meff.bodies[platform];
    World& world = run.meff.world;
    int refusedMeff = 0, refusedBox2D = 0;
    world.SetPreSolveCallback(
        [&](const PreSolveContact& c)
        {
            if (c.bodyA != platformId && c.bodyB != platformId)
            {
                return true;
            }
            const bool ok = PlatformAllows(c.bodyA == platformId, c.worldManifold.normal);
            refusedMeff += ok ? 0 : 1;
            return ok;
        });
    const b2Body* const b2Platform = run.box2d.Body(platform);
    run.events.preSolve = [&](b2Contact* contact)
    {
        const b2Body* a = contact->GetFixtureA()->GetBody();
        const b2Body* b = contact->GetFixtureB()->GetBody();
        if (a != b2Platform && b != b2Platform)
        {
            return true;
        }
        b2WorldManifold wm;
        contact->GetWorldManifold(&wm);
        const bool ok = PlatformAllows(a == b2Platform, {wm.normal.x, wm.normal.y});
        refusedBox2D += ok ? 0 : 1;
        return ok;
    };

    for (int step = 1; step <= run.scene.world.frames; ++step)
    {
        run.Step();
        run.RequireSameBodies(step);
        INFO("step " << step);
        REQUIRE(Describe(run.meff.world.GetContactBeginEvents()) ==
                Describe(run.events.contactBegins));
        REQUIRE(Describe(run.meff.world.GetContactEndEvents()) == Describe(run.events.contactEnds));
        REQUIRE(refusedMeff == refusedBox2D);
    }
    CHECK(refusedMeff > 0); // the callback did take contacts out
    // The three that went up through the platform rest on it; the one beside it on the ground.
    for (const std::size_t i : {2u, 3u, 4u})
    {
        CHECK(world.GetPosition(run.meff.bodies[i]).y > top);
        CHECK(std::abs(world.GetLinearVelocity(run.meff.bodies[i]).y) < Real(1e-2));
    }
    CHECK(world.GetPosition(run.meff.bodies[5]).y < Real(1));
    // The capped box is stopped by the bar only with continuous collision; without, it moves
    // 0.5 m a step and tunnels through the bar.
    CHECK((world.GetPosition(run.meff.bodies[7]).y < Real(1)) == continuous);
}

#endif // MEFF_DOUBLE
