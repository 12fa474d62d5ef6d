// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Shape filters (meff::Filter) decide which shapes collide, by Box2D 2.4.1's rule
// (b2ContactFilter::ShouldCollide): two shapes of the same non-zero group collide when the
// group is positive and never when it is negative; otherwise each one's category must share a
// bit with the other's mask. The broad phase already leaves out, inside its tree, the pairs
// whose bits cannot meet (collision/broad_phase.h: ProxyLayers), except for shapes in a
// positive group; this checks the rule end to end.
#include "analytic_support.h"

#include "meff/world.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <random>
#include <set>
#include <utility>
#include <vector>

using namespace meff;
using namespace meff::analytic;

namespace
{

/// The rule, written out apart from the engine's.
bool Box2DFilterAllows(const Filter& a, const Filter& b)
{
    if (a.groupIndex == b.groupIndex && a.groupIndex != 0)
    {
        return a.groupIndex > 0;
    }
    return (a.maskBits & b.categoryBits) != 0 && (a.categoryBits & b.maskBits) != 0;
}

} // namespace

TEST_CASE("Filters: shapes touch exactly when Box2D's filter rule lets them", "[filters]")
{
    // Balls of radius 0.5 scattered over a small square, so that many overlap, with filters
    // drawn from few bits and groups: categories of zero, masks of zero, positive groups whose
    // bits do not meet (they collide all the same), negative groups whose bits do (they never
    // collide). After one step, a pair overlapping by more than 0.1 m must touch exactly when
    // the rule allows it, and a pair 0.3 m apart must not touch.
    std::mt19937 rng(7); // fully specified by the standard: the same draws everywhere
    const std::uint16_t categories[] = {0, 1, 2, 4, 8};
    const std::int16_t groups[] = {0, 0, 1, -1, -1, 2};
    int allowed = 0, refused = 0, positiveGroupOverrides = 0, negativeGroupOverrides = 0;
    for (int trial = 0; trial < 4; ++trial)
    {
        World world = MakeWorld({0, 0});
        std::vector<Filter> filters;
        std::vector<Vec2> centres;
        for (int i = 0; i < 80; ++i)
        {
            Filter filter;
            filter.categoryBits = categories[rng() % 5];
            filter.maskBits = static_cast<std::uint16_t>(rng() % 16);
            filter.groupIndex = groups[rng() % 6];
            // Two statements: the order of a call's arguments is unspecified.
            const Real x = Real(rng() % 8000) / 1000;
            const Real y = Real(rng() % 8000) / 1000;
            const Vec2 centre(x, y);
            ShapeDef def = Material(1, Real(0.5));
            def.filter = filter;
            const BodyId body = world.CreateBody({.type = BodyType::Dynamic, .position = centre});
            REQUIRE(world.CreateShape(body, def, Circle{{0, 0}, Real(0.5)}).index == i);
            filters.push_back(filter);
            centres.push_back(centre);
        }
        world.Step(kDt);

        std::set<std::pair<std::int32_t, std::int32_t>> touching;
        for (const ContactPointReport& point : world.GetContactReports())
        {
            touching.insert(std::minmax(point.shapeA.index, point.shapeB.index));
        }
        for (std::int32_t i = 0; i < 80; ++i)
        {
            for (std::int32_t j = i + 1; j < 80; ++j)
            {
                INFO("trial " << trial << " shapes " << i << ", " << j);
                const Real gap = Distance(centres[i], centres[j]) - 1;
                const bool touches = touching.count({i, j}) == 1;
                if (gap < Real(-0.1))
                {
                    const Filter& a = filters[i];
                    const Filter& b = filters[j];
                    const bool expected = Box2DFilterAllows(a, b);
                    CHECK(touches == expected);
                    (expected ? allowed : refused) += 1;
                    const bool bitsMeet =
                        (a.maskBits & b.categoryBits) != 0 && (a.categoryBits & b.maskBits) != 0;
                    positiveGroupOverrides += expected && !bitsMeet ? 1 : 0;
                    negativeGroupOverrides += !expected && bitsMeet ? 1 : 0;
                }
                else if (gap > Real(0.3))
                {
                    CHECK_FALSE(touches);
                }
            }
        }
    }
    // Each kind of verdict was put to the test, groups overriding the bits both ways included
    // (a positive group is what the broad phase must not leave out by the bits).
    CHECK(allowed > 20);
    CHECK(refused > 20);
    CHECK(positiveGroupOverrides > 2);
    CHECK(negativeGroupOverrides > 2);
}
