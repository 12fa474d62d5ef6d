// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The contact solver by colours (SolverKind::Colour, engine/src/solvers/colour/
// colour_contact_solver.cpp): the colouring's invariant, the SIMD sine and cosine, analytic
// answers, agreement with the island-order solver where order cannot matter, and the settled
// state of a pyramid against Box2D 2.4.1.
#include "solvers/lanes/graph_colouring.h"
#include "solvers/lanes/wide_real.h"

#include "analytic_support.h"
#include "test_random.h"

#include "meff/scene.h"
#include "meff/validation.h"
#include "meff/world.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>
#include <vector>

using namespace meff;
using namespace meff::test;
using namespace meff::analytic;
using meff::detail::ConstraintBodies;
using meff::detail::ConstraintColouring;

namespace
{

ConstraintBodies MakeConstraint(std::int32_t a, std::int32_t b, bool aMoves, bool bMoves)
{
    return ConstraintBodies{a, b, aMoves, bMoves};
}

void Colour(const std::vector<ConstraintBodies>& constraints, ConstraintColouring& colouring)
{
    std::int32_t bodyCount = 0;
    for (const ConstraintBodies& c : constraints)
    {
        bodyCount = std::max({bodyCount, c.indexA + 1, c.indexB + 1});
    }
    detail::ColourConstraints(
        constraints.size(), static_cast<std::size_t>(bodyCount),
        [&](std::size_t i) { return constraints[i]; }, colouring);
}

/// Every constraint exactly once, in colours or the overflow; no colour writes a body twice;
/// island order kept within a colour.
void CheckColouring(const std::vector<ConstraintBodies>& constraints,
                    const ConstraintColouring& colouring)
{
    std::multiset<std::int32_t> seen(colouring.order.begin(), colouring.order.end());
    seen.insert(colouring.overflow.begin(), colouring.overflow.end());
    REQUIRE(seen.size() == constraints.size());
    for (std::size_t i = 0; i < constraints.size(); ++i)
    {
        REQUIRE(seen.count(static_cast<std::int32_t>(i)) == 1);
    }
    for (int c = 0; c < colouring.ColourCount(); ++c)
    {
        std::set<std::int32_t> written;
        std::int32_t previous = -1;
        for (std::int32_t k = colouring.colourStarts[c]; k < colouring.colourStarts[c + 1]; ++k)
        {
            const std::int32_t i = colouring.order[k];
            CHECK(i > previous);
            previous = i;
            const ConstraintBodies& c = constraints[i];
            if (c.movesA)
            {
                CHECK(written.insert(c.indexA).second);
            }
            if (c.movesB)
            {
                CHECK(written.insert(c.indexB).second);
            }
        }
    }
}

/// A world on Box2D's benchmark ground (a static box 2·halfWidth wide whose top is y = 0),
/// solving by colour or in the island order.
std::pair<World, BodyId> MakeGroundedWorld(bool coloured, Real halfWidth = 50)
{
    WorldDef def;
    def.solver.kind = coloured ? SolverKind::Colour : SolverKind::Box2D;
    def.allowSleep = false; // bodies at rest are read step after step (their contact support)
    World world(def);
    const BodyId ground = world.CreateBody({});
    world.CreateShape(ground, ShapeDef{}, MakeOffsetBox(halfWidth, 1, {0, -1}, 0));
    return {std::move(world), ground};
}

/// Each body's normal impulse over the last step, summed over its reported points (N·s).
std::vector<double> NormalSupport(const World& world, const std::vector<BodyId>& bodies)
{
    std::vector<double> support(bodies.size(), 0);
    for (const ContactPointReport& point : world.GetContactReports())
    {
        for (std::size_t i = 0; i < bodies.size(); ++i)
        {
            if (point.bodyA == bodies[i] || point.bodyB == bodies[i])
            {
                support[i] += point.normalImpulse;
            }
        }
    }
    return support;
}

} // namespace

TEST_CASE("Graph colouring: no colour moves a body twice; static bodies are shared", "[colouring]")
{
    Random random(7);
    std::vector<ConstraintBodies> constraints;
    // Body 0 static, bodies 1..40 dynamic: random pairs, many touching body 0.
    for (int i = 0; i < 300; ++i)
    {
        const std::int32_t a = random.Index(4) == 0 ? 0 : 1 + random.Index(40);
        std::int32_t b = 1 + random.Index(40);
        if (b == a)
        {
            b = 1 + (b % 40);
        }
        constraints.push_back(MakeConstraint(a, b, a != 0, true));
    }
    ConstraintColouring colouring;
    Colour(constraints, colouring);
    CheckColouring(constraints, colouring);
    CHECK(colouring.overflow.empty());

    // Contacts with only the static body and distinct dynamic ones all fit in one colour.
    std::vector<ConstraintBodies> onGround;
    for (int i = 1; i <= 50; ++i)
    {
        onGround.push_back(MakeConstraint(0, i, false, true));
    }
    Colour(onGround, colouring);
    CheckColouring(onGround, colouring);
    CHECK(colouring.ColourCount() == 1);
}

TEST_CASE("Graph colouring: a body with more contacts than colours overflows the rest",
          "[colouring]")
{
    // One dynamic body (0) touching 70 others: each contact needs its own colour.
    std::vector<ConstraintBodies> constraints;
    for (int i = 1; i <= 70; ++i)
    {
        constraints.push_back(MakeConstraint(0, i, true, true));
    }
    ConstraintColouring colouring;
    Colour(constraints, colouring);
    CheckColouring(constraints, colouring);
    CHECK(colouring.ColourCount() == detail::kMaxColours);
    CHECK(colouring.overflow.size() == 70 - detail::kMaxColours);
    // The overflow keeps island order: the last six contacts.
    CHECK(colouring.overflow.front() == detail::kMaxColours);
}

TEST_CASE("SIMD sine and cosine agree with the standard library", "[colouring]")
{
    Random random(11);
    double worst = 0;
    for (int i = 0; i < 20000; ++i)
    {
        detail::RealW angles{};
        for (int l = 0; l < detail::kLanes; ++l)
        {
            // Mostly the angles bodies have, some far out to exercise the reduction.
            angles[l] = i % 10 == 0 ? random.Uniform(-6000, 6000) : random.Uniform(-20, 20);
        }
        const detail::RotW q = detail::SinCosW(angles);
        for (int l = 0; l < detail::kLanes; ++l)
        {
            worst = std::max({worst, std::abs(double(q.s[l]) - std::sin(double(angles[l]))),
                              std::abs(double(q.c[l]) - std::cos(double(angles[l])))});
        }
    }
    // Two float ulps of 1 (2.4e-7): the polynomials' own error (6.5e-8 in float evaluation,
    // see SinCosW), the reduction's rounding and the polynomial's roundings each stay below one
    // ulp of values ≤ 1 in magnitude; measured: 8.2e-8.
    CHECK(worst <= 2 * double(kEps));

    // Beyond the reducible range the standard library answers, exactly (the angles go through
    // the random generator so that the compiler cannot fold std::sin at compile time).
    const detail::RealW farAngles{random.Uniform(1e5f, 1e5f), random.Uniform(-3e6f, -3e6f), 1, 2};
    const detail::RotW far = detail::SinCosW(farAngles);
    for (int l = 0; l < detail::kLanes; ++l)
    {
        CHECK(far.s[l] == std::sin(farAngles[l]));
        CHECK(far.c[l] == std::cos(farAngles[l]));
    }
}

TEST_CASE("Graph colouring: head-on circles exchange P = (1+e)(u2-u1) m_red",
          "[colouring][analytic]")
{
    const Real e = GENERATE(Real(0), Real(1));
    World world = MakeWorld({0, 0});
    SolverSettings solver = world.GetSolverSettings();
    solver.kind = SolverKind::Colour;
    world.SetSolverSettings(solver);
    const Real u1 = 4, u2 = -1;
    const BodyId b1 = AddBall(world, {-2, 0}, {u1, 0}, Real(0.5), Material(1, 0, e));
    const BodyId b2 = AddBall(world, {2, 0}, {u2, 0}, Real(0.5), Material(3, 0, e));
    const double m1 = world.GetMass(b1), m2 = world.GetMass(b2);
    int steps = 0;
    while (world.GetLinearVelocity(b1).x == u1 && steps < 240)
    {
        world.Step(kDt);
        ++steps;
    }
    REQUIRE(steps < 240);
    const double mRed = 1 / (1 / m1 + 1 / m2);
    const double P1 = (1 + e) * (u2 - u1) * mRed;
    // One contact point solved exactly in its lane: rounding only, as the island-order solver.
    const double vScale = std::abs(u1) + std::abs(u2);
    CHECK(world.GetLinearVelocity(b1).x == Approx(u1 + P1 / m1).margin(kRoundoff * vScale));
    CHECK(world.GetLinearVelocity(b2).x == Approx(u2 - P1 / m2).margin(kRoundoff * vScale));
}

TEST_CASE("Graph colouring: resting bodies hold m·g·dt and match the island-order solver",
          "[colouring][analytic]")
{
    // Boxes (two-point manifolds: block lanes) and circles (one point: scalar lanes) apart on
    // the ground: every contact touches its own body, so the colour order changes nothing and
    // both solvers must agree but for the position pass's sine and cosine (≤ 2 ulp apart).
    const auto build = [](bool coloured)
    {
        World world = MakeGroundedWorld(coloured).first;
        std::vector<BodyId> bodies;
        for (int i = 0; i < 11; ++i)
        {
            const BodyId body = world.CreateBody(
                {.type = BodyType::Dynamic, .position = {Real(-20 + 4 * i), Real(0.6)}});
            if (i % 2 == 0)
            {
                world.CreateShape(body, ShapeDef{.density = 2}, MakeBox(Real(0.5), Real(0.5)));
            }
            else
            {
                world.CreateShape(body, ShapeDef{.density = 2}, Circle{{0, 0}, Real(0.5)});
            }
            bodies.push_back(body);
        }
        return std::pair{std::move(world), bodies};
    };
    auto [coloured, colouredBodies] = build(true);
    auto [ordered, orderedBodies] = build(false);
    for (int step = 0; step < 180; ++step)
    {
        coloured.Step(kDt);
        ordered.Step(kDt);
    }
    for (std::size_t i = 0; i < colouredBodies.size(); ++i)
    {
        INFO("body " << i);
        const Vec2 p = coloured.GetPosition(colouredBodies[i]);
        const Vec2 q = ordered.GetPosition(orderedBodies[i]);
        // Resting bodies damp differences: ulp-level sine/cosine differences (≤ 2.4e-7
        // relative) in the position pass move a 0.5 m body by at most ~1e-7 m per step, and
        // they do not accumulate on a stable rest; 1e-5 m leaves a hundredfold margin.
        CHECK(std::abs(p.x - q.x) <= 1e-5);
        CHECK(std::abs(p.y - q.y) <= 1e-5);
    }
    // Each body rests: the summed normal impulse of its points is m·g·dt (float rounding of a
    // few operations on impulses of size m·g·dt).
    const std::vector<double> support = NormalSupport(coloured, colouredBodies);
    for (std::size_t i = 0; i < colouredBodies.size(); ++i)
    {
        const double mgdt = coloured.GetMass(colouredBodies[i]) * 10 * double(kDt);
        CHECK(support[i] == Approx(mgdt).epsilon(1e-4));
    }
}

TEST_CASE("Graph colouring without sleep: the awake world is one island, holding what the "
          "island search finds",
          "[colouring]")
{
    // Without sleep, solving by colour gathers the whole awake world as one island (island.h:
    // BuildWorldIsland) instead of searching islands from each awake body. No dynamic body
    // here has more than one constraint, so neither the split into islands nor the colour
    // order can change a result: the one-island world must match, bit for bit, a world that
    // allows sleep (so searches islands) but whose bodies may not sleep. One position sweep
    // per step, since the pass stops early per island but per world for the one island.
    // The scene holds what the gathering must include (contacts with static ground and with a
    // kinematic body, a lane joint to a static anchor, a joint between two dynamic bodies) and
    // leave out (a contact the pre-solve callback disabled, a sensor's overlap, a joint
    // between two static bodies), and a body created asleep, which the one-island gathering
    // must leave to the search until a ball wakes it.
    const auto build = [](bool allowSleep)
    {
        WorldDef def;
        def.solver.kind = SolverKind::Colour;
        def.solver.positionIterations = 1;
        def.allowSleep = allowSleep;
        World world(def);
        const BodyId ground = world.CreateBody({});
        world.CreateShape(ground, ShapeDef{}, MakeOffsetBox(50, 1, {0, -1}, 0));
        std::vector<BodyId> bodies;
        bodies.push_back(AddBox(world, BodyType::Dynamic, {-6, Real(0.6)}, Real(0.1), Real(0.5),
                                Real(0.5), Material(1, Real(0.6))));
        const BodyId pivot = AddAnchor(world, {0, 6});
        bodies.push_back(AddBall(world, {1, 6}, {0, 0}, Real(0.25), Material(1, 0)));
        world.CreateJoint(world.MakeRevoluteJointDef(pivot, bodies.back(), {0, 6}));
        // A free pair of balls joined to each other, high enough not to land within the run.
        bodies.push_back(AddBall(world, {-20, 20}, {1, 0}, Real(0.25), Material(1, 0)));
        bodies.push_back(AddBall(world, {-19, 20}, {0, 2}, Real(0.25), Material(1, 0)));
        world.CreateJoint(world.MakeRevoluteJointDef(bodies[2], bodies[3], {Real(-19.5), 20}));
        world.CreateJoint(
            world.MakeRevoluteJointDef(pivot, AddAnchor(world, {0, 8}), {0, 7})); // static pair
        const BodyId platform =
            AddBox(world, BodyType::Kinematic, {6, 3}, 0, 1, Real(0.2), Material(1, Real(0.6)));
        world.SetLinearVelocity(platform, {1, 0});
        bodies.push_back(platform);
        bodies.push_back(AddBox(world, BodyType::Dynamic, {6, Real(3.75)}, 0, Real(0.5), Real(0.5),
                                Material(1, Real(0.6))));
        ShapeDef sensor;
        sensor.isSensor = true;
        world.CreateShape(AddAnchor(world, {12, 2}), sensor, MakeBox(1, 1));
        bodies.push_back(AddBall(world, {12, 4}, {0, 0}, Real(0.25), Material(1, 0)));
        // A ball the pre-solve callback lets fall through the ground: its touching contact is
        // disabled, and solving it would hold the ball up.
        const BodyId ghost = AddBall(world, {18, 1}, {0, 0}, Real(0.25), Material(1, 0));
        bodies.push_back(ghost);
        world.SetPreSolveCallback([ghost](const PreSolveContact& c)
                                  { return c.bodyA != ghost && c.bodyB != ghost; });
        BodyDef asleep;
        asleep.type = BodyType::Dynamic;
        asleep.position = {-12, 20};
        asleep.awake = false;
        bodies.push_back(world.CreateBody(asleep));
        world.CreateShape(bodies.back(), Material(1, Real(0.6)), MakeBox(Real(0.5), Real(0.5)));
        bodies.push_back(AddBall(world, {-12, Real(21.5)}, {0, 0}, Real(0.25), Material(1, 0)));
        for (const BodyId body : bodies)
        {
            if (world.GetType(body) == BodyType::Dynamic)
            {
                world.SetSleepingAllowed(body, false);
            }
        }
        // SetSleepingAllowed(false) wakes a body: the sleeper sleeps again until hit.
        world.SetAwake(bodies[bodies.size() - 2], false);
        // Dead slots among the bodies and joints, which the gathering must skip.
        const BodyId doomed = AddBall(world, {30, 5}, {0, 0}, Real(0.25), Material(1, 0));
        world.CreateJoint(world.MakeRevoluteJointDef(pivot, doomed, {30, 6}));
        world.DestroyBody(doomed);
        return std::pair{std::move(world), bodies};
    };
    auto [oneIsland, oneBodies] = build(false);
    auto [searched, searchedBodies] = build(true);
    const BodyId sleeper = oneBodies[oneBodies.size() - 2];
    bool sleeperWoke = false;
    for (int step = 0; step < 90; ++step)
    {
        oneIsland.Step(kDt);
        searched.Step(kDt);
        sleeperWoke = sleeperWoke || oneIsland.IsAwake(sleeper);
        INFO("step " << step);
        for (std::size_t i = 0; i < oneBodies.size(); ++i)
        {
            INFO("body " << i);
            // Exactly equal: the same rows, solved in lanes that compute each constraint
            // alone, with no body in two constraints.
            REQUIRE(oneIsland.GetPosition(oneBodies[i]) == searched.GetPosition(searchedBodies[i]));
            REQUIRE(oneIsland.GetAngle(oneBodies[i]) == searched.GetAngle(searchedBodies[i]));
            REQUIRE(oneIsland.GetLinearVelocity(oneBodies[i]) ==
                    searched.GetLinearVelocity(searchedBodies[i]));
            REQUIRE(oneIsland.GetAngularVelocity(oneBodies[i]) ==
                    searched.GetAngularVelocity(searchedBodies[i]));
        }
    }
    // What the comparison covers happened: the sleeper was hit and woke, the box rode the
    // platform, the ball fell through the sensor to the ground, the ghost through the ground.
    CHECK(sleeperWoke);
    CHECK(oneIsland.GetPosition(oneBodies[5]).x > Real(6.5));
    CHECK(oneIsland.GetPosition(oneBodies[6]).y < Real(0.5));
    CHECK(oneIsland.GetPosition(oneBodies[7]).y < Real(-1));
}

TEST_CASE("Graph colouring: lanes prepare every manifold type as the island order does",
          "[colouring]")
{
    // Isolated contacts, each on its own dynamic body, so that the colour order changes
    // nothing: tilted boxes landing on a corner with the ground as shape B (FaceB) and as shape
    // A (FaceA), a ball on the ground (polygon and circle), two balls colliding in the air
    // (Circles), all bouncy (restitution bias), with a varying dt (warm-start scaling). The
    // lanes prepare their rows from the contacts (colour_contact_prepare.cpp) and the island
    // order by WorldManifold: both must give the same motion, and the same hit events (which
    // read the approach velocities the preparation records), for each solver option.
    struct Options
    {
        bool blockSolver, warmStarting, fromStepStart;
    };
    const Options options[] = {
        {true, true, false}, {false, true, false}, {true, false, false}, {true, true, true}};
    for (const Options& option : options)
    {
        const auto build = [&](bool coloured)
        {
            WorldDef def;
            def.solver.kind = coloured ? SolverKind::Colour : SolverKind::Box2D;
            def.solver.blockSolver = option.blockSolver;
            def.solver.warmStarting = option.warmStarting;
            def.solver.restitutionFromStepStart = option.fromStepStart;
            World world(def);
            ShapeDef bouncy = Material(1, Real(0.4), Real(0.5));
            bouncy.enableHitEvents = true; // the lanes' approach velocities feed hit events
            std::vector<BodyId> bodies;
            // Created before the ground: the box is shape A and the ground's face, which the
            // corner hits, is the reference (FaceB).
            bodies.push_back(
                AddBox(world, BodyType::Dynamic, {-8, 1}, Real(0.5), Real(0.5), Real(0.3), bouncy));
            const BodyId ground = world.CreateBody({});
            world.CreateShape(ground, ShapeDef{}, MakeOffsetBox(50, 1, {0, -1}, 0));
            bodies.push_back(AddBox(world, BodyType::Dynamic, {-4, 1}, Real(-0.7), Real(0.4),
                                    Real(0.2), bouncy));
            bodies.push_back(AddBall(world, {0, 1}, {1, -2}, Real(0.3), bouncy));
            // Two weightless balls meeting high above the ground, off-centre.
            for (const Real side : {Real(-1), Real(1)})
            {
                BodyDef def;
                def.type = BodyType::Dynamic;
                def.position = {6 + side, 8 + Real(0.2) * side};
                def.linearVelocity = {-3 * side, 0};
                def.gravityScale = 0;
                bodies.push_back(world.CreateBody(def));
                world.CreateShape(bodies.back(), bouncy, Circle{{0, 0}, Real(0.4)});
            }
            return std::pair{std::move(world), bodies};
        };
        auto [coloured, colouredBodies] = build(true);
        auto [ordered, orderedBodies] = build(false);
        double largest = 0;
        int hits = 0;
        for (int step = 0; step < 120; ++step)
        {
            const Real dt = step % 3 == 2 ? Real(1.0 / 90.0) : kDt;
            coloured.Step(dt);
            ordered.Step(dt);
            INFO("block " << option.blockSolver << " warm " << option.warmStarting
                          << " from step start " << option.fromStepStart << ", step " << step);
            REQUIRE(coloured.GetContactReports().size() == ordered.GetContactReports().size());
            const auto colouredHits = coloured.GetContactHitEvents();
            const auto orderedHits = ordered.GetContactHitEvents();
            REQUIRE(colouredHits.size() == orderedHits.size());
            for (std::size_t i = 0; i < colouredHits.size(); ++i)
            {
                hits += 1;
                largest = std::max<double>(largest, std::abs(colouredHits[i].approachSpeed -
                                                             orderedHits[i].approachSpeed));
            }
            for (std::size_t i = 0; i < colouredBodies.size(); ++i)
            {
                largest =
                    std::max<double>(largest, Distance(coloured.GetPosition(colouredBodies[i]),
                                                       ordered.GetPosition(orderedBodies[i])));
                largest = std::max<double>(largest, std::abs(coloured.GetAngle(colouredBodies[i]) -
                                                             ordered.GetAngle(orderedBodies[i])));
            }
        }
        INFO("largest difference " << largest << ", hit events " << hits);
        CHECK(hits >= 4); // at least the three landings and the balls' meeting (13 to 16 measured)
        // The lanes do the scalar preparation's operations in the same order; the two can
        // differ only by the sine and cosine the lanes compute (SinCosW, within 2 ulp of
        // std::sin/std::cos): 2.4e-7 relative on lever arms under a metre, grown through a few
        // bounces. Measured: 0 (bit-identical) for all four options. A lane with a wrong normal,
        // lever arm or bias is off by millimetres or more at the first impact.
        CHECK(largest < 1e-5);
    }
}

TEST_CASE("Graph colouring: a needle's two close points drop the second, as the island order does",
          "[colouring]")
{
    // A box 4 mm wide standing on its end: its two contact points are 4 mm apart, so the
    // block solver's K is ill-conditioned (k11² ≥ kMaxConditionNumber·det K) and only the
    // first point is solved, in the lanes (colour_contact_prepare.cpp) as in the island
    // order (contact_solver.cpp). One isolated contact, so the colour order changes nothing.
    const auto build = [](bool coloured)
    {
        World world = MakeGroundedWorld(coloured).first;
        const BodyId needle = AddBox(world, BodyType::Dynamic, {0, Real(0.5)}, 0, Real(0.002),
                                     Real(0.5), Material(1, Real(0.6)));
        return std::pair{std::move(world), needle};
    };
    auto [coloured, colouredNeedle] = build(true);
    auto [ordered, orderedNeedle] = build(false);
    for (int step = 0; step < 20; ++step)
    {
        coloured.Step(kDt);
        ordered.Step(kDt);
        INFO("step " << step);
        // One point solved and reported in both, the second dropped.
        REQUIRE(coloured.GetContactReports().size() == 1);
        REQUIRE(ordered.GetContactReports().size() == 1);
        // Both solve the same single row; they differ only by the position pass's SIMD sine
        // and cosine (≤ 2.4e-7 relative): 1e-6 m over 20 steps of a 1 m needle.
        CHECK(Distance(coloured.GetPosition(colouredNeedle), ordered.GetPosition(orderedNeedle)) <
              1e-6);
        CHECK(std::abs(coloured.GetAngle(colouredNeedle) - ordered.GetAngle(orderedNeedle)) < 1e-6);
    }
}

TEST_CASE("Graph colouring: a plank holding more boxes than there are colours still holds them",
          "[colouring][analytic]")
{
    // 70 boxes resting on one dynamic plank: the plank is in 71 contacts (70 boxes and the
    // ground), more than the 64 colours, so 7 of its contacts go to the overflow and are
    // solved one by one after the lanes, in the same island. Every box must still rest on the
    // plank, held by m·g·dt per step, and the ground must carry everything.
    auto [world, ground] = MakeGroundedWorld(true, 100);
    const BodyId plank = AddBox(world, BodyType::Dynamic, {0, Real(0.25)}, 0, 40, Real(0.25),
                                Material(1, Real(0.6)));
    std::vector<BodyId> boxes;
    for (int i = 0; i < 70; ++i)
    {
        boxes.push_back(AddBox(world, BodyType::Dynamic, {Real(-34.5 + i), Real(0.75)}, 0,
                               Real(0.25), Real(0.25), Material(1, Real(0.6))));
    }
    for (int step = 0; step < 120; ++step)
    {
        world.Step(kDt);
    }
    const std::vector<double> support = NormalSupport(world, boxes);
    const double groundSupport = NormalSupport(world, {ground})[0];
    double totalMass = world.GetMass(plank);
    for (std::size_t i = 0; i < boxes.size(); ++i)
    {
        INFO("box " << i);
        // Resting on the plank, which rests on the ground: two contacts below the box, each
        // 0.02 m of polygon skins thick and each resting between 0 and the linear slop
        // (0.005 m) of penetration, so the box's centre is at 0.75 + 2·0.02 − [0, 2·0.005].
        const double y = world.GetPosition(boxes[i]).y;
        CHECK(y > 0.78 - 1e-4);
        CHECK(y < 0.79 + 1e-4);
        const double mgdt = world.GetMass(boxes[i]) * 10 * double(kDt);
        // Float rounding of a few operations on impulses of size m·g·dt, as the resting test.
        CHECK(support[i] == Approx(mgdt).epsilon(1e-4));
        totalMass += world.GetMass(boxes[i]);
    }
    CHECK(groundSupport == Approx(totalMass * 10 * double(kDt)).epsilon(1e-4));
}

TEST_CASE("Graph colouring: pyramid20 settles where Box2D 2.4.1's does", "[colouring][validation]")
{
    meff::Scene scene = meff::LoadScene(
        (std::filesystem::path(MEFF_SOURCE_DIR) / "samples" / "bench" / "pyramid20.json").string());
    scene.world.solver.kind = SolverKind::Colour;
    // Another Gauss-Seidel order from the first step: no frame-by-frame agreement is expected
    // (horizon 0), only the settled state. 0.02 m: a twenty-fifth of a box; the measured
    // largest difference after 500 steps is 9 mm, from the order's different sag of the rows.
    scene.validation.chaotic = true;
    scene.validation.horizonFrames = 0;
    scene.validation.settle =
        meff::SceneSettleCheck{.position = 0.02, .angle = 0.01, .minimumHeight = 0.45};
    const auto result = meff::validation::Validate(scene);
    REQUIRE(result.settle);
    INFO("largest |dp| " << result.settle->position << " at " << result.settle->positionBody);
    CHECK(result.settle->passed);
    CHECK(result.settle->position > 0); // the order did change something: the mode is on
}

TEST_CASE("Graph colouring: a tumbler's boxes tumble as in Box2D's order, on average",
          "[colouring][validation]")
{
    // The tumbler is chaotic: after a few hundred steps no box is where it is in Box2D's
    // order, so only the pile as a whole can agree. The bench scene with 15 x 15 of its boxes,
    // turned through 150 degrees in 360 steps, in Box2D's order (bit-identical to Box2D
    // 2.4.1, see the validation tests) and by colour: no box may leave the container, and the
    // pile's mean height and mean speed over the last 3 s (an average over 225 boxes and 180
    // steps, which the chaos of single boxes hardly moves) must agree within the size of one
    // box, 0.25 m, and 0.25 m/s. Measured: 0.017 m and 0.012 m/s apart; lanes whose friction
    // bound is cut to 30 % put them 1.2 m and 0.56 m/s apart.
    meff::Scene scene = meff::LoadScene(
        (std::filesystem::path(MEFF_SOURCE_DIR) / "samples" / "bench" / "tumbler.json").string());
    std::erase_if(scene.bodies,
                  [](const meff::SceneBody& body)
                  {
                      int row = 0, column = 0;
                      return std::sscanf(body.name.c_str(), "box%d_%d", &row, &column) == 2 &&
                             (row >= 15 || column >= 15);
                  });
    REQUIRE(scene.bodies.size() == 2 + 15 * 15);
    struct Pile
    {
        double meanHeight = 0, meanSpeed = 0; ///< over the boxes and the last 180 steps
        int inside = 0;                       ///< boxes inside the container at the end
    };
    const auto run = [&scene](bool coloured)
    {
        meff::Scene copy = scene;
        copy.world.solver.kind = coloured ? SolverKind::Colour : SolverKind::Box2D;
        meff::BuiltScene built = meff::BuildWorld(copy);
        Pile pile;
        for (int step = 0; step < 360; ++step)
        {
            built.world.Step(kDt);
            if (step < 180)
            {
                continue;
            }
            for (std::size_t i = 2; i < built.bodies.size(); ++i)
            {
                pile.meanHeight += built.world.GetPosition(built.bodies[i]).y;
                pile.meanSpeed += built.world.GetLinearVelocity(built.bodies[i]).Length();
            }
        }
        pile.meanHeight /= 225.0 * 180;
        pile.meanSpeed /= 225.0 * 180;
        const Transform xf = built.world.GetTransform(built.bodyByName.at("tumbler"));
        for (std::size_t i = 2; i < built.bodies.size(); ++i)
        {
            const Vec2 local = MulT(xf, built.world.GetPosition(built.bodies[i]));
            // The walls' inner faces are 9.5 m from the centre.
            pile.inside += std::abs(local.x) < Real(9.5) && std::abs(local.y) < Real(9.5);
        }
        return pile;
    };
    const Pile ordered = run(false);
    const Pile coloured = run(true);
    INFO("mean height " << ordered.meanHeight << " / " << coloured.meanHeight << ", mean speed "
                        << ordered.meanSpeed << " / " << coloured.meanSpeed);
    CHECK(ordered.inside == 225);
    CHECK(coloured.inside == 225);
    CHECK(std::abs(coloured.meanHeight - ordered.meanHeight) < 0.25);
    CHECK(std::abs(coloured.meanSpeed - ordered.meanSpeed) < 0.25);
}
