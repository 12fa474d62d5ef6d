// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Tests of the broad phase's tree grown in place and built again (TreeUpdate::EnlargeAndRebuild,
// engine/src/collision/tree_rebuild.cpp): the colour and soft-step back ends' tree update.
#include "collision/broad_phase.h"
#include "test_random.h"
#include "meff/task_system.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <set>
#include <utility>
#include <vector>

using meff::AABB;
using meff::Real;
using meff::Vec2;
using meff::detail::BroadPhase;
using meff::detail::DynamicTree;
using meff::detail::FatBoxRule;
using meff::detail::ProxyLayers;
using meff::detail::TreeUpdate;
using meff::test::Random;

namespace
{

/// The throughput rule's margin, no stretch: every move past 5 cm leaves the fat box.
const FatBoxRule kRule{Real(0.05), 0};

AABB Box(Vec2 centre, Vec2 halfExtents)
{
    return {centre - halfExtents, centre + halfExtents};
}

AABB RandomBox(Random& rng, float worldHalfSize, float maxHalfExtent)
{
    const Vec2 c(rng.Uniform(-worldHalfSize, worldHalfSize),
                 rng.Uniform(-worldHalfSize, worldHalfSize));
    return Box(c, {rng.Uniform(0.05f, maxHalfExtent), rng.Uniform(0.05f, maxHalfExtent)});
}

AABB Translated(const AABB& box, Vec2 d)
{
    return {box.lowerBound + d, box.upperBound + d};
}

ProxyLayers RandomLayers(Random& rng)
{
    ProxyLayers layers;
    layers.categoryBits = static_cast<std::uint16_t>(1u << static_cast<unsigned>(rng.Index(4)));
    layers.maskBits = static_cast<std::uint16_t>(rng.Index(16));
    return layers;
}

/// Moves a random live leaf by up to `scale()` in x and y (scale is asked after the leaf is
/// picked), in the map and in the tree; returns its entry.
template <typename Scale>
std::map<std::int32_t, AABB>::iterator MoveRandomLeaf(DynamicTree& tree,
                                                      std::map<std::int32_t, AABB>& live,
                                                      Random& rng, Scale&& scale)
{
    auto it = std::next(live.begin(), rng.Index(static_cast<int>(live.size())));
    const float s = scale();
    const Vec2 d(rng.Uniform(-s, s), rng.Uniform(-s, s));
    it->second = Translated(it->second, d);
    tree.MoveProxy(it->first, it->second, d);
    return it;
}

DynamicTree RebuildingTree()
{
    DynamicTree tree(kRule);
    tree.SetTreeUpdate(TreeUpdate::EnlargeAndRebuild);
    return tree;
}

/// The query's leaves, sorted, against every live leaf's fat box tested one by one.
void CheckQueryAgainstBruteForce(const DynamicTree& tree, const std::map<std::int32_t, AABB>& live,
                                 const AABB& query)
{
    std::vector<std::int32_t> found;
    tree.Query(query,
               [&found](std::int32_t id)
               {
                   found.push_back(id);
                   return true;
               });
    std::vector<std::int32_t> expected;
    for (const auto& [id, box] : live)
    {
        if (meff::TestOverlap(tree.GetFatAABB(id), query))
        {
            expected.push_back(id);
        }
    }
    std::sort(found.begin(), found.end());
    CHECK(found == expected);
}

} // namespace

TEST_CASE("Tree rebuild: random creates, moves, destroys and rebuilds keep the tree valid and "
          "its queries exact",
          "[broad_phase][tree_rebuild]")
{
    for (std::uint64_t seed = 1; seed <= 4; ++seed)
    {
        Random rng(seed);
        DynamicTree tree = RebuildingTree();
        std::map<std::int32_t, AABB> live; // proxy id -> tight box
        std::map<std::int32_t, int> user;  // proxy id -> user data
        int rebuilds = 0;
        for (int op = 0; op < 3000; ++op)
        {
            INFO("seed " << seed << " op " << op);
            const int kind = live.size() < 20 ? 0 : rng.Index(20);
            if (kind <= 4)
            {
                const AABB box = RandomBox(rng, 50, 3);
                const std::int32_t id = tree.CreateProxy(box, op, RandomLayers(rng));
                REQUIRE(live.count(id) == 0);
                live[id] = box;
                user[id] = op;
            }
            else if (kind <= 15)
            {
                const auto it = MoveRandomLeaf(tree, live, rng,
                                               [&rng] { return rng.Index(4) == 0 ? 5.0f : 0.3f; });
                REQUIRE(tree.GetFatAABB(it->first).Contains(it->second));
            }
            else if (kind <= 17)
            {
                auto it = std::next(live.begin(), rng.Index(static_cast<int>(live.size())));
                tree.DestroyProxy(it->first);
                user.erase(it->first);
                live.erase(it);
            }
            else
            {
                // Rebuild changes internal nodes only: every leaf keeps its id, user data and
                // fat box, and no box is left grown.
                std::map<std::int32_t, AABB> fat;
                for (const auto& [id, box] : live)
                {
                    fat[id] = tree.GetFatAABB(id);
                }
                tree.Rebuild();
                ++rebuilds;
                CHECK(tree.CountEnlarged() == 0);
                for (const auto& [id, box] : fat)
                {
                    CHECK(tree.GetUserData(id) == user[id]);
                    CHECK(tree.GetFatAABB(id).lowerBound == box.lowerBound);
                    CHECK(tree.GetFatAABB(id).upperBound == box.upperBound);
                }
            }
            REQUIRE(tree.Validate());
            if (op % 50 == 0)
            {
                for (int q = 0; q < 10; ++q)
                {
                    CheckQueryAgainstBruteForce(tree, live, RandomBox(rng, 55, 8));
                }
            }
        }
        CHECK(rebuilds > 100); // the rebuilds were interleaved with everything else
        while (!live.empty())
        {
            tree.DestroyProxy(live.begin()->first);
            live.erase(live.begin());
            REQUIRE(tree.Validate());
        }
        CHECK(tree.GetHeight() == 0);
    }
}

TEST_CASE("Tree rebuild: a move grows boxes in place, marking only its ancestors, and the grown "
          "tree answers exactly until the rebuild",
          "[broad_phase][tree_rebuild]")
{
    Random rng(11);
    DynamicTree tree = RebuildingTree();
    std::map<std::int32_t, AABB> live;
    for (int i = 0; i < 400; ++i)
    {
        const AABB box = RandomBox(rng, 40, 1);
        live[tree.CreateProxy(box, i)] = box;
    }
    tree.Rebuild(); // nothing grew: a tree built by insertion stays as it is
    REQUIRE(tree.CountEnlarged() == 0);
    const int insertedHeight = tree.GetHeight();

    // One leaf moves far: its ancestors, and only they, are marked — at most the tree's height.
    const std::int32_t far = live.begin()->first;
    live[far] = Translated(live[far], {60, 60});
    tree.MoveProxy(far, live[far], {0, 0});
    const int marked = tree.CountEnlarged();
    CHECK(marked >= 1);
    CHECK(marked <= insertedHeight);
    REQUIRE(tree.Validate()); // grown boxes hold their children
    for (int q = 0; q < 50; ++q)
    {
        CheckQueryAgainstBruteForce(tree, live, RandomBox(rng, 45, 6));
    }
    CheckQueryAgainstBruteForce(tree, live, tree.GetFatAABB(far));

    tree.Rebuild();
    CHECK(tree.CountEnlarged() == 0);
    REQUIRE(tree.Validate());
    CheckQueryAgainstBruteForce(tree, live, tree.GetFatAABB(far));
}

TEST_CASE("Tree rebuild: built trees stay shallow, clustered boxes included",
          "[broad_phase][tree_rebuild]")
{
    // Splitting at the middle of the centres' extent halves random boxes: the height is near
    // log2(n). Centres at 2^i make the middle split peel off one box at a time; beyond 32
    // levels the build splits at the median, so the height stays at most 32 + ceil(log2 n)
    // (the bound in tree_rebuild.cpp), where peeling alone would make it n − 1.
    const auto moveAllAndRebuild =
        [](DynamicTree& tree, const std::vector<std::int32_t>& ids, const std::vector<AABB>& boxes)
    {
        for (std::size_t i = 0; i < ids.size(); ++i)
        {
            const AABB moved = Translated(boxes[i], {0, 1});
            tree.MoveProxy(ids[i], moved, {0, 1});
        }
        tree.Rebuild();
        REQUIRE(tree.Validate());
        REQUIRE(tree.CountEnlarged() == 0);
    };

    SECTION("random boxes: within 2 log2(n) + 2")
    {
        Random rng(5);
        DynamicTree tree = RebuildingTree();
        std::vector<std::int32_t> ids;
        std::vector<AABB> boxes;
        for (int i = 0; i < 2000; ++i)
        {
            boxes.push_back(RandomBox(rng, 100, 1));
            ids.push_back(tree.CreateProxy(boxes.back(), i));
        }
        moveAllAndRebuild(tree, ids, boxes);
        CHECK(tree.GetHeight() <= 2 * 11 + 2); // log2(2000) < 11
    }

    SECTION("centres at 2^i: at most 32 + ceil(log2 n), where peeling would give n - 1")
    {
        DynamicTree tree = RebuildingTree();
        std::vector<std::int32_t> ids;
        std::vector<AABB> boxes;
        for (int i = 0; i < 120; ++i)
        {
            boxes.push_back(Box({std::ldexp(Real(1), i), 0}, {0.1f, 0.1f}));
            ids.push_back(tree.CreateProxy(boxes.back(), i));
        }
        moveAllAndRebuild(tree, ids, boxes);
        CHECK(tree.GetHeight() <= 32 + 7); // log2(120) < 7; without the median, 71 (modelled)
    }

    SECTION("one thousand boxes at one place: the median split, height ceil(log2 n)")
    {
        DynamicTree tree = RebuildingTree();
        std::vector<std::int32_t> ids;
        std::vector<AABB> boxes;
        for (int i = 0; i < 1000; ++i)
        {
            boxes.push_back(Box({3, 4}, {0.5f, 0.5f}));
            ids.push_back(tree.CreateProxy(boxes.back(), i));
        }
        moveAllAndRebuild(tree, ids, boxes);
        CHECK(tree.GetHeight() == 10);
    }
}

TEST_CASE("Tree rebuild: the broad phase reports every new overlapping pair once, as with "
          "re-insertion",
          "[broad_phase][tree_rebuild]")
{
    // The same moves through two broad phases, one re-inserting (Box2D's) and one growing and
    // rebuilding: the fat boxes are the same rule's, so the pairs found must be the same set
    // (their order follows each tree's shape). UpdatePairs builds the grown tree first.
    Random rng(3);
    BroadPhase reinserting(kRule);
    BroadPhase rebuilding(kRule);
    rebuilding.SetTreeUpdate(TreeUpdate::EnlargeAndRebuild);
    std::vector<AABB> boxes;
    std::vector<std::int32_t> ids; // the same in both: the same pool, the same insertions
    for (int i = 0; i < 300; ++i)
    {
        boxes.push_back(RandomBox(rng, 25, 1.5f));
        ids.push_back(reinserting.CreateProxy(boxes.back(), i));
        REQUIRE(rebuilding.CreateProxy(boxes.back(), i) == ids.back());
    }
    const auto pairs = [](BroadPhase& bp)
    {
        std::vector<std::pair<std::int32_t, std::int32_t>> found;
        bp.UpdatePairs([&found](std::int32_t a, std::int32_t b)
                       { found.emplace_back(std::min(a, b), std::max(a, b)); });
        std::set<std::pair<std::int32_t, std::int32_t>> once(found.begin(), found.end());
        CHECK(once.size() == found.size());       // no pair twice
        CHECK(bp.GetTree().CountEnlarged() == 0); // the queries walked a rebuilt tree
        return once;
    };
    CHECK(pairs(reinserting) == pairs(rebuilding));
    for (int round = 0; round < 30; ++round)
    {
        INFO("round " << round);
        std::set<std::size_t> picked; // each moved once: a proxy buffered twice is queried twice
        while (picked.size() < 40)
        {
            picked.insert(static_cast<std::size_t>(rng.Index(300)));
        }
        for (const std::size_t i : picked)
        {
            const Vec2 d(rng.Uniform(-2, 2), rng.Uniform(-2, 2));
            boxes[i] = Translated(boxes[i], d);
            reinserting.MoveProxy(ids[i], boxes[i], d);
            rebuilding.MoveProxy(ids[i], boxes[i], d);
        }
        const auto expected = pairs(reinserting);
        CHECK(!expected.empty());
        CHECK(pairs(rebuilding) == expected);
        REQUIRE(rebuilding.GetTree().Validate());
    }
}

TEST_CASE("Tree rebuild: boxes that overflow to infinity leave a valid tree and exact queries",
          "[broad_phase][tree_rebuild]")
{
    // Shapes near the float range's ends have boxes reaching -inf or +inf: a subtree holding
    // both has a NaN centre, which the median split must still order (tree_rebuild.cpp).
    Random rng(9);
    DynamicTree tree = RebuildingTree();
    std::map<std::int32_t, AABB> live;
    for (int i = 0; i < 200; ++i)
    {
        const float far = i % 4 == 0 ? -3e38f : (i % 4 == 1 ? 3e38f : 0.0f);
        const AABB box = far == 0 ? RandomBox(rng, 20, 1) : Box({far, 0}, {1e38f, 1});
        live[tree.CreateProxy(box, i)] = box;
    }
    bool infinite = false;
    for (const auto& [id, box] : live)
    {
        const AABB& fat = tree.GetFatAABB(id);
        infinite = infinite || std::isinf(fat.lowerBound.x) || std::isinf(fat.upperBound.x);
    }
    REQUIRE(infinite); // the case this test is about
    for (int round = 0; round < 50; ++round)
    {
        INFO("round " << round);
        for (int k = 0; k < 10; ++k)
        {
            MoveRandomLeaf(tree, live, rng, [] { return 2.0f; });
        }
        tree.Rebuild();
        REQUIRE(tree.Validate());
        CHECK(tree.CountEnlarged() == 0);
        CheckQueryAgainstBruteForce(tree, live, RandomBox(rng, 25, 5));
    }
}

TEST_CASE("Tree rebuild: the same tree, node ids included, on any number of threads",
          "[broad_phase][tree_rebuild][threads]")
{
    // Trees given the same creates, moves and destroys, rebuilt on 1 (no task system), 2, 3 and
    // 4 threads: every query reports the same leaves in the same order (the tree's shape), and
    // the next proxies get the same ids (the free list the build leaves, so its node ids). Big
    // enough for the threaded build: thousands of units, most of them moved each round.
    const std::vector<int> threadCounts{1, 2, 3, 4};
    std::vector<std::unique_ptr<meff::TaskSystem>> pools;
    std::vector<DynamicTree> trees;
    for (const int threads : threadCounts)
    {
        pools.push_back(threads == 1 ? nullptr : meff::MakeThreadPool(threads));
        trees.push_back(RebuildingTree());
    }
    Random rng(21);
    std::vector<AABB> boxes;
    std::vector<std::int32_t> ids;
    for (int i = 0; i < 4000; ++i)
    {
        boxes.push_back(RandomBox(rng, 100, 1));
        std::int32_t id = 0;
        for (DynamicTree& tree : trees)
        {
            id = tree.CreateProxy(boxes.back(), i);
        }
        ids.push_back(id);
    }
    for (int round = 0; round < 6; ++round)
    {
        for (std::size_t i = 0; i < ids.size(); ++i)
        {
            if (rng.Index(4) == 0)
            {
                continue; // a quarter stays: kept subtrees
            }
            const Vec2 d(rng.Uniform(-2, 2), rng.Uniform(-2, 2));
            boxes[i] = Translated(boxes[i], d);
            for (DynamicTree& tree : trees)
            {
                tree.MoveProxy(ids[i], boxes[i], d);
            }
        }
        for (std::size_t t = 0; t < trees.size(); ++t)
        {
            trees[t].Rebuild(pools[t].get());
            REQUIRE(trees[t].Validate());
        }
        for (int q = 0; q < 40; ++q)
        {
            const AABB query = RandomBox(rng, 110, 15);
            std::vector<std::vector<std::int32_t>> found(trees.size());
            for (std::size_t t = 0; t < trees.size(); ++t)
            {
                trees[t].Query(query,
                               [&found, t](std::int32_t id)
                               {
                                   found[t].push_back(id);
                                   return true;
                               });
            }
            for (std::size_t t = 1; t < trees.size(); ++t)
            {
                CHECK(found[t] == found[0]);
            }
        }
        // A proxy made and destroyed takes the free list's first node: the same in every tree.
        std::vector<std::int32_t> next;
        for (DynamicTree& tree : trees)
        {
            CHECK(tree.GetHeight() == trees[0].GetHeight());
            next.push_back(tree.CreateProxy(RandomBox(rng, 100, 1), -1));
            tree.DestroyProxy(next.back());
        }
        for (const std::int32_t id : next)
        {
            CHECK(id == next[0]);
        }
    }
}
