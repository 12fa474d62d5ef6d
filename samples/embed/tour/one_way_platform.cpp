// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Tour stop: a one-way platform, the classic use of the pre-solve hook. The hook runs inside
// World::Step for every touching contact; returning false disables that contact for this step,
// so a box rising through the platform from below is let through, and once above it lands.
#include "tour.h"

#include <algorithm>
#include <cmath>

namespace meff::tour
{

OneWayPlatformResult RunOneWayPlatform(std::FILE* log)
{
    constexpr Real kStep = Real(1) / 60;
    constexpr Real kHalf = Real(0.5); // the box's half-extent (m)

    World world(WorldDef{});
    const BodyId ground = world.CreateBody(BodyDef{});
    world.CreateShape(ground, ShapeDef{}, MakeOffsetBox(20, 1, {0, -1}, 0));

    BodyDef platformDef;
    platformDef.position = {0, 3};
    const BodyId platformBody = world.CreateBody(platformDef);
    const ShapeId platform = world.CreateShape(platformBody, ShapeDef{}, MakeBox(3, Real(0.25)));
    OneWayPlatformResult result;
    result.platformTop = Real(3.25);

    BodyDef boxDef;
    boxDef.type = BodyType::Dynamic;
    boxDef.position = {0, kHalf};
    boxDef.linearVelocity = {0, 10}; // rises to about 5 m: well above the platform
    const BodyId box = world.CreateBody(boxDef);
    world.CreateShape(box, ShapeDef{}, MakeBox(kHalf, kHalf));

    // The contact counts only once the box's bottom is above the platform's top. The margin
    // of a few slops lets a box resting on the platform (sinking by up to the slop) stay on it.
    const Real margin = 3 * world.GetTolerances().linearSlop;
    world.SetPreSolveCallback(
        [&](const PreSolveContact& contact)
        {
            if (contact.shapeA != platform && contact.shapeB != platform)
            {
                return true; // every other contact is solid
            }
            // Reading the world is allowed here; changing it is not (the step is in progress).
            return world.GetPosition(box).y - kHalf > result.platformTop - margin;
        });

    result.highestY = world.GetPosition(box).y - kHalf;
    for (int step = 0; step < 360; ++step)
    {
        world.Step(kStep);
        const Real bottom = world.GetPosition(box).y - kHalf;
        result.highestY = std::max(result.highestY, bottom);
        const bool insidePlatform = bottom < result.platformTop && bottom + 2 * kHalf > 2.75f;
        if (insidePlatform && world.GetLinearVelocity(box).y > 0)
        {
            ++result.stepsBelowTopRising;
        }
    }
    result.finalBottomY = world.GetPosition(box).y - kHalf;
    result.finalSpeed = world.GetLinearVelocity(box).Length();

    if (log != nullptr)
    {
        std::fprintf(log,
                     "one-way platform: the box rose through the platform (top %.2f m) to "
                     "%.2f m and came to rest on it at %.3f m, speed %.4f m/s\n",
                     double(result.platformTop), double(result.highestY),
                     double(result.finalBottomY), double(result.finalSpeed));
    }
    return result;
}

} // namespace meff::tour
