// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// World::Draw: the world described to a DebugDraw, as Box2D's b2World::DebugDraw does. Only
// reads the world; every list is walked in a fixed order so that the same world always gives
// the same sequence of calls (a renderer built on it is then deterministic too).
#include "dynamics/world_state.h"
#include "joints/joint.h"
#include "meff/debug_draw.h"
#include "meff/world.h"

#include <cmath>
#include <variant>
#include <vector>

namespace meff
{

using namespace detail;

void DrawArrow(DebugDraw& draw, Vec2 tail, Vec2 tip, Real head, const DrawColor& color)
{
    Vec2 direction = tip - tail;
    const Real length = direction.Normalize();
    if (length == 0)
    {
        return;
    }
    draw.DrawSegment(tail, tip, color);
    // A head longer than a third of the shaft would swallow short arrows.
    const Real h = Min(head, length / Real(3));
    const Vec2 back = tip - h * direction;
    const Vec2 side = (Real(0.5) * h) * direction.Skew();
    draw.DrawSegment(tip, back + side, color);
    draw.DrawSegment(tip, back - side, color);
}

namespace
{

DrawColor BodyColor(const Body& body, const DrawPalette& colors)
{
    switch (body.type)
    {
    case BodyType::Static:
        return colors.staticBody;
    case BodyType::Kinematic:
        return colors.kinematicBody;
    case BodyType::Dynamic:
        break;
    }
    return body.awake ? colors.dynamicBody : colors.sleepingBody;
}

/// Where a ray from `origin` (inside the convex polygon) along the unit `direction` leaves it:
/// the nearest face the ray runs towards. A polygon has no axis of its own, so its angle line
/// runs from its centroid along the body's x axis to this point.
Vec2 PolygonExit(const Polygon& polygon, Vec2 origin, Vec2 direction)
{
    Real t = kMaxReal;
    for (int i = 0; i < polygon.count; ++i)
    {
        const Real rate = Dot(polygon.normals[i], direction);
        if (rate > 0)
        {
            t = Min(t, Dot(polygon.normals[i], polygon.vertices[i] - origin) / rate);
        }
    }
    return t == kMaxReal ? origin : origin + t * direction;
}

/// The rounded outline of a capsule or rounded polygon in world coordinates: each core edge
/// pushed out by the radius, joined by arcs about the vertices (about 8 chords per half turn,
/// at least one per corner).
std::vector<Vec2> RoundedOutline(const Polygon& core, const Transform& xf)
{
    std::vector<Vec2> outline;
    const int n = core.count;
    for (int i = 0; i < n; ++i)
    {
        const Vec2 from = core.normals[i > 0 ? i - 1 : n - 1];
        const Vec2 to = core.normals[i];
        const Real turn = std::atan2(Max(Cross(from, to), Real(0)), Dot(from, to));
        const int chords = Max(1, int(std::ceil(double(turn) * 8 / double(kPi))));
        for (int k = 0; k <= chords; ++k)
        {
            const Real a = turn * Real(k) / Real(chords);
            const Vec2 dir{std::cos(a) * from.x - std::sin(a) * from.y,
                           std::sin(a) * from.x + std::cos(a) * from.y};
            outline.push_back(Mul(xf, core.vertices[i] + core.radius * dir));
        }
    }
    return outline;
}

void DrawShape(DebugDraw& draw, const Shape& shape, const Transform& xf, const DrawColor& color)
{
    switch (shape.type)
    {
    case ShapeType::Circle:
    {
        const Vec2 center = Mul(xf, shape.circle.center);
        draw.DrawSolidCircle(center, shape.circle.radius, xf.q.GetXAxis(), color);
        break;
    }
    case ShapeType::Capsule:
        // The outline, and the core as the capsule's axis line.
        draw.DrawSolidPolygon(RoundedOutline(shape.polygon, xf), color);
        draw.DrawSegment(Mul(xf, shape.capsule.center1), Mul(xf, shape.capsule.center2), color);
        break;
    case ShapeType::Polygon:
    {
        const Polygon& polygon = shape.polygon;
        Vec2 vertices[kMaxPolygonVertices];
        for (int i = 0; i < polygon.count; ++i)
        {
            vertices[i] = Mul(xf, polygon.vertices[i]);
        }
        if (shape.rounded)
        {
            draw.DrawSolidPolygon(RoundedOutline(polygon, xf), color);
        }
        else
        {
            draw.DrawSolidPolygon(std::span<const Vec2>(vertices, std::size_t(polygon.count)),
                                  color);
        }
        const Vec2 exit = PolygonExit(polygon, polygon.centroid, Vec2{1, 0});
        draw.DrawSegment(Mul(xf, polygon.centroid), Mul(xf, exit), color);
        break;
    }
    case ShapeType::Segment:
        draw.DrawSegment(Mul(xf, shape.segment.point1), Mul(xf, shape.segment.point2), color);
        break;
    case ShapeType::ChainSegment:
    {
        // As Box2D draws chains: the line; the solid side is shown by a short tick along the
        // normal from the middle (a one-sided segment seen from behind is no wall).
        const Segment& segment = shape.chainSegment.segment;
        const Vec2 p1 = Mul(xf, segment.point1);
        const Vec2 p2 = Mul(xf, segment.point2);
        draw.DrawSegment(p1, p2, color);
        Vec2 normal = Cross(p2 - p1, Real(1));
        const Real length = normal.Normalize();
        const Vec2 middle = Real(0.5) * (p1 + p2);
        draw.DrawSegment(middle, middle + Min(Real(0.1) * length, Real(0.25)) * normal, color);
        break;
    }
    }
}

void DrawAABB(DebugDraw& draw, const AABB& box, const DrawColor& color)
{
    const Vec2 corners[4] = {box.lowerBound,
                             {box.upperBound.x, box.lowerBound.y},
                             box.upperBound,
                             {box.lowerBound.x, box.upperBound.y}};
    draw.DrawPolygon(corners, color);
}

/// The travel of a prismatic or wheel joint, as b2PrismaticJoint::Draw and b2WheelJoint::Draw
/// show it: with limits, the segment from the lower to the upper limit along the axis through
/// A's anchor, with a tick across each end; without, a metre of the axis either side.
void DrawSlideAxis(DebugDraw& draw, const Joint& joint, const Transform& xfA, Vec2 anchorA,
                   const DrawColor& color)
{
    Vec2 localAxis;
    bool enableLimit = false;
    Real lower = 0, upper = 0;
    if (const auto* p = std::get_if<PrismaticJoint>(&joint.data))
    {
        localAxis = p->localXAxisA;
        enableLimit = p->enableLimit;
        lower = p->lowerTranslation;
        upper = p->upperTranslation;
    }
    else if (const auto* w = std::get_if<WheelJoint>(&joint.data))
    {
        localAxis = w->localXAxisA;
        enableLimit = w->enableLimit;
        lower = w->lowerTranslation;
        upper = w->upperTranslation;
    }
    else
    {
        return;
    }
    const Vec2 axis = Mul(xfA.q, localAxis);
    if (enableLimit)
    {
        const Vec2 lowerPoint = anchorA + lower * axis;
        const Vec2 upperPoint = anchorA + upper * axis;
        const Vec2 tick = Real(0.5) * axis.Skew();
        draw.DrawSegment(lowerPoint, upperPoint, color);
        draw.DrawSegment(lowerPoint - tick, lowerPoint + tick, color);
        draw.DrawSegment(upperPoint - tick, upperPoint + tick, color);
    }
    else
    {
        draw.DrawSegment(anchorA - axis, anchorA + axis, color);
    }
}

} // namespace

void World::Draw(DebugDraw& draw, const DrawFlags& flags) const
{
    const WorldState& world = State();
    const InWalk walk(world); // DebugDraw's methods must not change what is drawn
    if (flags.contacts || flags.contactImpulses)
    {
        // As GetContactReports: built when first needed (the state is not const, this view is).
        BuildContactReports(const_cast<WorldState&>(world));
    }
    const DrawPalette& colors = flags.colors;

    // Creation order, so that later bodies are drawn over earlier ones, as the scene lists them.
    for (const BodyId id : world.bodyIds)
    {
        const Body& body = world.bodies[std::size_t(id.index)];
        const DrawColor color = BodyColor(body, colors);
        // body.shapes is newest first; drawing oldest first keeps the scene's order.
        for (auto it = body.shapes.rbegin(); it != body.shapes.rend(); ++it)
        {
            const Shape& shape = world.shapes[std::size_t(*it)];
            if (flags.shapes)
            {
                DrawShape(draw, shape, body.xf, color);
            }
            if (flags.aabbs)
            {
                DrawAABB(draw, shape.aabb, colors.aabb);
            }
        }
        if (flags.centersOfMass)
        {
            draw.DrawTransform(Transform(body.sweep.c, body.xf.q));
        }
    }

    if (flags.joints)
    {
        for (const JointId id : world.jointIds)
        {
            const Joint& joint = world.joints[std::size_t(id.index)].joint;
            const Body& bodyA = world.bodies[std::size_t(joint.bodyA)];
            const Body& bodyB = world.bodies[std::size_t(joint.bodyB)];
            const Vec2 anchorA = JointAnchorA(joint, bodyA.xf);
            const Vec2 anchorB = JointAnchorB(joint, bodyB.xf);
            if (joint.type == JointType::Mouse)
            {
                // As b2Joint::Draw for a mouse joint: the target (anchor A), the grabbed point
                // and the line between them; body A (the ground) takes no part.
                draw.DrawPoint(anchorA, flags.pointSize, colors.joint);
                draw.DrawPoint(anchorB, flags.pointSize, colors.joint);
                draw.DrawSegment(anchorA, anchorB, colors.joint);
                continue;
            }
            if (const auto* pulley = std::get_if<PulleyJoint>(&joint.data))
            {
                // As b2Joint::Draw for a pulley: the rope from each ground anchor down to its
                // body's anchor, and across between the ground anchors.
                draw.DrawSegment(pulley->groundAnchorA, anchorA, colors.joint);
                draw.DrawSegment(pulley->groundAnchorB, anchorB, colors.joint);
                draw.DrawSegment(pulley->groundAnchorA, pulley->groundAnchorB, colors.joint);
                draw.DrawPoint(anchorA, flags.pointSize, colors.joint);
                draw.DrawPoint(anchorB, flags.pointSize, colors.joint);
                continue;
            }
            // As b2Joint::Draw: each moving body's centre to its anchor, then anchor to anchor
            // (the rod of a distance joint). A static body's origin is usually far away and
            // says nothing, so it is left out.
            if (bodyA.type != BodyType::Static)
            {
                draw.DrawSegment(bodyA.sweep.c, anchorA, colors.joint);
            }
            if (bodyB.type != BodyType::Static)
            {
                draw.DrawSegment(bodyB.sweep.c, anchorB, colors.joint);
            }
            draw.DrawSegment(anchorA, anchorB, colors.joint);
            DrawSlideAxis(draw, joint, bodyA.xf, anchorA, colors.joint);
            draw.DrawPoint(anchorA, flags.pointSize, colors.joint);
            draw.DrawPoint(anchorB, flags.pointSize, colors.joint);
        }
    }

    for (const ContactPointReport& contact : world.contactReports)
    {
        if (flags.contacts)
        {
            draw.DrawPoint(contact.point, flags.pointSize, colors.contactPoint);
            draw.DrawSegment(contact.point, contact.point + flags.normalLength * contact.normal,
                             colors.contactNormal);
        }
        if (flags.contactImpulses)
        {
            // The impulse on body B acts along the normal (A to B).
            const Vec2 tip =
                contact.point + (flags.impulseScale * contact.normalImpulse) * contact.normal;
            DrawArrow(draw, contact.point, tip, flags.arrowHead, colors.contactImpulse);
        }
    }

    if (flags.jointReactions)
    {
        for (const JointId id : world.jointIds)
        {
            const Joint& joint = world.joints[std::size_t(id.index)].joint;
            const Vec2 anchorB = JointAnchorB(joint, world.bodies[std::size_t(joint.bodyB)].xf);
            // invDt = 1: the reaction as the last step's impulse (N·s), the contacts' unit.
            const JointReaction reaction = GetJointReaction(joint, Real(1));
            DrawArrow(draw, anchorB, anchorB + flags.impulseScale * reaction.force, flags.arrowHead,
                      colors.jointReaction);
        }
    }
}

} // namespace meff
