// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Micro-benchmarks of the pieces a step spends its time in (see docs/performance.md).
#include "collision/broad_phase.h"
#include "model/body.h"
#include "model/contact.h"
#include "model/shape.h"
#include "solvers/shared/contact_solver.h"
#include "meff/collision.h"
#include "meff/ray_cast.h"
#include "meff/world.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <utility>
#include <vector>

using namespace meff;
using namespace meff::detail;

namespace
{

Polygon SkinnedBox(Real h)
{
    Polygon p = MakeBox(h, h);
    p.radius = Real(0.01); // the world's polygon skin
    return p;
}

/// Two unit boxes resting face to face, the second slightly turned: a two-point manifold.
void BM_CollidePolygons(benchmark::State& state)
{
    const Polygon box = SkinnedBox(Real(0.5));
    const Transform xfA({0, 0}, Rot(0));
    const Transform xfB({Real(0.1), Real(0.99)}, Rot(Real(0.05)));
    Manifold manifold;
    for (auto _ : state)
    {
        CollidePolygons(manifold, box, xfA, box, xfB);
        benchmark::DoNotOptimize(manifold);
    }
}
BENCHMARK(BM_CollidePolygons);

void BM_CollidePolygonAndCircle(benchmark::State& state)
{
    const Polygon box = SkinnedBox(Real(0.5));
    const Circle circle{{0, 0}, Real(0.25)};
    const Transform xfA({0, 0}, Rot(0));
    const Transform xfB({Real(0.3), Real(0.74)}, Rot(0));
    Manifold manifold;
    for (auto _ : state)
    {
        CollidePolygonAndCircle(manifold, box, xfA, circle, xfB);
        benchmark::DoNotOptimize(manifold);
    }
}
BENCHMARK(BM_CollidePolygonAndCircle);

/// One velocity iteration over N box-on-box contacts (a column of N+1 boxes): the contact row
/// update of the solver's inner loop, friction and the 2×2 normal block.
void BM_ContactRowUpdate(benchmark::State& state)
{
    const int n = static_cast<int>(state.range(0));
    const Polygon box = SkinnedBox(Real(0.5));
    std::vector<Body> bodies(n + 1);
    std::vector<Contact> contacts(n);
    std::vector<std::int32_t> indices(n);
    std::vector<Position> positions(n + 1);
    std::vector<Velocity> velocities(n + 1);
    for (int i = 0; i <= n; ++i)
    {
        Body& b = bodies[i];
        b.type = i == 0 ? BodyType::Static : BodyType::Dynamic;
        b.mass = i == 0 ? 0 : 1;
        b.invMass = i == 0 ? 0 : 1;
        b.I = i == 0 ? 0 : Real(1) / 6;
        b.invI = i == 0 ? 0 : 6;
        b.xf = Transform({0, Real(i) * Real(0.995)}, Rot(0));
        b.sweep.c = b.xf.p;
        b.islandIndex = i;
        positions[i] = {b.xf.p, 0};
        velocities[i] = {{0, Real(-0.1)}, 0};
    }
    for (int i = 0; i < n; ++i)
    {
        Contact& c = contacts[i];
        c.shapeA = i;
        c.shapeB = i + 1;
        c.bodyA = i;
        c.bodyB = i + 1;
        c.radiusA = box.radius;
        c.radiusB = box.radius;
        c.friction = Real(0.6);
        c.restitutionThreshold = 1;
        CollidePolygons(c.manifold, box, bodies[i].xf, box, bodies[i + 1].xf);
        indices[i] = i;
    }
    SolverData data;
    data.positions = positions.data();
    data.velocities = velocities.data();
    ContactSolver solver;
    solver.Prepare({indices, contacts, bodies}, data);
    for (auto _ : state)
    {
        solver.SolveVelocities(data);
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * n);
}
BENCHMARK(BM_ContactRowUpdate)->Arg(64)->Arg(1024);

/// The broad phase after every body moved a little: re-fit the moved boxes, find new pairs.
void BM_BroadPhaseUpdate(benchmark::State& state)
{
    const int n = static_cast<int>(state.range(0));
    BroadPhase broadPhase(Real(0.1));
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> coordinate(-50, 50);
    std::vector<AABB> boxes(n);
    std::vector<std::int32_t> proxies(n);
    for (int i = 0; i < n; ++i)
    {
        const Vec2 c{coordinate(rng), coordinate(rng)};
        boxes[i] = {c - Vec2{Real(0.5), Real(0.5)}, c + Vec2{Real(0.5), Real(0.5)}};
        proxies[i] = broadPhase.CreateProxy(boxes[i], i);
    }
    broadPhase.UpdatePairs([](std::int32_t, std::int32_t) {});
    Real direction = Real(0.05);
    long pairs = 0;
    for (auto _ : state)
    {
        // Every box drifts 0.05 m, back and forth: most stay inside their fat boxes, some don't.
        const Vec2 d{direction, 0};
        for (int i = 0; i < n; ++i)
        {
            boxes[i].lowerBound += d;
            boxes[i].upperBound += d;
            broadPhase.MoveProxy(proxies[i], boxes[i], d);
        }
        broadPhase.UpdatePairs([&pairs](std::int32_t, std::int32_t) { ++pairs; });
        direction = -direction;
    }
    benchmark::DoNotOptimize(pairs);
    state.SetItemsProcessed(state.iterations() * n);
}
BENCHMARK(BM_BroadPhaseUpdate)->Arg(1000)->Arg(10000);

/// One World::Step of N boxes resting side by side on a ground segment, every box its own
/// island (static bodies do not join islands), all asleep (second argument 1) or all awake
/// (0, sleeping off). What sleeping saves: the asleep world should cost only the per-step
/// sweeps over bodies and contacts that Box2D 2.4.1 also makes (flags, forces, narrow-phase
/// skip), nothing per island.
void BM_StepRestingBoxes(benchmark::State& state)
{
    const int n = static_cast<int>(state.range(0));
    const bool asleep = state.range(1) != 0;
    WorldDef def;
    def.allowSleep = asleep;
    World world(def);
    const Real spacing = Real(1.5);
    const BodyId ground = world.CreateBody({});
    world.CreateShape(ground, ShapeDef{}, Segment{{-1, 0}, {spacing * Real(n), 0}});
    std::vector<BodyId> boxes;
    for (int i = 0; i < n; ++i)
    {
        const BodyId box = world.CreateBody(
            {.type = BodyType::Dynamic, .position = {spacing * Real(i), Real(0.52)}});
        world.CreateShape(box, ShapeDef{}, MakeBox(Real(0.5), Real(0.5)));
        boxes.push_back(box);
    }
    const Real dt = Real(1) / Real(60);
    for (int i = 0; i < 120; ++i) // settle: every box comes to rest and, if allowed, sleeps
    {
        world.Step(dt);
    }
    if (asleep)
    {
        for (const BodyId box : boxes)
        {
            if (world.IsAwake(box))
            {
                state.SkipWithError("a box is still awake after settling");
                return;
            }
        }
    }
    for (auto _ : state)
    {
        world.Step(dt);
    }
    benchmark::DoNotOptimize(world.GetStepCount());
    state.SetItemsProcessed(state.iterations() * n);
}
BENCHMARK(BM_StepRestingBoxes)
    ->ArgNames({"bodies", "asleep"})
    ->Args({1000, 0})
    ->Args({1000, 1})
    ->Args({5000, 0})
    ->Args({5000, 1})
    ->Unit(benchmark::kMicrosecond);

/// A world of 1000 static shapes (boxes and circles, alternating) scattered over 100 m × 100 m,
/// and 256 random rays of 30 m through it.
struct RayWorld
{
    World world{WorldDef{.gravity = {0, 0}}};
    std::vector<ShapeId> shapes;
    std::vector<std::pair<Vec2, Vec2>> rays; ///< origin, translation

    RayWorld()
    {
        std::mt19937 rng(11);
        std::uniform_real_distribution<float> coordinate(-50, 50);
        std::uniform_real_distribution<float> angle(-3.14159f, 3.14159f);
        for (int i = 0; i < 1000; ++i)
        {
            const BodyId body = world.CreateBody(
                {.position = {coordinate(rng), coordinate(rng)}, .angle = angle(rng)});
            shapes.push_back(i % 2 == 0 ? world.CreateShape(body, {}, MakeBox(Real(0.5), Real(0.3)))
                                        : world.CreateShape(body, {}, Circle{{0, 0}, Real(0.4)}));
        }
        for (int i = 0; i < 256; ++i)
        {
            const Real a = angle(rng);
            rays.push_back({{coordinate(rng), coordinate(rng)},
                            {Real(30) * std::cos(a), Real(30) * std::sin(a)}});
        }
    }
};

/// World::CastRayClosest through the broad phase.
void BM_CastRayClosest(benchmark::State& state)
{
    const RayWorld scene;
    std::size_t next = 0;
    int hits = 0;
    for (auto _ : state)
    {
        const auto& [origin, translation] = scene.rays[next++ % scene.rays.size()];
        hits += scene.world.CastRayClosest(origin, translation).hit ? 1 : 0;
    }
    benchmark::DoNotOptimize(hits);
}
BENCHMARK(BM_CastRayClosest);

/// The same rays tested against every shape, geometry and transforms copied out beforehand:
/// what the broad phase saves.
void BM_CastRayClosestBruteForce(benchmark::State& state)
{
    const RayWorld scene;
    struct Target
    {
        Transform xf;
        bool isBox;
        Polygon box;
        Circle circle;
    };
    std::vector<Target> targets;
    for (const ShapeId id : scene.shapes)
    {
        const bool isBox = scene.world.GetShapeType(id) == ShapeType::Polygon;
        targets.push_back({scene.world.GetTransform(scene.world.GetBody(id)), isBox,
                           isBox ? scene.world.GetPolygon(id) : Polygon{},
                           isBox ? Circle{} : scene.world.GetCircle(id)});
    }
    std::size_t next = 0;
    int hits = 0;
    for (auto _ : state)
    {
        const auto& [origin, translation] = scene.rays[next++ % scene.rays.size()];
        const RayCastInput input{origin, origin + translation, 1};
        Real closest = 2;
        for (const Target& target : targets)
        {
            RayCastOutput output;
            const bool hit = target.isBox ? RayCast(target.box, target.xf, input, output)
                                          : RayCast(target.circle, target.xf, input, output);
            if (hit && output.fraction < closest)
            {
                closest = output.fraction;
            }
        }
        hits += closest <= 1 ? 1 : 0;
    }
    benchmark::DoNotOptimize(hits);
}
BENCHMARK(BM_CastRayClosestBruteForce);

} // namespace

BENCHMARK_MAIN();
