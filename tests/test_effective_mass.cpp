// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Oracle 1: the effective mass at an offset point (shared/seed/effective-mass.md),
//   m_eff⁻¹ = m⁻¹ + I⁻¹ (r × n)²,
// checked through the public API: an impulse P along n applied at the world point c + r of a
// free body changes the velocity of that material point along n by exactly P·m_eff⁻¹.
#include "analytic_support.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace meff;
using namespace meff::analytic;

namespace
{

struct OffsetCase
{
    Vec2 n; ///< impulse direction (unit)
    Vec2 r; ///< application point minus centre of mass, world frame (m)
};

// Directions and lever arms chosen so that (r × n)²/I ranges from 0 (through the centre) to
// several times 1/m: the rotational term is not a small correction.
const OffsetCase kCases[] = {
    {{1, 0}, {0, 0}},                                    // through the centre: m_eff = m
    {{1, 0}, {Real(-0.4), 0}},                           // r ∥ n: still m_eff = m
    {{1, 0}, {0, Real(0.3)}},                            // r ⟂ n on the short side
    {{0, 1}, {Real(0.8), 0}},                            // r ⟂ n on the long side
    {{0, -1}, {Real(-0.8), Real(0.3)}},                  // a corner
    {{Real(0.6), Real(-0.8)}, {Real(-0.5), Real(0.25)}}, // oblique
    {{Real(-0.28), Real(0.96)}, {Real(0.7), Real(-0.2)}},
};

} // namespace

TEST_CASE("Effective mass: an offset impulse changes the point's normal velocity by "
          "P(1/m + (r x n)^2/I)",
          "[analytic][effective-mass]")
{
    // The body's orientation must not matter: r and n are world vectors.
    const Real angle = GENERATE(Real(0), Real(0.7));
    World world = MakeWorld({0, 0});
    const Real hx = Real(0.8), hy = Real(0.3), density = Real(2.5);
    const BodyId box =
        AddBox(world, BodyType::Dynamic, {1, 2}, angle, hx, hy, Material(density, 0));

    const double m = world.GetMass(box);
    const double I = world.GetRotationalInertia(box);
    // A uniform box: m = ρ·4·hx·hy, I = m(w² + h²)/12 = m(hx² + hy²)/3 about its centre. The
    // polygon mass routine sums triangles and shifts the inertia from a vertex to the centroid
    // (a cancellation of ~4×), so a few dozen roundings: kRoundoff.
    REQUIRE(m == Approx(double(density) * 4 * hx * hy).epsilon(kRoundoff));
    REQUIRE(I == Approx(m * (double(hx) * hx + double(hy) * hy) / 3).epsilon(kRoundoff));

    const Real P = Real(1.7); // N·s
    for (const OffsetCase& c : kCases)
    {
        CAPTURE(c.n.x, c.n.y, c.r.x, c.r.y);
        world.SetLinearVelocity(box, {0, 0});
        world.SetAngularVelocity(box, 0);
        const Vec2 center = world.GetWorldCenter(box);
        world.ApplyLinearImpulse(box, P * c.n, center + c.r);

        const Vec2 v = world.GetLinearVelocity(box);
        const Real w = world.GetAngularVelocity(box);
        // Velocity of the material point at r: v + ω × r.
        const double vpx = double(v.x) - double(w) * c.r.y;
        const double vpy = double(v.y) + double(w) * c.r.x;
        const double dvn = vpx * c.n.x + vpy * c.n.y;

        const double rxn = double(c.r.x) * c.n.y - double(c.r.y) * c.n.x;
        const double invMeff = 1 / m + rxn * rxn / I; // the seed's m_eff⁻¹
        // Scale of the terms that are rounded: |P|/m and |P|·|r|²/I.
        const double scale = P * (1 / m + (double(c.r.x) * c.r.x + double(c.r.y) * c.r.y) / I);
        // Velocities are each one multiply-add of float values (v += P/m·n, ω += (r×P)/I):
        // rounding only, kRoundoff of the largest term.
        CHECK(dvn == Approx(P * invMeff).margin(kRoundoff * scale));
        // The split behind it: linear part P·n/m, angular part (r × P·n)/I.
        CHECK(v.x == Approx(P * c.n.x / m).margin(kRoundoff * scale));
        CHECK(v.y == Approx(P * c.n.y / m).margin(kRoundoff * scale));
        CHECK(w == Approx(P * rxn / I).margin(kRoundoff * scale));
    }
}

TEST_CASE("Effective mass: the impulse m_eff * u stops a point's normal motion (the contact "
          "solver's principle)",
          "[analytic][effective-mass]")
{
    World world = MakeWorld({0, 0});
    const BodyId box =
        AddBox(world, BodyType::Dynamic, {-1, 3}, Real(0.3), Real(0.6), Real(0.4), Material(3, 0));
    world.SetLinearVelocity(box, {Real(1.5), Real(-2)});
    world.SetAngularVelocity(box, Real(2.5));
    const double m = world.GetMass(box);
    const double I = world.GetRotationalInertia(box);

    const Vec2 r{Real(0.5), Real(-0.45)};
    const Vec2 n{Real(0.8), Real(0.6)};
    const Vec2 v0 = world.GetLinearVelocity(box);
    const Real w0 = world.GetAngularVelocity(box);
    const double u =
        (double(v0.x) - double(w0) * r.y) * n.x + (double(v0.y) + double(w0) * r.x) * n.y;
    REQUIRE(std::abs(u) > 1); // the point really moves along n

    const double rxn = double(r.x) * n.y - double(r.y) * n.x;
    const double meff = 1 / (1 / m + rxn * rxn / I);
    const Real P = Real(-meff * u);
    world.ApplyLinearImpulse(box, P * n, world.GetWorldCenter(box) + r);

    const Vec2 v = world.GetLinearVelocity(box);
    const Real w = world.GetAngularVelocity(box);
    const double un = (double(v.x) - double(w) * r.y) * n.x + (double(v.y) + double(w) * r.x) * n.y;
    // Zero up to the rounding of velocities of size |v0| + |ω0|·|r| (≈ 3.7 m/s here).
    const double scale = std::abs(double(v0.x)) + std::abs(double(v0.y)) +
                         std::abs(double(w0)) * (std::abs(double(r.x)) + std::abs(double(r.y)));
    CHECK(un == Approx(0).margin(kRoundoff * scale));
    // The tangential motion of the point is changed too, unless r ∥ n (it is not here) —
    // that coupling is why a contact needs the full effective mass, not 1/m.
}

TEST_CASE("Effective mass: a free body keeps its velocities through a step without gravity",
          "[analytic][effective-mass]")
{
    World world = MakeWorld({0, 0});
    const BodyId box =
        AddBox(world, BodyType::Dynamic, {0, 0}, 0, Real(0.8), Real(0.3), Material(2, 0));
    world.ApplyLinearImpulse(box, {Real(1.2), Real(-0.7)}, {Real(0.3), Real(0.2)});
    const Vec2 v = world.GetLinearVelocity(box);
    const Real w = world.GetAngularVelocity(box);
    for (int i = 0; i < 10; ++i)
    {
        world.Step(kDt);
    }
    // Zero gravity and no damping: v += h·0 and v *= 1/(1 + h·0) = 1 are exact in floating
    // point, so the velocities must be bit-identical.
    CHECK(world.GetLinearVelocity(box).x == v.x);
    CHECK(world.GetLinearVelocity(box).y == v.y);
    CHECK(world.GetAngularVelocity(box) == w);
}
