// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The continuous stage's queue of candidate impacts (engine/src/dynamics/impact_queue.h). It
// must find what Box2D 2.4.1's walk of the contact list finds: the smallest alpha, the first in
// list order among equals, from the contacts an event may have changed. The whole stage is
// checked bit for bit against Box2D 2.4.1 by validating samples/scenes/impact_storm.json (every
// back end's continuous stage is the same code); here, the queue's rules one by one, and the
// event-local listing against listing every candidate after every event in the other back ends.
#include <catch2/catch.hpp>

#include "dynamics/impact_queue.h"
#include "dynamics/pair_rules.h"
#include "dynamics/step_stages.h"
#include "dynamics/world_state.h"
#include "meff/scene.h"
#include "meff/world.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

using namespace meff;
using detail::ImpactQueue;
using detail::WorldState;

namespace
{

/// A world's state made by hand: a static body and four dynamic ones, each with a circle, and
/// the contacts a test makes itself (no step).
struct QueueWorld
{
    WorldState state{WorldDef{}};
    std::int32_t ground = 0;
    std::vector<std::int32_t> balls; ///< shape indices

    QueueWorld()
    {
        for (int i = 0; i < 5; ++i)
        {
            detail::Body& body = state.bodies.Slots().emplace_back();
            body.type = i == 0 ? BodyType::Static : BodyType::Dynamic;
            detail::Shape& shape = state.shapes.Slots().emplace_back();
            shape.alive = true;
            shape.body = i;
            shape.type = ShapeType::Circle;
            shape.circle = Circle{{0, 0}, 1};
            if (i > 0)
            {
                balls.push_back(i);
            }
        }
    }

    WorldState& State() { return state; }

    /// Makes the contact of two shapes (it goes to the front of the list) and returns its index.
    std::int32_t Contact(std::int32_t shapeA, std::int32_t shapeB)
    {
        detail::CreateContact(state, shapeA, shapeB);
        return state.contactList;
    }
};

std::vector<std::int32_t> Taken(const WorldState& state, ImpactQueue& queue)
{
    const std::vector<std::int32_t>& taken = queue.TakeChanged(state);
    return {taken.begin(), taken.end()};
}

} // namespace

TEST_CASE("Impact queue: the smallest alpha first, the list's first among equals",
          "[continuous][impact_queue]")
{
    QueueWorld q;
    const std::int32_t c1 = q.Contact(q.ground, q.balls[0]);
    const std::int32_t c2 = q.Contact(q.ground, q.balls[1]);
    const std::int32_t c3 = q.Contact(q.ground, q.balls[2]);
    // Two ordinary dynamic bodies: Box2D never sweeps their contact, so it is no candidate.
    q.Contact(q.balls[0], q.balls[1]);

    ImpactQueue queue;
    queue.Begin(q.State());
    // The newest contact heads the list, as b2ContactManager::AddPair puts it.
    REQUIRE(Taken(q.State(), queue) == std::vector<std::int32_t>{c3, c2, c1});
    queue.Set(q.State(), c1, Real(0.5));
    queue.Set(q.State(), c2, Real(0.5));
    queue.Set(q.State(), c3, Real(0.5));
    Real alpha = 0;
    // All at 0.5: the walk keeps the first it meets with the smallest alpha, the list's head.
    CHECK(queue.PopFirst(alpha) == c3);
    CHECK(alpha == Real(0.5));
    CHECK(queue.PopFirst(alpha) == c2);
    CHECK(queue.PopFirst(alpha) == c1);
    CHECK(queue.PopFirst(alpha) == detail::kNullIndex);

    queue.Begin(q.State());
    Taken(q.State(), queue);
    queue.Set(q.State(), c3, Real(0.75));
    queue.Set(q.State(), c1, Real(0.25));
    queue.Set(q.State(), c2, Real(0.5));
    CHECK(queue.PopFirst(alpha) == c1); // a smaller alpha wins wherever it is in the list
    CHECK(alpha == Real(0.25));
}

TEST_CASE("Impact queue: an event's contacts are listed again, their impacts replaced or dropped",
          "[continuous][impact_queue]")
{
    QueueWorld q;
    const std::int32_t c1 = q.Contact(q.ground, q.balls[0]);
    const std::int32_t c2 = q.Contact(q.ground, q.balls[1]);
    ImpactQueue queue;
    queue.Begin(q.State());
    Taken(q.State(), queue);
    queue.Set(q.State(), c1, Real(0.5));
    queue.Set(q.State(), c2, Real(0.25));
    Real alpha = 0;
    REQUIRE(queue.PopFirst(alpha) == c2);

    // The event on c2 moved ball 1 and refreshed c2: c2 alone is listed (the static ground's
    // other contacts do not change), and c1's entry is still good.
    queue.EventDone(q.State(), c2);
    REQUIRE(Taken(q.State(), queue) == std::vector<std::int32_t>{c2});
    queue.Set(q.State(), c2, Real(0.75));
    queue.Set(q.State(), c2, Real(0.75)); // the same impact again: its entry stands
    // An event on c1 lists it again; now it has no impact to act on: its entry at 0.5 goes.
    queue.EventDone(q.State(), c1);
    REQUIRE(Taken(q.State(), queue) == std::vector<std::int32_t>{c1});
    queue.Drop(c1);
    CHECK(queue.PopFirst(alpha) == c2);
    CHECK(alpha == Real(0.75));
    CHECK(queue.PopFirst(alpha) == detail::kNullIndex);
}

TEST_CASE("Impact queue: a contact made during the stage goes before the whole list",
          "[continuous][impact_queue]")
{
    QueueWorld q;
    const std::int32_t c1 = q.Contact(q.ground, q.balls[0]);
    ImpactQueue queue;
    queue.Begin(q.State());
    REQUIRE(Taken(q.State(), queue) == std::vector<std::int32_t>{c1});
    queue.Set(q.State(), c1, Real(0.5));

    const std::int32_t c2 = q.Contact(q.ground, q.balls[1]);
    const std::int32_t c3 = q.Contact(q.ground, q.balls[2]);
    // A new contact is one of a moved body, which the event lists with all its contacts.
    queue.EventDone(q.State(), c2);
    queue.EventDone(q.State(), c3);
    REQUIRE(Taken(q.State(), queue) == std::vector<std::int32_t>{c3, c2});
    queue.Set(q.State(), c2, Real(0.5));
    queue.Set(q.State(), c3, Real(0.5));
    Real alpha = 0;
    CHECK(queue.PopFirst(alpha) == c3);
    CHECK(queue.PopFirst(alpha) == c2);
    CHECK(queue.PopFirst(alpha) == c1);
}

TEST_CASE("Swept contacts: the continuous stage's candidates stay listed as contacts come and go",
          "[continuous][impact_queue]")
{
    QueueWorld q;
    const std::int32_t c1 = q.Contact(q.ground, q.balls[0]);
    const std::int32_t c2 = q.Contact(q.ground, q.balls[1]);
    const std::int32_t c3 = q.Contact(q.ground, q.balls[2]);
    const std::int32_t between = q.Contact(q.balls[0], q.balls[1]);
    CHECK((q.state.contacts[between].flags & detail::Contact::Swept) == 0);
    detail::DestroyContact(q.state, c1); // the last one takes its slot
    detail::DestroyContact(q.state, between);
    const std::int32_t c4 = q.Contact(q.ground, q.balls[3]);
    REQUIRE(q.state.sweptContacts.size() == 3);
    for (std::size_t slot = 0; slot < q.state.sweptContacts.size(); ++slot)
    {
        const std::int32_t c = q.state.sweptContacts[slot];
        CHECK(q.state.contacts[c].sweptSlot == static_cast<std::int32_t>(slot));
        CHECK((q.state.contacts[c].flags & detail::Contact::Swept) != 0);
    }
    ImpactQueue queue;
    queue.Begin(q.State());
    // c4 reused c1's index, or another: either way it is the list's head now.
    CHECK(Taken(q.State(), queue) == std::vector<std::int32_t>{c4, c3, c2});
}

TEST_CASE("Impact queue: a kinematic body's other contacts are listed only when the event woke "
          "it",
          "[continuous][impact_queue]")
{
    for (const bool asleep : {true, false})
    {
        QueueWorld q;
        detail::Body& paddle = q.state.bodies.Slots().emplace_back();
        paddle.type = BodyType::Kinematic;
        paddle.awake = !asleep;
        detail::Shape& shape = q.state.shapes.Slots().emplace_back();
        shape.alive = true;
        shape.body = 5;
        shape.type = ShapeType::Circle;
        shape.circle = Circle{{0, 0}, 1};
        const std::int32_t hit = q.Contact(5, q.balls[0]);
        const std::int32_t other = q.Contact(5, q.balls[1]);
        ImpactQueue queue;
        queue.Begin(q.State());
        REQUIRE(Taken(q.State(), queue) == std::vector<std::int32_t>{other, hit});

        queue.BeforeEvent(q.State(), hit);
        q.state.bodies[5].awake = true; // the event wakes the paddle, as AdvanceToImpact does
        queue.EventDone(q.State(), hit);
        INFO("paddle asleep before the event: " << asleep);
        // Ball 0 is dynamic: its contacts are listed. The paddle's contact with ball 1 changes
        // only if the paddle woke: its cached impact stays (Box2D invalidates dynamic bodies').
        const std::vector<std::int32_t> expected =
            asleep ? std::vector<std::int32_t>{other, hit} : std::vector<std::int32_t>{hit};
        CHECK(Taken(q.State(), queue) == expected);
    }
}

TEST_CASE("Impact queue: impacts the stage would not act on are not kept",
          "[continuous][impact_queue]")
{
    QueueWorld q;
    const std::int32_t c1 = q.Contact(q.ground, q.balls[0]);
    ImpactQueue queue;
    queue.Begin(q.State());
    Taken(q.State(), queue);
    // b2World::SolveTOI stops when the earliest alpha is above 1 − 10ε.
    const Real last = Real(1) - Real(10) * kEpsilon;
    queue.Set(q.State(), c1, std::nextafter(last, Real(2)));
    queue.Set(q.State(), c1, Real(1));
    queue.Set(q.State(), c1, std::numeric_limits<Real>::quiet_NaN());
    Real alpha = 0;
    CHECK(queue.PopFirst(alpha) == detail::kNullIndex);
    queue.Set(q.State(), c1, last);
    CHECK(queue.PopFirst(alpha) == c1);
}

TEST_CASE("Impact queue: with a user callback that could wake any body, every candidate is "
          "listed after every event",
          "[continuous][impact_queue]")
{
    QueueWorld q;
    const std::int32_t c1 = q.Contact(q.ground, q.balls[0]);
    const std::int32_t c2 = q.Contact(q.ground, q.balls[1]);
    q.state.customFilter = [](ShapeId, ShapeId) { return true; };
    ImpactQueue queue;
    queue.Begin(q.State());
    REQUIRE(Taken(q.State(), queue) == std::vector<std::int32_t>{c2, c1});
    queue.EventDone(q.State(), c1);
    CHECK(Taken(q.State(), queue) == std::vector<std::int32_t>{c2, c1});
}

TEST_CASE("Impact queue: listing only what an event changed steps as listing every candidate "
          "after every event, in every back end",
          "[continuous][impact_queue]")
{
    // With a custom filter installed the queue lists every candidate after every event (the
    // walk, over the contacts it can act on); one that lets everything through changes nothing
    // else. Box2D's back end is validated against Box2D 2.4.1 itself (ctest validate.*).
    const Scene storm =
        LoadScene(std::string(MEFF_SOURCE_DIR) + "/samples/scenes/impact_storm.json");
    for (const SolverKind kind : {SolverKind::Colour, SolverKind::SoftStep})
    {
        Scene scene = storm;
        scene.world.solver.kind = kind;
        BuiltScene local = BuildWorld(scene);
        BuiltScene everything = BuildWorld(scene);
        everything.world.SetCustomFilterCallback([](ShapeId, ShapeId) { return true; });
        for (int frame = 1; frame <= scene.world.frames; ++frame)
        {
            local.Step(scene.world.dt);
            everything.Step(scene.world.dt);
            INFO("back end " << static_cast<int>(kind) << ", frame " << frame);
            REQUIRE(local.world.GetStateHash() == everything.world.GetStateHash());
        }
    }
}
