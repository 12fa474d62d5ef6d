// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Time of impact (meff/distance.h TimeOfImpact, Sweep::Advance/Normalize): analytic cases,
// and golden checks against Box2D 2.4.1's b2TimeOfImpact for random sweeps of circles,
// polygons and segments: the same state and a bit-identical t.
#include "meff/distance.h"
#include "meff/error.h"

#include <box2d/b2_circle_shape.h>
#include <box2d/b2_edge_shape.h>
#include <box2d/b2_polygon_shape.h>
#include <box2d/b2_time_of_impact.h>

#include <catch2/catch.hpp>

#include "box2d_shape_pair.h"
#include "test_random.h"

#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

using namespace meff;

namespace
{

Sweep MakeSweep(Vec2 c0, Vec2 c, Real a0 = 0, Real a = 0)
{
    Sweep sweep;
    sweep.c0 = c0;
    sweep.c = c;
    sweep.a0 = a0;
    sweep.a = a;
    return sweep;
}

} // namespace

TEST_CASE("Sweep::Advance moves the start and keeps the end", "[toi][sweep]")
{
    Sweep sweep = MakeSweep({0, 0}, {10, 0}, 0, 1);
    sweep.Advance(Real(0.25));
    CHECK(sweep.c0.x == Approx(2.5));
    CHECK(sweep.a0 == Approx(0.25));
    CHECK(sweep.alpha0 == Approx(0.25));
    // Fractions stay fractions of the whole step: 0.5 is halfway from the original start.
    sweep.Advance(Real(0.5));
    CHECK(sweep.c0.x == Approx(5));
    CHECK(sweep.c.x == 10);
    CHECK(sweep.GetTransform(0).p.x == Approx(5));

    Sweep turned = MakeSweep({0, 0}, {0, 0}, Real(7.0), Real(7.5));
    turned.Normalize();
    CHECK(turned.a0 == Approx(7.0 - 2 * kPi).epsilon(1e-5));
    CHECK(turned.a - turned.a0 == Approx(0.5).epsilon(1e-5));
}

TEST_CASE("TimeOfImpact of a circle flying at a thin box", "[toi]")
{
    TOIInput input;
    Polygon wall = MakeBox(Real(0.1), 2);
    wall.radius = Real(0.01);
    input.proxyA = MakeProxy(wall);
    input.proxyB = MakeProxy(Circle{{0, 0}, Real(0.5)});
    input.sweepA = MakeSweep({0, 0}, {0, 0});
    input.sweepB = MakeSweep({-5, 0}, {5, 0});
    const TOIOutput out = TimeOfImpact(input);
    REQUIRE(out.state == TOIOutput::State::Touching);
    // The cores stop at target = radii − 3·slop = 0.495 apart: centre at x = −0.595.
    const double x = -5 + 10 * double(out.t);
    CHECK(x == Approx(-0.595).margin(0.25 * 0.005 + 1e-5));

    SECTION("a sweep that stops short is separated, t = tMax")
    {
        input.sweepB = MakeSweep({-5, 0}, {-1, 0});
        const TOIOutput apart = TimeOfImpact(input);
        CHECK(apart.state == TOIOutput::State::Separated);
        CHECK(apart.t == 1);
    }
    SECTION("a sweep that starts with the cores overlapping gives up")
    {
        input.sweepB = MakeSweep({0, 0}, {5, 0});
        const TOIOutput overlapped = TimeOfImpact(input);
        CHECK(overlapped.state == TOIOutput::State::Overlapped);
        CHECK(overlapped.t == 0);
    }
    SECTION("tMax bounds the search")
    {
        input.tMax = Real(0.3);
        const TOIOutput early = TimeOfImpact(input);
        CHECK(early.state == TOIOutput::State::Separated);
        CHECK(early.t == Real(0.3));
    }
}

TEST_CASE("TimeOfImpact of a spinning box against a segment", "[toi]")
{
    // A long thin box turning a quarter turn about its centre, 1 m above a segment: its end
    // sweeps down through the segment partway through the turn.
    TOIInput input;
    input.proxyA = MakeProxy(Segment{{-5, 0}, {5, 0}, Real(0.01)});
    Polygon bar = MakeBox(2, Real(0.1));
    bar.radius = Real(0.01);
    input.proxyB = MakeProxy(bar);
    input.sweepA = MakeSweep({0, 0}, {0, 0});
    input.sweepB = MakeSweep({0, 1}, {0, 1}, 0, kPi / 2);
    const TOIOutput out = TimeOfImpact(input);
    REQUIRE(out.state == TOIOutput::State::Touching);
    // At the impact the bar's lowest corner is `target` above the segment's core.
    const Transform xf = input.sweepB.GetTransform(out.t);
    Real lowest = kMaxReal;
    for (int i = 0; i < bar.count; ++i)
    {
        lowest = Min(lowest, Mul(xf, bar.vertices[i]).y);
    }
    CHECK(lowest == Approx(0.02 - 3 * 0.005).margin(0.25 * 0.005 + 1e-5));
    CHECK(out.t > 0);
    CHECK(out.t < Real(0.5));
}

#ifndef MEFF_DOUBLE

namespace
{

using meff::test::Random;

using meff::test::ShapePair;

/// Random shapes at this test's sizes (see box2d_shape_pair.h).
ShapePair RandomShape(Random& rng)
{
    return meff::test::RandomShape(rng, {0.3f, 0.02f, 0.8f, 0.8f});
}

struct SweepPair
{
    Sweep meff;
    b2Sweep box2d;
};

SweepPair RandomSweep(Random& rng, Vec2 c0, Vec2 c, float angleRange)
{
    SweepPair s;
    s.meff.localCenter = {rng.Uniform(-0.2f, 0.2f), rng.Uniform(-0.2f, 0.2f)};
    s.meff.c0 = c0;
    s.meff.c = c;
    s.meff.a0 = rng.Uniform(-angleRange, angleRange);
    s.meff.a = s.meff.a0 + rng.Uniform(-2, 2);
    s.meff.alpha0 = 0;
    s.box2d.localCenter.Set(s.meff.localCenter.x, s.meff.localCenter.y);
    s.box2d.c0.Set(c0.x, c0.y);
    s.box2d.c.Set(c.x, c.y);
    s.box2d.a0 = s.meff.a0;
    s.box2d.a = s.meff.a;
    s.box2d.alpha0 = 0;
    return s;
}

} // namespace

TEST_CASE("TimeOfImpact agrees bit for bit with Box2D 2.4.1's b2TimeOfImpact", "[toi][box2d]")
{
    Random rng(4242);
    int counts[5] = {0, 0, 0, 0, 0};
    for (int trial = 0; trial < 4000; ++trial)
    {
        const ShapePair a = RandomShape(rng);
        const ShapePair b = RandomShape(rng);
        // A drifts near the origin; B flies across it from a few metres away (some sweeps
        // miss, some start overlapping), with large start angles now and then.
        const Vec2 a0{rng.Uniform(-0.5f, 0.5f), rng.Uniform(-0.5f, 0.5f)};
        const Vec2 a1 = a0 + Vec2{rng.Uniform(-0.5f, 0.5f), rng.Uniform(-0.5f, 0.5f)};
        const float angle = rng.Uniform(0, 6.2831853f);
        const float distance = rng.Uniform(0.5f, 6);
        const Vec2 b0{distance * std::cos(angle), distance * std::sin(angle)};
        const Vec2 b1 =
            Vec2{rng.Uniform(-1.5f, 1.5f), rng.Uniform(-1.5f, 1.5f)} - rng.Uniform(0, 1) * b0;
        const float angleRange = rng.Index(4) == 0 ? 20.0f : 3.0f;
        const SweepPair sweepA = RandomSweep(rng, a0, a1, angleRange);
        const SweepPair sweepB = RandomSweep(rng, b0, b1, angleRange);
        const float tMax = rng.Index(4) == 0 ? rng.Uniform(0.2f, 1) : 1.0f;

        b2TOIInput b2Input;
        b2Input.proxyA.Set(a.box2d.get(), 0);
        b2Input.proxyB.Set(b.box2d.get(), 0);
        b2Input.sweepA = sweepA.box2d;
        b2Input.sweepB = sweepB.box2d;
        b2Input.tMax = tMax;
        b2TOIOutput b2Out;
        b2TimeOfImpact(&b2Out, &b2Input);

        TOIInput input;
        input.proxyA = a.proxy;
        input.proxyB = b.proxy;
        input.sweepA = sweepA.meff;
        input.sweepB = sweepB.meff;
        input.tMax = tMax;
        const TOIOutput out = TimeOfImpact(input);

        INFO("trial " << trial);
        REQUIRE(static_cast<int>(out.state) == static_cast<int>(b2Out.state));
        REQUIRE(out.t == b2Out.t);
        ++counts[static_cast<int>(out.state)];
    }
    INFO("unknown " << counts[0] << ", failed " << counts[1] << ", overlapped " << counts[2]
                    << ", touching " << counts[3] << ", separated " << counts[4]);
    CHECK(counts[3] > 1000); // touching
    CHECK(counts[4] > 300);  // separated
    CHECK(counts[2] > 50);   // overlapped
}

#endif // MEFF_DOUBLE
