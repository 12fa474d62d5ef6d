// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The character mover (meff/mover.h, World::CollideMover, World::CastMover): the plane solver
// and the velocity clip against hand-worked answers, and a capsule character walking into a
// wall, falling onto a floor and climbing a ramp in a world.
#include "error_checks.h"
#include "meff/mover.h"
#include "meff/world.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

using namespace meff;

TEST_CASE("SolvePlanes pushes out of each plane along its normal", "[mover][planes]")
{
    SECTION("one plane: out by the overlap")
    {
        std::vector<CollisionPlane> planes{{.normal = {0, 1}, .separation = Real(-0.1)}};
        const PlaneSolverResult result = SolvePlanes({0, 0}, planes);
        CHECK(result.translation.x == 0);
        CHECK(result.translation.y == Approx(0.1));
        CHECK(planes[0].push == Approx(0.1));
        CHECK(result.iterations == 2); // the second sweep finds nothing left to do
    }
    SECTION("a floor and a wall: out of both (a corner)")
    {
        std::vector<CollisionPlane> planes{{.normal = {0, 1}, .separation = Real(-0.1)},
                                           {.normal = {-1, 0}, .separation = Real(-0.2)}};
        const PlaneSolverResult result = SolvePlanes({0, 0}, planes);
        CHECK(result.translation.x == Approx(-0.2));
        CHECK(result.translation.y == Approx(0.1));
    }
    SECTION("a floor and a 45° slope: every separation ≥ 0 within the tolerance")
    {
        const Real h = std::sqrt(Real(0.5));
        std::vector<CollisionPlane> planes{{.normal = {0, 1}, .separation = Real(-0.1)},
                                           {.normal = {-h, h}, .separation = Real(-0.05)}};
        const PlaneSolverResult result = SolvePlanes({0, 0}, planes, Real(1e-6));
        for (const CollisionPlane& plane : planes)
        {
            // Each sweep leaves the last plane exact; the others drift by less than the
            // tolerance's change in push.
            CHECK(plane.separation + Dot(plane.normal, result.translation) >= Real(-1e-5));
        }
        CHECK(result.iterations < 20);
    }
    SECTION("the wanted move keeps its part along the plane")
    {
        // Walking right and down into a floor touched at the start: the floor takes the down.
        std::vector<CollisionPlane> planes{{.normal = {0, 1}, .separation = 0}};
        const PlaneSolverResult result = SolvePlanes({1, Real(-0.5)}, planes);
        CHECK(result.translation.x == 1);
        CHECK(result.translation.y == Approx(0).margin(1e-7));
        CHECK(planes[0].push == Approx(0.5));
    }
    SECTION("a plane past the mover does not pull it back")
    {
        std::vector<CollisionPlane> planes{{.normal = {0, 1}, .separation = Real(0.3)}};
        const PlaneSolverResult result = SolvePlanes({0, Real(-0.2)}, planes);
        CHECK(result.translation.y == Approx(-0.2));
        CHECK(planes[0].push == 0);
    }
    SECTION("the push limit: a soft plane pushes at most so far")
    {
        std::vector<CollisionPlane> planes{
            {.normal = {0, 1}, .separation = Real(-0.1), .pushLimit = Real(0.03)}};
        const PlaneSolverResult result = SolvePlanes({0, 0}, planes);
        CHECK(result.translation.y == Approx(0.03));
        CHECK(planes[0].push == Approx(0.03));
    }
    SECTION("squeezed between two planes: it stops after 20 sweeps, not far off")
    {
        std::vector<CollisionPlane> planes{{.normal = {0, 1}, .separation = Real(-0.1)},
                                           {.normal = {0, -1}, .separation = Real(-0.1)}};
        const PlaneSolverResult result = SolvePlanes({0, 0}, planes);
        CHECK(result.iterations == 20);
        CHECK(std::abs(result.translation.y) <= Real(0.1) + Real(1e-6));
    }
}

TEST_CASE("ClipVector removes the speed into the planes that pushed", "[mover][planes]")
{
    CollisionPlane floor{.normal = {0, 1}, .separation = 0, .push = Real(0.01)};
    CollisionPlane wall{.normal = {-1, 0}, .separation = 0, .push = Real(0.02)};
    CHECK(ClipVector({3, -4}, std::vector<CollisionPlane>{floor}) == Vec2(3, 0));
    CHECK(ClipVector({3, -4}, std::vector<CollisionPlane>{floor, wall}) == Vec2(0, 0));
    // Moving away from a plane keeps the speed.
    CHECK(ClipVector({-3, 4}, std::vector<CollisionPlane>{floor, wall}) == Vec2(-3, 4));
    // A plane that did not push, or that is not to clip, leaves it alone.
    CollisionPlane idle = floor;
    idle.push = 0;
    CHECK(ClipVector({3, -4}, std::vector<CollisionPlane>{idle}) == Vec2(3, -4));
    CollisionPlane through = floor;
    through.clipVelocity = false;
    CHECK(ClipVector({3, -4}, std::vector<CollisionPlane>{through}) == Vec2(3, -4));
}

namespace
{

constexpr Real kDt = Real(1) / Real(60);
constexpr Real kRadius = Real(0.3);

/// A standing capsule whose lower cap's centre is at `position`.
Capsule CharacterAt(Vec2 position)
{
    return {position, position + Vec2(0, 1), kRadius};
}

/// One move of the character whose lower cap's centre is at `position`.
void Move(const World& world, Vec2& position, Vec2& velocity)
{
    const CharacterMove move = world.MoveCharacter(CharacterAt(position), velocity, kDt);
    position += move.translation;
    velocity = move.velocity;
}

/// The smallest separation of the character at `position` from any shape (m).
Real Clearance(const World& world, Vec2 position)
{
    Real smallest = kMaxReal;
    world.CollideMover(CharacterAt(position), {},
                       [&](ShapeId, const CollisionPlane& plane)
                       {
                           smallest = Min(smallest, plane.separation);
                           return true;
                       });
    return smallest;
}

} // namespace

TEST_CASE("A capsule character falls onto a floor, walks into a wall and stops there",
          "[mover][world]")
{
    World world(WorldDef{});
    const BodyId floor = world.CreateBody({.position = {0, -1}});
    world.CreateShape(floor, {}, MakeBox(10, 1)); // top face y = 0
    const BodyId wall = world.CreateBody({.position = {Real(3.5), 2}});
    world.CreateShape(wall, {}, MakeBox(Real(0.5), 2));  // face x = 3
    const Real skin = world.GetTolerances().polygonSkin; // a polygon's rounding (m)

    Vec2 position{0, 1};
    Vec2 velocity{2, 0};
    Real lowest = kMaxReal;
    for (int i = 0; i < 180; ++i)
    {
        velocity.x = 2;               // the game walks it right at 2 m/s
        velocity.y -= Real(10) * kDt; // and gravity pulls
        Move(world, position, velocity);
        lowest = Min(lowest, Clearance(world, position));
    }
    // It never sank into anything by more than the solver's tolerance (1e-4 m) plus the
    // planes' linear model's error over one step's move.
    CHECK(lowest > Real(-1e-3));
    // It rests on the floor (its cap the radius plus the box's skin above the face) and
    // against the wall (the same out from its face), within the plane solver's tolerance
    // and a step's gravity (g·dt² = 2.8 mm, taken back by the floor's push every step).
    CHECK(position.y == Approx(kRadius + skin).margin(1e-3));
    CHECK(position.x == Approx(3 - kRadius - skin).margin(1e-3));
    // The walls took the speed into them.
    CHECK(velocity.x == Approx(0).margin(1e-6));
    CHECK(velocity.y == Approx(0).margin(1e-6));
}

TEST_CASE("A capsule character walks up a 20° ramp on its surface", "[mover][world]")
{
    World world(WorldDef{});
    const BodyId ground = world.CreateBody({});
    const Real slope = std::tan(Real(20) * Real(3.14159265358979) / 180);
    world.CreateShape(ground, {}, Segment{{-2, 0}, {20, 22 * slope}});

    Vec2 position{0, 2};
    Vec2 velocity{0, 0};
    for (int i = 0; i < 240; ++i)
    {
        velocity.x = 1;
        velocity.y -= Real(10) * kDt;
        Move(world, position, velocity);
    }
    // Four seconds at 1 m/s along x, pushed back along the ramp's normal each step by
    // the weight's part: it gets well up the ramp...
    CHECK(position.x > Real(2));
    // ...and stays on its surface: the cap's centre its radius plus the segment's skin out
    // from the ramp's line (through (−2, 0)), within the plane solver's tolerance and a
    // step's gravity.
    const Real skin = world.GetTolerances().polygonSkin;
    const Vec2 normal = (Real(1) / std::sqrt(1 + slope * slope)) * Vec2(-slope, 1);
    const Real height = Dot(normal, position - Vec2(-2, 0));
    CHECK(height == Approx(kRadius + skin).margin(3e-3));
}

TEST_CASE("A capsule character walks up a step lower than its radius; a higher one stops it",
          "[mover][world]")
{
    // A floor (top y = 0) and, from x = 2 on, a step of height h. Below the radius the cap
    // meets the step's corner on its rounded lower side, whose plane leans back towards the
    // character: the push out of it lifts the character, and walking on carries it onto the
    // step. Above the radius the cap's side meets the step's face: a wall.
    const Real h = GENERATE(Real(0.1), Real(0.2), Real(0.5));
    CAPTURE(h);
    World world(WorldDef{});
    const BodyId floor = world.CreateBody({.position = {0, -1}});
    world.CreateShape(floor, {}, MakeBox(10, 1));
    const BodyId step = world.CreateBody({.position = {6, h - 1}});
    world.CreateShape(step, {}, MakeBox(4, 1)); // face x = 2, top y = h
    const Real skin = world.GetTolerances().polygonSkin;

    Vec2 position{0, kRadius + skin};
    Vec2 velocity{0, 0};
    Real lowest = kMaxReal;
    for (int i = 0; i < 120; ++i)
    {
        velocity.x = 2;
        velocity.y -= Real(10) * kDt;
        Move(world, position, velocity);
        lowest = Min(lowest, Clearance(world, position));
    }
    // Never into the floor or the step by more than the planes' linear model over one move.
    CHECK(lowest > Real(-1e-3));
    if (h < kRadius)
    {
        // On the step, 2 m/s for 2 s from x = 0 less what the climb cost: past its edge, and
        // resting on it as on the floor (radius plus skin above the top, within the plane
        // solver's tolerance and a step's gravity, as above).
        CHECK(position.x > Real(3));
        CHECK(position.y == Approx(h + kRadius + skin).margin(1e-3));
    }
    else
    {
        CHECK(position.x == Approx(2 - kRadius - skin).margin(1e-3));
        CHECK(position.y == Approx(kRadius + skin).margin(1e-3));
    }
}

TEST_CASE("MoveCharacter is the move meff/mover.h lays out, bit for bit", "[mover][world]")
{
    // A corner: a floor and a wall, the character pressed into both and walking into them.
    World world(WorldDef{});
    const BodyId ground = world.CreateBody({});
    world.CreateShape(ground, {}, Segment{{-10, 0}, {10, 0}});
    world.CreateShape(ground, {}, Segment{{1, 0}, {1, 5}});
    const Vec2 position{Real(0.65), Real(0.28)};
    const Vec2 velocity{3, -2};

    const Vec2 target = position + kDt * velocity;
    std::vector<CollisionPlane> planes;
    world.CollideMover(CharacterAt(target), {},
                       [&](ShapeId, const CollisionPlane& plane)
                       {
                           planes.push_back(plane);
                           return true;
                       });
    // From the start: the move along v, then the planes' fix (collided at the target).
    const Vec2 goal = kDt * velocity + SolvePlanes({0, 0}, planes).translation;
    const Vec2 translation = world.CastMover(CharacterAt(position), goal) * goal;

    const CharacterMove move = world.MoveCharacter(CharacterAt(position), velocity, kDt);
    CHECK(move.planeCount == 2);
    CHECK(move.translation == translation);
    CHECK(move.velocity == ClipVector(velocity, planes));
    // Pushed out of both: up off the floor and left off the wall.
    CHECK(move.translation.x < kDt * velocity.x);
    CHECK(move.translation.y > kDt * velocity.y);
}

TEST_CASE("MoveCharacter gathers at most kMaxMoverPlanes planes", "[mover][world]")
{
    // 40 pebbles under the character: it stands on the first 16 the broad phase gives and
    // still moves (no overflow, no allocation of its own).
    World world(WorldDef{});
    const BodyId ground = world.CreateBody({});
    for (int i = 0; i < 40; ++i)
    {
        world.CreateShape(ground, {}, Circle{{Real(-0.2) + Real(0.01) * Real(i), 0}, Real(0.05)});
    }
    const CharacterMove move = world.MoveCharacter(CharacterAt({0, Real(0.3)}), {0, -1}, kDt);
    CHECK(move.planeCount == kMaxMoverPlanes);
    CHECK(move.translation.IsValid());
    CHECK(move.velocity.y > -1); // the pebbles it stands on took part of the fall
}

TEST_CASE("CastMover: a wall ahead stops the move, the floor it stands on does not",
          "[mover][world]")
{
    World world(WorldDef{});
    const BodyId ground = world.CreateBody({});
    world.CreateShape(ground, {}, Segment{{-10, 0}, {10, 0}});
    world.CreateShape(ground, {}, Segment{{3, 0}, {3, 5}});
    const Vec2 standing{0, kRadius}; // touching the floor
    // Along the floor: nothing in the way for 2 m.
    CHECK(world.CastMover(CharacterAt(standing), {2, 0}) == 1);
    // Into the wall: the cap reaches x = 3 − r after 3 − r m of the 4 m asked, give or take
    // the shape cast's target separation (a linear slop, 5 mm).
    const Real fraction = world.CastMover(CharacterAt(standing), {4, 0});
    CHECK(fraction * 4 == Approx(3 - kRadius).margin(0.006));
    // Down into the floor it stands on: stopped at once.
    CHECK(world.CastMover(CharacterAt(standing), {0, -1}) == Approx(0).margin(0.006));
}

TEST_CASE("The mover queries refuse a bad capsule and translation", "[mover][errors]")
{
    World world(WorldDef{});
    const auto message = [](auto&& call) { return meff::test::ErrorMessageOf(call); };
    const Capsule flat{{0, 0}, {0, 1}, 0};
    CHECK_THAT(
        message(
            [&]
            { world.CollideMover(flat, {}, [](ShapeId, const CollisionPlane&) { return true; }); }),
        Catch::StartsWith("World::CollideMover: mover: Capsule::radius"));
    CHECK_THAT(message(
                   [&] {
                       world.CastMover(flat, {1, 0});
                   }),
               Catch::StartsWith("World::CastMover: mover: Capsule::radius"));
    CHECK_THAT(message(
                   [&] {
                       world.CastMover(CharacterAt({0, 0}), {kMaxReal * 2, 0});
                   }),
               Catch::StartsWith("World::CastMover: translation"));
    CHECK_THAT(message(
                   [&] {
                       world.MoveCharacter(CharacterAt({0, 0}), {1, 0}, 0);
                   }),
               Catch::StartsWith("World::MoveCharacter: dt: must be finite and > 0, got 0"));
    CHECK_THAT(message(
                   [&] {
                       world.MoveCharacter(CharacterAt({0, 0}),
                                           {std::numeric_limits<Real>::quiet_NaN(), 0}, kDt);
                   }),
               Catch::StartsWith("World::MoveCharacter: velocity: must be finite"));
    CHECK_THAT(message(
                   [&] {
                       world.MoveCharacter(flat, {1, 0}, kDt);
                   }),
               Catch::StartsWith("World::MoveCharacter: mover: Capsule::radius"));
    // Moved by 1e30 m/s for a step, the capsule's ends round together: named as this call's,
    // not as a bad argument of CollideMover, which MoveCharacter calls.
    CHECK_THAT(message(
                   [&] {
                       world.MoveCharacter(CharacterAt({0, 0}), {0, Real(1e30)}, kDt);
                   }),
               Catch::StartsWith("World::MoveCharacter: mover moved by velocity · dt: Capsule::"));
}
