// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Oracle 6: a box on a static ramp of angle θ with Coulomb friction μ (restitution 0).
//   tan θ > μ: it slides with a = g (sin θ − μ cos θ);
//   tan θ < μ: it stays put.
// Both shapes get the same μ, since friction mixes as √(μA·μB).
#include "analytic_support.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace meff;
using namespace meff::analytic;

namespace
{

struct Ramp
{
    World world = MakeWorld({0, -10});
    BodyId box;
    Vec2 t; ///< unit vector up the ramp
    Vec2 n; ///< unit normal of the ramp's surface, out of it

    Ramp(double thetaDeg, Real mu, Real s0)
    {
        const double theta = thetaDeg * kPiD / 180;
        t = {Real(std::cos(theta)), Real(std::sin(theta))};
        n = {-t.y, t.x};
        const ShapeDef material = Material(1, mu, 0);
        // The ramp: a static 16 × 0.5 slab turned by θ about the origin; its top face is the
        // line through 0.25·n along t.
        const Real rampHalfThickness = Real(0.25);
        AddBox(world, BodyType::Static, {0, 0}, Real(theta), 8, rampHalfThickness, material);
        // A 0.5 × 0.5 box at distance s0 up the ramp, turned to lie flat on it, resting with
        // the solver's equilibrium gap: the two 0.01 m skins overlapping by the 0.005 m slop,
        // so there is nothing for the position solver to push apart.
        const Tolerances& tol = world.GetTolerances();
        const Real half = Real(0.25);
        const Real gap = 2 * tol.polygonSkin - tol.linearSlop;
        const Real up = rampHalfThickness + gap + half;
        box = AddBox(world, BodyType::Dynamic, s0 * t + up * n, Real(theta), half, half, material);
    }

    double S() const
    {
        return double(world.GetPosition(box).x) * t.x + double(world.GetPosition(box).y) * t.y;
    }
    double Vs() const
    {
        const Vec2 v = world.GetLinearVelocity(box);
        return double(v.x) * t.x + double(v.y) * t.y;
    }
    double Vn() const
    {
        const Vec2 v = world.GetLinearVelocity(box);
        return double(v.x) * n.x + double(v.y) * n.y;
    }
};

} // namespace

TEST_CASE("Box on a ramp with tan(theta) > mu slides with a = g(sin(theta) - mu cos(theta))",
          "[analytic][friction][ramp]")
{
    struct Case
    {
        double thetaDeg;
        Real mu;
    };
    // tan 30° = 0.577: well above μ = 0.2 (a = 3.27 m/s²) and just above μ = 0.5 (0.67 m/s²);
    // tan 45° = 1 vs μ = 0.3 (a = 4.95 m/s²).
    const Case c = GENERATE(Case{30, Real(0.2)}, Case{30, Real(0.5)}, Case{45, Real(0.3)});
    CAPTURE(c.thetaDeg, c.mu);
    const double g = 10;
    const double theta = c.thetaDeg * kPiD / 180;
    const double a = g * (std::sin(theta) - c.mu * std::cos(theta)); // down the ramp

    Ramp ramp(c.thetaDeg, c.mu, 5);
    // Let the contact settle (warm-started normal impulses reach m·g·cos θ·dt) for 0.25 s.
    for (int i = 0; i < 15; ++i)
    {
        ramp.world.Step(kDt);
    }
    const double s1 = ramp.S(), v1 = ramp.Vs();
    REQUIRE(v1 < 0);  // sliding has started (down the ramp)
    const int N = 60; // 1 s more: the box slides ≤ 4 m, staying on the 8 m half-ramp
    for (int i = 0; i < N; ++i)
    {
        ramp.world.Step(kDt);
    }
    const double T = N * double(kDt);
    const double v2 = ramp.Vs(), s2 = ramp.S();

    // Each step of steady sliding: gravity adds g·dt, the normal row cancels the normal part
    // exactly (impulse m g cos θ dt, shared by the two points and solved as a block), and each
    // point's friction row saturates at μ·λn. So the velocity changes by exactly −a·dt per step
    // once the warm-started impulses have converged. What is left: the friction rows' iteration
    // residual (they see the previous iteration's λn; converged after the settling steps) and
    // float rounding of a velocity of up to |v| ≈ 5 m/s, a few ulps (≈ 1e-6 m/s) per step,
    // ≤ 1e-4 m/s over 60 steps: below 1e-3 of the smallest a·T (0.67 m/s).
    // Tolerance 1e-3·a·T on the velocity change, 1e-3·a·T² on the displacement.
    INFO("acceleration measured " << -(v2 - v1) / T << " m/s^2, expected " << a);
    CHECK(v2 - v1 == Approx(-a * T).margin(1e-3 * a * T));
    // Displacement of semi-implicit Euler under constant a: Σ dt·(v1 − a·dt·k), k = 1..N,
    //   = v1 T − ½ a T² − ½ a T dt  (the last term is the scheme's O(dt) offset).
    const double ds = v1 * T - 0.5 * a * T * T - 0.5 * a * T * kDt;
    CHECK(s2 - s1 == Approx(ds).margin(1e-3 * a * T * T));
    // It slides flat: no normal velocity, no rotation (the block solver balances the torque of
    // friction by shifting the normal impulse between the two points).
    CHECK(std::abs(ramp.Vn()) <= 1e-3 * a * T);
    CHECK(std::abs(ramp.world.GetAngularVelocity(ramp.box)) <= 1e-3 * a * T / 0.25);
}

TEST_CASE("Box on a ramp with tan(theta) < mu stays put", "[analytic][friction][ramp]")
{
    struct Case
    {
        double thetaDeg;
        Real mu;
    };
    // tan 20° = 0.364 < 0.6; tan 25° = 0.466 < 0.5 (7% from slipping).
    const Case c = GENERATE(Case{20, Real(0.6)}, Case{25, Real(0.5)});
    CAPTURE(c.thetaDeg, c.mu);

    Ramp ramp(c.thetaDeg, c.mu, 2);
    const Vec2 start = ramp.world.GetPosition(ramp.box);
    double maxSlide = 0;
    for (int i = 0; i < 120; ++i) // 2 s
    {
        ramp.world.Step(kDt);
        const Vec2 p = ramp.world.GetPosition(ramp.box);
        const double slide = double(p.x - start.x) * ramp.t.x + double(p.y - start.y) * ramp.t.y;
        maxSlide = std::max(maxSlide, std::abs(slide));
    }
    // Static friction is a velocity constraint that holds exactly while |f| < μ·λn, so the only
    // tangential motion is the iteration residual of the first steps, before warm starting has
    // built the impulses up. Bound: 1 mm over 2 s, a fifth of the linear slop (the solver's own
    // length tolerance).
    INFO("largest slide along the ramp: " << maxSlide << " m");
    CHECK(maxSlide < 0.2 * ramp.world.GetTolerances().linearSlop);
    CHECK(std::abs(ramp.world.GetAngle(ramp.box) - Real(c.thetaDeg * kPiD / 180)) < 1e-3);
}
