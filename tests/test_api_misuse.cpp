// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Misuse of the library's API (docs/hostile-input.md, "Task systems", "Shapes"): a task system
// that breaks its contract, a hand-built polygon whose centroid is outside it, an exception
// thrown by the user's code in the middle of a step: each is refused or reported with an error
// that names it, never a crash or a silently wrong simulation, and the world stays usable.
#include <catch2/catch.hpp>

#include "error_checks.h"
#include "test_random.h"
#include "meff/task_system.h"
#include "meff/world.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

using namespace meff;

namespace
{

constexpr Real kDt = Real(1) / 60;

/// A ground and `columns` × `rows` boxes and circles of 1 m resting on it and on each other:
/// hundreds of contacts from the first step, enough for the colour and soft-step back ends to
/// hand the narrow phase, the contact lanes and the bodies to the task system in several ranges.
World RestingGrid(SolverKind kind, int columns = 30, int rows = 20)
{
    World world(WorldDef{.solver = {.kind = kind}});
    const BodyId ground = world.CreateBody({});
    world.CreateShape(ground, ShapeDef{}, MakeOffsetBox(100, 1, {0, -1}, 0));
    for (int i = 0; i < columns; ++i)
    {
        for (int j = 0; j < rows; ++j)
        {
            const BodyId body = world.CreateBody(
                {.type = BodyType::Dynamic,
                 .position = {Real(i) * Real(1.01) - Real(columns) / 2, Real(0.5) + Real(j)}});
            if ((i + j) % 3 == 0)
            {
                world.CreateShape(body, ShapeDef{}, Circle{{0, 0}, Real(0.5)});
            }
            else
            {
                world.CreateShape(body, ShapeDef{}, MakeBox(Real(0.5), Real(0.5)));
            }
        }
    }
    return world;
}

void StepTimes(World& world, int steps)
{
    for (int i = 0; i < steps; ++i)
    {
        world.Step(kDt);
    }
}

/// How a job system stand-in breaks task_system.h's contract.
enum class Breach
{
    None,
    RunsARangeTwice,
    SkipsARange,
    WorkerIndexTooLarge,
    NegativeWorkerIndex,
    RangeBeyondCount,
};

/// A job system on the calling thread that cuts each job into ranges of minRange, names worker
/// r mod 3 for range r, and breaks the contract as told once it has run `honestJobs` jobs.
class BreachingTasks final : public TaskSystem
{
  public:
    explicit BreachingTasks(Breach breach, int honestJobs = 0)
        : m_breach(breach), m_honestJobs(honestJobs)
    {
    }
    int ThreadCount() const override { return threadCount; }
    void ParallelFor(int count, int minRange,
                     FunctionRef<void(int begin, int end, int worker)> task) override
    {
        if (beforeJob)
        {
            beforeJob();
        }
        const Breach breach = m_honestJobs-- > 0 ? Breach::None : m_breach;
        for (int begin = 0, r = 0; begin < count; begin += minRange, ++r)
        {
            const int end = std::min(count, begin + minRange);
            const int worker = breach == Breach::WorkerIndexTooLarge   ? 3
                               : breach == Breach::NegativeWorkerIndex ? -1
                                                                       : r % 3;
            if (breach == Breach::SkipsARange && r == 1)
            {
                continue;
            }
            task(begin, breach == Breach::RangeBeyondCount && end == count ? end + 1 : end, worker);
            if (breach == Breach::RunsARangeTwice && r == 0)
            {
                task(begin, end, worker);
            }
        }
    }

    int threadCount = 3; ///< what ThreadCount() answers
    /// Called before each job (it may throw, as a game's job system might).
    std::function<bool()> beforeJob;

  private:
    Breach m_breach;
    int m_honestJobs;
};

} // namespace

TEST_CASE("A task system's thread count outside 1 to 1024, or changed while a world uses it, is "
          "refused",
          "[misuse][threads]")
{
    World world = RestingGrid(SolverKind::Colour, 4, 4);
    BreachingTasks tasks(Breach::None);
    // A count of 2^31 - 1 was accepted, and the first step asked for 16 GB of per-worker
    // scratch (AddressSanitizer: out of memory).
    for (const int count : {0, -1, 1025, std::numeric_limits<int>::max()})
    {
        tasks.threadCount = count;
        MEFF_CHECK_ERROR_WITH(world.SetTaskSystem(&tasks),
                              Catch::Equals("World::SetTaskSystem: ThreadCount() is " +
                                            std::to_string(count) + ", must be from 1 to 1024"));
        CHECK(world.GetTaskSystem() == nullptr);
    }
    tasks.threadCount = 3;
    world.SetTaskSystem(&tasks);
    CHECK(world.GetTaskSystem() == &tasks);
    world.Step(kDt);
    // Dropping to 0 after SetTaskSystem divided by zero in the user's own pool and left the
    // engine's per-worker scratch sized for 3; now the step is refused before it begins.
    const std::uint64_t hash = world.GetStateHash();
    tasks.threadCount = 0;
    MEFF_CHECK_ERROR_WITH(world.Step(kDt),
                          Catch::StartsWith("World::Step: the task system's ThreadCount() is 0, "
                                            "was 3 at World::SetTaskSystem"));
    CHECK(world.GetStepCount() == 1);
    CHECK(world.GetStateHash() == hash);
    tasks.threadCount = 2;
    world.SetTaskSystem(&tasks); // given again: its new count is the world's
    world.Step(kDt);
    CHECK(world.GetStepCount() == 2);
}

#if MEFF_EXCEPTIONS
TEST_CASE("An exception from the pre-solve callback, the custom filter or the task system leaves "
          "the world frozen, readable and restorable",
          "[misuse][callbacks]")
{
    for (const SolverKind kind : {SolverKind::Box2D, SolverKind::Colour, SolverKind::SoftStep})
    {
        World reference = RestingGrid(kind);
        StepTimes(reference, 2);
        const WorldSnapshot snapshot = reference.SaveSnapshot();
        StepTimes(reference, 5);
        for (int thrower = 0; thrower < 3; ++thrower)
        {
            if (thrower == 2 && kind == SolverKind::Box2D)
            {
                continue; // it steps on the calling thread whatever task system it is lent
            }
            CAPTURE(SolverKindName(kind), thrower);
            World world = RestingGrid(kind);
            StepTimes(world, 2);
            int calls = 0;
            const auto maybeThrow = [&calls]
            {
                if (++calls == 3)
                {
                    throw std::runtime_error("the game's code");
                }
                return true;
            };
            BreachingTasks tasks(Breach::None);
            if (thrower == 0)
            {
                world.SetPreSolveCallback([&](const PreSolveContact&) { return maybeThrow(); });
            }
            else if (thrower == 1)
            {
                // Asked about new pairs: the grid is moved sideways onto fresh neighbours.
                world.SetCustomFilterCallback([&](ShapeId, ShapeId) { return maybeThrow(); });
                for (const BodyId body : world.GetBodies())
                {
                    world.SetLinearVelocity(body, {5, 0});
                }
            }
            else
            {
                world.SetTaskSystem(&tasks);
                world.SetPreSolveCallback([&](const PreSolveContact&) { return true; });
                tasks.beforeJob = maybeThrow;
            }
            CHECK_THROWS_WITH(StepTimes(world, 30), "the game's code");
            world.SetPreSolveCallback({});
            world.SetCustomFilterCallback({});
            world.SetTaskSystem(nullptr);
            CHECK_THROWS_WITH(world.Step(kDt), Catch::Contains("an earlier step failed"));
            // Readable: queries, reports, a snapshot.
            int found = 0;
            world.OverlapAABB({{-100, -100}, {100, 100}}, {},
                              [&found](ShapeId)
                              {
                                  ++found;
                                  return true;
                              });
            CHECK(found == 601);
            CHECK(world.GetContactReports().size() < 10000);
            const WorldSnapshot frozen = world.SaveSnapshot();
            CHECK(!frozen.IsEmpty());
            world.RestoreSnapshot(snapshot);
            StepTimes(world, 5);
            CHECK(world.GetStateHash() == reference.GetStateHash());
        }
    }
}

// A breach is found when the job returns, halfway through a step: it is thrown (meff::Error),
// which leaves the step half done and the world frozen. (Without exceptions the error handler
// gets the message and the program ends: the step can be neither finished nor undone.)
TEST_CASE("A task system that runs a range twice, skips one, or gives a worker index or a range "
          "outside its bounds stops the step with an error, and the world can be restored",
          "[misuse][threads]")
{
    // Before: running a range twice or skipping one went unsaid (the state differed from the
    // one-thread world's), a skipped range then read an unwritten index (libstdc++'s assertion,
    // vector<Body>), and a worker index of 3 or -1 or a range one past the count wrote outside
    // the engine's per-worker scratch and pair batches.
    const struct
    {
        Breach breach;
        const char* problem;
    } cases[] = {
        {Breach::RunsARangeTwice, "indices, some of them not exactly once"},
        {Breach::SkipsARange, "indices, some of them not exactly once"},
        {Breach::WorkerIndexTooLarge, "gave a worker index outside [0, ThreadCount()) (range "},
        {Breach::NegativeWorkerIndex, "gave a worker index outside [0, ThreadCount()) (range "},
        {Breach::RangeBeyondCount, "gave a range outside the job's indices (range ["},
    };
    for (const SolverKind kind : {SolverKind::Colour, SolverKind::SoftStep})
    {
        World reference = RestingGrid(kind);
        StepTimes(reference, 3);
        const WorldSnapshot snapshot = reference.SaveSnapshot();
        StepTimes(reference, 3);
        for (const auto& c : cases)
        {
            CAPTURE(SolverKindName(kind), c.problem);
            World world = RestingGrid(kind);
            StepTimes(world, 3);
            BreachingTasks tasks(c.breach, 5);
            world.SetTaskSystem(&tasks);
            std::string message;
            try
            {
                StepTimes(world, 3);
            }
            catch (const Error& error)
            {
                message = error.what();
            }
            CHECK_THAT(message, Catch::StartsWith("TaskSystem::ParallelFor: a job of ") &&
                                    Catch::Contains(c.problem) &&
                                    Catch::EndsWith("the step is left half done and the world "
                                                    "is frozen (restore a snapshot)"));
            CHECK_THROWS_WITH(world.Step(kDt), Catch::Contains("an earlier step failed"));
            world.SetTaskSystem(nullptr);
            world.RestoreSnapshot(snapshot);
            StepTimes(world, 3);
            CHECK(world.GetStateHash() == reference.GetStateHash());
        }
    }
}
#endif

TEST_CASE("A hand-built polygon whose centroid lies outside it is refused; MakePolygon's pass",
          "[misuse][geometry]")
{
    // A one-sided segment (a chain's) and a rounded polygon's manifolds tell which side the
    // polygon is on by its centroid: this box with its centroid moved out below fell through
    // the chain it rested on, unsaid.
    Polygon box = MakeBox(Real(0.5), Real(0.5));
    box.centroid = {0, -2};
    World world;
    const BodyId body = world.CreateBody({.type = BodyType::Dynamic, .position = {0, 1}});
    MEFF_CHECK_ERROR_WITH(
        world.CreateShape(body, ShapeDef{}, box),
        Catch::Equals("Polygon::centroid: must be inside the polygon (its area centroid (build "
                      "polygons with MakePolygon or MakeBox)), got (0, -2), outside edge 0"));
    CHECK(world.GetShapes(body).empty());

    // Thin and far-off polygons from MakePolygon keep passing: their centroids, rounded to the
    // coordinates' precision, may land on an edge, which the check allows for.
    test::Random random(7);
    int triangles = 0;
    for (int i = 0; i < 2000; ++i)
    {
        const Real size = Real(std::pow(10.0, random.Uniform(-1, 4)));
        const Real thin = size * Real(std::pow(10.0, random.Uniform(-5, 0)));
        const Vec2 at{random.Uniform(-1e6f, 1e6f), random.Uniform(-1e6f, 1e6f)};
        const Vec2 points[] = {at, at + Vec2{size, random.Uniform(-1, 1) * size},
                               at + Vec2{random.Uniform(0, 1) * size, thin}};
        const std::string message = test::ErrorMessageOf([&] { MakePolygon(points); });
        CAPTURE(size, thin, at.x, at.y);
        CHECK_THAT(message, !Catch::Contains("centroid"));
        triangles += message == "accepted" ? 1 : 0;
    }
    // Seed 7 makes 1,956 of them polygons (the rest are refused as too thin, never for the
    // centroid): the loop is not vacuous.
    CHECK(triangles > 1900);
    // A sliver along the diagonal, centred on the origin, its middle vertices near the origin:
    // the centroid's rounding grows with the polygon's extent (ComputeCentroid works from the
    // first vertex), not with the small coordinates of the edge it is tested against.
    int slivers = 0;
    for (const Real length : {Real(1), Real(10), Real(1000)})
    {
        for (int k = 2; k <= 256; k *= 2)
        {
            const Real w = Real(k) * kEpsilon * length;
            for (const Vec2 d :
                 {Vec2{0, 0}, Vec2{Real(1e-3), Real(3e-3)}, Vec2{Real(-0.37), Real(0.11)}})
            {
                const Vec2 points[] = {Vec2{-length, -length} + d, Vec2{w, -w} + d,
                                       Vec2{length, Real(1.01) * length} + d, Vec2{-w, w} + d};
                const std::string message = test::ErrorMessageOf([&] { MakePolygon(points); });
                CAPTURE(length, w, d.x, d.y);
                CHECK_THAT(message, !Catch::Contains("centroid"));
                slivers += message == "accepted" ? 1 : 0;
            }
        }
    }
    CHECK(slivers == 3 * 8 * 3); // every sliver is a polygon: the loop above is not vacuous
}

TEST_CASE("SaveSnapshot from the pre-solve callback is refused: half a step is no state to step "
          "on from",
          "[misuse][snapshot]")
{
    // A snapshot saved in continuous collision's sub-step kept the last step's end-event count
    // over this step's shorter list; the step after RestoreSnapshot erased past the list's end
    // (AddressSanitizer: negative-size-param).
    for (const SolverKind kind : {SolverKind::Box2D, SolverKind::Colour, SolverKind::SoftStep})
    {
        CAPTURE(SolverKindName(kind));
        World world = RestingGrid(kind, 4, 4);
        const BodyId bullet = world.CreateBody({.type = BodyType::Dynamic,
                                                .position = {0, 30},
                                                .linearVelocity = {0, -300},
                                                .bullet = true});
        world.CreateShape(bullet, ShapeDef{}, Circle{{0, 0}, Real(0.1)});
        std::vector<std::string> refusals;
        world.SetPreSolveCallback(
            [&](const PreSolveContact&)
            {
                refusals.push_back(test::ErrorMessageOf([&] { world.SaveSnapshot(); }));
                return true;
            });
        StepTimes(world, 20);
        REQUIRE(!refusals.empty());
        CHECK_THAT(refusals.front(),
                   Catch::Equals("World::SaveSnapshot: called during World::Step (from the "
                                 "pre-solve callback); a half-done step cannot be stepped on "
                                 "from: save the snapshot before or after Step"));
        world.SetPreSolveCallback({});
        const WorldSnapshot snapshot = world.SaveSnapshot(); // between steps: as ever
        const std::uint64_t hash = world.GetStateHash();
        StepTimes(world, 10);
        world.RestoreSnapshot(snapshot);
        CHECK(world.GetStateHash() == hash);
    }
}
