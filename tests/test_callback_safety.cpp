// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The user's callbacks (issue 36): installing a pre-solve callback that enables every contact,
// or a custom filter that allows every pair, changes no result in any back end; a callback may
// not change the world (itself included) while a step runs, and a refusal names the callback
// it came from; nor may a query's callback, or DebugDraw's methods, while they walk the world.
#include <catch2/catch.hpp>

#include "error_checks.h"
#include "world_fixtures.h"
#include "meff/debug_draw.h"
#include "meff/world.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

using namespace meff;

namespace
{

constexpr SolverKind kKinds[] = {SolverKind::Box2D, SolverKind::Colour, SolverKind::SoftStep};

/// A settling pile (contacts begin, rest and end: the colour and soft-step back ends recycle
/// the manifolds of resting ones) under back end `kind`.
World Pile(SolverKind kind)
{
    World world = test::MakePile(24, 3, Real(0.9), Real(0.2));
    SolverSettings settings = world.GetSolverSettings();
    settings.kind = kind;
    world.SetSolverSettings(settings);
    return world;
}

/// The state hash after each of `steps` steps.
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

TEST_CASE("A pre-solve callback that enables every contact changes no trajectory",
          "[callbacks][determinism]")
{
    for (const SolverKind kind : kKinds)
    {
        CAPTURE(SolverKindName(kind));
        World plain = Pile(kind);
        const std::vector<std::uint64_t> expected = Hashes(plain, 240);

        World withCallback = Pile(kind);
        int calls = 0;
        withCallback.SetPreSolveCallback(
            [&calls](const PreSolveContact&)
            {
                ++calls;
                return true;
            });
        // Bit for bit, every step (they differed from the second step on by colour and soft
        // step: recycling kept manifolds was off with a callback).
        CHECK(Hashes(withCallback, 240) == expected);
        CHECK(calls > 1000); // it was asked, every step, about every touching contact

        World withFilter = Pile(kind);
        withFilter.SetCustomFilterCallback([](ShapeId, ShapeId) { return true; });
        CHECK(Hashes(withFilter, 240) == expected);
    }
}

TEST_CASE("A snapshot restored into a world with a no-op pre-solve callback steps as the "
          "world it was saved from",
          "[callbacks][snapshot]")
{
    for (const SolverKind kind : kKinds)
    {
        CAPTURE(SolverKindName(kind));
        World source = Pile(kind);
        Hashes(source, 60);
        const WorldSnapshot snapshot = source.SaveSnapshot();
        const std::vector<std::uint64_t> expected = Hashes(source, 60);

        World peer = Pile(kind);
        peer.SetPreSolveCallback([](const PreSolveContact&) { return true; });
        peer.RestoreSnapshot(snapshot);
        CHECK(Hashes(peer, 60) == expected);
    }
}

TEST_CASE("A callback cannot replace itself, or change the world, while a step runs",
          "[callbacks][lifecycle]")
{
    // Replacing the running callback destroyed its closure under it (AddressSanitizer:
    // heap-use-after-free, every back end); it is refused like Create and Destroy.
    for (const SolverKind kind : kKinds)
    {
        CAPTURE(SolverKindName(kind));
        World world = Pile(kind);
        const BodyId body = world.GetBodies()[1];
        std::vector<std::string> refusals;
        const auto expectRefused = [&refusals](auto&& call)
        { refusals.push_back(meff::test::ErrorMessageOf(call)); };
        const std::string padding(64, 'x'); // the closure's state, on the heap
        world.SetPreSolveCallback(
            [&, padding](const PreSolveContact&)
            {
                if (!refusals.empty())
                {
                    return !padding.empty();
                }
                expectRefused([&] { world.SetPreSolveCallback({}); });
                expectRefused([&] { world.SetCustomFilterCallback({}); });
                expectRefused([&] { world.SetTaskSystem(nullptr); });
                expectRefused([&] { world.SetGravity({0, 0}); });
                expectRefused([&] { world.SetLinearVelocity(body, {1, 0}); });
                expectRefused([&] { world.ApplyForceToCenter(body, {1, 0}, true); });
                expectRefused([&] { world.SetSolverSettings(world.GetSolverSettings()); });
                expectRefused([&] { world.SetAllowSleeping(false); });
                return !padding.empty(); // reads the closure: freed if it had been replaced
            });
        for (int i = 0; i < 120 && refusals.empty(); ++i)
        {
            world.Step(Real(1) / 60);
        }
        REQUIRE(refusals.size() == 8);
        for (const std::string& refusal : refusals)
        {
            CHECK_THAT(refusal, Catch::Contains("called during World::Step (from the pre-solve "
                                                "callback)"));
        }
        world.Step(Real(1) / 60); // nothing changed: the world steps on
    }
}

TEST_CASE("Misuse inside the custom filter is refused, named as from the custom filter",
          "[callbacks][lifecycle]")
{
    World world = Pile(SolverKind::Colour);
    std::string refused;
    const std::string padding(64, 'x');
    world.SetCustomFilterCallback(
        [&, padding](ShapeId, ShapeId)
        {
            if (refused.empty())
            {
                // Replacing itself would destroy it under it.
                refused = meff::test::ErrorMessageOf([&] { world.SetCustomFilterCallback({}); });
                MEFF_CHECK_ERROR_WITH(world.CreateBody({}),
                                      Catch::Contains("(from the custom filter)"));
            }
            return !padding.empty();
        });
    for (int i = 0; i < 120 && refused.empty(); ++i)
    {
        world.Step(Real(1) / 60);
    }
    CHECK_THAT(refused, Catch::StartsWith("World::SetCustomFilterCallback: called during "
                                          "World::Step (from the custom filter)"));
    world.Step(Real(1) / 60);
}

namespace
{

/// A DebugDraw that calls `onDraw` from each of its methods.
class CallingDraw final : public DebugDraw
{
  public:
    explicit CallingDraw(std::function<void()> onDraw) : m_onDraw(std::move(onDraw)) {}
    void DrawPolygon(std::span<const Vec2>, const DrawColor&) override { m_onDraw(); }
    void DrawSolidPolygon(std::span<const Vec2>, const DrawColor&) override { m_onDraw(); }
    void DrawCircle(Vec2, Real, const DrawColor&) override { m_onDraw(); }
    void DrawSolidCircle(Vec2, Real, Vec2, const DrawColor&) override { m_onDraw(); }
    void DrawSegment(Vec2, Vec2, const DrawColor&) override { m_onDraw(); }
    void DrawTransform(const Transform&) override { m_onDraw(); }
    void DrawPoint(Vec2, Real, const DrawColor&) override { m_onDraw(); }

  private:
    std::function<void()> m_onDraw;
};

} // namespace

TEST_CASE("A query's callback, or DebugDraw's methods, cannot change the world they walk",
          "[callbacks][queries][lifecycle]")
{
    // Destroying a body from an overlap callback freed the tree nodes the query was walking
    // (AddressSanitizer: heap-use-after-free); every call that changes the world is refused
    // from there, as from the pre-solve callback, and the world is left as it was.
    World world = Pile(SolverKind::Colour);
    Hashes(world, 60);
    const std::vector<BodyId> bodies = world.GetBodies();
    const BodyId ground = bodies.front();
    const BodyId box = bodies[bodies.size() / 2];
    const Vec2 boxCentre = world.GetPosition(box);
    const JointId hinge = world.CreateJoint(world.MakeRevoluteJointDef(ground, box, boxCentre));
    const std::uint64_t before = world.GetStateHash();

    std::vector<std::string> refusals;
    int calls = 0;
    // Each call that would change the world, tried from inside the walk.
    const auto tryChanges = [&]
    {
        ++calls;
        if (calls > 1)
        {
            return; // once per query is enough
        }
        const auto expectRefused = [&refusals](auto&& call)
        { refusals.push_back(meff::test::ErrorMessageOf(call)); };
        expectRefused([&] { world.DestroyBody(box); });
        expectRefused([&] { world.DestroyBody(ground); });
        expectRefused([&] { static_cast<void>(world.CreateBody({})); });
        expectRefused([&] { world.SetTransform(box, {0, 100}, 0); });
        expectRefused([&] { world.Step(Real(1) / 60); });
        expectRefused([&] { world.RestoreSnapshot(world.SaveSnapshot()); });
        expectRefused([&] { static_cast<void>(world.CreateShape(box, {}, Circle{{}, 1})); });
        expectRefused(
            [&] { static_cast<void>(world.CreateJoint(world.MakeWeldJointDef(ground, box, {}))); });
        expectRefused([&] { world.DestroyJoint(hinge); });
    };
    constexpr std::size_t kTries = 9; // the calls tryChanges makes
    const AABB everything{{-1000, -1000}, {1000, 1000}};
    const QueryFilter all{};

    SECTION("OverlapAABB")
    {
        world.OverlapAABB(everything, all,
                          [&](ShapeId)
                          {
                              tryChanges();
                              return true;
                          });
    }
    SECTION("OverlapPoint")
    {
        world.OverlapPoint(boxCentre, all,
                           [&](ShapeId)
                           {
                               tryChanges();
                               return true;
                           });
    }
    SECTION("CastRay")
    {
        world.CastRay({-100, boxCentre.y}, {200, 0}, all,
                      [&](ShapeId, Vec2, Vec2, Real)
                      {
                          tryChanges();
                          return Real(1);
                      });
    }
    SECTION("CastShape")
    {
        world.CastShape(Circle{{0, 0}, Real(0.25)}, Transform({-100, boxCentre.y}, Rot(0)),
                        {200, 0}, all,
                        [&](ShapeId, Vec2, Vec2, Real)
                        {
                            tryChanges();
                            return Real(1);
                        });
    }
    SECTION("CollideMover")
    {
        // Standing on the ground, clear of the pile: 2 cm above the segment.
        const Capsule mover{{-10, Real(0.32)}, {-10, Real(0.72)}, Real(0.3)};
        world.CollideMover(mover, all,
                           [&](ShapeId, const CollisionPlane&)
                           {
                               tryChanges();
                               return true;
                           });
    }
    SECTION("Draw")
    {
        CallingDraw draw(tryChanges);
        world.Draw(draw);
    }

    REQUIRE(calls > 0);
    REQUIRE(refusals.size() == kTries);
    for (const std::string& refusal : refusals)
    {
        CHECK_THAT(refusal, Catch::Contains("called while a query or World::Draw walks the world "
                                            "(from its callback)"));
    }
    CHECK(world.GetStateHash() == before); // nothing changed
    CHECK(world.GetBodies() == bodies);
    // After the walk, the same calls are accepted again.
    MEFF_CHECK_NO_ERROR(world.DestroyJoint(hinge));
    MEFF_CHECK_NO_ERROR(world.DestroyBody(box));
    MEFF_CHECK_NO_ERROR(world.Step(Real(1) / 60));
}

TEST_CASE("A query's callback may push what it finds: the same as pushing after the query",
          "[callbacks][queries]")
{
    // Impulses, velocities and waking change no tree node, list or pool a walk reads: allowed
    // from a callback, they give the world that collecting the ids and pushing after gives.
    World during = Pile(SolverKind::Colour);
    World after = Pile(SolverKind::Colour);
    Hashes(during, 60);
    Hashes(after, 60);
    const AABB blast{{-2, 0}, {2, 4}};
    const auto push = [](World& world, ShapeId shape)
    {
        const BodyId body = world.GetBody(shape);
        world.ApplyLinearImpulse(body, {0, 2}, world.GetWorldCenter(body), true);
        world.SetAngularVelocity(body, 1);
    };
    during.OverlapAABB(blast, {},
                       [&](ShapeId shape)
                       {
                           push(during, shape);
                           return true;
                       });
    std::vector<ShapeId> found;
    after.OverlapAABB(blast, {},
                      [&](ShapeId shape)
                      {
                          found.push_back(shape);
                          return true;
                      });
    REQUIRE(found.size() > 3);
    for (const ShapeId shape : found)
    {
        push(after, shape);
    }
    CHECK(during.GetStateHash() == after.GetStateHash());
    CHECK(Hashes(during, 60) == Hashes(after, 60));
}

TEST_CASE("A query from the pre-solve callback: its callback is inside the step",
          "[callbacks][queries][lifecycle]")
{
    World world = Pile(SolverKind::Colour);
    const BodyId box = world.GetBodies().back();
    std::string refused;
    world.SetPreSolveCallback(
        [&](const PreSolveContact&)
        {
            if (refused.empty())
            {
                world.OverlapAABB({{-1000, -1000}, {1000, 1000}}, {},
                                  [&](ShapeId)
                                  {
                                      refused = meff::test::ErrorMessageOf(
                                          [&] { world.DestroyBody(box); });
                                      return false;
                                  });
            }
            return true;
        });
    for (int i = 0; i < 120 && refused.empty(); ++i)
    {
        world.Step(Real(1) / 60);
    }
    CHECK_THAT(refused, Catch::Contains("called during World::Step (from the pre-solve callback)"));
    world.SetPreSolveCallback({});
    MEFF_CHECK_NO_ERROR(world.DestroyBody(box));
}

TEST_CASE("Only the worlds being walked refuse: a query inside another world's query callback",
          "[callbacks][queries][lifecycle]")
{
    World outer = Pile(SolverKind::Colour);
    World inner = Pile(SolverKind::Colour);
    World other = Pile(SolverKind::Colour);
    const BodyId outerBox = outer.GetBodies().back();
    const BodyId innerBox = inner.GetBodies().back();
    const AABB everything{{-1000, -1000}, {1000, 1000}};
    std::string fromInnerToOuter, fromInnerToInner, fromOuterToOther;
    bool once = false;
    outer.OverlapAABB(
        everything, {},
        [&](ShapeId)
        {
            if (once)
            {
                return true;
            }
            once = true;
            inner.OverlapAABB(everything, {},
                              [&](ShapeId)
                              {
                                  // Both walks are open: the outer world is walked too.
                                  fromInnerToOuter = meff::test::ErrorMessageOf(
                                      [&] { outer.DestroyBody(outerBox); });
                                  fromInnerToInner = meff::test::ErrorMessageOf(
                                      [&] { inner.DestroyBody(innerBox); });
                                  return false;
                              });
            // A world no walk is on may change.
            fromOuterToOther = meff::test::ErrorMessageOf([&] { other.SetGravity({0, -5}); });
            return true;
        });
    CHECK_THAT(fromInnerToOuter, Catch::Contains("walks the world"));
    CHECK_THAT(fromInnerToInner, Catch::Contains("walks the world"));
    CHECK(fromOuterToOther == "accepted");
    MEFF_CHECK_NO_ERROR(outer.DestroyBody(outerBox));
    MEFF_CHECK_NO_ERROR(inner.DestroyBody(innerBox));
}

#if MEFF_EXCEPTIONS
TEST_CASE("A query left by an exception from its callback leaves the world changeable",
          "[callbacks][queries][lifecycle]")
{
    World world = Pile(SolverKind::Colour);
    const BodyId box = world.GetBodies().back();
    struct Stop
    {
    };
    CHECK_THROWS_AS(world.OverlapAABB({{-1000, -1000}, {1000, 1000}}, {},
                                      [](ShapeId) -> bool { throw Stop{}; }),
                    Stop);
    MEFF_CHECK_NO_ERROR(world.DestroyBody(box));
}
#endif
