// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Oracles 2 and 5: collision impulses from the seed (shared/seed/effective-mass.md),
//   P = (1 + e)(u2 − u1)·m_red,   m_red⁻¹ = m1eff⁻¹ + m2eff⁻¹,   m_eff⁻¹ = m⁻¹ + I⁻¹(r × n)²,
// for head-on circles, for a circle striking a free box off its centre, and for a ball
// bouncing on static ground (rebound height e²·h).
//
// Solver facts used (Box2D 2.4.1, shared/notes/box2d-2.4.1-facts.md): a one-point manifold is
// solved exactly by the first velocity iteration (λ = −m_red(vn − bias) with the bias −e·vn0)
// and later iterations add nothing; restitution applies only when the approach speed exceeds
// the restitution threshold (1 m/s by default); the position solver moves positions but never
// velocities; a contact is narrow-phased at the start of a step, so it is solved in the first
// step that starts with the shapes overlapping (boxes are 0.01 m larger: the polygon skin).
#include "analytic_support.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>

using namespace meff;
using namespace meff::analytic;

namespace
{

/// Steps until `body`'s velocity differs from `v0` (the first step that solves a contact on a
/// body flying freely without gravity, whose velocity is otherwise bit-constant). Returns the
/// number of steps taken, or -1 if nothing happened within maxSteps.
int StepUntilVelocityChanges(World& world, BodyId body, Vec2 v0, int maxSteps)
{
    for (int i = 1; i <= maxSteps; ++i)
    {
        world.Step(kDt);
        if (world.GetLinearVelocity(body) != v0)
        {
            return i;
        }
    }
    return -1;
}

} // namespace

TEST_CASE("Head-on circles with mass ratio 1:3 exchange P = (1+e)(u2-u1) m_red",
          "[analytic][collision]")
{
    const Real e = GENERATE(Real(0), Real(0.5), Real(1));
    CAPTURE(e);
    World world = MakeWorld({0, 0});
    const Real radius = Real(0.5);
    const Real u1 = 4, u2 = -1; // approach speed 5 m/s, far above the 1 m/s threshold
    const BodyId b1 = AddBall(world, {-2, 0}, {u1, 0}, radius, Material(1, 0, e));
    const BodyId b2 = AddBall(world, {2, 0}, {u2, 0}, radius, Material(3, 0, e));
    const std::array<BodyId, 2> both{b1, b2};
    const double m1 = world.GetMass(b1), m2 = world.GetMass(b2);
    REQUIRE(m2 / m1 == Approx(3).epsilon(kRoundoff));

    const Momentum p0 = LinearMomentum(world, both);
    const double e0 = KineticEnergy(world, both);
    // Scales for the rounding bounds: momentum and speed magnitudes in play.
    const double pScale = m1 * std::abs(u1) + m2 * std::abs(u2);
    const double vScale = std::abs(u1) + std::abs(u2);

    const int impactStep = StepUntilVelocityChanges(world, b1, {u1, 0}, 240);
    REQUIRE(impactStep > 0);

    // The normal is exactly x (centres on y = 0): the seed's closed form with m_eff = m for
    // both (r ∥ n, no rotation).
    const double mRed = 1 / (1 / m1 + 1 / m2);
    const double P1 = (1 + e) * (u2 - u1) * mRed; // impulse on body 1 (negative: pushed back)
    const double v1 = u1 + P1 / m1;
    const double v2 = u2 - P1 / m2;
    {
        INFO("impact solved in step " << impactStep);
        // One contact point, solved exactly: rounding only.
        CHECK(world.GetLinearVelocity(b1).x == Approx(v1).margin(kRoundoff * vScale));
        CHECK(world.GetLinearVelocity(b2).x == Approx(v2).margin(kRoundoff * vScale));
        CHECK(world.GetLinearVelocity(b1).y == 0);
        CHECK(world.GetLinearVelocity(b2).y == 0);
        CHECK(world.GetAngularVelocity(b1) == 0);
        CHECK(world.GetAngularVelocity(b2) == 0);

        const Momentum p = LinearMomentum(world, both);
        CHECK(p.x == Approx(p0.x).margin(kRoundoff * pScale));
        CHECK(p.y == Approx(p0.y).margin(kRoundoff * pScale));
        // Energy lost: (1 − e²)·½·m_red·(u1 − u2)² (zero for e = 1).
        const double lost = (1 - double(e) * e) * 0.5 * mRed * (u1 - u2) * (u1 - u2);
        CHECK(KineticEnergy(world, both) == Approx(e0 - lost).margin(kRoundoff * e0));
    }

    // Later steps: while the circles still overlap, the contact is warm-started with the old
    // impulse and the solver takes it back (a separating or resting contact ends with λ = 0),
    // so the velocities stay the closed-form ones up to rounding. Each such step applies and
    // removes an impulse of size ≤ m_red·|u1 − u2| on each body: ≤ 4 roundings of velocities of
    // size vScale per step, hence the bound 4·kEps·vScale per step (momentum likewise).
    const int later = 120;
    for (int i = 0; i < later; ++i)
    {
        world.Step(kDt);
    }
    const double drift = 4 * kEps * later;
    CHECK(world.GetLinearVelocity(b1).x == Approx(v1).margin(drift * vScale));
    CHECK(world.GetLinearVelocity(b2).x == Approx(v2).margin(drift * vScale));
    const Momentum p = LinearMomentum(world, both);
    CHECK(p.x == Approx(p0.x).margin(drift * pScale));
    CHECK(p.y == Approx(p0.y).margin(drift * pScale));
}

TEST_CASE("Restitution needs an approach faster than the threshold (Box2D 2.4.1 rule)",
          "[analytic][collision]")
{
    // e = 1 but an approach of 0.6 m/s < restitutionThreshold (1 m/s): the contact is solved
    // as perfectly inelastic, both circles ending with the centre-of-mass velocity.
    World world = MakeWorld({0, 0});
    const Real u1 = Real(0.4), u2 = Real(-0.2);
    const BodyId b1 = AddBall(world, {-1, 0}, {u1, 0}, Real(0.5), Material(1, 0, 1));
    const BodyId b2 = AddBall(world, {1, 0}, {u2, 0}, Real(0.5), Material(3, 0, 1));
    const double m1 = world.GetMass(b1), m2 = world.GetMass(b2);
    const int impactStep = StepUntilVelocityChanges(world, b1, {u1, 0}, 240);
    REQUIRE(impactStep > 0);
    const double vcm = (m1 * u1 + m2 * u2) / (m1 + m2); // −0.05 m/s
    const double vScale = std::abs(u1) + std::abs(u2);
    CHECK(world.GetLinearVelocity(b1).x == Approx(vcm).margin(kRoundoff * vScale));
    CHECK(world.GetLinearVelocity(b2).x == Approx(vcm).margin(kRoundoff * vScale));
}

TEST_CASE("A circle striking a free box off its centre: m_red from both effective masses",
          "[analytic][collision][effective-mass]")
{
    const Real e = GENERATE(Real(0), Real(0.5), Real(1));
    // Height of the circle's path above the box's centre. The box's left face spans
    // |y| ≤ hy = 1, so the circle's centre stays in that face's region and the contact normal
    // is exactly ±x, with the contact point at the height d of the circle's centre.
    const Real d = GENERATE(Real(0), Real(0.45), Real(0.8));
    CAPTURE(e, d);

    World world = MakeWorld({0, 0});
    const Real hx = Real(0.5), hy = 1;
    const BodyId box = AddBox(world, BodyType::Dynamic, {0, 0}, 0, hx, hy, Material(1, 0, e));
    const Real u = 4; // m/s along +x
    const BodyId ball = AddBall(world, {-3, d}, {u, 0}, Real(0.25), Material(4, 0, e));
    const std::array<BodyId, 2> both{box, ball};

    const double mb = world.GetMass(box), Ib = world.GetRotationalInertia(box);
    const double mc = world.GetMass(ball);
    REQUIRE(mb == Approx(2).epsilon(kRoundoff));
    REQUIRE(Ib == Approx(2 * (0.25 + 1) / 3).epsilon(kRoundoff));

    // Angular momentum about the origin, Σ m (x·vy − y·vx) + I·ω, is conserved by any pair of
    // equal and opposite impulses at a common point. It is evaluated with the positions at the
    // start of the impact step (where the solver applied the impulses).
    const auto angularMomentum = [&](Vec2 cBox, Vec2 cBall)
    {
        const Vec2 vb = world.GetLinearVelocity(box), vc = world.GetLinearVelocity(ball);
        return mb * (double(cBox.x) * vb.y - double(cBox.y) * vb.x) +
               Ib * world.GetAngularVelocity(box) +
               mc * (double(cBall.x) * vc.y - double(cBall.y) * vc.x) +
               world.GetRotationalInertia(ball) * world.GetAngularVelocity(ball);
    };
    const double L0 = angularMomentum(world.GetWorldCenter(box), world.GetWorldCenter(ball));
    const Momentum p0 = LinearMomentum(world, both);

    Vec2 boxBefore, ballBefore;
    int impactStep = -1;
    for (int i = 1; i <= 240 && impactStep < 0; ++i)
    {
        boxBefore = world.GetWorldCenter(box);
        ballBefore = world.GetWorldCenter(ball);
        world.Step(kDt);
        if (world.GetLinearVelocity(ball) != Vec2{u, 0})
        {
            impactStep = i;
        }
    }
    REQUIRE(impactStep > 0);
    INFO("impact solved in step " << impactStep);
    // The box had not moved before the impact, so the lever arm is r = (−hx − skin, d): only
    // its y component enters r × n for n = x.
    REQUIRE(boxBefore.x == 0);
    REQUIRE(boxBefore.y == 0);

    const double invMeffBox = 1 / mb + double(d) * d / Ib; // (r × n)² = d²
    const double invMeffBall = 1 / mc;                     // r ∥ n through the centre
    const double mRed = 1 / (invMeffBox + invMeffBall);
    const double P = (1 + e) * u * mRed; // on the box, along +x
    const double vScale = u;

    // One contact point solved exactly: rounding only.
    CHECK(world.GetLinearVelocity(ball).x == Approx(u - P / mc).margin(kRoundoff * vScale));
    CHECK(world.GetLinearVelocity(ball).y == Approx(0).margin(kRoundoff * vScale));
    CHECK(world.GetAngularVelocity(ball) == Approx(0).margin(kRoundoff * vScale));
    CHECK(world.GetLinearVelocity(box).x == Approx(P / mb).margin(kRoundoff * vScale));
    CHECK(world.GetLinearVelocity(box).y == Approx(0).margin(kRoundoff * vScale));
    // The impulse acts above the centre (d > 0) pushing +x: a clockwise spin ω = −P·d/I.
    CHECK(world.GetAngularVelocity(box) == Approx(-P * d / Ib).margin(kRoundoff * vScale));

    // The contact point's normal velocities: separation at e·u.
    const double vPointBox = world.GetLinearVelocity(box).x - world.GetAngularVelocity(box) * d;
    CHECK(world.GetLinearVelocity(ball).x - vPointBox ==
          Approx(-double(e) * u).margin(kRoundoff * vScale));

    const Momentum p = LinearMomentum(world, both);
    CHECK(p.x == Approx(p0.x).margin(kRoundoff * mc * u));
    CHECK(p.y == Approx(p0.y).margin(kRoundoff * mc * u));
    CHECK(angularMomentum(boxBefore, ballBefore) ==
          Approx(L0).margin(kRoundoff * mc * u * (std::abs(double(d)) + 3)));

    // Linear momentum stays conserved whatever happens next (the spinning box may strike the
    // ball again): every impulse is applied equally and oppositely. Rounding: ≤ 4 velocity
    // roundings per body per step (warm start, solve), 4·kEps·(m·|v|) per step.
    const int later = 120;
    for (int i = 0; i < later; ++i)
    {
        world.Step(kDt);
    }
    const Momentum pLater = LinearMomentum(world, both);
    const double drift = 4 * kEps * later;
    CHECK(pLater.x == Approx(p0.x).margin(drift * (mb + mc) * u));
    CHECK(pLater.y == Approx(p0.y).margin(drift * (mb + mc) * u));
}

TEST_CASE("A ball dropped on static ground rebounds to e^2 h", "[analytic][collision][bounce]")
{
    const Real e = GENERATE(Real(0.5), Real(0.8));
    const bool segmentGround = GENERATE(true, false);
    const Real dt = GENERATE(Real(1.0 / 60.0), Real(1.0 / 240.0));
    CAPTURE(e, segmentGround, dt);

    World world = MakeWorld({0, -10});
    const double g = 10;
    const Real skin = world.GetTolerances().polygonSkin;
    // Ground surface at y = 0; both ground kinds collide `skin` above it (segment radius or
    // polygon skin), so the ball touches when its centre is at y = radius + skin.
    const BodyId ground = AddAnchor(world, {0, 0});
    const ShapeDef groundMaterial = Material(1, Real(0.6), 0);
    if (segmentGround)
    {
        world.CreateShape(ground, groundMaterial, Segment{{-5, 0}, {5, 0}});
    }
    else
    {
        world.CreateShape(ground, groundMaterial, MakeOffsetBox(5, Real(0.5), {0, Real(-0.5)}, 0));
    }
    const Real radius = Real(0.1);
    const double touch = radius + skin; // centre height at first touch
    const double h = 1;                 // drop height of the ball's lowest point above touch
    // Restitution mixes as max(e_ball, e_ground) = e.
    const BodyId ball =
        AddBall(world, {0, Real(touch + h)}, {0, 0}, radius, Material(1, Real(0.6), e));

    // Fall, bounce (vy turns positive), rise, and record the apex.
    bool bounced = false;
    double apex = -1;
    for (int i = 0; i < int(3 / dt); ++i)
    {
        world.Step(dt);
        const Vec2 v = world.GetLinearVelocity(ball);
        const double y = world.GetPosition(ball).y;
        if (!bounced && v.y > 0)
        {
            bounced = true;
        }
        if (bounced)
        {
            apex = std::max(apex, y);
            if (v.y < 0 && y < apex - 0.05)
            {
                break; // falling again
            }
        }
    }
    REQUIRE(bounced);
    const double rebound = apex - touch;

    // Error bounds, from the discrete step. Let v = √(2gh) and p ∈ [0, v·dt] the depth below
    // the touching height at the start of the step that first solves the contact.
    //  - Fall: semi-implicit Euler loses ½g²dt² of energy per unit mass each step, so
    //    ½v_k² = g(h + p) − ½g·dt·v_k; the restitution bias uses the post-gravity speed
    //    v_in = v_k + g·dt, hence v_in²/(2g) = h + p + ½v·dt + O(g·dt²).
    //  - Bounce: v_up = e·v_in (one point, solved exactly). The position solver then lifts the
    //    ball by Δ ≤ (1 − (1 − β)³)(p − slop) < 0.488·p (β = 0.2, 3 iterations) without
    //    touching its velocity. A second lift in the next step needs the ball still deeper
    //    than slop after rising e·v·dt: at most 0.488·max(0, 0.512p − e·v·dt) more.
    //  - Rise: semi-implicit Euler starting with v_up climbs v_up²/(2g) + ½v_up·dt.
    //  So rebound − e²h = −(1 − e²)p + Δ + ½e(1 + e)v·dt + O(g·dt²), which lies in
    //    [−(1 − e²)·v·dt,  (max(0, e² − 0.512) + 0.488·max(0, 0.512 − e) + ½e(1 + e))·v·dt],
    //  within ±v·dt for e ≤ 0.8; the O(g·dt²) terms (apex sampling, the ½g·dt·v_k vs ½g·dt·v
    //  difference) are bounded by g·dt² (2.8 mm at 60 Hz). Continuous collision, if the engine
    //  does it, only makes p smaller (≤ 3·slop).
    const double vImpact = std::sqrt(2 * g * h);
    const double ee = double(e) * e;
    const double lower = -(1 - ee) * vImpact * dt - g * dt * dt;
    const double upper =
        (std::max(0.0, ee - 0.512) + 0.488 * std::max(0.0, 0.512 - e) + 0.5 * e * (1 + e)) *
            vImpact * dt +
        g * dt * dt;
    INFO("rebound " << rebound << " m, expected e^2 h = " << ee * h << " m, allowed error ["
                    << lower << ", " << upper << "] m");
    CHECK(rebound - ee * h >= lower);
    CHECK(rebound - ee * h <= upper);
}
