// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Oracles 3, 4 and 8: pinned bodies and pendulums.
//   3. A rod pinned at one end, released horizontally: α = 3g/(2L) and a pin reaction of
//      m·g/4 upward on the first step.
//   4. A body pinned off its centre, spinning without gravity: the pin pulls with the
//      centripetal force m·ω²·d; ω is constant up to the velocity-level constraint's known
//      O((ω·dt)²) energy loss per step.
//   8. A rigid distance-joint pendulum: period 2π√(L/g) for small amplitudes.
#include "analytic_support.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace meff;
using namespace meff::analytic;

TEST_CASE("Rod pinned at one end, released horizontally: alpha = 3g/(2L), pin reaction mg/4 up",
          "[analytic][joint][pendulum]")
{
    // Solving the point constraint as a 2×2 block or as two scalar rows must agree here: with
    // the rod horizontal the lever arm rB = (−L/2, 0) makes K diagonal.
    const bool blockJoints = GENERATE(true, false);
    CAPTURE(blockJoints);
    WorldDef def;
    def.gravity = {0, -10};
    def.solver.blockJoints = blockJoints;
    World world{def};
    const double g = 10;

    const Real L = 2, thickness = Real(0.04); // hx = 1, hy = 0.02: a thin rod
    const Real hx = L / 2, hy = thickness / 2;
    const BodyId ground = AddAnchor(world, {0, 0});
    const BodyId rod = AddBox(world, BodyType::Dynamic, {hx, 0}, 0, hx, hy, Material(5, 0));
    const JointId pin = world.CreateJoint(world.MakeRevoluteJointDef(ground, rod, {0, 0}));
    REQUIRE(world.GetBodyB(pin) == rod);

    const double m = world.GetMass(rod);
    const double Ic = world.GetRotationalInertia(rod);
    REQUIRE(Ic == Approx(m * (double(hx) * hx + double(hy) * hy) / 3).epsilon(kRoundoff));

    world.Step(kDt);

    // Exact rigid-body values for this box (thickness included): about the pin,
    //   I_pin = Ic + m·hx², α = m·g·hx / I_pin;
    // Newton for the centre, a_c = α × r_c = (0, −α·hx), gives the pin force on the rod
    //   F = m(a_c − g) = (0, m·g·Ic/I_pin) = (0, g·m_eff),  m_eff = 1/(1/m + hx²/Ic),
    // the seed's effective mass of the rod at its end. For a thin rod (hy → 0) α → 3g/(2L)
    // and F → m·g/4.
    const double Ipin = Ic + m * hx * hx;
    const double alpha = m * g * hx / Ipin;
    const double meff = 1 / (1 / m + double(hx) * hx / Ic);
    const double force = g * meff;

    // Why the first step is exact: the step is semi-implicit Euler, v1 = v0 + h·g then the
    // velocity constraint J·v1 = 0 solved exactly (one joint, no other constraint: the block
    // solve, or two decoupled scalar rows, are exact and later iterations add nothing). With
    // v0 = 0 there is no centripetal term, so J·v1 = 0 is the same linear system as J·a = 0 for
    // the true acceleration: ω1 = h·α and the impulse is h·F, both exactly (up to rounding).
    const double omega = world.GetAngularVelocity(rod);
    CHECK(-omega / kDt == Approx(alpha).epsilon(kRoundoff)); // clockwise: the free end falls
    const JointReaction reaction = world.GetReaction(pin, 1 / kDt);
    CHECK(reaction.force.x == Approx(0).margin(kRoundoff * force));
    CHECK(reaction.force.y == Approx(force).epsilon(kRoundoff)); // on the rod, upward
    CHECK(reaction.torque == Approx(0).margin(kRoundoff * force * L));

    // The thin-rod textbook values, within this rod's thickness correction: exactly,
    //   α/α_thin = 4hx²/(4hx² + hy²)            ≈ 1 − hy²/(4hx²)   (−1e-4 here),
    //   F/F_thin = 4(hx² + hy²)/(4hx² + hy²)    ≈ 1 + 3hy²/(4hx²)  (+3e-4 here).
    const double thick = double(hy) * hy / (4 * double(hx) * hx);
    CHECK(-omega / kDt == Approx(3 * g / (2 * L)).epsilon(thick + kRoundoff));
    CHECK(reaction.force.y == Approx(m * g / 4).epsilon(3 * thick + kRoundoff));
}

namespace
{

/// A 1 × 0.5 box (density 1) whose centre is d = 0.6 m from a pin at the origin (a 3-4-5
/// offset, so not along an axis), spinning about the pin at ω0 = 2 rad/s without gravity.
struct SpinningBody
{
    static constexpr double d = 0.6;
    static constexpr Real w0 = 2;
    World world = MakeWorld({0, 0});
    BodyId body;
    JointId pin;
    double m = 0, Ic = 0, Ipin = 0;

    SpinningBody()
    {
        const BodyId ground = AddAnchor(world, {0, 0});
        const Vec2 c0{Real(0.48), Real(0.36)};
        body =
            AddBox(world, BodyType::Dynamic, c0, Real(0.3), Real(0.5), Real(0.25), Material(1, 0));
        pin = world.CreateJoint(world.MakeRevoluteJointDef(ground, body, {0, 0}));
        m = world.GetMass(body);
        Ic = world.GetRotationalInertia(body);
        Ipin = Ic + m * d * d;
        // Start in a consistent rigid rotation about the pin: v = ω × (c − pin).
        world.SetAngularVelocity(body, w0);
        world.SetLinearVelocity(body, Cross(w0, c0));
    }

    // The known approximation, Box2D's "slow energy loss of spinning pinned bodies": the joint
    // is a velocity constraint at the start-of-step pose. Over a step the body turns by
    // θ = ω·dt; at the new pose its velocity (tangent at the old pose) has a radial part that
    // the pin impulse removes. That impulse passes through the pin, so it keeps the angular
    // momentum about the pin, I_c·ω + m (c − pin) × v = (I_c + m d² cos θ)·ω, leaving
    // ω' = ω (I_c + m d² cos θ)/I_pin: a relative loss per step of
    //   δ(ω) = (m d²/I_pin)(1 − cos(ω·dt)) ≈ (m d²/I_pin)(ω·dt)²/2     (4.3e-4 at 60 Hz).
    // The first step loses nothing: the body starts consistent with the constraint at its
    // pose. So the loss over a time T is ≈ T·(m d²/I_pin)·ω²·dt/2: first order in dt.
    // The model's neglected terms: the position solver pulls the centre back to the circle
    // along a slightly different line than the rotation assumed (cos θ becomes 1/√(1 + θ²)
    // to that order), a relative difference of (2/3)θ² in δ. Tolerance θ² relative.
    double ModelLoss(double dt, int steps) const
    {
        const double ratio = m * d * d / Ipin;
        double w = w0;
        for (int i = 1; i < steps; ++i) // steps − 1 lossy steps
        {
            w *= 1 - ratio * (1 - std::cos(w * dt));
        }
        return 1 - w / w0;
    }
};

} // namespace

TEST_CASE("Body pinned off its centre spinning without gravity: reaction m w^2 d, w constant "
          "up to the known O(dt) loss",
          "[analytic][joint]")
{
    SpinningBody s;
    World& world = s.world;
    const double d = SpinningBody::d;
    double wPrev = SpinningBody::w0;
    const int steps = 300; // 5 s, ~1.6 turns
    for (int i = 1; i <= steps; ++i)
    {
        const Vec2 cBefore = world.GetWorldCenter(s.body);
        world.Step(kDt);
        const double w = world.GetAngularVelocity(s.body);
        const JointReaction reaction = world.GetReaction(s.pin, 1 / kDt);
        const double F = std::hypot(double(reaction.force.x), double(reaction.force.y));
        const double theta = wPrev * kDt;
        const double expectedF = s.m * wPrev * wPrev * d;
        INFO("step " << i << ": omega " << w << " rad/s, |F| " << F << " N, m w^2 d " << expectedF
                     << " N");
        if (i == 1)
        {
            // The start is consistent with the constraint: nothing to correct, up to rounding
            // of the momentum m·ω·d.
            CHECK(F <= kRoundoff * s.m * wPrev * d / kDt);
        }
        else
        {
            // Centripetal reaction. The step's impulse is m·(v' − v), v turned by θ = ω·dt:
            // |F| = m·ω·d·2 sin(θ/2)/dt = m ω² d (1 − θ²/24), times the ratio of the speeds
            // after and before (1 − δ, δ ≈ 0.39 θ²), plus a tangential part of relative size
            // δ/θ that adds O(θ²) to the magnitude: all below θ² relative (1.1e-3 at 60 Hz).
            CHECK(F == Approx(expectedF).epsilon(theta * theta));
            // It points at the pin from the centre at the step's start, within θ (the impulse
            // bisects the turn between the step's start and the previous step's, θ/2 away).
            const double cosAngle =
                -(double(reaction.force.x) * cBefore.x + double(reaction.force.y) * cBefore.y) /
                (F * std::hypot(double(cBefore.x), double(cBefore.y)));
            CHECK(cosAngle >= std::cos(theta));
        }
        // No torque: the pin is a point constraint without motor or limit.
        CHECK(reaction.torque == Approx(0).margin(kRoundoff * expectedF * d));
        // ω never grows (the projection only removes energy), up to rounding.
        CHECK(w <= wPrev * (1 + kRoundoff));
        wPrev = w;
        // The body stays pinned: its anchor stays within the linear slop of the pin.
        const Vec2 anchor = world.GetAnchorB(s.pin);
        CHECK(std::hypot(double(anchor.x), double(anchor.y)) <= world.GetTolerances().linearSlop);
    }
    // ω after 5 s: down by ≈ 11% at 60 Hz, exactly as the model of the known loss says
    // (tolerance θ² relative, see SpinningBody::ModelLoss).
    const double loss = 1 - world.GetAngularVelocity(s.body) / SpinningBody::w0;
    const double model = s.ModelLoss(kDt, steps);
    const double theta = SpinningBody::w0 * kDt;
    INFO("loss of omega after 5 s: " << loss << ", model " << model);
    CHECK(loss == Approx(model).epsilon(theta * theta));
}

TEST_CASE("Spinning pinned body: the angular-velocity loss follows the model and vanishes "
          "linearly in dt",
          "[analytic][joint]")
{
    // 2 s at 60, 120 and 240 Hz. The loss over a fixed time is first order in dt (about
    // 4.8%, 2.5% and 1.3% here), so ω is constant in the limit dt → 0, and at every rate it is
    // the model's (tolerance θ² relative, θ = ω0·dt).
    const int rate = GENERATE(60, 120, 240);
    CAPTURE(rate);
    SpinningBody s;
    const Real dt = Real(1.0 / rate);
    const int steps = 2 * rate;
    for (int i = 0; i < steps; ++i)
    {
        s.world.Step(dt);
    }
    const double loss = 1 - s.world.GetAngularVelocity(s.body) / SpinningBody::w0;
    const double model = s.ModelLoss(dt, steps);
    const double theta = SpinningBody::w0 * double(dt);
    INFO("loss of omega over 2 s: " << loss << ", model " << model);
    CHECK(loss == Approx(model).epsilon(theta * theta));
    // First order: loss ≈ T·(m d²/I_pin)·ω0²·dt/2, the same loss·rate at every rate, up to the
    // loss lowering ω² itself (by ~2·loss at the end, ~loss on average: relative ≤ 2·loss)
    // and the lossless first step (relative 1/steps).
    const double firstOrder = 2 * (s.m * SpinningBody::d * SpinningBody::d / s.Ipin) *
                              double(SpinningBody::w0) * SpinningBody::w0 * double(dt) / 2;
    CHECK(loss == Approx(firstOrder).epsilon(2 * firstOrder + 1.0 / steps));
}

TEST_CASE("Rigid distance-joint pendulum: period 2 pi sqrt(L/g) at small amplitude",
          "[analytic][joint][pendulum]")
{
    World world = MakeWorld({0, -10});
    const double g = 10;
    const double L = 1;
    const double theta0 = 0.1; // rad (5.7°)
    const BodyId pivot = AddAnchor(world, {0, 0});
    // A small circle bob hung from its centre: the joint's lever arm on the bob is zero, so
    // the bob's rotation decouples and it is a point mass.
    const Vec2 bobStart{Real(L * std::sin(theta0)), Real(-L * std::cos(theta0))};
    const BodyId bob = AddBall(world, bobStart, {0, 0}, Real(0.05), Material(1, 0));
    DistanceJointDef def = world.MakeDistanceJointDef(pivot, bob, {0, 0}, bobStart);
    REQUIRE(def.length == Approx(L).epsilon(kRoundoff));
    def.minLength = def.length; // a rigid rod: min = max = length, no spring
    def.maxLength = def.length;
    def.hertz = 0;
    world.CreateJoint(def);

    // Upward zero crossings of x, located by linear interpolation between steps (at a crossing
    // x'' = −(g/L)·x = 0, so the interpolation error is O(dt³) in time, negligible).
    std::vector<double> crossings;
    double xPrev = bobStart.x;
    const int steps = 12 * 60; // 12 s, 6 periods
    double maxLengthError = 0;
    for (int i = 1; i <= steps; ++i)
    {
        world.Step(kDt);
        const Vec2 p = world.GetPosition(bob);
        maxLengthError =
            std::max(maxLengthError, std::abs(std::hypot(double(p.x), double(p.y)) - L));
        if (xPrev < 0 && p.x >= 0)
        {
            const double f = -xPrev / (p.x - xPrev);
            crossings.push_back((i - 1 + f) * double(kDt));
        }
        xPrev = p.x;
    }
    REQUIRE(crossings.size() >= 5);
    const double period = (crossings.back() - crossings.front()) / double(crossings.size() - 1);

    // Expected: the small-angle period with the finite-amplitude correction,
    //   T = 2π√(L/g)·(1 + θ0²/16 + 11θ0⁴/3072)          (+6.3e-4 at θ0 = 0.1),
    // and the step's own, known, period error: the step is semi-implicit Euler (v += h·a, then
    // x += h·v) with the bob projected back onto the circle; for a linear oscillator of
    // frequency Ω that scheme has cos(Ω_h·dt) = 1 − Ω²dt²/2, so Ω_h = Ω(1 + Ω²dt²/24 + O(dt⁴))
    // and the period is shorter by the factor (1 − Ω²dt²/24)      (−1.16e-4 here).
    // Left out: the amplitude lost to the velocity-level constraint (< 0.5% of θ0 over the run,
    // moving the θ0²/16 term by < 3e-6), O(Ω⁴dt⁴) ≈ 1e-8, and the crossing interpolation
    // (≤ Ω²dt³/8 ≈ 6e-6 s per crossing, averaged over 5 periods: < 1e-6 relative).
    // Tolerance 2e-5 relative: five times the sum of those (4e-6).
    const double Omega2 = g / L;
    const double T0 = 2 * kPiD * std::sqrt(L / g);
    const double amplitudeFactor = 1 + theta0 * theta0 / 16 + 11 * std::pow(theta0, 4) / 3072;
    const double stepFactor = 1 - Omega2 * double(kDt) * kDt / 24;
    const double expected = T0 * amplitudeFactor * stepFactor;
    INFO("period " << period << " s, expected " << expected << " s (small-angle " << T0
                   << " s, with amplitude " << T0 * amplitudeFactor << " s)");
    CHECK(period == Approx(expected).epsilon(2e-5));
    // And so the textbook 2π√(L/g) itself holds within the two corrections: θ0²/16 + Ω²dt²/24.
    CHECK(period ==
          Approx(T0).epsilon(theta0 * theta0 / 16 + Omega2 * double(kDt) * kDt / 24 + 2e-5));
    // Rigid: the position step projects the bob back onto the circle (C = |d| − L, impulse
    // −m·C, no Baumgarte): the length stays within the linear slop.
    CHECK(maxLengthError <= world.GetTolerances().linearSlop);
}
