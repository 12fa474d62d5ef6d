// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// World::Draw through the DebugDraw interface: which primitives a world turns into, in which
// colours, and that the flags switch each part on and off. No graphics involved.
#include "meff/debug_draw.h"
#include "meff/world.h"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

using namespace meff;

namespace
{

/// Remembers every call as a short line, e.g. "solid_circle r=0.5".
class RecordingDraw final : public DebugDraw
{
  public:
    std::vector<std::string> calls;
    std::vector<DrawColor> colors;

    void DrawPolygon(std::span<const Vec2> vertices, const DrawColor& color) override
    {
        Record("polygon n=" + std::to_string(vertices.size()), color);
    }
    void DrawSolidPolygon(std::span<const Vec2> vertices, const DrawColor& color) override
    {
        Record("solid_polygon n=" + std::to_string(vertices.size()), color);
    }
    void DrawCircle(Vec2, Real, const DrawColor& color) override { Record("circle", color); }
    void DrawSolidCircle(Vec2, Real radius, Vec2 axis, const DrawColor& color) override
    {
        Record("solid_circle", color);
        radii.push_back(radius);
        axes.push_back(axis);
    }
    void DrawSegment(Vec2 p1, Vec2 p2, const DrawColor& color) override
    {
        Record("segment", color);
        segments.push_back({p1, p2});
    }
    void DrawTransform(const Transform&) override { Record("transform", DrawColor{}); }
    void DrawPoint(Vec2, Real, const DrawColor& color) override { Record("point", color); }

    int Count(const std::string& call) const
    {
        int n = 0;
        for (const std::string& c : calls)
        {
            n += c == call ? 1 : 0;
        }
        return n;
    }

    std::vector<Real> radii;
    std::vector<Vec2> axes;
    std::vector<std::pair<Vec2, Vec2>> segments;

  private:
    void Record(std::string call, const DrawColor& color)
    {
        calls.push_back(std::move(call));
        colors.push_back(color);
    }
};

bool Same(const DrawColor& a, const DrawColor& b)
{
    return a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a;
}

} // namespace

TEST_CASE("World::Draw draws each shape in its body type's colour", "[debug_draw]")
{
    World world{WorldDef{}};
    const BodyId ground = world.CreateBody(BodyDef{});
    world.CreateShape(ground, ShapeDef{}, Segment{{-5, 0}, {5, 0}});
    const BodyId platform =
        world.CreateBody(BodyDef{.type = BodyType::Kinematic, .position = {0, 2}});
    world.CreateShape(platform, ShapeDef{}, MakeBox(1, Real(0.1)));
    const BodyId ball =
        world.CreateBody(BodyDef{.type = BodyType::Dynamic, .position = {3, 1}, .angle = kPi / 2});
    world.CreateShape(ball, ShapeDef{}, Circle{{0, 0}, Real(0.5)});

    RecordingDraw draw;
    const DrawFlags flags;
    world.Draw(draw, flags);
    // Creation order: the ground segment, the platform (filled, then its angle line), the ball.
    REQUIRE(draw.calls ==
            std::vector<std::string>{"segment", "solid_polygon n=4", "segment", "solid_circle"});
    CHECK(Same(draw.colors[0], flags.colors.staticBody));
    CHECK(Same(draw.colors[1], flags.colors.kinematicBody));
    CHECK(Same(draw.colors[3], flags.colors.dynamicBody));
    // Three body types, three colours, and a fourth for sleeping bodies.
    CHECK_FALSE(Same(flags.colors.staticBody, flags.colors.kinematicBody));
    CHECK_FALSE(Same(flags.colors.kinematicBody, flags.colors.dynamicBody));
    CHECK_FALSE(Same(flags.colors.dynamicBody, flags.colors.sleepingBody));
    CHECK_FALSE(Same(flags.colors.staticBody, flags.colors.sleepingBody));
    // Put to sleep, the ball is drawn in the sleeping colour.
    world.SetAwake(ball, false);
    RecordingDraw asleep;
    world.Draw(asleep, flags);
    REQUIRE(asleep.colors.size() == draw.colors.size());
    CHECK(Same(asleep.colors[3], flags.colors.sleepingBody));
    // The ball, turned a quarter turn, shows it with its axis pointing up.
    CHECK(draw.radii[0] == Real(0.5));
    CHECK(double(draw.axes[0].x) == Approx(0).margin(1e-6));
    CHECK(double(draw.axes[0].y) == Approx(1));
    // The platform's angle line runs from its centre to the middle of its right side.
    const auto [from, to] = draw.segments[1];
    CHECK(double(from.x) == Approx(0).margin(1e-6));
    CHECK(double(from.y) == Approx(2));
    CHECK(double(to.x) == Approx(1));
    CHECK(double(to.y) == Approx(2));
}

TEST_CASE("World::Draw flags add joints, contacts, impulses and boxes", "[debug_draw]")
{
    World world{WorldDef{}};
    const BodyId ground = world.CreateBody(BodyDef{});
    world.CreateShape(ground, ShapeDef{}, Segment{{-5, 0}, {5, 0}});
    const BodyId box = world.CreateBody(BodyDef{.type = BodyType::Dynamic, .position = {0, 0.5f}});
    world.CreateShape(box, ShapeDef{}, MakeBox(Real(0.5), Real(0.5)));
    const BodyId bob = world.CreateBody(BodyDef{.type = BodyType::Dynamic, .position = {3, 3}});
    world.CreateShape(bob, ShapeDef{}, Circle{{0, 0}, Real(0.25)});
    world.CreateJoint(world.MakeRevoluteJointDef(ground, bob, {3, 4}));
    for (int i = 0; i < 10; ++i)
    {
        world.Step(Real(1) / Real(60));
    }
    const int points = int(world.GetContactReports().size());
    REQUIRE(points == 2); // the box rests on the ground on its two bottom corners

    RecordingDraw shapesOnly;
    world.Draw(shapesOnly, DrawFlags{.joints = false});
    CHECK(shapesOnly.Count("point") == 0);

    RecordingDraw all;
    world.Draw(all, DrawFlags{.joints = true,
                              .contacts = true,
                              .contactImpulses = true,
                              .jointReactions = true,
                              .aabbs = true,
                              .centersOfMass = true});
    // Two anchor points of the joint, one point per contact.
    CHECK(all.Count("point") == 2 + points);
    CHECK(all.Count("polygon n=4") == 3); // one box per shape
    CHECK(all.Count("transform") == 3);   // one per body
    // Segments: ground; box angle line; joint (bob's centre to its anchor, anchor to anchor);
    // a normal per contact point; three strokes per impulse arrow (contacts and the joint).
    CHECK(all.Count("segment") == 1 + 1 + 2 + points + 3 * (points + 1));
    const DrawFlags defaults;
    bool sawImpulse = false;
    bool sawReaction = false;
    for (const DrawColor& color : all.colors)
    {
        sawImpulse = sawImpulse || Same(color, defaults.colors.contactImpulse);
        sawReaction = sawReaction || Same(color, defaults.colors.jointReaction);
    }
    CHECK(sawImpulse);
    CHECK(sawReaction);
}

TEST_CASE("DrawArrow draws a shaft and a two-stroke head, nothing when empty", "[debug_draw]")
{
    RecordingDraw draw;
    DrawArrow(draw, {0, 0}, {2, 0}, Real(0.3), DrawColor{});
    REQUIRE(draw.Count("segment") == 3);
    CHECK(double(draw.segments[1].second.x) == Approx(1.7));
    CHECK(double(draw.segments[1].second.y) == Approx(0.15));
    RecordingDraw empty;
    DrawArrow(empty, {1, 1}, {1, 1}, Real(0.3), DrawColor{});
    CHECK(empty.calls.empty());
}

TEST_CASE("World::Draw draws a chain's segments with a tick on their solid side", "[debug_draw]")
{
    World world{WorldDef{}};
    const BodyId ground = world.CreateBody(BodyDef{});
    // Listed right to left: solid side up.
    const std::vector<Vec2> points{{4, 0}, {0, 0}, {-4, 0}};
    world.CreateChain(ground, ShapeDef{}, Chain{.points = points});
    RecordingDraw draw;
    world.Draw(draw, DrawFlags{});
    // Each segment, then a tick from its middle along the normal: 0.1 of its length, at most
    // 0.25 m, so 0.25 m up for these 4 m segments.
    REQUIRE(draw.calls == std::vector<std::string>{"segment", "segment", "segment", "segment"});
    for (int k = 0; k < 2; ++k)
    {
        const auto [p1, p2] = draw.segments[std::size_t(2 * k)];
        const auto [tail, tip] = draw.segments[std::size_t(2 * k + 1)];
        CHECK(double(p1.y) == 0);
        CHECK(double(p2.y) == 0);
        CHECK(double(tail.x) == Approx(0.5 * (p1.x + p2.x)));
        CHECK(double(tail.y) == 0);
        CHECK(double(tip.x) == Approx(tail.x));
        CHECK(double(tip.y) == Approx(0.25));
    }
}

TEST_CASE("World::Draw draws gear and friction joints as b2Joint::Draw: centres, anchors, the line "
          "between",
          "[debug_draw]")
{
    // Two wheels on hinges to the ground, 3 m apart, coupled by a gear; a box held by a
    // friction joint at (6, 1). Shapes off: only joints are drawn, in creation order.
    World world{WorldDef{.gravity = {0, 0}}};
    const BodyId ground = world.CreateBody(BodyDef{});
    const auto wheel = [&](Vec2 at)
    {
        const BodyId body = world.CreateBody(BodyDef{.type = BodyType::Dynamic, .position = at});
        world.CreateShape(body, ShapeDef{}, Circle{{0, 0}, Real(0.5)});
        return body;
    };
    const BodyId left = wheel({0, 2});
    const BodyId right = wheel({3, 2});
    const JointId hingeL = world.CreateJoint(world.MakeRevoluteJointDef(ground, left, {0, 2}));
    const JointId hingeR = world.CreateJoint(world.MakeRevoluteJointDef(ground, right, {3, 2}));
    world.CreateJoint(GearJointDef{hingeL, hingeR, 2, false});
    const BodyId box = world.CreateBody(BodyDef{.type = BodyType::Dynamic, .position = {6, 0}});
    world.CreateShape(box, ShapeDef{}, MakeBox(Real(0.5), Real(0.5)));
    world.CreateJoint(world.MakeFrictionJointDef(ground, box, {6, 1}));

    RecordingDraw draw;
    DrawFlags flags;
    flags.shapes = false;
    world.Draw(draw, flags);
    using Segment = std::pair<Vec2, Vec2>;
    const auto drawn = [&](Vec2 a, Vec2 b)
    {
        for (const Segment& s : draw.segments)
        {
            if ((s.first == a && s.second == b) || (s.first == b && s.second == a))
            {
                return true;
            }
        }
        return false;
    };
    // The gear's bodies are the hinges' wheels, its anchors their hubs: the line between the
    // two wheel centres is the gear.
    CHECK(drawn({0, 2}, {3, 2}));
    // The friction joint: the box's centre to its anchor, and the (coincident) anchors; the
    // static ground's origin is left out.
    CHECK(drawn({6, 0}, {6, 1}));
    CHECK_FALSE(drawn({0, 0}, {6, 1}));
    // Two anchor points per joint: two hinges, the gear, the friction joint.
    CHECK(draw.Count("point") == 2 * 4);
}
