// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// World promises that are not physics: no heap allocation per step once warmed up, contact
// lifecycle events, and the order of reports.
#include <catch2/catch.hpp>

#include "world_fixtures.h"
#include "meff/scene.h"
#include "meff/task_system.h"
#include "meff/world.h"

#include <atomic>
#include <cstdlib>
#include <memory>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
std::atomic<long> g_allocations{0};
}

// g++ says __SANITIZE_ADDRESS__, clang __has_feature(address_sanitizer).
#if defined(__SANITIZE_ADDRESS__)
#define MEFF_TEST_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define MEFF_TEST_ASAN 1
#endif
#endif

#if defined(MEFF_TEST_ASAN)
// From the sanitizer runtime's allocator interface (sanitizer/allocator_interface.h, which
// Debian ships only with clang): GCC's libasan exports it too.
extern "C" int __sanitizer_install_malloc_and_free_hooks(void (*mallocHook)(const volatile void*,
                                                                            std::size_t),
                                                         void (*freeHook)(const volatile void*));

// Under AddressSanitizer (-DMEFF_SANITIZE=ON) the sanitizer owns operator new and delete: a
// replacement here mixes its allocations with ASan's and is reported as alloc-dealloc
// mismatch. Count through ASan's allocation hook instead, which sees every allocation too.
namespace
{
void CountAllocation(const volatile void*, std::size_t)
{
    ++g_allocations;
}
void IgnoreFree(const volatile void*) {}
[[maybe_unused]] const int g_hooksInstalled =
    __sanitizer_install_malloc_and_free_hooks(CountAllocation, IgnoreFree);
} // namespace
#else
// Count every allocation in the test program; a window of steps is measured below.
void* operator new(std::size_t size)
{
    ++g_allocations;
    if (void* p = std::malloc(size == 0 ? 1 : size))
    {
        return p;
    }
    throw std::bad_alloc();
}
void operator delete(void* p) noexcept
{
    std::free(p);
}
void operator delete(void* p, std::size_t) noexcept
{
    std::free(p);
}
#endif

using namespace meff;

namespace
{

World MakePile()
{
    return meff::test::MakePile(12, 4, Real(0.3), 0);
}

} // namespace

TEST_CASE("UsesThreads says whether the back end hands work to the task system", "[world]")
{
    World world{WorldDef{}};
    CHECK_FALSE(world.UsesThreads()); // no task system
    const std::unique_ptr<TaskSystem> pool = MakeThreadPool(2);
    world.SetTaskSystem(pool.get());
    CHECK_FALSE(world.UsesThreads()); // the default back end, Box2D's, stays on one thread
    for (const SolverKind kind : {SolverKind::Colour, SolverKind::SoftStep})
    {
        SolverSettings settings = world.GetSolverSettings();
        settings.kind = kind;
        world.SetSolverSettings(settings);
        CHECK(world.UsesThreads());
    }
    world.SetTaskSystem(nullptr);
    CHECK_FALSE(world.UsesThreads());
}

TEST_CASE("a warmed-up world does not allocate while stepping", "[world]")
{
    World world = MakePile();
    // Warm-up: the pile falls and settles, so every pool and buffer reaches its size.
    for (int i = 0; i < 600; ++i)
    {
        world.Step(Real(1) / 60);
    }
    REQUIRE(world.GetTouchingContactCount() >= 6); // the pile rests on itself and the floor
    const long before = g_allocations.load();
    for (int i = 0; i < 120; ++i)
    {
        world.Step(Real(1) / 60);
    }
    CHECK(g_allocations.load() - before == 0);
}

TEST_CASE("a warmed-up world stepping by colour or soft step on a thread pool does not allocate",
          "[world][threads]")
{
    // large_pyramid (contact lanes) and joint_grid (joint lanes): their colours and bodies are
    // many enough to be spread over the pool's threads (tests/test_threads.cpp checks that
    // they are, for both back ends), so the pool's jobs are measured too.
    for (const SolverKind kind : {SolverKind::Colour, SolverKind::SoftStep})
        for (const char* name : {"large_pyramid", "joint_grid"})
        {
            INFO(name << " by " << SolverKindName(kind));
            Scene scene =
                LoadScene(std::string(MEFF_SOURCE_DIR) + "/samples/bench/" + name + ".json");
            scene.world.solver.kind = kind;
            BuiltScene built = BuildWorld(scene);
            const std::unique_ptr<TaskSystem> pool = MakeThreadPool(2);
            built.world.SetTaskSystem(pool.get());
            const Real dt = static_cast<Real>(scene.world.dt);
            // Warm-up: the boxes rest on each other (the joints hold each other) from the start,
            // so the contacts are all made in the first step; the rest fills the solver's
            // buffers to their size. Buffers still grow later when a step passes their peak:
            // as the pyramid's boxes settle off their neighbours' corners, contacts end (gdb: all
            // 4 allocations of the soft step's steps 31-50 are the end-event list doubling) and
            // others begin (the colour back end's steps 61-80: that list 4 times and its contact
            // rows' arrays 3 times, as the contact count passed its peak). Such growth is
            // amortized, not per step: each back end is measured over 20 steps without a new
            // peak.
            const int warmUp = kind == SolverKind::SoftStep ? 60 : 30;
            for (int i = 0; i < warmUp; ++i)
            {
                built.world.Step(dt);
            }
            const long before = g_allocations.load();
            for (int i = 0; i < 20; ++i)
            {
                built.world.Step(dt);
            }
            CHECK(g_allocations.load() - before == 0);
        }
}

TEST_CASE("a warmed-up soft step solving a joint tree does not allocate", "[world][joint_tree]")
{
    // chain_heavy_weight's 21 hinges are one tree (soft_joint_tree.h): its selection, order and
    // factors are rebuilt every step in buffers kept from the first.
    Scene scene =
        LoadScene(std::string(MEFF_SOURCE_DIR) + "/samples/extreme/chain_heavy_weight.json");
    scene.world.solver.kind = SolverKind::SoftStep;
    BuiltScene built = BuildWorld(scene);
    const Real dt = static_cast<Real>(scene.world.dt);
    for (int i = 0; i < 10; ++i)
    {
        built.world.Step(dt);
    }
    const long before = g_allocations.load();
    for (int i = 0; i < 60; ++i)
    {
        built.world.Step(dt);
    }
    CHECK(g_allocations.load() - before == 0);
}

TEST_CASE("a warmed-up world finding pairs in batches on a thread pool does not allocate",
          "[world][threads]")
{
    // The pinwheels (world_fixtures.h): a hundred bars turning among static dots leave their
    // fat boxes together every few steps, so the pair finding runs in several batches on the
    // pool's threads (tests/test_threads.cpp checks that it does) and contacts are made and
    // destroyed as each bar passes a dot, in a cycle of a quarter turn (0.52 s at 3 rad/s). Warmed
    // up for over a turn, every batch's list, the contact pool and the pair set have reached their
    // size.
    for (const SolverKind kind : {SolverKind::Colour, SolverKind::SoftStep})
    {
        INFO("solver kind " << static_cast<int>(kind));
        World world = meff::test::MakePinwheels(kind, true);
        const std::unique_ptr<TaskSystem> pool = MakeThreadPool(2);
        world.SetTaskSystem(pool.get());
        for (int i = 0; i < 180; ++i)
        {
            world.Step(Real(1) / 60);
        }
        const long before = g_allocations.load();
        for (int i = 0; i < 120; ++i)
        {
            world.Step(Real(1) / 60);
        }
        CHECK(g_allocations.load() - before == 0);
    }
}

TEST_CASE("contact begin and end events bracket a bounce", "[world]")
{
    World world;
    const BodyId ground = world.CreateBody({});
    const ShapeId floor = world.CreateShape(ground, ShapeDef{}, Segment{{-5, 0}, {5, 0}});
    const BodyId ball = world.CreateBody({.type = BodyType::Dynamic, .position = {0, 1}});
    const ShapeId shape =
        world.CreateShape(ball, ShapeDef{.restitution = 1}, Circle{{0, 0}, Real(0.25)});

    int begins = 0, ends = 0, firstBegin = -1, firstEnd = -1;
    for (int i = 0; i < 120; ++i)
    {
        world.Step(Real(1) / 60);
        for (const ContactEvent& e : world.GetContactBeginEvents())
        {
            // The segment is shape A of a segment-circle pair (Box2D's order).
            CHECK(e.shapeA == floor);
            CHECK(e.shapeB == shape);
            firstBegin = firstBegin < 0 ? i : firstBegin;
            ++begins;
        }
        for (const ContactEvent& e : world.GetContactEndEvents())
        {
            CHECK(e.shapeB == shape);
            firstEnd = firstEnd < 0 ? i : firstEnd;
            ++ends;
        }
    }
    // Dropped from 0.75 m above contact with e = 1 it bounces back up, so the contact begins and
    // then ends at least once, in that order.
    CHECK(begins >= 1);
    CHECK(ends >= 1);
    CHECK(firstBegin < firstEnd);
}

TEST_CASE("contact reports name touching pairs with impulses that hold the weight", "[world]")
{
    World world{WorldDef{.allowSleep = false}}; // the resting box's reports are read each step
    const BodyId ground = world.CreateBody({});
    world.CreateShape(ground, ShapeDef{}, Segment{{-5, 0}, {5, 0}});
    const BodyId box = world.CreateBody({.type = BodyType::Dynamic, .position = {0, Real(0.5)}});
    world.CreateShape(box, ShapeDef{.density = 2}, MakeBox(Real(0.5), Real(0.5)));
    const Real dt = Real(1) / 60;
    for (int i = 0; i < 180; ++i)
    {
        world.Step(dt);
    }
    Real total = 0;
    for (const ContactPointReport& r : world.GetContactReports())
    {
        CHECK(r.bodyA == ground);
        CHECK(r.bodyB == box);
        CHECK(r.normal.y == Approx(1).margin(1e-6)); // from the ground (A) up to the box (B)
        total += r.normalImpulse;
    }
    // At rest the normal impulses carry the weight for one step: m·g·dt = 2·10/60 N·s. The
    // iterative solver converges to it within float round-off of warm-started impulses.
    CHECK(total == Approx(2 * 10 * dt).epsilon(1e-4));
}

TEST_CASE("contact reports describe the step even when read after the world changed", "[world]")
{
    // The reports are built when first read (contact_reports.h). Moving or destroying what
    // they describe before reading them must not change them: each world here is changed
    // after its steps and before its first read, and must report exactly what an unchanged
    // twin read at once reports.
    struct Scene
    {
        World world;
        BodyId box, ball;
        ShapeId ballShape;
    };
    const auto build = []
    {
        Scene scene;
        const BodyId ground = scene.world.CreateBody({});
        scene.world.CreateShape(ground, ShapeDef{}, MakeOffsetBox(10, 1, {0, -1}, 0));
        scene.box = scene.world.CreateBody({.type = BodyType::Dynamic, .position = {-2, 1}});
        scene.world.CreateShape(scene.box, ShapeDef{.density = 2}, MakeBox(Real(0.5), Real(0.5)));
        scene.ball = scene.world.CreateBody({.type = BodyType::Dynamic, .position = {2, 1}});
        scene.ballShape =
            scene.world.CreateShape(scene.ball, ShapeDef{.density = 1}, Circle{{0, 0}, Real(0.5)});
        for (int i = 0; i < 40; ++i)
        {
            scene.world.Step(Real(1) / 60);
        }
        return scene;
    };
    Scene reference = build();
    const std::vector<ContactPointReport> expected(reference.world.GetContactReports().begin(),
                                                   reference.world.GetContactReports().end());
    REQUIRE(expected.size() == 3); // the box's two points and the ball's one

    const auto same = [&](const World& world)
    {
        const auto reports = world.GetContactReports();
        REQUIRE(reports.size() == expected.size());
        for (std::size_t i = 0; i < reports.size(); ++i)
        {
            CHECK(reports[i].bodyA == expected[i].bodyA);
            CHECK(reports[i].bodyB == expected[i].bodyB);
            CHECK(reports[i].shapeA == expected[i].shapeA);
            CHECK(reports[i].shapeB == expected[i].shapeB);
            CHECK(reports[i].featureKey == expected[i].featureKey);
            CHECK(reports[i].pointIndex == expected[i].pointIndex);
            CHECK(reports[i].point == expected[i].point);
            CHECK(reports[i].normal == expected[i].normal);
            CHECK(reports[i].separation == expected[i].separation);
            CHECK(reports[i].normalImpulse == expected[i].normalImpulse);
            CHECK(reports[i].tangentImpulse == expected[i].tangentImpulse);
        }
    };
    SECTION("a body moved")
    {
        Scene scene = build();
        scene.world.SetTransform(scene.box, {5, 5}, Real(0.3));
        same(scene.world);
    }
    SECTION("a shape destroyed, its slot reused")
    {
        Scene scene = build();
        scene.world.DestroyShape(scene.ballShape);
        scene.world.CreateShape(scene.ball, ShapeDef{}, Circle{{0, 0}, Real(2)});
        same(scene.world);
    }
    SECTION("a body destroyed, its slot reused")
    {
        Scene scene = build();
        scene.world.DestroyBody(scene.box);
        const BodyId other =
            scene.world.CreateBody({.type = BodyType::Dynamic, .position = {-7, 4}, .angle = 1});
        scene.world.CreateShape(other, ShapeDef{}, MakeBox(1, 2));
        same(scene.world);
    }
    SECTION("read twice")
    {
        Scene scene = build();
        same(scene.world);
        same(scene.world);
    }
}

TEST_CASE("destroying a body ends its contacts and invalidates its ids", "[world]")
{
    World world;
    const BodyId ground = world.CreateBody({});
    world.CreateShape(ground, ShapeDef{}, Segment{{-5, 0}, {5, 0}});
    const BodyId box = world.CreateBody({.type = BodyType::Dynamic, .position = {0, Real(0.5)}});
    const ShapeId shape = world.CreateShape(box, ShapeDef{}, MakeBox(Real(0.5), Real(0.5)));
    world.Step(Real(1) / 60);
    world.Step(Real(1) / 60);
    REQUIRE(world.GetTouchingContactCount() == 1);
    world.DestroyBody(box);
    CHECK(world.GetContactCount() == 0);
    CHECK_FALSE(world.IsValid(box));
    CHECK_FALSE(world.IsValid(shape));
    CHECK_THROWS_AS(world.GetPosition(box), InvalidArgument);
    // A new body may reuse the slot but not the id.
    const BodyId again = world.CreateBody({.type = BodyType::Dynamic});
    CHECK(again.index == box.index);
    CHECK_FALSE(again == box);
    CHECK_THROWS_AS(world.GetPosition(box), InvalidArgument);
    world.Step(Real(1) / 60);
}

TEST_CASE("destroying bodies while walking GetBodies destroys exactly the ones chosen",
          "[world][lifecycle]")
{
    // The idiom a game writes (world.h, GetBodies). With a view of the live list, each
    // destruction shifted the list under the walk: every other body was skipped and the walk
    // read past the end (ASan: container-overflow).
    World world = test::MakePile(12, 3, Real(1.2), 0);
    world.Step(Real(1) / 60);
    const std::vector<BodyId> before = world.GetBodies(); // the ground and 12 bodies
    REQUIRE(before.size() == 13);
    const auto chosen = [&](BodyId body) { return world.GetPosition(body).y > 6; };
    std::vector<BodyId> expectedSurvivors;
    for (const BodyId body : before)
    {
        if (!chosen(body))
        {
            expectedSurvivors.push_back(body);
        }
    }
    REQUIRE(expectedSurvivors.size() < before.size()); // the test destroys something...
    REQUIRE(expectedSurvivors.size() > 1);             // ...and keeps something
    for (const BodyId body : world.GetBodies())
    {
        if (chosen(body))
        {
            world.DestroyBody(body);
        }
    }
    CHECK(world.GetBodies() == expectedSurvivors);
    world.Step(Real(1) / 60);

    // Every body, the same way: none is left, and the world still steps.
    for (const BodyId body : world.GetBodies())
    {
        world.DestroyBody(body);
    }
    CHECK(world.GetBodies().empty());
    world.Step(Real(1) / 60);
}

TEST_CASE("destroying shapes and joints while walking their lists", "[world][lifecycle]")
{
    World world;
    const BodyId ground = world.CreateBody({});
    const BodyId body = world.CreateBody({.type = BodyType::Dynamic, .position = {0, 2}});
    for (int i = 0; i < 6; ++i)
    {
        world.CreateShape(body, ShapeDef{}, Circle{{Real(i) * Real(0.1), 0}, Real(0.2)});
    }
    std::vector<JointId> joints;
    for (int i = 0; i < 5; ++i)
    {
        joints.push_back(world.CreateJoint(world.MakeRevoluteJointDef(ground, body, {0, 2})));
    }
    for (const ShapeId shape : world.GetShapes(body))
    {
        world.DestroyShape(shape);
    }
    CHECK(world.GetShapes(body).empty());
    CHECK(world.GetMass(body) == 0); // every shape's mass went with it
    for (const JointId joint : world.GetJoints())
    {
        world.DestroyJoint(joint);
    }
    CHECK(world.GetJoints().empty());
    for (const JointId joint : joints)
    {
        CHECK_FALSE(world.IsValid(joint));
    }
}

TEST_CASE("a moved-from World refuses every call with an error that says so", "[world][lifecycle]")
{
    World world = test::MakePile(4, 2, 1, 0);
    const BodyId body = world.GetBodies()[1];
    World moved = std::move(world);
    moved.Step(Real(1) / 60); // the state went with the move
    CHECK(moved.IsValid(body));
    // The source segfaulted on any call (its state is null); now each throws.
    CHECK_THROWS_WITH(world.Step(Real(1) / 60), Catch::Contains("moved from"));
    CHECK_THROWS_WITH(world.GetPosition(body), Catch::Contains("moved from"));
    CHECK_THROWS_AS(world.GetBodies(), InvalidArgument);
    CHECK_THROWS_AS(world.CreateBody({}), InvalidArgument);
    CHECK_THROWS_AS(world.IsValid(body), InvalidArgument);
    CHECK_THROWS_AS(world.GetStateHash(), InvalidArgument);
    CHECK_THROWS_AS(world.CastRayClosest({0, 0}, {1, 0}), InvalidArgument);
    // Assigning a world to it makes it usable again.
    world = World{};
    CHECK(world.GetBodies().empty());
}

TEST_CASE("Step and world changes from the pre-solve callback are refused, not recursed into",
          "[world][lifecycle]")
{
    World world = test::MakePile(4, 2, 1, 0);
    const WorldSnapshot start = world.SaveSnapshot();
    int calls = 0;
    std::string refused;
    world.SetPreSolveCallback(
        [&](const PreSolveContact&)
        {
            ++calls;
            try
            {
                world.Step(Real(1) / 60); // recursed until the stack overflowed
            }
            catch (const InvalidArgument& error)
            {
                refused = error.what();
            }
            CHECK_THROWS_AS(world.CreateBody({}), InvalidArgument);
            CHECK_THROWS_AS(world.DestroyBody(world.GetBodies()[1]), InvalidArgument);
            CHECK_THROWS_AS(world.RestoreSnapshot(start), InvalidArgument);
            return true;
        });
    for (int i = 0; i < 120 && calls == 0; ++i)
    {
        world.Step(Real(1) / 60);
    }
    REQUIRE(calls > 0);
    CHECK_THAT(refused, Catch::Contains("called during World::Step"));
    // The refusals were caught inside the callback: the world goes on stepping.
    world.Step(Real(1) / 60);

    // An exception let out of the callback leaves its step half done: the world freezes, and a
    // snapshot thaws it.
    world.SetPreSolveCallback([&](const PreSolveContact&) -> bool
                              { throw std::runtime_error("the game's own error"); });
    CHECK_THROWS_WITH(world.Step(Real(1) / 60), "the game's own error");
    CHECK_THROWS_WITH(world.Step(Real(1) / 60), Catch::Contains("an earlier step failed"));
    world.SetPreSolveCallback({});
    world.RestoreSnapshot(start);
    world.Step(Real(1) / 60);
}
