// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The Box2D cross-validation: the comparison rules (meff/validation.h), the mirror, and that
// validation can fail.
#include "meff/box2d_mirror.h"
#include "meff/scene.h"
#include "meff/validation.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

using meff::validation::BodySample;
using meff::validation::CompareFrames;
using meff::validation::ContactSample;
using meff::validation::FrameErrors;
using meff::validation::FrameSample;
using meff::validation::JointSample;
using meff::validation::Tolerances;

namespace
{

constexpr double kDt = 1.0 / 60.0;

FrameSample TwoBodies()
{
    FrameSample frame;
    frame.bodies.push_back({});
    frame.bodies.push_back({1, 2, 0.5, 3, -1, 0.25});
    return frame;
}

bool Has(const FrameErrors& errors, const std::string& quantity)
{
    for (const std::string& exceeded : errors.exceeded)
    {
        if (exceeded == quantity)
        {
            return true;
        }
    }
    return false;
}

// A box dropped on the ground next to a ball rolling into it: contacts, friction, restitution.
const char* const kBoxesScene = R"({
  "meff_scene": 1, "name": "boxes",
  "world": {"frames": 120},
  "bodies": [
    {"name": "ground", "type": "static",
     "shapes": [{"type": "segment", "points": [[-10, 0], [10, 0]]}]},
    {"name": "box", "type": "dynamic", "position": [0, 1], "angle": 0.3,
     "shapes": [{"type": "box", "half_width": 0.5, "half_height": 0.25}]},
    {"name": "top", "type": "dynamic", "position": [0, 1.6],
     "shapes": [{"type": "box", "half_width": 0.3, "half_height": 0.2}]},
    {"name": "ball", "type": "dynamic", "position": [2, 0.5], "linear_velocity": [-2, 0],
     "shapes": [{"type": "circle", "radius": 0.3, "restitution": 0.5}]}
  ]
})";

const char* const kPendulumScene = R"({
  "meff_scene": 1, "name": "pendulum",
  "world": {"frames": 120},
  "bodies": [
    {"name": "pivot", "type": "static", "position": [0, 5]},
    {"name": "bob", "type": "dynamic", "position": [2, 5],
     "shapes": [{"type": "circle", "radius": 0.25}]}
  ],
  "joints": [{"type": "revolute", "name": "pin", "body_a": "pivot", "body_b": "bob",
              "anchor": [0, 5]}]
})";

} // namespace

TEST_CASE("Validation: identical frames have no error", "[validation]")
{
    const FrameSample frame = TwoBodies();
    const FrameErrors errors = CompareFrames(frame, frame, kDt, Tolerances{}, 7);
    CHECK(errors.frame == 7);
    CHECK(errors.position == 0);
    CHECK(errors.angle == 0);
    CHECK(errors.velocity == 0);
    CHECK(errors.contactImpulse == 0);
    CHECK(errors.jointImpulse == 0);
    CHECK(errors.positionBody == -1); // nothing holds a maximum of zero
    CHECK_FALSE(errors.Exceeds());
}

TEST_CASE("Validation: body errors are measured, attributed and judged", "[validation]")
{
    const FrameSample box2d = TwoBodies();
    FrameSample meff = box2d;
    meff.bodies[1].x += 3e-5;
    meff.bodies[1].y += 4e-5; // |Δp| = 5e-5 m: within 1e-4
    meff.bodies[1].angle += 2e-4;
    meff.bodies[1].angularVelocity += 2e-3; // rad/s, judged as a velocity
    const FrameErrors errors = CompareFrames(meff, box2d, kDt, Tolerances{});
    CHECK(errors.position == Approx(5e-5));
    CHECK(errors.positionBody == 1);
    CHECK(errors.angle == Approx(2e-4));
    CHECK(errors.angleBody == 1);
    CHECK(errors.linearVelocity == 0);
    CHECK(errors.angularVelocity == Approx(2e-3));
    CHECK(errors.velocity == Approx(2e-3));
    CHECK(errors.velocityBody == 1);
    CHECK_FALSE(Has(errors, "position"));
    CHECK(Has(errors, "angle"));
    CHECK(Has(errors, "velocity"));

    SECTION("a non-finite state is the largest error of all")
    {
        meff.bodies[0].x = std::nan("");
        const FrameErrors nan = CompareFrames(meff, box2d, kDt, Tolerances{});
        CHECK(std::isnan(nan.position));
        CHECK(Has(nan, "position"));
    }
}

TEST_CASE("Validation: contact points match by shape pair and feature key", "[validation]")
{
    FrameSample box2d = TwoBodies();
    FrameSample meff = box2d;
    // Box2D: ground(0)/box(1) points with keys 1 and 2, and one point only it has.
    box2d.contacts.push_back({{0, 0, 1, 0, 1}, 100.0, 0.5});
    box2d.contacts.push_back({{0, 0, 1, 0, 2}, 1.0, 0.0});
    box2d.contacts.push_back({{0, 0, 1, 1, 1}, 0.0, 0.0});
    // meff: the same two points, A and B the other way round, in the other order.
    meff.contacts.push_back({{1, 0, 0, 0, 2}, 1.0005, 0.0});
    meff.contacts.push_back({{1, 0, 0, 0, 1}, 100.05, 0.5});

    SECTION("an impulse within the relative tolerance passes; the point missing from meff "
            "is counted, and with zero impulse it costs nothing")
    {
        const FrameErrors errors = CompareFrames(meff, box2d, kDt, Tolerances{});
        CHECK(errors.contactPointsMeff == 2);
        CHECK(errors.contactPointsBox2D == 3);
        CHECK(errors.onlyInBox2D == 1);
        CHECK(errors.onlyInMeff == 0);
        CHECK(errors.contactImpulse == Approx(0.05)); // 100.05 vs 100: 5e-4 relative
        REQUIRE(errors.contact);
        CHECK(errors.contact->featureKey == 1);
        CHECK(errors.contactRatio == Approx(0.5));
        CHECK_FALSE(errors.Exceeds());
    }
    SECTION("a small impulse is held to the absolute tolerance")
    {
        meff.contacts[0].normalImpulse = 1.0015; // 1.5e-3 > max(1e-3, 1e-3 × 1)
        const FrameErrors errors = CompareFrames(meff, box2d, kDt, Tolerances{});
        CHECK(errors.contactRatio == Approx(1.5));
        CHECK(Has(errors, "contact_impulse"));
    }
    SECTION("a point only one engine has is compared against zero")
    {
        meff.contacts.push_back({{1, 0, 2, 0, 7}, 0.0, 0.01});
        const FrameErrors errors = CompareFrames(meff, box2d, kDt, Tolerances{});
        CHECK(errors.onlyInMeff == 1);
        CHECK(errors.contactImpulse == Approx(0.05));
        CHECK(errors.contactRatio == Approx(10.0));
        CHECK(Has(errors, "contact_impulse"));
    }
    SECTION("the friction impulse counts as much as the normal one")
    {
        meff.contacts[1].tangentImpulse = 0.6;
        const FrameErrors errors = CompareFrames(meff, box2d, kDt, Tolerances{});
        CHECK(errors.contactImpulse == Approx(0.1));
        CHECK(Has(errors, "contact_impulse"));
    }
}

TEST_CASE("Validation: joint reactions are compared as impulses", "[validation]")
{
    FrameSample box2d = TwoBodies();
    box2d.joints.push_back({0.0, 10.0, 0.0});
    FrameSample meff = box2d;
    meff.joints[0].fy = 10.12; // 0.12 N × dt = 2e-3 N·s
    FrameErrors errors = CompareFrames(meff, box2d, kDt, Tolerances{});
    CHECK(errors.jointImpulse == Approx(0.12 * kDt));
    CHECK(errors.joint == 0);
    CHECK(Has(errors, "joint_impulse"));

    meff.joints[0].fy = 10.0;
    meff.joints[0].torque = 0.03; // 5e-4 N·m·s
    errors = CompareFrames(meff, box2d, kDt, Tolerances{});
    CHECK(errors.jointImpulse == Approx(0.03 * kDt));
    CHECK_FALSE(errors.Exceeds());
}

TEST_CASE("Validation: frames of different scenes are refused", "[validation]")
{
    FrameSample other = TwoBodies();
    other.bodies.pop_back();
    CHECK_THROWS_AS(CompareFrames(TwoBodies(), other, kDt, Tolerances{}), std::invalid_argument);
}

TEST_CASE("Validation: the mirror builds the scene in Box2D", "[validation]")
{
    const meff::Scene scene = meff::ParseScene(kBoxesScene, "boxes.json");
    meff::validation::Box2DMirror mirror(scene);
    CHECK(mirror.World().GetBodyCount() == 4);
    CHECK(mirror.Body(1)->GetFixtureList()->GetFriction() == Approx(0.6f));
    CHECK(mirror.Body(3)->GetFixtureList()->GetRestitution() == 0.5f);
    CHECK(mirror.Body(1)->GetMass() == Approx(0.5f)); // 1 × 0.25 m², density 1
    // Box2D's last-created body heads its body list, as in meff.
    CHECK(mirror.World().GetBodyList() == mirror.Body(3));
    for (int i = 0; i < 60; ++i)
    {
        mirror.Step();
    }
    const FrameSample frame = mirror.Sample();
    REQUIRE(frame.bodies.size() == 4);
    REQUIRE_FALSE(frame.contacts.empty());
    // After a second the top box rests on the lower one: the weight it carries per step.
    double topSupport = 0;
    for (const ContactSample& contact : frame.contacts)
    {
        if ((contact.key.bodyA == 1 && contact.key.bodyB == 2) ||
            (contact.key.bodyA == 2 && contact.key.bodyB == 1))
        {
            topSupport += contact.normalImpulse;
        }
    }
    CHECK(topSupport == Approx(0.24 * 10.0 * kDt).epsilon(0.05)); // 0.24 kg
}

TEST_CASE("Validation: the bundled kinds of scene agree with Box2D", "[validation]")
{
    for (const char* text : {kBoxesScene, kPendulumScene})
    {
        const meff::Scene scene = meff::ParseScene(text, "scene.json");
        for (const bool block : {true, false})
        {
            meff::validation::RunOptions options;
            options.blockSolver = block;
            const auto result = meff::validation::Validate(scene, options);
            INFO(scene.name << ", block solver " << block);
            CHECK(result.passed);
            CHECK_FALSE(result.divergenceFrame);
            CHECK(result.frames == 120);
            CHECK(result.perFrame.size() == 121);
            CHECK(result.position.value <= 1e-4);
            CHECK(result.onlyInMeff == 0);
            CHECK(result.onlyInBox2D == 0);
        }
    }
}

TEST_CASE("Validation can fail: meff with 4 velocity iterations against Box2D's 8", "[validation]")
{
    const meff::Scene scene = meff::ParseScene(kBoxesScene, "boxes.json");
    meff::validation::RunOptions options;
    options.meffVelocityIterations = 4;
    const auto result = meff::validation::Validate(scene, options);
    CHECK_FALSE(result.passed);
    REQUIRE(result.divergenceFrame);
    CHECK(*result.divergenceFrame >= 1);
    CHECK_FALSE(result.divergenceQuantities.empty());
    CHECK(result.meffVelocityIterations == 4);
    CHECK(result.box2dVelocityIterations == 8);
    CHECK_FALSE(result.notes.empty());
}

TEST_CASE("Validation: chaotic scenes agree up to their horizon, then settle", "[validation]")
{
    meff::Scene scene = meff::ParseScene(R"({
      "meff_scene": 1, "name": "stack",
      "world": {"frames": 240},
      "bodies": [
        {"name": "ground", "type": "static",
         "shapes": [{"type": "segment", "points": [[-5, 0], [5, 0]]}]},
        {"name": "b0", "type": "dynamic", "position": [0, 0.515],
         "shapes": [{"type": "box", "half_width": 0.5, "half_height": 0.5}]},
        {"name": "b1", "type": "dynamic", "position": [0.01, 1.53],
         "shapes": [{"type": "box", "half_width": 0.5, "half_height": 0.5}]},
        {"name": "b2", "type": "dynamic", "position": [-0.01, 2.545],
         "shapes": [{"type": "box", "half_width": 0.5, "half_height": 0.5}]}
      ],
      "validate": {"chaotic": true, "horizon_frames": 120,
                   "settle": {"position": 0.01, "angle": 0.01, "min_height": 0.4}}
    })",
                                         "stack.json");
    REQUIRE(scene.validation.chaotic);
    REQUIRE(scene.validation.horizonFrames == 120);
    REQUIRE(scene.validation.settle);
    CHECK(scene.validation.settle->minimumHeight == 0.4);

    const auto result = meff::validation::Validate(scene);
    CHECK(result.chaotic);
    // The frame-by-frame part holds before the horizon...
    for (const FrameErrors& frame : result.perFrame)
    {
        if (frame.frame <= result.horizonFrames)
        {
            INFO("frame " << frame.frame);
            CHECK_FALSE(frame.Exceeds());
        }
    }
    // ...and the stack ends standing where Box2D's does.
    REQUIRE(result.settle);
    CHECK(result.settle->passed);
    CHECK(result.settle->lowestHeight.value() > 0.4);
    CHECK(result.passed);

    SECTION("a divergence before the horizon fails the scene")
    {
        meff::validation::RunOptions options;
        options.meffVelocityIterations = 2;
        const auto failed = meff::validation::Validate(scene, options);
        REQUIRE(failed.divergenceFrame);
        CHECK(*failed.divergenceFrame <= failed.horizonFrames);
        CHECK_FALSE(failed.passed);
    }
    SECTION("an unreachable settled height fails the scene")
    {
        scene.validation.settle->minimumHeight = 5.0;
        const auto failed = meff::validation::Validate(scene);
        REQUIRE(failed.settle);
        CHECK_FALSE(failed.settle->passed);
        CHECK_FALSE(failed.passed);
    }
}

TEST_CASE("Validation: the scene's validate section is checked", "[validation][scene]")
{
    const std::string head = R"({"meff_scene": 1, "bodies": [], "validate": )";
    CHECK_THROWS_AS(meff::ParseScene(head + R"({"horizon_frames": 10}})", "a.json"),
                    meff::SceneError);
    CHECK_THROWS_AS(meff::ParseScene(head + R"({"chaotic": true}})", "b.json"), meff::SceneError);
    CHECK_THROWS_AS(meff::ParseScene(head + R"({"settle": {"height": 1}}})", "c.json"),
                    meff::SceneError);
    const meff::Scene scene = meff::ParseScene(
        head + R"({"tolerances": {"impulse_relative": 0.01}, "settle": {}}})", "d.json");
    CHECK(scene.tolerances.impulseRelative == 0.01);
    CHECK_FALSE(scene.validation.chaotic);
    REQUIRE(scene.validation.settle);
    CHECK(scene.validation.settle->position == 0.05);
    CHECK_FALSE(scene.validation.settle->angle);
}

TEST_CASE("Validation: a setting Box2D cannot mirror is said, and what can be compared is judged",
          "[validation]")
{
    // The boxes by colour: the same rows in another order. Before, the run simply FAILed at the
    // first round-off difference with no note; now the setting is named, frame 0 must agree,
    // and the settled state is judged (every body within 0.05 m of Box2D's final position).
    meff::Scene colour = meff::ParseScene(kBoxesScene, "boxes.json");
    colour.world.solver.kind = meff::SolverKind::Colour;
    const auto result = meff::validation::Validate(colour);
    CHECK(result.unmirrored == std::vector<std::string>{"world.solver \"colour\""});
    REQUIRE(result.notes.size() == 2);
    CHECK_THAT(result.notes[0], Catch::Contains("world.solver is \"colour\", which Box2D 2.4.1 "
                                                "does not have"));
    CHECK_THAT(result.notes[1], Catch::Contains("judged by what can be compared"));
    REQUIRE_FALSE(result.perFrame.empty());
    CHECK(result.perFrame[0].position == 0); // the worlds as built are the same
    REQUIRE(result.settle);
    CHECK(result.passed == result.settle->passed);
    CHECK(result.passed);

    // A setting that changes nothing in this scene is not reported: without restitution,
    // restitution_from_step_start is Box2D's rule, and the run agrees exactly.
    meff::Scene pendulum = meff::ParseScene(kPendulumScene, "pendulum.json");
    pendulum.world.solver.restitutionFromStepStart = true;
    const auto exact = meff::validation::Validate(pendulum);
    CHECK(exact.unmirrored.empty());
    CHECK(exact.notes.empty());
    CHECK(exact.passed);
    CHECK(exact.position.value == 0);

    // With restitution it is reported, and judged by the settled state: a ball with e = 0.5
    // bouncing on the ground comes to rest on it in both engines.
    meff::Scene bounce = meff::ParseScene(kBoxesScene, "boxes.json");
    bounce.world.solver.restitutionFromStepStart = true;
    bounce.world.frames = 300;
    const auto bounced = meff::validation::Validate(bounce);
    CHECK(bounced.unmirrored == std::vector<std::string>{"world.restitution_from_step_start"});
    CHECK_THAT(bounced.notes[0], Catch::Contains("every bounce differs by about g·dt"));
    REQUIRE(bounced.settle);
    CHECK(bounced.passed == bounced.settle->passed);
}
