// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The user's callbacks (issue 36): installing a pre-solve callback that enables every contact,
// or a custom filter that allows every pair, changes no result in any back end; a callback may
// not change the world (itself included) while a step runs, and a refusal names the callback
// it came from.
#include <catch2/catch.hpp>

#include "error_checks.h"
#include "world_fixtures.h"
#include "meff/world.h"

#include <cstdint>
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
