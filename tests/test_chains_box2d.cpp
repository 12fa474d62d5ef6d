// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Golden checks of chains and one-sided segments against Box2D 2.4.1 itself (libbox2d): the
// segment manifolds against b2CollideEdgeAndPolygon and b2CollideEdgeAndCircle for one-sided
// edges with random ghost vertices (and for two-sided ones), the ray casts against
// b2EdgeShape::RayCast and b2ChainShape::RayCast, and a world of chains, built through the
// API, stepped beside a b2World of b2ChainShape fixtures: every body's state bit for bit at
// every step, through a chain on a moving kinematic body and a chain destroyed and re-made
// mid-run.
#ifndef MEFF_DOUBLE

#include "meff/collision.h"
#include "meff/ray_cast.h"
#include "meff/world.h"

#include <box2d/box2d.h>

#include <catch2/catch.hpp>

#include "box2d_shape_pair.h"
#include "test_random.h"

#include <cmath>
#include <memory>
#include <vector>

using namespace meff;
using meff::test::Pose;
using meff::test::Random;
using meff::test::RandomPose;
using meff::test::RequireSameManifold;

namespace
{

b2Vec2 ToB2(Vec2 v)
{
    return {v.x, v.y};
}

/// A one-sided segment with ghosts in both engines: ends within ±2 m, each ghost 0.3 to 2 m
/// beyond its end in a direction turned up to ±2.5 rad from the segment's, so that both
/// convex and concave neighbours, gentle and sharp, are drawn.
ChainSegment RandomChainSegment(Random& rng, b2EdgeShape& edge)
{
    for (;;)
    {
        const Vec2 v1{rng.Uniform(-2, 2), rng.Uniform(-2, 2)};
        const Vec2 v2{rng.Uniform(-2, 2), rng.Uniform(-2, 2)};
        if (DistanceSquared(v1, v2) < Real(0.01))
        {
            continue;
        }
        const Real heading = std::atan2(v2.y - v1.y, v2.x - v1.x);
        const Real turn0 = rng.Uniform(-2.5f, 2.5f);
        const Real length0 = rng.Uniform(0.3f, 2.0f);
        const Real turn3 = rng.Uniform(-2.5f, 2.5f);
        const Real length3 = rng.Uniform(0.3f, 2.0f);
        const Vec2 v0 = v1 - length0 * Vec2(std::cos(heading + turn0), std::sin(heading + turn0));
        const Vec2 v3 = v2 + length3 * Vec2(std::cos(heading + turn3), std::sin(heading + turn3));
        edge.SetOneSided(ToB2(v0), ToB2(v1), ToB2(v2), ToB2(v3));
        return ChainSegment{v0, Segment{v1, v2, edge.m_radius}, v3};
    }
}

} // namespace

TEST_CASE("Segment manifolds agree bit for bit with b2CollideEdgeAndPolygon and "
          "b2CollideEdgeAndCircle, one-sided with ghosts and two-sided",
          "[manifold][chain][box2d]")
{
    Random rng(19);
    // How often each path of the one-sided test decided the outcome, measured against the
    // same segment made two-sided: culled or skipped (two-sided touches, one-sided not),
    // snapped or otherwise changed (both touch, different normals), and agreed.
    int oneSidedTouching = 0, removed = 0, changed = 0, twoSidedTouching = 0;
    int circleTouching = 0, circleRemoved = 0;
    for (int trial = 0; trial < 30000; ++trial)
    {
        b2EdgeShape b2Edge;
        const ChainSegment segment = RandomChainSegment(rng, b2Edge);
        const Pose poseA = RandomPose(rng, 0.3f, 3.2f);
        const Pose poseB = RandomPose(rng, 1.5f, 3.2f);
        INFO("trial " << trial);

        b2EdgeShape b2TwoSided;
        b2TwoSided.SetTwoSided(b2Edge.m_vertex1, b2Edge.m_vertex2);
        b2Manifold expected, expectedTwoSided;
        Manifold m, twoSided;
        if (trial % 3 == 0)
        {
            b2CircleShape circle;
            circle.m_p.Set(rng.Uniform(-0.3f, 0.3f), rng.Uniform(-0.3f, 0.3f));
            circle.m_radius = rng.Uniform(0.05f, 1.0f);
            const Circle meffCircle{{circle.m_p.x, circle.m_p.y}, circle.m_radius};
            b2CollideEdgeAndCircle(&expected, &b2Edge, poseA.box2d, &circle, poseB.box2d);
            CollideChainSegmentAndCircle(m, segment, poseA.meff, meffCircle, poseB.meff);
            b2CollideEdgeAndCircle(&expectedTwoSided, &b2TwoSided, poseA.box2d, &circle,
                                   poseB.box2d);
            CollideSegmentAndCircle(twoSided, segment.segment, poseA.meff, meffCircle, poseB.meff);
            const bool touching = RequireSameManifold(m, expected);
            circleTouching += touching ? 1 : 0;
            circleRemoved += RequireSameManifold(twoSided, expectedTwoSided) && !touching;
            continue;
        }
        meff::test::ShapePair polygon;
        do
        {
            polygon = meff::test::RandomShape(rng, {0.5f, 0.05f, 1.0f, 1.0f});
        } while (polygon.type != ShapeType::Polygon);
        const auto& b2Polygon = static_cast<const b2PolygonShape&>(*polygon.box2d);
        b2CollideEdgeAndPolygon(&expected, &b2Edge, poseA.box2d, &b2Polygon, poseB.box2d);
        CollideChainSegmentAndPolygon(m, segment, poseA.meff, polygon.polygon, poseB.meff);
        b2CollideEdgeAndPolygon(&expectedTwoSided, &b2TwoSided, poseA.box2d, &b2Polygon,
                                poseB.box2d);
        CollideSegmentAndPolygon(twoSided, segment.segment, poseA.meff, polygon.polygon,
                                 poseB.meff);
        const bool touching = RequireSameManifold(m, expected);
        const bool touchingTwoSided = RequireSameManifold(twoSided, expectedTwoSided);
        oneSidedTouching += touching ? 1 : 0;
        twoSidedTouching += touchingTwoSided ? 1 : 0;
        removed += touchingTwoSided && !touching ? 1 : 0;
        changed += touching && touchingTwoSided &&
                           !(m.localNormal == twoSided.localNormal && m.type == twoSided.type)
                       ? 1
                       : 0;
    }
    // Every path was taken often. Measured with this seed, of 20000 polygons: 2553 touch the
    // one-sided segment, 5726 the two-sided one, 3173 lost their points to the back-side cull
    // or a ghost's skip, 399 were snapped to another face or normal; of 10000 circles, 1062
    // touch and 1285 were culled or skipped.
    CHECK(oneSidedTouching > 1000);
    CHECK(twoSidedTouching > 2000);
    CHECK(removed > 1000);
    CHECK(changed > 100);
    CHECK(circleTouching > 500);
    CHECK(circleRemoved > 500);
}

TEST_CASE("Segment ray casts agree with b2EdgeShape::RayCast, one-sided and two-sided",
          "[queries][chain][box2d]")
{
    Random rng(23);
    int hits = 0, frontHits = 0, backMisses = 0;
    for (int trial = 0; trial < 5000; ++trial)
    {
        b2EdgeShape b2Edge;
        const ChainSegment segment = RandomChainSegment(rng, b2Edge);
        const Pose pose = RandomPose(rng, 2, 3.2f);
        b2RayCastInput b2Input;
        b2Input.p1 =
            b2Vec2{pose.box2d.p.x + rng.Uniform(-4, 4), pose.box2d.p.y + rng.Uniform(-4, 4)};
        b2Input.p2 =
            b2Vec2{pose.box2d.p.x + rng.Uniform(-2, 2), pose.box2d.p.y + rng.Uniform(-2, 2)};
        b2Input.maxFraction = trial % 2 == 0 ? 1.0f : rng.Uniform(0.1f, 1.5f);
        const RayCastInput input{
            {b2Input.p1.x, b2Input.p1.y}, {b2Input.p2.x, b2Input.p2.y}, b2Input.maxFraction};

        b2RayCastOutput expected{};
        const bool b2Hit = b2Edge.RayCast(&expected, b2Input, pose.box2d, 0);
        RayCastOutput output;
        REQUIRE(RayCast(segment, pose.meff, input, output) == b2Hit);
        if (b2Hit)
        {
            ++frontHits;
            REQUIRE(output.fraction == expected.fraction);
            REQUIRE(output.normal.x == expected.normal.x);
            REQUIRE(output.normal.y == expected.normal.y);
        }

        // The same segment two-sided: hit from either side.
        b2EdgeShape b2TwoSided;
        b2TwoSided.SetTwoSided(b2Edge.m_vertex1, b2Edge.m_vertex2);
        const bool b2HitTwoSided = b2TwoSided.RayCast(&expected, b2Input, pose.box2d, 0);
        REQUIRE(RayCast(segment.segment, pose.meff, input, output) == b2HitTwoSided);
        backMisses += b2HitTwoSided && !b2Hit ? 1 : 0;
        if (b2HitTwoSided)
        {
            ++hits;
            REQUIRE(output.fraction == expected.fraction);
            REQUIRE(output.normal.x == expected.normal.x);
            REQUIRE(output.normal.y == expected.normal.y);
        }
    }
    // Both sides were hit, and the one-sided cast refused the back: measured 904 two-sided
    // hits, 447 from the front, 457 from behind.
    CHECK(hits > 600);
    CHECK(frontHits > 300);
    CHECK(backMisses > 300);
}

namespace
{

/// One world in both engines, built through each one's API in the same order.
struct TwinWorlds
{
    b2World box2d{b2Vec2(0, -10)};
    World meff{WorldDef{.gravity = {0, -10}, .allowSleep = false}}; // as box2d's, below
    std::vector<b2Body*> b2Bodies;
    std::vector<BodyId> bodies;

    TwinWorlds()
    {
        box2d.SetAllowSleeping(false);
        box2d.SetContinuousPhysics(true);
        box2d.SetSubStepping(false);
    }

    std::size_t AddBody(BodyType type, Vec2 position, Real angle, Vec2 velocity = {},
                        Real angularVelocity = 0)
    {
        b2BodyDef def;
        def.type = type == BodyType::Static      ? b2_staticBody
                   : type == BodyType::Kinematic ? b2_kinematicBody
                                                 : b2_dynamicBody;
        def.position = ToB2(position);
        def.angle = angle;
        def.linearVelocity = ToB2(velocity);
        def.angularVelocity = angularVelocity;
        b2Bodies.push_back(box2d.CreateBody(&def));
        bodies.push_back(meff.CreateBody(BodyDef{.type = type,
                                                 .position = position,
                                                 .angle = angle,
                                                 .linearVelocity = velocity,
                                                 .angularVelocity = angularVelocity}));
        return bodies.size() - 1;
    }

    static b2FixtureDef FixtureDef(const b2Shape* shape, const ShapeDef& def)
    {
        b2FixtureDef fixture;
        fixture.shape = shape;
        fixture.density = def.density;
        fixture.friction = def.friction;
        fixture.restitution = def.restitution;
        fixture.restitutionThreshold = def.restitutionThreshold;
        return fixture;
    }

    b2Fixture* AddChain(std::size_t body, std::span<const Vec2> points, bool loop,
                        const ShapeDef& def, ChainId& id)
    {
        std::vector<b2Vec2> b2Points;
        for (const Vec2 p : points)
        {
            b2Points.push_back(ToB2(p));
        }
        b2ChainShape chain;
        Chain meffChain{.points = points, .loop = loop};
        if (loop)
        {
            chain.CreateLoop(b2Points.data(), static_cast<int32>(b2Points.size()));
        }
        else
        {
            // meff's default ghosts continue the end segments straight on; give Box2D those.
            const Vec2 prev = points[0] + (points[0] - points[1]);
            const std::size_t n = points.size();
            const Vec2 next = points[n - 1] + (points[n - 1] - points[n - 2]);
            chain.CreateChain(b2Points.data(), static_cast<int32>(b2Points.size()), ToB2(prev),
                              ToB2(next));
        }
        const b2FixtureDef fixture = FixtureDef(&chain, def);
        id = meff.CreateChain(bodies[body], def, meffChain);
        return b2Bodies[body]->CreateFixture(&fixture);
    }

    void AddBox(std::size_t body, Real hx, Real hy, const ShapeDef& def)
    {
        b2PolygonShape box;
        box.SetAsBox(hx, hy);
        const b2FixtureDef fixture = FixtureDef(&box, def);
        b2Bodies[body]->CreateFixture(&fixture);
        meff.CreateShape(bodies[body], def, MakeBox(hx, hy));
    }

    void AddCircle(std::size_t body, Real radius, const ShapeDef& def)
    {
        b2CircleShape circle;
        circle.m_radius = radius;
        const b2FixtureDef fixture = FixtureDef(&circle, def);
        b2Bodies[body]->CreateFixture(&fixture);
        meff.CreateShape(bodies[body], def, Circle{{0, 0}, radius});
    }

    void AddOneSided(std::size_t body, Vec2 v0, Vec2 v1, Vec2 v2, Vec2 v3, const ShapeDef& def)
    {
        b2EdgeShape edge;
        edge.SetOneSided(ToB2(v0), ToB2(v1), ToB2(v2), ToB2(v3));
        const b2FixtureDef fixture = FixtureDef(&edge, def);
        b2Bodies[body]->CreateFixture(&fixture);
        meff.CreateShape(bodies[body], def, ChainSegment{v0, Segment{v1, v2}, v3});
    }

    /// Every body's transform and velocities, bit for bit.
    void RequireSame() const
    {
        for (std::size_t i = 0; i < bodies.size(); ++i)
        {
            INFO("body " << i);
            meff::test::RequireSameTransform(meff.GetTransform(bodies[i]),
                                             b2Bodies[i]->GetTransform());
            REQUIRE(meff.GetLinearVelocity(bodies[i]).x == b2Bodies[i]->GetLinearVelocity().x);
            REQUIRE(meff.GetLinearVelocity(bodies[i]).y == b2Bodies[i]->GetLinearVelocity().y);
            REQUIRE(meff.GetAngularVelocity(bodies[i]) == b2Bodies[i]->GetAngularVelocity());
        }
        REQUIRE(meff.GetContactCount() == box2d.GetContactCount());
    }

    /// Box queries over everything report the bodies of the same proxies in the same order
    /// (one report per chain child, as meff's per segment): the broad-phase trees have the
    /// same shape, which proxies created, moved and destroyed in another order would change.
    void RequireSameTree()
    {
        class Collect : public b2QueryCallback
        {
          public:
            bool ReportFixture(b2Fixture* fixture) override
            {
                bodies.push_back(fixture->GetBody());
                return true;
            }
            std::vector<const b2Body*> bodies;
        };
        b2AABB everything;
        everything.lowerBound.Set(-100, -100);
        everything.upperBound.Set(100, 100);
        Collect collect;
        box2d.QueryAABB(&collect, everything);
        std::vector<const b2Body*> reported;
        meff.OverlapAABB({{-100, -100}, {100, 100}}, {},
                         [&](ShapeId shape)
                         {
                             const BodyId body = meff.GetBody(shape);
                             for (std::size_t i = 0; i < bodies.size(); ++i)
                             {
                                 if (bodies[i] == body)
                                 {
                                     reported.push_back(b2Bodies[i]);
                                 }
                             }
                             return true;
                         });
        REQUIRE(reported == collect.bodies);
    }
};

} // namespace

TEST_CASE("A world of chains steps bit for bit beside Box2D 2.4.1's b2ChainShape", "[chain][box2d]")
{
    TwinWorlds twins;
    const ShapeDef ground{.friction = Real(0.6)};
    const std::size_t groundBody = twins.AddBody(BodyType::Static, {0, 0}, 0);
    // A zig-zag terrain from right to left (solid side up) with flat collinear runs, convex
    // and concave corners; a container loop (clockwise: solid inside); a one-sided ledge.
    const std::vector<Vec2> terrain{{20, 0}, {16, 0}, {14, 1}, {12, 1}, {10, 1},
                                    {8, 0},  {6, 0},  {4, 0},  {2, 2},  {0, 2}};
    ChainId terrainId;
    b2Fixture* terrainFixture = twins.AddChain(groundBody, terrain, false, ground, terrainId);
    const std::vector<Vec2> bowl{{-10, 8}, {-6, 2}, {-2, 2}, {-2, 8},
                                 {-4, 8},  {-4, 4}, {-8, 4}, {-8, 8}};
    ChainId bowlId;
    twins.AddChain(groundBody, bowl, true, ground, bowlId);
    twins.AddOneSided(groundBody, {26, 3}, {25, 3}, {22, 3}, {21, 2}, ground);
    // A kinematic body carrying a chain, moving right and turning.
    const std::size_t carrier = twins.AddBody(BodyType::Kinematic, {30, 2}, 0, {1, 0}, 0.1f);
    const std::vector<Vec2> tray{{2, 0}, {1, 0}, {0, 0}, {-1, 0}, {-2, 0}};
    ChainId trayId;
    twins.AddChain(carrier, tray, false, ground, trayId);

    // Dynamic shapes dropped on all of it.
    Random rng(5);
    for (int i = 0; i < 24; ++i)
    {
        const Vec2 position{rng.Uniform(-9, 31), rng.Uniform(4, 9)};
        const std::size_t body =
            twins.AddBody(BodyType::Dynamic, position, rng.Uniform(-1, 1), {rng.Uniform(-2, 2), 0});
        const ShapeDef def{.friction = rng.Uniform(0.1f, 0.8f)};
        if (i % 2 == 0)
        {
            twins.AddBox(body, rng.Uniform(0.2f, 0.6f), rng.Uniform(0.2f, 0.6f), def);
        }
        else
        {
            twins.AddCircle(body, rng.Uniform(0.2f, 0.6f), def);
        }
    }

    const float dt = 1.0f / 60.0f;
    int chainContacts = 0;
    for (int step = 1; step <= 360; ++step)
    {
        twins.box2d.Step(dt, 8, 3);
        twins.meff.Step(dt);
        INFO("step " << step);
        twins.RequireSame();
        if (step % 30 == 0)
        {
            twins.RequireSameTree();
        }
        for (const b2Contact* c = twins.box2d.GetContactList(); c != nullptr; c = c->GetNext())
        {
            chainContacts +=
                c->IsTouching() && c->GetFixtureA()->GetType() == b2Shape::e_chain ? 1 : 0;
        }
        if (step == 150)
        {
            // Destroy the terrain under whatever rests on it, then make it again: the proxies
            // go and come back in the same order, so the trees stay the same.
            twins.b2Bodies[groundBody]->DestroyFixture(terrainFixture);
            twins.meff.DestroyChain(terrainId);
            REQUIRE_FALSE(twins.meff.IsValid(terrainId));
            twins.RequireSameTree();
            terrainFixture = twins.AddChain(groundBody, terrain, false, ground, terrainId);
            twins.RequireSame();
            twins.RequireSameTree();
        }
    }
    // Touching chain contacts summed over the steps (measured 4882): the chains carried the
    // pile all along.
    CHECK(chainContacts > 3000);
}

#endif // MEFF_DOUBLE
