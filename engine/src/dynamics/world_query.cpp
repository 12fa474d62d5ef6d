// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// World queries through the broad phase: ray casts, box and point overlaps, shape casts.
//
// Ray casts reproduce Box2D 2.4.1's b2World::RayCast (b2DynamicTree::RayCast, the fixture's
// RayCast, the hit point (1 − f)·p1 + f·p2, the callback's clipping), so that the same world
// gives the same hits in the same order. Box overlaps are b2World::QueryAABB. Point overlaps
// and shape casts, which Box2D 2.4.1 lacks, follow Box2D v3's b2World_OverlapPoint and
// b2World_CastShape: the broad phase finds candidates, an exact test per shape decides.
//
// Every query only reads the world; while one walks it, calls that would add, remove or move
// what it reads (from the query's callback) are refused (RequireNotWalked).
#include "collision/broad_phase.h"
#include "core/report_error.h"
#include "dynamics/world_state.h"
#include "model/shape_proxy.h"
#include "meff/distance.h"
#include "meff/ray_cast.h"
#include "meff/validity.h"
#include "meff/world.h"

#include <array>
#include <span>
#include <string>

namespace meff
{

using namespace detail;

namespace
{

[[nodiscard]] bool RequireValidTransform(const Transform& xf, const char* where)
{
    if (!xf.p.IsValid() || !meff::IsValid(xf.q.s) || !meff::IsValid(xf.q.c))
    {
        return Refuse(
            InvalidArgument(std::string(where) + ": must be finite, got p = " + NumberText(xf.p) +
                            ", q = (s " + NumberText(xf.q.s) + ", c " + NumberText(xf.q.c) + ")"));
    }
    return true;
}

/// The live shape `id` names; nullptr (reported) for a null or stale id.
const Shape* ResolveShape(const WorldState& world, ShapeId id, const char* where)
{
    return world.shapes.Resolve(id, "shape", where);
}

/// Box2D v3's b2ShouldQueryShape: each side's category must be in the other's mask.
bool IsSeen(const Shape& shape, QueryFilter filter)
{
    return (shape.def.filter.categoryBits & filter.maskBits) != 0 &&
           (shape.def.filter.maskBits & filter.categoryBits) != 0;
}

ShapeId IdOf(const WorldState& world, std::int32_t index)
{
    return {index, world.shapes[index].generation};
}

bool RayCastShape(const Shape& shape, const Transform& xf, const RayCastInput& input,
                  RayCastOutput& output)
{
    switch (shape.type)
    {
    case ShapeType::Circle:
        return RayCast(shape.circle, xf, input, output);
    case ShapeType::Polygon:
        return shape.rounded ? RayCastRounded(shape.polygon, xf, input, output)
                             : RayCast(shape.polygon, xf, input, output);
    case ShapeType::Capsule:
        return RayCastRounded(shape.polygon, xf, input, output);
    case ShapeType::Segment:
        return RayCast(shape.segment, xf, input, output);
    case ShapeType::ChainSegment:
        // b2ChainShape::RayCast casts at a plain (two-sided) edge: a chain is hit from both
        // sides, a lone one-sided segment only from its front.
        return shape.chain >= 0 ? RayCast(shape.chainSegment.segment, xf, input, output)
                                : RayCast(shape.chainSegment, xf, input, output);
    }
    return false;
}

bool TestPointShape(const Shape& shape, const Transform& xf, Vec2 point)
{
    switch (shape.type)
    {
    case ShapeType::Circle:
        return TestPoint(shape.circle, xf, point);
    case ShapeType::Polygon:
        return shape.rounded ? TestPointRounded(shape.polygon, xf, point)
                             : TestPoint(shape.polygon, xf, point);
    case ShapeType::Capsule:
        return TestPointRounded(shape.polygon, xf, point);
    case ShapeType::Segment:
        return TestPoint(shape.segment, xf, point);
    case ShapeType::ChainSegment:
        return TestPoint(shape.chainSegment, xf, point);
    }
    return false;
}

/// The closest-hit callback: clipping the ray at every hit leaves only closer ones to report.
struct ClosestHit
{
    RayResult result;
    Real operator()(ShapeId shape, Vec2 point, Vec2 normal, Real fraction)
    {
        result = {shape, point, normal, fraction, true};
        return fraction;
    }
};

[[nodiscard]] bool RequireValidCastShape(const Circle& circle)
{
    return RequireFinite(circle.center, "World::CastShape: shape.center") &&
           RequirePositive(circle.radius, "World::CastShape: shape.radius");
}

[[nodiscard]] bool RequireValidCastShape(const Polygon& polygon)
{
    if (polygon.count < 3 || polygon.count > kMaxPolygonVertices)
    {
        return Refuse(InvalidArgument("World::CastShape: shape.count: must be in [3, 8] (build "
                                      "polygons with MakePolygon or MakeBox), got " +
                                      std::to_string(polygon.count)));
    }
    for (int i = 0; i < polygon.count; ++i)
    {
        if (!RequireFinite(polygon.vertices[i], "World::CastShape: shape.vertices"))
        {
            return false;
        }
    }
    return RequireNonNegative(polygon.radius, "World::CastShape: shape.radius");
}

[[nodiscard]] bool RequireValidCastShape(const Capsule& capsule, const Tolerances& tolerances,
                                         const char* what = "World::CastShape: shape")
{
    if (const std::optional<Refusal> refusal = CheckCapsule(capsule, tolerances.linearSlop))
    {
        return Refuse(
            InvalidArgument(std::string(what) + ": " + refusal->field + ": " + refusal->reason));
    }
    return true;
}

/// The shape cast behind the CastShape overloads: `proxy` at `start` swept by `translation`.
void CastProxy(const WorldState& world, const DistanceProxy& proxy, const AABB& startBox,
               const Transform& start, Vec2 translation, QueryFilter filter, CastCallback callback)
{
    const InWalk walk(world); // the callback must not change what is walked
    const Tolerances& tolerances = world.tolerances;

    // The broad phase is searched with the path of the start box's centre, every fat box grown
    // by the start box's half-extents. ShapeCast gives each shape a radius of at least
    // polygonSkin and stops when the cores are within radiusA + radiusB − polygonSkin plus
    // its tolerance of linearSlop/2, so the start box (which holds the cast shape's own
    // radius) is grown by polygonSkin + linearSlop more to never miss a shape ShapeCast hits.
    const Real grow = tolerances.polygonSkin + tolerances.linearSlop;
    const Vec2 halfExtents = startBox.GetExtents() + Vec2(grow, grow);
    const Vec2 center = startBox.GetCenter();
    const RayCastInput path{center, center + translation, 1};

    world.broadPhase.BoxCast(
        path, halfExtents,
        [&](const RayCastInput& subInput, std::int32_t proxyId) -> Real
        {
            const std::int32_t index = world.broadPhase.GetUserData(proxyId);
            const Shape& shape = world.shapes[index];
            if (!IsSeen(shape, filter))
            {
                return Real(-1);
            }
            ShapeCastInput input;
            input.proxyA = MakeProxy(shape);
            input.proxyB = proxy;
            input.transformA = world.bodies[shape.body].xf;
            input.transformB = start;
            input.translationB = translation;
            input.polygonSkin = tolerances.polygonSkin;
            input.linearSlop = tolerances.linearSlop;
            ShapeCastOutput output;
            // Beyond the current clip counts as a miss, as for ray casts.
            if (!ShapeCast(input, output) || output.lambda > subInput.maxFraction)
            {
                return subInput.maxFraction;
            }
            return callback(IdOf(world, index), output.point, output.normal, output.lambda);
        });
}

} // namespace

void World::CastRay(Vec2 origin, Vec2 translation, QueryFilter filter, CastCallback callback) const
{
    if (!RequireFinite(origin, "World::CastRay: origin") ||
        !RequireFinite(translation, "World::CastRay: translation") ||
        !RequireFinite(origin + translation, "World::CastRay: origin + translation"))
    {
        return;
    }
    const WorldState& world = State();
    const InWalk walk(world); // the callback must not change what is walked

    const RayCastInput input{origin, origin + translation, 1};
    world.broadPhase.RayCast(
        input,
        [&](const RayCastInput& subInput, std::int32_t proxyId) -> Real
        {
            const std::int32_t index = world.broadPhase.GetUserData(proxyId);
            const Shape& shape = world.shapes[index];
            if (!IsSeen(shape, filter))
            {
                return Real(-1);
            }
            RayCastOutput output;
            if (!RayCastShape(shape, world.bodies[shape.body].xf, subInput, output))
            {
                // A miss leaves the ray as it is (Box2D returns the current maxFraction).
                return subInput.maxFraction;
            }
            const Real fraction = output.fraction;
            const Vec2 point = (Real(1) - fraction) * subInput.p1 + fraction * subInput.p2;
            return callback(IdOf(world, index), point, output.normal, fraction);
        });
}

RayResult World::CastRayClosest(Vec2 origin, Vec2 translation, QueryFilter filter) const
{
    ClosestHit closest;
    CastRay(origin, translation, filter, closest);
    return closest.result;
}

void World::OverlapAABB(const AABB& box, QueryFilter filter, OverlapCallback callback) const
{
    if (!box.IsValid())
    {
        ReportError(InvalidArgument("World::OverlapAABB: box: must be finite with lowerBound <= "
                                    "upperBound, got " +
                                    NumberText(box.lowerBound) + " to " +
                                    NumberText(box.upperBound)));
        return;
    }
    const WorldState& world = State();
    const InWalk walk(world); // the callback must not change what is walked
    world.broadPhase.Query(box, {filter.categoryBits, filter.maskBits},
                           [&](std::int32_t proxyId)
                           {
                               // The layered query reports only shapes the filter sees.
                               return callback(IdOf(world, world.broadPhase.GetUserData(proxyId)));
                           });
}

void World::OverlapPoint(Vec2 point, QueryFilter filter, OverlapCallback callback) const
{
    if (!RequireFinite(point, "World::OverlapPoint: point"))
    {
        return;
    }
    const WorldState& world = State();
    const InWalk walk(world); // the callback must not change what is walked
    // A shape containing the point has it inside its tight box, so inside its fat box.
    world.broadPhase.Query(AABB{point, point}, {filter.categoryBits, filter.maskBits},
                           [&](std::int32_t proxyId)
                           {
                               const std::int32_t index = world.broadPhase.GetUserData(proxyId);
                               const Shape& shape = world.shapes[index];
                               if (!TestPointShape(shape, world.bodies[shape.body].xf, point))
                               {
                                   return true;
                               }
                               return callback(IdOf(world, index));
                           });
}

void World::CastShape(const Circle& shape, const Transform& start, Vec2 translation,
                      QueryFilter filter, CastCallback callback) const
{
    if (!RequireValidCastShape(shape) || !RequireValidTransform(start, "World::CastShape: start") ||
        !RequireFinite(translation, "World::CastShape: translation"))
    {
        return;
    }
    CastProxy(State(), MakeProxy(shape), ComputeAABB(shape, start), start, translation, filter,
              callback);
}

void World::CastShape(const Polygon& shape, const Transform& start, Vec2 translation,
                      QueryFilter filter, CastCallback callback) const
{
    if (!RequireValidCastShape(shape) || !RequireValidTransform(start, "World::CastShape: start") ||
        !RequireFinite(translation, "World::CastShape: translation"))
    {
        return;
    }
    CastProxy(State(), MakeProxy(shape), ComputeAABB(shape, start), start, translation, filter,
              callback);
}

void World::CastShape(const Capsule& shape, const Transform& start, Vec2 translation,
                      QueryFilter filter, CastCallback callback) const
{
    if (!RequireValidCastShape(shape, State().tolerances) ||
        !RequireValidTransform(start, "World::CastShape: start") ||
        !RequireFinite(translation, "World::CastShape: translation"))
    {
        return;
    }
    CastProxy(State(), MakeProxy(shape), ComputeAABB(shape, start), start, translation, filter,
              callback);
}

void World::CollideMover(
    const Capsule& mover, QueryFilter filter,
    FunctionRef<bool(ShapeId shape, const CollisionPlane& plane)> callback) const
{
    if (!RequireValidCastShape(mover, State().tolerances, "World::CollideMover: mover"))
    {
        return;
    }
    const WorldState& world = State();
    const InWalk walk(world); // the callback must not change what is walked
    const DistanceProxy moverProxy = MakeProxy(mover);
    const Transform identity{}; // the mover is in world coordinates
    world.broadPhase.Query(
        ComputeAABB(mover, identity), {filter.categoryBits, filter.maskBits},
        [&](std::int32_t proxyId)
        {
            const std::int32_t index = world.broadPhase.GetUserData(proxyId);
            const Shape& shape = world.shapes[index];
            // The cores' closest points: the normal runs between them and the surfaces lie
            // each core's radius out along it.
            DistanceInput input;
            input.proxyA = MakeProxy(shape);
            input.proxyB = moverProxy;
            input.transformA = world.bodies[shape.body].xf;
            input.transformB = identity;
            SimplexCache cache;
            const DistanceOutput output = ShapeDistance(input, cache);
            if (output.distance <= 10 * kEpsilon)
            {
                return true; // the mover's core is inside the shape: no normal to push along
            }
            CollisionPlane plane;
            plane.normal = (Real(1) / output.distance) * (output.pointB - output.pointA);
            plane.separation = output.distance - input.proxyA.radius - moverProxy.radius;
            return callback(IdOf(world, index), plane);
        });
}

Real World::CastMover(const Capsule& mover, Vec2 translation, QueryFilter filter) const
{
    if (!RequireValidCastShape(mover, State().tolerances, "World::CastMover: mover") ||
        !RequireFinite(translation, "World::CastMover: translation"))
    {
        return {};
    }
    Real fraction = 1;
    const Transform identity{}; // the mover is in world coordinates
    CastShape(mover, identity, translation, filter,
              [&](ShapeId, Vec2, Vec2 normal, Real hit) -> Real
              {
                  // A shape touched at the start or slid along is not in the way.
                  if (Dot(normal, translation) >= 0)
                  {
                      return Real(-1);
                  }
                  fraction = Min(fraction, hit);
                  return hit;
              });
    return fraction;
}

CharacterMove World::MoveCharacter(const Capsule& mover, Vec2 velocity, Real dt,
                                   QueryFilter filter) const
{
    if (!RequireValidCastShape(mover, State().tolerances, "World::MoveCharacter: mover") ||
        !RequireFinite(velocity, "World::MoveCharacter: velocity") ||
        !RequirePositive(dt, "World::MoveCharacter: dt"))
    {
        return {};
    }
    const Vec2 step = dt * velocity;
    if (!RequireFinite(step, "World::MoveCharacter: velocity · dt"))
    {
        return {};
    }
    const Capsule target{mover.center1 + step, mover.center2 + step, mover.radius};
    // Checked here, under this call's name: moved far enough, the capsule's ends round together
    // or leave the float range, which CollideMover would report as its own argument's fault.
    if (!RequireValidCastShape(target, State().tolerances,
                               "World::MoveCharacter: mover moved by velocity · dt"))
    {
        return {};
    }
    std::array<CollisionPlane, kMaxMoverPlanes> planes;
    int count = 0;
    CollideMover(target, filter,
                 [&](ShapeId, const CollisionPlane& plane)
                 {
                     planes[std::size_t(count++)] = plane;
                     return count < kMaxMoverPlanes;
                 });
    const std::span<CollisionPlane> met(planes.data(), std::size_t(count));
    // The planes were collided at the target: the solver's translation is from there.
    const Vec2 goal = step + SolvePlanes({0, 0}, met).translation;
    CharacterMove move;
    move.translation = CastMover(mover, goal, filter) * goal;
    move.velocity = ClipVector(velocity, met);
    move.planeCount = count;
    return move;
}

RayResult World::CastShapeClosest(const Capsule& shape, const Transform& start, Vec2 translation,
                                  QueryFilter filter) const
{
    ClosestHit closest;
    CastShape(shape, start, translation, filter, closest);
    return closest.result;
}

RayResult World::CastShapeClosest(const Circle& shape, const Transform& start, Vec2 translation,
                                  QueryFilter filter) const
{
    ClosestHit closest;
    CastShape(shape, start, translation, filter, closest);
    return closest.result;
}

RayResult World::CastShapeClosest(const Polygon& shape, const Transform& start, Vec2 translation,
                                  QueryFilter filter) const
{
    ClosestHit closest;
    CastShape(shape, start, translation, filter, closest);
    return closest.result;
}

AABB World::GetShapeAABB(ShapeId id) const
{
    const auto* const found = ResolveShape(State(), id, "World::GetShapeAABB");
    if (found == nullptr)
    {
        return {};
    }
    const Shape& shape = *found;
    return shape.ComputeAABB(State().bodies[shape.body].xf);
}

AABB World::GetShapeFatAABB(ShapeId id) const
{
    const auto* const found = ResolveShape(State(), id, "World::GetShapeFatAABB");
    if (found == nullptr)
    {
        return {};
    }
    const Shape& shape = *found;
    return State().broadPhase.GetFatAABB(shape.proxyId);
}

} // namespace meff
