// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// A world in other length units (pixels) behaves as the same world in metres, scaled, when its
// tolerances come from TolerancesForLengthUnits.
#include <catch2/catch.hpp>

#include "error_checks.h"
#include "meff/world.h"

#include <cmath>

using namespace meff;

namespace
{

/// A box dropped onto a tilted ramp, everything in lengths multiplied by `k`.
struct RampRun
{
    Vec2 position;
    Real angle;
};

RampRun RunRamp(Real k, const Tolerances& tolerances)
{
    World world{WorldDef{.gravity = {0, -10 * k}, .tolerances = tolerances}};
    const BodyId ground = world.CreateBody({.angle = Real(0.3)});
    world.CreateShape(ground, ShapeDef{.friction = Real(0.2)}, MakeBox(10 * k, Real(0.5) * k));
    const BodyId box = world.CreateBody(
        {.type = BodyType::Dynamic, .position = {-2 * k, 2 * k}, .angle = Real(0.3)});
    // Density scales as 1/k² so masses stay equal; friction and angles are dimensionless.
    world.CreateShape(box, ShapeDef{.density = 1 / (k * k), .friction = Real(0.2)},
                      MakeBox(Real(0.5) * k, Real(0.25) * k));
    for (int i = 0; i < 240; ++i)
    {
        world.Step(Real(1) / 60);
    }
    return {world.GetPosition(box), world.GetAngle(box)};
}

} // namespace

TEST_CASE("a world in pixels is the metre world scaled, with scaled tolerances", "[units]")
{
    const Real k = 32; // pixels per metre, a power of two: scaling is exact in float
    const RampRun metres = RunRamp(1, Tolerances{});
    const RampRun pixels = RunRamp(k, TolerancesForLengthUnits(k));
    // With k a power of two every length, tolerance and intermediate scales exactly, so the runs
    // agree to float round-off of the unscaled quantities (sin/cos of the same angles).
    CHECK(pixels.position.x / k == Approx(metres.position.x).margin(1e-5));
    CHECK(pixels.position.y / k == Approx(metres.position.y).margin(1e-5));
    CHECK(pixels.angle == Approx(metres.angle).margin(1e-5));
    // The box did slide (tan 0.3 > 0.2), so the comparison covers contacts and friction.
    CHECK(std::abs(metres.position.x + 2) > Real(0.5));

    // Without the scaled tolerances the pixel world settles differently (a 0.005 px slop and a
    // 0.01 px skin are a different simulation), which is why the setting exists.
    const RampRun unscaled = RunRamp(k, Tolerances{});
    CHECK(std::abs(unscaled.position.y / k - metres.position.y) > 1e-4);
}

TEST_CASE("TolerancesForLengthUnits refuses a non-positive scale", "[units]")
{
    MEFF_CHECK_ERROR(TolerancesForLengthUnits(0));
    MEFF_CHECK_ERROR(TolerancesForLengthUnits(-1));
    CHECK(TolerancesForLengthUnits(100).linearSlop == Approx(0.5));
    CHECK(TolerancesForLengthUnits(100).angularSlop == Tolerances{}.angularSlop);
}
