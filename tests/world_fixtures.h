// Small worlds shared by tests.
#pragma once

#include "meff/world.h"

namespace meff::test
{

/// `count` boxes and circles (alternating) dropped in `columns` columns `spacing` apart onto a
/// segment into a pile: contacts come and go and warm starting matters while it settles.
inline World MakePile(int count, int columns, Real spacing, Real circleRestitution)
{
    World world;
    const BodyId ground = world.CreateBody({});
    world.CreateShape(ground, ShapeDef{}, Segment{{-20, 0}, {20, 0}});
    for (int i = 0; i < count; ++i)
    {
        const BodyId body = world.CreateBody(
            {.type = BodyType::Dynamic, .position = {spacing * Real(i % columns), Real(1 + i)}});
        if (i % 2 == 0)
        {
            world.CreateShape(body, ShapeDef{}, MakeBox(Real(0.4), Real(0.3)));
        }
        else
        {
            world.CreateShape(body, ShapeDef{.restitution = circleRestitution},
                              Circle{{0, 0}, Real(0.35)});
        }
    }
    return world;
}

} // namespace meff::test
