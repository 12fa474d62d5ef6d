// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The exact answers of validation/include/meff/analytic.h that `meff sweep` and the tests
// compare the engines with: checked here against values worked out by hand, so that a slip in
// the one copy shows before it moves every error a sweep reports.
#include "meff/analytic.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace meff::analytic;

TEST_CASE("OnRod turns counter-clockwise from down", "[analytic][unit]")
{
    // Exact in double: cos and sin of 0 and the products with 0, ±1 and 2 are exact; at π/2
    // cos is 6.1e-17, so 1e-15 m is rounding.
    const Vec2d pivot{1, 2};
    const Vec2d down{0, -1};
    const Vec2d hanging = OnRod(pivot, down, 2, 0);
    CHECK(hanging.x == 1);
    CHECK(hanging.y == 0);
    const Vec2d quarter = OnRod(pivot, down, 2, std::acos(-1.0) / 2);
    CHECK(quarter.x == Approx(3).margin(1e-15));
    CHECK(quarter.y == Approx(2).margin(1e-15));
}

TEST_CASE("An ideal cradle swings its first ball, then its last", "[analytic][unit]")
{
    // Released at ψ0 = −0.5 rad: on the first ball's side only the first ball moves.
    const double psi0 = -0.5;
    CHECK(CradleBallAngle(0, 3, psi0, -0.3) == -0.3);
    CHECK(CradleBallAngle(1, 3, psi0, -0.3) == 0);
    CHECK(CradleBallAngle(2, 3, psi0, -0.3) == 0);
    // At the bottom the first ball has just arrived; past it the last ball swings out.
    CHECK(CradleBallAngle(0, 3, psi0, 0) == 0);
    CHECK(CradleBallAngle(0, 3, psi0, 0.2) == 0);
    CHECK(CradleBallAngle(1, 3, psi0, 0.2) == 0);
    CHECK(CradleBallAngle(2, 3, psi0, 0.2) == 0.2);
}

TEST_CASE("A dropped ball rebounds to e² of each height until the threshold", "[analytic][unit]")
{
    // Dropped from rest 1 m above its touching height 0.1 m, g = 10 m/s², e = 0.5: it arrives
    // at √20 = 4.47 m/s and leaves at 2.24, 1.12, 0.56 m/s; the last is below the threshold of
    // 1 m/s, so three rebounds, of e², e⁴ and e⁶ metres. Relative 1e-12: a few roundings of
    // √ and squares in double.
    const double e = 0.5;
    const std::vector<double> apexes = BounceApexes(e, 1, 10, 1.1, 0, 0.1, 10);
    REQUIRE(apexes.size() == 3);
    CHECK(apexes[0] == Approx(0.1 + 0.25).epsilon(1e-12));
    CHECK(apexes[1] == Approx(0.1 + 0.0625).epsilon(1e-12));
    CHECK(apexes[2] == Approx(0.1 + 0.015625).epsilon(1e-12));
    // The first top comes at √0.2 + 0.2236 = 0.671 s: a shorter run reaches none.
    CHECK(BounceApexes(e, 1, 10, 1.1, 0, 0.1, 0.6).empty());
    // No threshold and no restitution: one rebound of height 0, not an endless list.
    const std::vector<double> dead = BounceApexes(0, 0, 10, 1.1, 0, 0.1, 10);
    REQUIRE(dead.size() == 1);
    CHECK(dead[0] == 0.1);
}

TEST_CASE("A small swing of the exact pendulum keeps its period", "[analytic][unit]")
{
    // k = 4 /s², so ω = 2 rad/s and the small-swing period is π s; at ψ0 = 0.01 rad the true
    // period is longer by the fraction ψ0²/16 = 6e-6, which moves the angle at the quarter,
    // half and whole period by at most ψ0·ω·T·6e-6 = 4e-7 rad, and the speed by a relative 6e-6:
    // margins of 1e-6 rad and 1e-4 hold that. RK4 at 0.8 ms steps adds ~1e-13.
    const double pi = std::acos(-1.0);
    const double psi0 = 0.01;
    const int samples = 4;
    const PendulumMotion motion(4, psi0, 0, pi / samples, 1000, samples);
    CHECK(motion.Angle(0) == psi0);
    CHECK(std::abs(motion.Angle(1)) < 1e-6);
    CHECK(motion.Angle(2) == Approx(-psi0).margin(1e-6));
    CHECK(motion.Angle(4) == Approx(psi0).margin(1e-6));
    CHECK(motion.AngularVelocity(1) == Approx(-2 * psi0).epsilon(1e-4));
}
