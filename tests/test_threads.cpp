// Threads (task_system.h, World::SetTaskSystem): the default pool runs every index of a job
// exactly once, and a world stepped on 1, 2, 3 or 8 threads — or on a job system that runs the
// ranges in an unusual order — has the state hash of the same world stepped on one thread,
// every step.
#include <catch2/catch.hpp>

#include "meff/scene.h"
#include "meff/task_system.h"
#include "meff/world.h"

#include <algorithm>
#include <atomic>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

using namespace meff;

namespace
{

/// A game's job system stand-in that wraps another task system and counts what it was given:
/// the jobs cut into more than one range, and the ranges a thread other than the caller ran.
class CountingTasks final : public TaskSystem
{
  public:
    explicit CountingTasks(int threads) : m_inner(MakeThreadPool(threads)) {}
    int ThreadCount() const override { return m_inner->ThreadCount(); }
    void ParallelFor(int count, int minRange,
                     FunctionRef<void(int begin, int end, int worker)> task) override
    {
        jobs += count >= 2 * minRange ? 1 : 0;
        m_inner->ParallelFor(count, minRange,
                             [&](int begin, int end, int worker)
                             {
                                 if (worker != 0)
                                 {
                                     otherWorkerRanges.fetch_add(1, std::memory_order_relaxed);
                                 }
                                 task(begin, end, worker);
                             });
    }

    int jobs = 0; ///< jobs of at least two minimum ranges
    std::atomic<int> otherWorkerRanges{0};

  private:
    std::unique_ptr<TaskSystem> m_inner;
};

/// A job system that runs on the calling thread but cuts each job into ranges of exactly
/// minRange, runs them last to first and names a different worker for each (of three): the
/// order and the worker must not change the results.
class BackwardsTasks final : public TaskSystem
{
  public:
    int ThreadCount() const override { return 3; }
    void ParallelFor(int count, int minRange,
                     FunctionRef<void(int begin, int end, int worker)> task) override
    {
        const int ranges = (count + minRange - 1) / minRange;
        for (int r = ranges - 1; r >= 0; --r)
        {
            task(r * minRange, std::min(count, (r + 1) * minRange), (2 * r + 1) % 3);
        }
    }
};

/// A bench scene (samples/bench/) stepped by `kind`.
Scene BenchScene(const std::string& name, SolverKind kind = SolverKind::Colour)
{
    Scene scene = LoadScene(std::string(MEFF_SOURCE_DIR) + "/samples/bench/" + name + ".json");
    scene.world.solver.kind = kind;
    return scene;
}

Scene LargePyramid()
{
    return BenchScene("large_pyramid");
}

/// large_pyramid with joints: every 9th box hinged to the next one at their midpoint (plain
/// revolute joints: the colour back end's joint lanes) and every 13th tied to the box 37 on by
/// a distance joint (solved one by one), both holding the boxes' present poses.
void AddJoints(BuiltScene& built, const Scene& scene)
{
    World& world = built.world;
    for (std::size_t i = 1; i + 37 < scene.bodies.size(); ++i)
    {
        const BodyId a = built.bodies[i];
        if (i % 9 == 0)
        {
            const BodyId b = built.bodies[i + 1];
            const Vec2 anchor = Real(0.5) * (world.GetPosition(a) + world.GetPosition(b));
            world.CreateJoint(world.MakeRevoluteJointDef(a, b, anchor));
        }
        if (i % 13 == 0)
        {
            const BodyId b = built.bodies[i + 37];
            world.CreateJoint(
                world.MakeDistanceJointDef(a, b, world.GetPosition(a), world.GetPosition(b)));
        }
    }
}

/// Steps `worlds` and `reference` alike, `steps` times, requiring equal state hashes after
/// every step.
void StepAlike(BuiltScene& reference, std::vector<BuiltScene>& worlds, int steps, Real dt)
{
    for (int step = 0; step < steps; ++step)
    {
        reference.world.Step(dt);
        const std::uint64_t expected = reference.world.GetStateHash();
        for (std::size_t w = 0; w < worlds.size(); ++w)
        {
            worlds[w].world.Step(dt);
            INFO("world " << w << ", step " << step);
            REQUIRE(worlds[w].world.GetStateHash() == expected);
        }
    }
}

/// The scene stepped on one thread and on pools of 1, 2, 3 and 8 threads (and on
/// BackwardsTasks), hashes compared every step; the pools must really have split the work,
/// more than `jobsPerStep` jobs of two ranges or more a step.
void CheckThreadCounts(const Scene& scene, bool withJoints, int steps, int jobsPerStep = 1)
{
    const auto build = [&]
    {
        BuiltScene built = BuildWorld(scene);
        if (withJoints)
        {
            AddJoints(built, scene);
        }
        return built;
    };
    BuiltScene reference = build();
    std::vector<std::unique_ptr<CountingTasks>> pools;
    BackwardsTasks backwards;
    std::vector<BuiltScene> worlds;
    for (const int threads : {1, 2, 3, 8})
    {
        pools.push_back(std::make_unique<CountingTasks>(threads));
        worlds.push_back(build());
        worlds.back().world.SetTaskSystem(pools.back().get());
    }
    worlds.push_back(build());
    worlds.back().world.SetTaskSystem(&backwards);

    StepAlike(reference, worlds, steps, static_cast<Real>(scene.world.dt));
    for (std::size_t p = 0; p < pools.size(); ++p)
    {
        INFO("pool of " << pools[p]->ThreadCount() << " threads");
        CHECK(pools[p]->jobs > jobsPerStep * steps);
        if (pools[p]->ThreadCount() > 1)
        {
            // Hundreds of jobs of several ranges each: the pool's threads took some of them.
            CHECK(pools[p]->otherWorkerRanges.load() > 0);
        }
    }
}

} // namespace

TEST_CASE("The thread pool runs every index of a job exactly once, in ranges of at least "
          "minRange, on workers below ThreadCount, job after job",
          "[threads]")
{
    for (const int threads : {1, 2, 3, 8})
    {
        const std::unique_ptr<TaskSystem> pool = MakeThreadPool(threads);
        REQUIRE(pool->ThreadCount() == threads);
        for (int round = 0; round < 20; ++round) // the same pool, reused job after job
        {
            for (const int count : {0, 1, 2, 63, 64, 65, 127, 128, 1000, 4097})
            {
                for (const int minRange : {1, 7, 64, 1000})
                {
                    std::vector<std::atomic<int>> visits(static_cast<std::size_t>(count));
                    std::atomic<int> shortRanges{0}, badWorkers{0}, badRanges{0};
                    pool->ParallelFor(count, minRange,
                                      [&](int begin, int end, int worker)
                                      {
                                          if (begin < 0 || end > count || begin >= end)
                                          {
                                              badRanges.fetch_add(1);
                                              return;
                                          }
                                          if (end - begin < minRange)
                                          {
                                              shortRanges.fetch_add(
                                                  1); // allowed once: the last range
                                          }
                                          if (worker < 0 || worker >= threads)
                                          {
                                              badWorkers.fetch_add(1);
                                          }
                                          for (int i = begin; i < end; ++i)
                                          {
                                              visits[static_cast<std::size_t>(i)].fetch_add(1);
                                          }
                                      });
                    INFO(threads << " threads, count " << count << ", minRange " << minRange);
                    REQUIRE(badRanges.load() == 0);
                    REQUIRE(badWorkers.load() == 0);
                    REQUIRE(shortRanges.load() <= 1);
                    REQUIRE(std::all_of(visits.begin(), visits.end(),
                                        [](const std::atomic<int>& v) { return v.load() == 1; }));
                }
            }
        }
    }
    CHECK_THROWS_AS(MakeThreadPool(0), InvalidArgument);
}

TEST_CASE("large_pyramid by colour has the same state hash every step on 1, 2, 3 and 8 "
          "threads",
          "[threads]")
{
    // 40 steps: the pyramid's 5,050 boxes settle under load from the first step, every
    // contact of every colour solved each step (sleep is off in the bench scenes).
    // The contact lanes handed their colours over: large_pyramid's colours hold hundreds of
    // groups of four contacts, more than two ranges of kMinGroupsPerTask (64), and its 5,050
    // bodies are more than two ranges of kMinBodiesPerTask (512) for the per-body loops.
    CheckThreadCounts(LargePyramid(), false, 40);
}

TEST_CASE("joint_grid by colour has the same state hash every step on 1, 2, 3 and 8 threads",
          "[threads]")
{
    // joint_grid: 10,000 bodies, 19,794 plain revolute joints (the joint lanes), no contact.
    // Its colours hold over a thousand groups of four joints each, more than two ranges of
    // kMinJointGroupsPerTask (128), so each of the 8 velocity sweeps a step hands at least one
    // job per colour to the threads, besides the 3 per-body loops (integrating velocities and
    // positions, writing the bodies back: 10,000 bodies, many ranges of 512): more than 11
    // jobs a step shows that the joint lanes were spread. The grid swings under gravity from
    // its top row, every joint loaded, from the first step.
    CheckThreadCounts(BenchScene("joint_grid"), false, 20, 11);
}

TEST_CASE("The Box2D back end steps on one thread whatever task system the world has", "[threads]")
{
    // Its results are Box2D 2.4.1's, bit for bit, in Box2D's order: nothing of it is handed to
    // the threads, and its state hash is the one of a world without them.
    const Scene scene = BenchScene("joint_grid", SolverKind::Box2D);
    BuiltScene reference = BuildWorld(scene);
    BuiltScene threaded = BuildWorld(scene);
    CountingTasks pool(2);
    threaded.world.SetTaskSystem(&pool);
    const Real dt = static_cast<Real>(scene.world.dt);
    for (int step = 0; step < 3; ++step)
    {
        reference.world.Step(dt);
        threaded.world.Step(dt);
        REQUIRE(threaded.world.GetStateHash() == reference.world.GetStateHash());
    }
    CHECK(pool.jobs == 0);
}

TEST_CASE("large_pyramid with revolute and distance joints by colour has the same state hash "
          "every step on 1, 2, 3 and 8 threads",
          "[threads]")
{
    CheckThreadCounts(LargePyramid(), true, 30);
}

TEST_CASE("The task system is configuration: kept across RestoreSnapshot, outside the state "
          "hash",
          "[threads]")
{
    const Scene scene = LargePyramid();
    BuiltScene built = BuildWorld(scene);
    const std::unique_ptr<TaskSystem> pool = MakeThreadPool(2);
    CHECK(built.world.GetTaskSystem() == nullptr);
    const std::uint64_t before = built.world.GetStateHash();
    built.world.SetTaskSystem(pool.get());
    CHECK(built.world.GetStateHash() == before);
    CHECK(built.world.GetTaskSystem() == pool.get());

    const WorldSnapshot snapshot = built.world.SaveSnapshot();
    const Real dt = static_cast<Real>(scene.world.dt);
    for (int step = 0; step < 5; ++step)
    {
        built.world.Step(dt);
    }
    const std::uint64_t afterFive = built.world.GetStateHash();
    built.world.RestoreSnapshot(snapshot);
    CHECK(built.world.GetTaskSystem() == pool.get());
    // Stepping on from the snapshot, now on one thread, repeats the same five steps.
    built.world.SetTaskSystem(nullptr);
    for (int step = 0; step < 5; ++step)
    {
        built.world.Step(dt);
    }
    CHECK(built.world.GetStateHash() == afterFive);
}
