// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The embedding tour (samples/embed/tour/) keeps its promises: each stop is run and what a game
// would observe is checked against what the feature guarantees. Built with the samples, as
// meff_tour_tests, when the tests are built too.
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>

#include "tour.h"

#include <cmath>

using namespace meff;

TEST_CASE("tour: the one-way platform lets the box up through it and holds it on top", "[tour]")
{
    const tour::OneWayPlatformResult r = tour::RunOneWayPlatform();
    // Thrown at 10 m/s from the ground, the box's bottom would reach v²/2g = 5 m: it must pass
    // well above the platform's top (3.25 m), having risen through it for several steps.
    CHECK(r.highestY > r.platformTop + 1);
    CHECK(r.stepsBelowTopRising >= 2);
    // Then it rests on the platform, not on the ground (3 m lower). Resting polygons keep their
    // skins (0.01 m each) apart less the slop the solver leaves (0.005 m), so the box's bottom
    // settles 0.015 m above the platform's top; 1 mm covers the residual of the position pass.
    const Tolerances tolerances;
    const Real rest = r.platformTop + 2 * tolerances.polygonSkin - tolerances.linearSlop;
    CHECK(std::abs(r.finalBottomY - rest) < 1e-3f);
    CHECK(r.finalSpeed < 1e-3f); // at rest after 6 s
}

TEST_CASE("tour: the laser hits what the geometry says", "[tour]")
{
    const tour::RayCastResult r = tour::RunRayCast();
    // Exact geometry (ray casts ignore the polygon skin, as Box2D): the glass pane's left face
    // is x = −0.1, the ball's left edge x = 4 − 0.5; float rounding of one fraction·length
    // product is far below 1e-5 m at these sizes.
    CHECK(r.closestWithGlass.x == Approx(-0.1f).margin(1e-5));
    CHECK(r.closestWithGlass.y == Approx(1.0f).margin(1e-5));
    CHECK(r.closestThroughGlass.x == Approx(3.5f).margin(1e-5));
    CHECK(r.closestThroughGlass.y == Approx(1.0f).margin(1e-5));
    // Glass, ball and right wall lie on the ray; skipping the glass leaves two.
    CHECK(r.hitsWithGlass == 3);
    CHECK(r.hitsThroughGlass == 2);
    // The room is closed: every ray of the sweep hits, and inside the walls' inner faces.
    REQUIRE(static_cast<int>(r.sweepPoints.size()) == r.sweepRays);
    for (const Vec2 p : r.sweepPoints)
    {
        CHECK(p.x >= -9.5f - 1e-4f);
        CHECK(p.x <= 9.5f + 1e-4f);
        CHECK(p.y >= -1e-4f);
        CHECK(p.y <= 10 + 1e-4f);
    }
}

TEST_CASE("tour: the car sits on its springs as m·g/k says and drives over the bump", "[tour]")
{
    const tour::CarResult r = tour::RunCar();
    // A soft constraint at rest holds C = F/k exactly (its accumulated impulse is k·C·h each
    // step); what remains is the damped rebound after 2 s at ζ = 0.7 (e^(−ζωt) ≈ 1e-15) and
    // float rounding, so 1% is generous.
    CHECK(r.restSag == Approx(r.expectedSag).epsilon(0.01));
    // At 15 rad/s a 0.4 m wheel would roll 6 m/s; in 4 s the car must cover the 12 m to the
    // bump and cross it, without flipping or dropping the chassis to the ground.
    CHECK(r.distance > 15);
    CHECK(r.largestTilt < 0.5f);
    CHECK(r.lowestChassisY > 0.4f);
}

TEST_CASE("tour: rollback replays bit-identically and sees a different input", "[tour]")
{
    const tour::RollbackResult r = tour::RunRollback();
    CHECK(r.replayedSteps == 60);
    CHECK(r.replayMatches);
    CHECK(r.differentInputDiffers);
}
