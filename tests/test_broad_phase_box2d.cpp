// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Golden check of the broad phase against Box2D 2.4.1 itself (Debian's libbox2d-dev, link with
// -lbox2d): the same operations on b2BroadPhase/b2DynamicTree and on ours must give the same
// proxy ids, bit-identical fat boxes, the same tree height, the same query visiting order and
// the same UpdatePairs pair sequence. Only meaningful with float as the scalar.
#include "collision/broad_phase.h"

#include <box2d/b2_broad_phase.h>
#include <box2d/b2_common.h>
#include <box2d/b2_dynamic_tree.h>

#include <catch2/catch.hpp>

#include "test_random.h"

#include <cmath>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#ifndef MEFF_DOUBLE

using meff::AABB;
using meff::Real;
using meff::Vec2;
using meff::detail::BroadPhase;
using meff::detail::DynamicTree;

namespace
{

using PairList = std::vector<std::pair<std::int32_t, std::int32_t>>;

using meff::test::Random;

b2AABB ToBox2D(const AABB& box)
{
    b2AABB result;
    result.lowerBound.Set(box.lowerBound.x, box.lowerBound.y);
    result.upperBound.Set(box.upperBound.x, box.upperBound.y);
    return result;
}

void* ToUserData(std::int32_t value)
{
    return reinterpret_cast<void*>(static_cast<std::intptr_t>(value));
}

std::int32_t FromUserData(void* value)
{
    return static_cast<std::int32_t>(reinterpret_cast<std::intptr_t>(value));
}

bool SameBox(const AABB& ours, const b2AABB& theirs)
{
    // Exact: the fat boxes must round identically.
    return ours.lowerBound.x == theirs.lowerBound.x && ours.lowerBound.y == theirs.lowerBound.y &&
           ours.upperBound.x == theirs.upperBound.x && ours.upperBound.y == theirs.upperBound.y;
}

/// Box2D's UpdatePairs callback: records (userDataA, userDataB).
struct PairRecorder
{
    PairList pairs;
    void AddPair(void* a, void* b) { pairs.emplace_back(FromUserData(a), FromUserData(b)); }
};

/// Box2D's Query callback: records the visited proxy ids.
struct QueryRecorder
{
    std::vector<std::int32_t> ids;
    bool QueryCallback(int32 proxyId)
    {
        ids.push_back(proxyId);
        return true;
    }
};

/// One body-like proxy of the scenario.
struct Mover
{
    std::int32_t proxyId = -1;
    AABB box;
    Vec2 velocity;
};

AABB RandomBox(Random& rng, float worldHalfSize, float maxHalfExtent)
{
    const Vec2 c(rng.Uniform(-worldHalfSize, worldHalfSize),
                 rng.Uniform(-worldHalfSize, worldHalfSize));
    const Vec2 h(rng.Uniform(0.05f, maxHalfExtent), rng.Uniform(0.05f, maxHalfExtent));
    return {c - h, c + h};
}

/// Drives a b2BroadPhase and ours through the same random scenario and compares them after
/// every step.
void RunScenario(std::uint64_t seed, int steps)
{
    Random rng(seed);
    b2BroadPhase theirs;
    BroadPhase ours(Real(b2_aabbExtension));

    std::map<std::int32_t, Mover> movers; // by user data
    std::int32_t nextUserData = 0;

    auto create = [&](const AABB& box, Vec2 velocity)
    {
        const std::int32_t userData = nextUserData++;
        const int32 theirId = theirs.CreateProxy(ToBox2D(box), ToUserData(userData));
        const std::int32_t ourId = ours.CreateProxy(box, userData);
        REQUIRE(ourId == theirId);
        movers[userData] = {ourId, box, velocity};
    };

    auto compareState = [&]()
    {
        REQUIRE(ours.GetProxyCount() == theirs.GetProxyCount());
        REQUIRE(ours.GetTree().GetHeight() == theirs.GetTreeHeight());
        for (const auto& [userData, mover] : movers)
        {
            REQUIRE(ours.GetUserData(mover.proxyId) == userData);
            REQUIRE(SameBox(ours.GetFatAABB(mover.proxyId), theirs.GetFatAABB(mover.proxyId)));
        }
    };

    for (int i = 0; i < 60; ++i)
    {
        create(RandomBox(rng, 30, 1.5f), {rng.Uniform(-2, 2), rng.Uniform(-2, 2)});
    }

    for (int step = 0; step < steps; ++step)
    {
        INFO("seed " << seed << " step " << step);

        // Motion like a simulation step: displacement = velocity * dt, with a few bodies
        // stopping (zero displacement, the shrink test), kicked hard, or teleported.
        const float dt = 1.0f / 60.0f;
        for (auto& [userData, mover] : movers)
        {
            const int event = rng.Index(100);
            if (event < 5)
            {
                mover.velocity = Vec2(0, 0);
            }
            else if (event < 8)
            {
                mover.velocity = Vec2(rng.Uniform(-60, 60), rng.Uniform(-60, 60));
            }
            else if (event < 30)
            {
                mover.velocity += Vec2(rng.Uniform(-1, 1), rng.Uniform(-1, 1));
            }
            Vec2 d = dt * mover.velocity;
            if (event == 99)
            {
                d = Vec2(rng.Uniform(-20, 20), rng.Uniform(-20, 20));
            }
            mover.box.lowerBound += d;
            mover.box.upperBound += d;
            // Keep the scene compact so that pairs keep forming.
            const Vec2 c = mover.box.GetCenter();
            if (std::abs(c.x) > 40 || std::abs(c.y) > 40)
            {
                mover.velocity = -1.0f * mover.velocity;
            }
            theirs.MoveProxy(mover.proxyId, ToBox2D(mover.box), b2Vec2(d.x, d.y));
            ours.MoveProxy(mover.proxyId, mover.box, d);
        }

        // Some churn: destroy, create (reusing freed ids), touch.
        const int churn = rng.Index(4);
        for (int k = 0; k < churn && movers.size() > 10; ++k)
        {
            auto it = std::next(movers.begin(), rng.Index(static_cast<int>(movers.size())));
            theirs.DestroyProxy(it->second.proxyId);
            ours.DestroyProxy(it->second.proxyId);
            movers.erase(it);
        }
        const int births = rng.Index(4);
        for (int k = 0; k < births; ++k)
        {
            create(RandomBox(rng, 30, 1.5f), {rng.Uniform(-2, 2), rng.Uniform(-2, 2)});
        }
        if (rng.Index(5) == 0)
        {
            auto it = std::next(movers.begin(), rng.Index(static_cast<int>(movers.size())));
            theirs.TouchProxy(it->second.proxyId);
            ours.TouchProxy(it->second.proxyId);
        }

        compareState();

        // Pairs: the same sequence, in the same order.
        PairRecorder recorder;
        theirs.UpdatePairs(&recorder);
        PairList ourPairs;
        ours.UpdatePairs([&ourPairs](std::int32_t a, std::int32_t b)
                         { ourPairs.emplace_back(a, b); });
        REQUIRE(ourPairs == recorder.pairs);

        // Queries: the same leaves, in the same order.
        for (int q = 0; q < 3; ++q)
        {
            const AABB query = RandomBox(rng, 35, 6);
            QueryRecorder theirQuery;
            theirs.Query(&theirQuery, ToBox2D(query));
            std::vector<std::int32_t> ourQuery;
            ours.Query(query,
                       [&ourQuery](std::int32_t id)
                       {
                           ourQuery.push_back(id);
                           return true;
                       });
            REQUIRE(ourQuery == theirQuery.ids);
        }
    }
    REQUIRE(ours.GetTree().Validate());
}

} // namespace

TEST_CASE("Broad phase matches Box2D 2.4.1: ids, fat boxes, pairs, query order",
          "[broad_phase][box2d]")
{
    for (std::uint64_t seed = 1; seed <= 6; ++seed)
    {
        RunScenario(seed, 300);
    }
}

TEST_CASE("Dynamic tree matches Box2D 2.4.1: MoveProxy decisions and pool growth",
          "[broad_phase][box2d]")
{
    Random rng(11);
    b2DynamicTree theirs;
    DynamicTree ours(Real(b2_aabbExtension));
    std::vector<std::pair<std::int32_t, AABB>> live;

    // Enough proxies to double the pool several times (16 -> 1024 nodes).
    for (int i = 0; i < 500; ++i)
    {
        const AABB box = RandomBox(rng, 100, 2);
        const std::int32_t id = ours.CreateProxy(box, i);
        REQUIRE(theirs.CreateProxy(ToBox2D(box), ToUserData(i)) == id);
        live.emplace_back(id, box);
    }
    REQUIRE(ours.GetHeight() == theirs.GetHeight());

    for (int op = 0; op < 5000; ++op)
    {
        INFO("op " << op);
        auto& [id, box] = live[static_cast<std::size_t>(rng.Index(500))];
        // Displacements around the thresholds: inside the margin, just past it, large, zero.
        const float scales[] = {0.0f, 0.02f, 0.1f, 0.12f, 0.5f, 5.0f};
        const float scale = scales[rng.Index(6)];
        const Vec2 d(rng.Uniform(-scale, scale), rng.Uniform(-scale, scale));
        box.lowerBound += d;
        box.upperBound += d;
        const bool ourMove = ours.MoveProxy(id, box, d);
        const bool theirMove = theirs.MoveProxy(id, ToBox2D(box), b2Vec2(d.x, d.y));
        REQUIRE(ourMove == theirMove);
        REQUIRE(ours.WasMoved(id) == theirs.WasMoved(id));
        REQUIRE(SameBox(ours.GetFatAABB(id), theirs.GetFatAABB(id)));
        ours.ClearMoved(id);
        theirs.ClearMoved(id);
        REQUIRE(ours.GetHeight() == theirs.GetHeight());
    }
    for (const auto& [id, box] : live)
    {
        REQUIRE(SameBox(ours.GetFatAABB(id), theirs.GetFatAABB(id)));
    }
    // The same structure shows as the same query visiting order.
    for (int q = 0; q < 100; ++q)
    {
        const AABB query = RandomBox(rng, 100, 20);
        QueryRecorder theirQuery;
        theirs.Query(&theirQuery, ToBox2D(query));
        std::vector<std::int32_t> ourQuery;
        ours.Query(query,
                   [&ourQuery](std::int32_t id)
                   {
                       ourQuery.push_back(id);
                       return true;
                   });
        REQUIRE(ourQuery == theirQuery.ids);
    }
    REQUIRE(ours.Validate());
}

TEST_CASE("Broad phase matches Box2D 2.4.1 on grid-aligned boxes (cost ties)",
          "[broad_phase][box2d]")
{
    // Equal boxes at regular spacing (grids, pyramids, stacks) make the insertion costs and
    // the subtree heights tie exactly, which exercises every tie-break rule.
    for (int layout = 0; layout < 3; ++layout)
    {
        INFO("layout " << layout);
        b2BroadPhase theirs;
        BroadPhase ours(Real(b2_aabbExtension));
        std::vector<std::pair<std::int32_t, AABB>> live;

        auto compare = [&]()
        {
            PairRecorder recorder;
            theirs.UpdatePairs(&recorder);
            PairList ourPairs;
            ours.UpdatePairs([&ourPairs](std::int32_t a, std::int32_t b)
                             { ourPairs.emplace_back(a, b); });
            REQUIRE(ourPairs == recorder.pairs);
            REQUIRE(ours.GetTree().GetHeight() == theirs.GetTreeHeight());
            for (const auto& [id, box] : live)
            {
                REQUIRE(SameBox(ours.GetFatAABB(id), theirs.GetFatAABB(id)));
            }
        };

        const int rows = 12;
        for (int row = 0; row < rows; ++row)
        {
            const int count = layout == 0 ? rows - row : (layout == 1 ? 1 : 10);
            for (int k = 0; k < count; ++k)
            {
                // Pyramid (0), vertical stack (1), grid (2) of 1 m boxes, touching.
                const float x = layout == 0 ? 0.5f * static_cast<float>(row) + static_cast<float>(k)
                                            : static_cast<float>(k);
                const float y = 0.5f + static_cast<float>(row);
                const AABB box{{x - 0.5f, y - 0.5f}, {x + 0.5f, y + 0.5f}};
                const std::int32_t userData = static_cast<std::int32_t>(live.size());
                const std::int32_t id = ours.CreateProxy(box, userData);
                REQUIRE(theirs.CreateProxy(ToBox2D(box), ToUserData(userData)) == id);
                live.emplace_back(id, box);
            }
        }
        // A ground box under everything.
        {
            const AABB ground{{-20, -1}, {20, 0}};
            const auto userData = static_cast<std::int32_t>(live.size());
            const std::int32_t id = ours.CreateProxy(ground, userData);
            REQUIRE(theirs.CreateProxy(ToBox2D(ground), ToUserData(userData)) == id);
        }
        compare();

        // Everything falls by exact binary fractions, some faster; then stops.
        for (int step = 0; step < 40; ++step)
        {
            INFO("step " << step);
            for (std::size_t i = 0; i < live.size(); ++i)
            {
                auto& [id, box] = live[i];
                const float dy = step < 30 ? -0.0625f * static_cast<float>(1 + i % 3) : 0.0f;
                const Vec2 d(0, dy);
                box.lowerBound += d;
                box.upperBound += d;
                theirs.MoveProxy(id, ToBox2D(box), b2Vec2(d.x, d.y));
                ours.MoveProxy(id, box, d);
            }
            compare();
        }
    }
}

#endif // MEFF_DOUBLE
