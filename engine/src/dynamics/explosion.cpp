// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// World::Explode: a radial impulse at one instant, as Box2D v3's b2World_Explode describes it
// (position, radius, linear falloff, impulse per length of the shape facing the centre, mask).
// The impulse on a shape is J = p·w·s along the line from the centre to the shape's closest
// point, w the shape's width across that line (its projection on the perpendicular, radius
// included) and s the falloff scale, so a wide box takes more than a thin edge-on one.
#include "core/report_error.h"
#include "dynamics/world_state.h"
#include "model/shape_proxy.h"
#include "meff/distance.h"
#include "meff/validity.h"
#include "meff/world.h"

#include <string>
#include <vector>

namespace meff
{

using namespace detail;

namespace
{

/// The shape's extent along unit direction `line` (its width seen from across it), radius
/// included: max − min of the core's projection, plus 2r.
Real ProjectedWidth(const DistanceProxy& proxy, Vec2 line)
{
    Real low = Dot(proxy.vertices[0], line);
    Real high = low;
    for (int i = 1; i < proxy.count; ++i)
    {
        const Real p = Dot(proxy.vertices[i], line);
        low = Min(low, p);
        high = Max(high, p);
    }
    return high - low + 2 * proxy.radius;
}

/// The centroid of the shape's core in body coordinates (mean of the proxy's vertices: the
/// circle's centre, a polygon's vertex average, enough for a direction).
Vec2 CoreCentre(const DistanceProxy& proxy)
{
    Vec2 sum{0, 0};
    for (int i = 0; i < proxy.count; ++i)
    {
        sum += proxy.vertices[i];
    }
    return (Real(1) / Real(proxy.count)) * sum;
}

} // namespace

void World::Explode(const ExplosionDef& def)
{
    if (!RequireFinite(def.position, "World::Explode: ExplosionDef::position") ||
        !RequireNonNegative(def.radius, "World::Explode: ExplosionDef::radius") ||
        !RequireNonNegative(def.falloff, "World::Explode: ExplosionDef::falloff") ||
        !RequireFinite(def.impulsePerLength, "World::Explode: ExplosionDef::impulsePerLength") ||
        !RequireNotStepping(State(), "World::Explode"))
    {
        return;
    }

    struct Push
    {
        BodyId body;
        Vec2 impulse, point;
    };
    std::vector<Push> pushes;
    const WorldState& world = State();
    const Real reach = def.radius + def.falloff;
    for (const Shape& shape : world.shapes)
    {
        if (!shape.alive || shape.def.isSensor ||
            (shape.def.filter.categoryBits & def.maskBits) == 0 ||
            (shape.type != ShapeType::Circle && shape.type != ShapeType::Polygon &&
             shape.type != ShapeType::Capsule))
        {
            continue;
        }
        const Body& body = world.bodies[shape.body];
        if (body.type != BodyType::Dynamic)
        {
            continue;
        }
        // Distance from the centre to the shape's surface (radius included), in the body's
        // frame so that far from the origin the difference is taken before rounding.
        const DistanceProxy proxy = MakeProxy(shape);
        const Vec2 centre = MulT(body.xf, def.position);
        DistanceInput input;
        input.proxyA = proxy;
        input.proxyB.vertices[0] = centre;
        input.proxyB.count = 1;
        input.useRadii = true;
        SimplexCache cache;
        const DistanceOutput output = ShapeDistance(input, cache);
        if (output.distance > reach)
        {
            continue;
        }
        const Vec2 closest = output.distance > 0 ? output.pointA : CoreCentre(proxy);
        Vec2 direction = closest - centre;
        const Real length = direction.Length();
        // A centre on the shape's own centre has no direction: push along +x.
        direction = length > 10 * kEpsilon ? (Real(1) / length) * direction : Vec2{1, 0};
        const Real scale = output.distance > def.radius && def.falloff > 0
                               ? Clamp((reach - output.distance) / def.falloff, Real(0), Real(1))
                               : Real(1);
        const Real magnitude =
            def.impulsePerLength * ProjectedWidth(proxy, {-direction.y, direction.x}) * scale;
        const BodyId id{shape.body, body.generation};
        pushes.push_back({id, magnitude * Mul(body.xf.q, direction), Mul(body.xf, closest)});
    }
    for (const Push& push : pushes)
    {
        ApplyLinearImpulse(push.body, push.impulse, push.point, true);
    }
}

} // namespace meff
