// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Tour stop: ray casts. A game asks "what does this laser / line of sight / bullet hit first?"
// (CastRayClosest) and "what does it pass through?" (CastRay with a callback that decides, hit
// by hit, to skip, clip or stop). Both walk the broad phase's tree, not every shape.
#include "tour.h"

#include <cmath>

namespace meff::tour
{

namespace
{

constexpr std::uint16_t kSolid = 0x0001;
constexpr std::uint16_t kGlass = 0x0002;

} // namespace

RayCastResult RunRayCast(std::FILE* log)
{
    World world(WorldDef{});

    // A closed room 20 m × 10 m.
    const BodyId room = world.CreateBody(BodyDef{});
    world.CreateShape(room, ShapeDef{}, MakeOffsetBox(10, Real(0.5), {0, Real(-0.5)}, 0));
    world.CreateShape(room, ShapeDef{}, MakeOffsetBox(10, Real(0.5), {0, Real(10.5)}, 0));
    world.CreateShape(room, ShapeDef{}, MakeOffsetBox(Real(0.5), 5, {Real(-10), 5}, 0));
    world.CreateShape(room, ShapeDef{}, MakeOffsetBox(Real(0.5), 5, {Real(10), 5}, 0));

    // A glass pane at x = 0 and a ball at x = 4 on the laser's line y = 1.
    ShapeDef glass;
    glass.filter.categoryBits = kGlass;
    world.CreateShape(room, glass, MakeOffsetBox(Real(0.1), 2, {0, 2}, 0));
    world.CreateShape(room, ShapeDef{}, Circle{{4, 1}, Real(0.5)});

    const Vec2 origin{-5, 1};
    const Vec2 translation{20, 0}; // ends beyond the right wall's inner face at x = 9.5

    RayCastResult result;
    const RayResult first = world.CastRayClosest(origin, translation);
    result.closestWithGlass = first.point;
    QueryFilter solidOnly;
    solidOnly.maskBits = kSolid;
    result.closestThroughGlass = world.CastRayClosest(origin, translation, solidOnly).point;

    // Every hit: returning 1 keeps the ray at full length, so all shapes along it report.
    world.CastRay(origin, translation, QueryFilter{},
                  [&](ShapeId, Vec2, Vec2, Real)
                  {
                      ++result.hitsWithGlass;
                      return Real(1);
                  });
    world.CastRay(origin, translation, QueryFilter{},
                  [&](ShapeId shape, Vec2, Vec2, Real)
                  {
                      if (world.GetShapeDef(shape).filter.categoryBits == kGlass)
                      {
                          return Real(-1); // look through it
                      }
                      ++result.hitsThroughGlass;
                      return Real(1);
                  });

    // A sweep of 32 rays from a point in the room's left half: in a closed room every ray hits
    // something.
    result.sweepRays = 32;
    const Vec2 centre{-5, 5};
    for (int i = 0; i < result.sweepRays; ++i)
    {
        const Real angle = Real(2) * kPi * Real(i) / Real(result.sweepRays);
        const Vec2 direction{std::cos(angle), std::sin(angle)};
        const RayResult hit = world.CastRayClosest(centre, Real(30) * direction);
        if (hit.hit)
        {
            result.sweepPoints.push_back(hit.point);
        }
    }

    if (log != nullptr)
    {
        std::fprintf(log,
                     "ray cast: closest hit (%.2f, %.2f) is the glass; through the glass "
                     "(%.2f, %.2f) is the ball; %d hits along the ray, %d without the glass; "
                     "%zu of %d sweep rays hit\n",
                     double(result.closestWithGlass.x), double(result.closestWithGlass.y),
                     double(result.closestThroughGlass.x), double(result.closestThroughGlass.y),
                     result.hitsWithGlass, result.hitsThroughGlass, result.sweepPoints.size(),
                     result.sweepRays);
    }
    return result;
}

} // namespace meff::tour
