// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The scene loader: every bundled sample loads and builds; every class of bad input is refused
// with exactly the message a user should see.
#include "meff/scene.h"

#include <catch2/catch.hpp>

#include "scene_errors.h"

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

using namespace meff;
using meff::test::ErrorsOf;

namespace
{

/// A valid scene with one dynamic body whose single shape is `shape` (JSON text).
std::string SceneWithShape(const std::string& shape)
{
    return R"({ "meff_scene": 1, "bodies": [ { "name": "b", "type": "dynamic", "shapes": [ )" +
           shape + R"( ] } ] })";
}

using Messages = std::vector<std::string>;

} // namespace

TEST_CASE("Every bundled sample loads, describes itself and builds", "[scene]")
{
    const std::filesystem::path directory =
        std::filesystem::path(MEFF_SOURCE_DIR) / "samples" / "scenes";
    int count = 0;
    for (const auto& entry : std::filesystem::directory_iterator(directory))
    {
        if (entry.path().extension() != ".json")
        {
            continue;
        }
        ++count;
        const std::string path = entry.path().string();
        INFO(path);
        Scene scene;
        REQUIRE_NOTHROW(scene = LoadScene(path));
        CHECK(scene.name == entry.path().stem().string());
        CHECK(scene.description.size() > 50);
        CHECK(scene.world.dt == Approx(1.0 / 60.0));
        CHECK(scene.world.frames > 0);
        CHECK_FALSE(scene.bodies.empty());
        const BuiltScene built = BuildWorld(scene);
        CHECK(built.bodies.size() == scene.bodies.size());
        CHECK(built.joints.size() == scene.joints.size());
        CHECK(built.world.GetBodies().size() == scene.bodies.size());
    }
    // The issue lists 15 scenes; more may come, none may go.
    CHECK(count >= 15);
}

TEST_CASE("A minimal scene gets every default", "[scene]")
{
    const Scene scene = ParseScene(R"({
        "meff_scene": 1,
        "bodies": [
            { "name": "ground", "type": "static" },
            { "name": "bob", "type": "dynamic", "position": [3, 4],
              "shapes": [ { "type": "circle", "radius": 0.5 } ] } ],
        "joints": [ { "type": "distance", "name": "rod", "body_a": "ground", "body_b": "bob",
                      "anchor_a": [0, 0], "anchor_b": [3, 4] } ] })",
                                   "dir/minimal.json");
    CHECK(scene.name == "minimal");
    CHECK(scene.description.empty());
    CHECK(scene.world.gravity.x == 0);
    CHECK(scene.world.gravity.y == -10);
    CHECK(scene.world.dt == 1.0 / 60.0);
    CHECK(scene.world.frames == 240);
    CHECK(scene.world.solver.velocityIterations == 8);
    CHECK(scene.world.solver.positionIterations == 3);
    CHECK(scene.world.solver.warmStarting);
    CHECK(scene.world.solver.blockSolver);
    CHECK_FALSE(scene.world.allowSleep);
    CHECK_FALSE(scene.world.continuous);
    CHECK_FALSE(scene.camera.has_value());
    CHECK(scene.bodies[1].allowSleep); // Box2D's b2BodyDef defaults
    CHECK(scene.bodies[1].awake);

    const SceneShape& shape = scene.bodies[1].shapes[0];
    CHECK(shape.density == 1);
    CHECK(shape.friction == 0.6);
    CHECK(shape.restitution == 0);
    CHECK(shape.restitutionThreshold == 1);
    CHECK(shape.filter.category == 1);
    CHECK(shape.filter.mask == 0xFFFF);
    CHECK(shape.filter.group == 0);

    // A distance joint given only its anchors is a rigid rod of the anchors' distance.
    const SceneJoint& rod = scene.joints[0];
    CHECK(rod.bodyIndexA == 0);
    CHECK(rod.bodyIndexB == 1);
    CHECK(rod.length == 5);
    CHECK(rod.minLength == 5);
    CHECK(rod.maxLength == 5);
    CHECK(rod.stiffnessHz == 0);
}

TEST_CASE("BuildWorld places bodies, shapes and world-point joint anchors", "[scene]")
{
    const Scene scene = ParseScene(R"({
        "meff_scene": 1, "world": { "gravity": [0, -9.8], "velocity_iterations": 5 },
        "bodies": [
            { "name": "ground", "type": "static" },
            { "name": "rod", "type": "dynamic", "position": [1, 5], "angle": 0.25,
              "shapes": [ { "type": "box", "half_width": 1, "half_height": 0.05 },
                          { "type": "polygon", "vertices": [[0, 0], [1, 0], [0, 1]] } ] } ],
        "joints": [ { "type": "revolute", "name": "pin", "body_a": "ground",
                      "body_b": "rod", "anchor": [0, 5] } ] })",
                                   "build.json");
    BuiltScene built = BuildWorld(scene);
    const BodyId rod = built.bodyByName.at("rod");
    CHECK(built.bodies[1] == rod);
    CHECK(built.SceneIndexOf(rod) == std::optional<std::size_t>(1));
    CHECK(built.world.GetPosition(rod).x == 1);
    CHECK(built.world.GetPosition(rod).y == 5);
    CHECK(built.world.GetAngle(rod) == Approx(0.25));
    CHECK(built.world.GetGravity().y == Approx(-9.8));
    CHECK(built.world.GetSolverSettings().velocityIterations == 5);
    CHECK(built.shapes[1].size() == 2);
    const JointId pin = built.jointByName.at("pin");
    CHECK(built.world.GetAnchorB(pin).x == Approx(0).margin(1e-6));
    CHECK(built.world.GetAnchorB(pin).y == Approx(5));
}

TEST_CASE("Scene errors: JSON syntax, with line and column", "[scene][errors]")
{
    CHECK(ErrorsOf("{ \"meff_scene\": 1,\n  \"bodies\": [ } ") ==
          Messages{"x.json: line 2, column 15: syntax error while parsing value - unexpected "
                   "'}'; expected '[', '{', or a literal"});
    CHECK(ErrorsOf("") == Messages{"x.json: line 1, column 1: syntax error while parsing value - "
                                   "unexpected end of input; expected '[', '{', or a literal"});
}

TEST_CASE("Scene errors: missing fields", "[scene][errors]")
{
    CHECK(
        ErrorsOf(
            R"({ "bodies": [ { "type": "dynamic", "shapes": [ { "type": "circle", "radius": 1 } ] } ] })") ==
        Messages{"x.json: meff_scene: required field is missing (the format version: write "
                 "\"meff_scene\": 1)",
                 "x.json: bodies[0].name: required field is missing"});
    CHECK(ErrorsOf(SceneWithShape(R"({ "type": "box", "half_width": 1 })")) ==
          Messages{"x.json: bodies[0].shapes[0].half_height: required field is missing"});
}

TEST_CASE("Scene errors: mistyped fields", "[scene][errors]")
{
    CHECK(ErrorsOf(R"({ "meff_scene": 1, "world": { "dt": "0.01", "warm_starting": 1,
                        "gravity": [0], "frames": 2.5 }, "bodies": {} })") ==
          Messages{"x.json: world.gravity: must be [x, y] with two finite numbers, got [0]",
                   "x.json: world.dt: must be a number, got \"0.01\"",
                   "x.json: world.frames: must be an integer in [0, 2147483647], got 2.5",
                   "x.json: world.warm_starting: must be true or false, got 1",
                   "x.json: bodies: must be an array, got {}"});
    CHECK(ErrorsOf(R"({ "meff_scene": 1, "bodies": [ { "name": "b", "type": "Dynamic" } ] })") ==
          Messages{"x.json: bodies[0].type: must be one of \"static\", \"kinematic\", "
                   "\"dynamic\", got \"Dynamic\""});
}

TEST_CASE("Scene errors: unknown fields", "[scene][errors]")
{
    CHECK(ErrorsOf(SceneWithShape(R"({ "type": "circle", "radius": 1, "frition": 0.2 })")) ==
          Messages{"x.json: bodies[0].shapes[0].frition: unknown field (known fields here: type, "
                   "radius, center, density, friction, restitution, restitution_threshold, "
                   "tangent_speed, rolling_resistance, filter, sensor)"});
}

TEST_CASE("Scene errors: a key given twice in one object", "[scene][errors]")
{
    CHECK(ErrorsOf(SceneWithShape(R"({ "type": "circle", "radius": 1, "radius": 2 })")) ==
          Messages{"x.json: bodies[0].shapes[0].radius: duplicate key: each field may appear "
                   "only once"});
}

TEST_CASE("Scene errors: JSON nested deeper than the limit is refused where it gets too deep",
          "[scene][errors]")
{
    // 100,000 levels: before the limit, every open level kept its whole path (quadratic memory:
    // 40,000 levels took 3 GB); now reading stops at level 65 with the path to it.
    std::string path;
    for (std::size_t level = 0; level < 64; ++level)
    {
        path += "[0]";
    }
    CHECK(ErrorsOf(std::string(100000, '[')) ==
          Messages{"x.json: " + path +
                   ": nested deeper than 64 levels (a scene needs about 7): "
                   "not a scene file"});
    // Objects count too, and the path names their keys.
    std::string objects;
    for (int level = 0; level < 70; ++level)
    {
        objects += "{\"a\": [1, ";
    }
    const Messages deep = ErrorsOf(objects);
    REQUIRE(deep.size() == 1);
    CHECK(deep[0].rfind("x.json: a[1].a[1].a[1].", 0) == 0);
    CHECK(deep[0].find("nested deeper than 64 levels") != std::string::npos);
    // 64 levels are read (and refused for what they say, not for their depth; the value shown
    // is cut at 80 characters).
    CHECK(ErrorsOf(std::string(64, '[') + "1" + std::string(64, ']')) ==
          Messages{"x.json: the scene must be a JSON object, got " + std::string(64, '[') + "1" +
                   std::string(12, ']') + "..."});
}

TEST_CASE("Scene errors: messages deep inside arrays name the right element", "[scene][errors]")
{
    // An open container's path goes through its parent array's last element, not the next one.
    CHECK(ErrorsOf(R"({ "meff_scene": 1, "bodies": [ { "name": "a", "type": "static" },
        { "name": "b", "type": "dynamic", "shapes": [ { "type": "circle", "radius": 1 },
          { "type": "circle", "radius": 1, "filter": { "group": 1, "group": 2 } } ] } ] })") ==
          Messages{"x.json: bodies[1].shapes[1].filter.group: duplicate key: each field may "
                   "appear only once"});
    CHECK(ErrorsOf(R"({ "meff_scene": 1, "bodies": [ { "name": "a", "type": "static" },
        { "name": "b", "type": "static", "shapes": [ { "type": "polygon",
          "vertices": [[0, 0], [1, 0], [1, 1e400]] } ] } ] })") ==
          Messages{"x.json: bodies[1].shapes[0].vertices[2][1]: must be a finite number, got "
                   "1e400"});
}

TEST_CASE("Scene errors: names not unique, not defined or malformed", "[scene][errors]")
{
    CHECK(ErrorsOf(R"({ "meff_scene": 1,
        "bodies": [ { "name": "box", "type": "static" }, { "name": "box", "type": "dynamic", "shapes": [ { "type": "circle", "radius": 1 } ] },
                    { "name": "my box", "type": "dynamic",
                      "shapes": [ { "type": "circle", "radius": 1 } ] } ],
        "joints": [ { "type": "revolute", "name": "pin", "body_a": "grund", "body_b": "box",
                      "anchor": [0, 0] },
                    { "type": "revolute", "name": "pin", "body_a": "box", "body_b": "box",
                      "anchor": [0, 0] } ] })") ==
          Messages{"x.json: bodies[2].name: must be 1 to 64 letters, digits, '_', '-' or '.', got "
                   "\"my box\"",
                   "x.json: bodies[1].name: duplicate name (also used by bodies[0]), got \"box\"",
                   "x.json: joints[0].body_a: no body has this name, got \"grund\"",
                   "x.json: joints[1].body_b: must differ from body_a, got \"box\"",
                   "x.json: joints[1].name: duplicate name (also used by joints[0]), got \"pin\""});
}

TEST_CASE("Scene errors: non-positive radius and sizes", "[scene][errors]")
{
    CHECK(ErrorsOf(SceneWithShape(R"({ "type": "circle", "radius": -1 })")) ==
          Messages{"x.json: bodies[0].shapes[0].radius: must be > 0, got -1"});
    CHECK(ErrorsOf(SceneWithShape(R"({ "type": "box", "half_width": 0, "half_height": -0.5 })")) ==
          Messages{"x.json: bodies[0].shapes[0].half_width: must be > 0, got 0",
                   "x.json: bodies[0].shapes[0].half_height: must be > 0, got -0.5"});
}

TEST_CASE("Scene errors: degenerate polygons and segments", "[scene][errors]")
{
    CHECK(ErrorsOf(
              SceneWithShape(R"({ "type": "polygon", "vertices": [[0, 0], [1, 0], [2, 0]] })")) ==
          Messages{"x.json: bodies[0].shapes[0].vertices: must enclose a non-zero area (the "
                   "points are collinear or coincide), got [[0, 0], [1, 0], [2, 0]]"});
    CHECK(
        ErrorsOf(SceneWithShape(
            R"({ "type": "polygon", "vertices": [[0, 0], [1, 0], [1, 1], [0, 1], [0.5, 0.5]] })")) ==
        Messages{"x.json: bodies[0].shapes[0].vertices: must be the corners of a convex polygon "
                 "(a point lies inside the hull, or two points are closer than 0.0025 m), got "
                 "[[0, 0], [1, 0], [1, 1], [0, 1], [0.5, 0.5]]"});
    CHECK(ErrorsOf(SceneWithShape(R"({ "type": "polygon", "vertices": [[0, 0], [1, 0]] })")) ==
          Messages{"x.json: bodies[0].shapes[0].vertices: must list 3 to 8 points, got [[0, 0], "
                   "[1, 0]]"});
    // A segment may be on a dynamic body (as in Box2D), but gives it no mass.
    CHECK(ErrorsOf(SceneWithShape(R"({ "type": "segment", "points": [[0, 0], [1, 0]] })")) ==
          Messages{"x.json: bodies[0].shapes: a dynamic body needs mass: give one of its circles, "
                   "boxes or polygons a density > 0 (segments and chains have none), got "
                   "[{\"points\": [[0, 0], [1, 0]], \"type\": \"segment\"}]"});
}

TEST_CASE("Scene errors: numbers that are not finite", "[scene][errors]")
{
    // JSON has no NaN or infinity; 1e400 overflows a double while parsing, and 1e39 a float.
    CHECK(ErrorsOf(SceneWithShape(R"({ "type": "circle", "radius": 1e400 })")) ==
          Messages{"x.json: bodies[0].shapes[0].radius: must be a finite number, got 1e400"});
    CHECK(ErrorsOf(SceneWithShape(R"({ "type": "circle", "radius": "NaN" })")) ==
          Messages{"x.json: bodies[0].shapes[0].radius: must be a finite number, got \"NaN\""});
    CHECK(ErrorsOf(SceneWithShape(R"({ "type": "circle", "radius": 1, "center": [0, "-inf"] })")) ==
          Messages{"x.json: bodies[0].shapes[0].center: must be [x, y] with two finite numbers, "
                   "got [0, \"-inf\"]"});
    if (sizeof(Real) == sizeof(float))
    {
        CHECK(ErrorsOf(SceneWithShape(R"({ "type": "circle", "radius": 1e39 })")) ==
              Messages{"x.json: bodies[0].shapes[0].radius: must be a finite number (at most "
                       "3.40282347e+38 in magnitude), got 1e+39"});
    }
}

TEST_CASE("Scene errors: values out of range, all reported together", "[scene][errors]")
{
    CHECK(ErrorsOf(R"({ "meff_scene": 1,
        "world": { "dt": 0, "frames": -1, "velocity_iterations": 0, "position_iterations": 1001 },
        "bodies": [ { "name": "b", "type": "dynamic", "linear_damping": -1, "shapes": [
            { "type": "circle", "radius": 1, "density": -2, "friction": -0.1,
              "restitution": 1.5, "restitution_threshold": -1,
              "filter": { "category": 70000, "mask": -1, "group": 40000 } } ] } ] })") ==
          Messages{
              "x.json: world.dt: must be > 0, got 0",
              "x.json: world.frames: must be an integer in [0, 2147483647], got -1",
              "x.json: world.velocity_iterations: must be an integer in [1, 1000], got 0",
              "x.json: world.position_iterations: must be an integer in [0, 1000], got 1001",
              "x.json: bodies[0].linear_damping: must be >= 0, got -1",
              "x.json: bodies[0].shapes[0].density: must be >= 0, got -2",
              "x.json: bodies[0].shapes[0].friction: must be >= 0, got -0.1",
              "x.json: bodies[0].shapes[0].restitution: must be in [0, 1], got 1.5",
              "x.json: bodies[0].shapes[0].restitution_threshold: must be >= 0, got -1",
              "x.json: bodies[0].shapes[0].filter.category: must be an integer in [0, 65535], "
              "got 70000",
              "x.json: bodies[0].shapes[0].filter.mask: must be an integer in [0, 65535], got -1",
              "x.json: bodies[0].shapes[0].filter.group: must be an integer in [-32768, 32767], "
              "got 40000"});
}

TEST_CASE("Scene errors: joint values out of range", "[scene][errors]")
{
    CHECK(ErrorsOf(R"({ "meff_scene": 1,
        "bodies": [ { "name": "a", "type": "static" }, { "name": "b", "type": "dynamic",
                      "shapes": [ { "type": "circle", "radius": 1 } ] },
                    { "name": "c", "type": "kinematic" } ],
        "joints": [
            { "type": "revolute", "name": "j0", "body_a": "a", "body_b": "b", "anchor": [0, 0],
              "lower_angle": 1, "upper_angle": 0, "max_motor_torque": -1 },
            { "type": "distance", "name": "j1", "body_a": "a", "body_b": "b",
              "anchor_a": [0, 0], "anchor_b": [0, 0] },
            { "type": "distance", "name": "j2", "body_a": "a", "body_b": "b", "anchor_a": [0, 0],
              "anchor_b": [0, 1], "min_length": 0.7, "max_length": 0.5 },
            { "type": "revolute", "name": "j3", "body_a": "a", "body_b": "c", "anchor": [0, 0] },
            { "type": "gears", "name": "j4", "body_a": "a", "body_b": "b" } ] })") ==
          Messages{"x.json: joints[0].upper_angle: must be >= lower_angle (1), got 0",
                   "x.json: joints[0].max_motor_torque: must be >= 0, got -1",
                   "x.json: joints[1].length: is missing and anchor_a and anchor_b coincide; "
                   "give a length > 0",
                   "x.json: joints[2].max_length: must be >= min_length (0.7), got 0.5",
                   "x.json: joints[4].type: must be one of \"revolute\", \"distance\", "
                   "\"prismatic\", \"wheel\", \"weld\", \"motor\", \"mouse\", \"friction\", "
                   "\"pulley\", \"gear\", got "
                   "\"gears\""});
}

TEST_CASE("Scene errors: prismatic and wheel joint fields", "[scene][errors][prismatic][wheel]")
{
    CHECK(ErrorsOf(R"({ "meff_scene": 1,
        "bodies": [ { "name": "a", "type": "static" }, { "name": "b", "type": "dynamic",
                      "shapes": [ { "type": "circle", "radius": 1 } ] } ],
        "joints": [
            { "type": "prismatic", "name": "j0", "body_a": "a", "body_b": "b", "anchor": [0, 0],
              "axis": [0, 1], "lower_translation": 3, "upper_translation": 1,
              "max_motor_force": -5 },
            { "type": "wheel", "name": "j1", "body_a": "a", "body_b": "b", "anchor": [0, 0],
              "axis": [0, 0], "max_motor_torque": -1, "stiffness_hz": -4,
              "max_motor_force": 2 },
            { "type": "prismatic", "name": "j2", "body_a": "a", "body_b": "b",
              "anchor": [0, 0] } ] })") ==
          Messages{"x.json: joints[0].lower_translation: must be <= upper_translation (1), got 3",
                   "x.json: joints[0].max_motor_force: must be >= 0, got -5",
                   "x.json: joints[1].axis: must not be [0, 0] (it is the direction the joint "
                   "slides along), got [0, 0]",
                   "x.json: joints[1].max_motor_torque: must be >= 0, got -1",
                   "x.json: joints[1].stiffness_hz: must be >= 0, got -4",
                   "x.json: joints[1].max_motor_force: unknown field (known fields here: type, "
                   "name, body_a, body_b, collide_connected, local_anchor_a, local_anchor_b, "
                   "anchor, local_axis_a, axis, enable_limit, lower_translation, "
                   "upper_translation, enable_motor, motor_speed, max_motor_torque, "
                   "stiffness_hz, damping_ratio)",
                   "x.json: joints[2].axis: required field is missing"});
}

TEST_CASE("Scene: prismatic and wheel joints are built as written", "[scene][prismatic][wheel]")
{
    const Scene scene = ParseScene(R"({ "meff_scene": 1,
        "bodies": [ { "name": "a", "type": "static" }, { "name": "b", "type": "dynamic",
                      "position": [1, 2], "shapes": [ { "type": "circle", "radius": 0.5 } ] } ],
        "joints": [
            { "type": "prismatic", "name": "slide", "body_a": "a", "body_b": "b",
              "anchor": [1, 2], "axis": [0, 2], "enable_limit": true,
              "lower_translation": -1, "upper_translation": 2, "enable_motor": true,
              "motor_speed": 0.5, "max_motor_force": 30 },
            { "type": "wheel", "name": "hub", "body_a": "a", "body_b": "b", "anchor": [1, 2],
              "axis": [0, 1], "stiffness_hz": 3, "damping_ratio": 0.5,
              "enable_motor": true, "motor_speed": -4, "max_motor_torque": 7 } ] })",
                                   "x.json");
    REQUIRE(scene.joints.size() == 2);
    const SceneJoint& slide = scene.joints[0];
    CHECK(slide.type == JointType::Prismatic);
    CHECK(slide.axis.x == 0);
    CHECK(slide.axis.y == 2);
    CHECK(slide.enableLimit);
    CHECK(slide.lowerTranslation == -1);
    CHECK(slide.upperTranslation == 2);
    CHECK(slide.maxMotorForce == 30);
    const SceneJoint& hub = scene.joints[1];
    CHECK(hub.type == JointType::Wheel);
    CHECK(hub.stiffnessHz == 3);
    CHECK(hub.dampingRatio == 0.5);
    CHECK(hub.maxMotorTorque == 7);

    BuiltScene built = BuildWorld(scene);
    CHECK(built.world.GetJointType(built.joints[0]) == JointType::Prismatic);
    CHECK(built.world.GetJointType(built.joints[1]) == JointType::Wheel);
    CHECK(built.world.GetJointTranslation(built.joints[0]) == 0);
}

TEST_CASE("Scene errors: static bodies do not move", "[scene][errors]")
{
    CHECK(ErrorsOf(R"({ "meff_scene": 1, "bodies": [ { "name": "g", "type": "static",
                        "linear_velocity": [1, 0], "angular_velocity": 2 } ] })") ==
          Messages{"x.json: bodies[0].linear_velocity: must be [0, 0] for a static body, got "
                   "[1, 0]",
                   "x.json: bodies[0].angular_velocity: must be 0 for a static body, got 2"});
}

TEST_CASE("Scene errors: an unknown format version stops everything else", "[scene][errors]")
{
    CHECK(ErrorsOf(R"({ "meff_scene": 2, "bodies": "anything" })") ==
          Messages{"x.json: meff_scene: must be 1 (the only version of the format), got 2"});
    CHECK(ErrorsOf("[1, 2]") == Messages{"x.json: the scene must be a JSON object, got [1, 2]"});
}

TEST_CASE("Scene errors: files that cannot be read", "[scene][errors]")
{
    try
    {
        LoadScene("/nonexistent/scene.json");
        FAIL("no error");
    }
    catch (const SceneError& error)
    {
        CHECK(error.messages() ==
              Messages{"/nonexistent/scene.json: cannot open: No such file or directory"});
        CHECK(std::string(error.what()) == error.messages()[0]);
    }
}

TEST_CASE("Per-body allow_sleep and awake reach the world", "[scene][sleeping]")
{
    const Scene scene = ParseScene(R"({
        "meff_scene": 1,
        "world": { "allow_sleep": true },
        "bodies": [
            { "name": "sleeper", "type": "dynamic", "position": [0, 4], "awake": false,
              "shapes": [ { "type": "circle", "radius": 0.5 } ] },
            { "name": "insomniac", "type": "dynamic", "allow_sleep": false,
              "shapes": [ { "type": "circle", "radius": 0.5 } ] } ] })",
                                   "dir/sleep.json");
    CHECK(scene.world.allowSleep);
    CHECK_FALSE(scene.bodies[0].awake);
    CHECK_FALSE(scene.bodies[1].allowSleep);
    const BuiltScene built = BuildWorld(scene);
    CHECK(built.world.GetAllowSleeping());
    CHECK_FALSE(built.world.IsAwake(built.bodies[0]));
    CHECK(built.world.IsSleepingAllowed(built.bodies[0]));
    CHECK(built.world.IsAwake(built.bodies[1]));
    CHECK_FALSE(built.world.IsSleepingAllowed(built.bodies[1]));
}

TEST_CASE("Scene errors: weld, motor and mouse joint fields", "[scene][errors][joints]")
{
    CHECK(ErrorsOf(R"({ "meff_scene": 1,
        "bodies": [ { "name": "ground", "type": "static" },
                    { "name": "box", "type": "dynamic",
                      "shapes": [ { "type": "circle", "radius": 1 } ] } ],
        "joints": [ { "type": "weld", "name": "w", "body_a": "ground", "body_b": "box",
                      "stiffness_hz": -1, "max_force": 3 },
                    { "type": "motor", "name": "m", "body_a": "ground", "body_b": "box",
                      "correction_factor": 1.5, "max_torque": -2, "linear_offset": [1] },
                    { "type": "mouse", "name": "u", "body_a": "box", "body_b": "ground",
                      "anchor": [0, 0] },
                    { "type": "spring", "name": "s", "body_a": "ground", "body_b": "box" } ] })") ==
          Messages{
              "x.json: joints[0].anchor: required field is missing",
              "x.json: joints[0].stiffness_hz: must be >= 0, got -1",
              "x.json: joints[0].max_force: unknown field (known fields here: type, name, body_a, "
              "body_b, collide_connected, local_anchor_a, local_anchor_b, anchor, "
              "reference_angle, stiffness_hz, damping_ratio)",
              "x.json: joints[1].linear_offset: must be [x, y] with two finite numbers, got [1]",
              "x.json: joints[1].max_torque: must be >= 0, got -2",
              "x.json: joints[1].correction_factor: must be in [0, 1], got 1.5",
              "x.json: joints[2].body_b: must be dynamic for a mouse joint (it drags body B), got "
              "\"ground\"",
              "x.json: joints[2].max_force: required field is missing",
              "x.json: joints[3].type: must be one of \"revolute\", \"distance\", \"prismatic\", "
              "\"wheel\", \"weld\", \"motor\", \"mouse\", \"friction\", \"pulley\", \"gear\", "
              "got \"spring\""});
}

TEST_CASE("Scene files: weld, motor and mouse joints load their fields", "[scene][joints]")
{
    const Scene scene = ParseScene(R"({ "meff_scene": 1,
        "bodies": [ { "name": "ground", "type": "static" },
                    { "name": "box", "type": "dynamic",
                      "shapes": [ { "type": "circle", "radius": 1 } ] } ],
        "joints": [ { "type": "weld", "name": "w", "body_a": "ground", "body_b": "box",
                      "anchor": [1, 2], "stiffness_hz": 3, "damping_ratio": 0.5 },
                    { "type": "motor", "name": "m", "body_a": "ground", "body_b": "box" },
                    { "type": "motor", "name": "m2", "body_a": "ground", "body_b": "box",
                      "linear_offset": [1, 2], "angular_offset": 0.5, "max_force": 7,
                      "max_torque": 8, "correction_factor": 1 },
                    { "type": "mouse", "name": "u", "body_a": "ground", "body_b": "box",
                      "anchor": [0.5, 0], "max_force": 100 } ] })",
                                   "x.json");
    REQUIRE(scene.joints.size() == 4);
    const SceneJoint& weld = scene.joints[0];
    CHECK(weld.type == JointType::Weld);
    CHECK(weld.anchor.x == 1);
    CHECK(weld.stiffnessHz == 3);
    CHECK(weld.dampingRatio == 0.5);
    const SceneJoint& motor = scene.joints[1];
    CHECK(motor.type == JointType::Motor);
    CHECK_FALSE(motor.linearOffset.has_value()); // taken from the bodies at creation
    CHECK_FALSE(motor.angularOffset.has_value());
    CHECK(motor.maxForce == 1); // b2MotorJointDef's defaults
    CHECK(motor.maxTorque == 1);
    CHECK(motor.correctionFactor == 0.3);
    const SceneJoint& motor2 = scene.joints[2];
    REQUIRE(motor2.linearOffset.has_value());
    CHECK(motor2.linearOffset->y == 2);
    CHECK(motor2.angularOffset == 0.5);
    CHECK(motor2.maxForce == 7);
    CHECK(motor2.maxTorque == 8);
    CHECK(motor2.correctionFactor == 1);
    const SceneJoint& mouse = scene.joints[3];
    CHECK(mouse.type == JointType::Mouse);
    CHECK(mouse.target.x == 0.5); // defaults to the grabbed point
    CHECK(mouse.maxForce == 100);
    CHECK(mouse.stiffnessHz == Approx(5)); // MouseJointDef's defaults
    CHECK(mouse.dampingRatio == Approx(0.7));

    // And the world gets them: the weld its anchor, the mouse its target.
    const BuiltScene built = BuildWorld(scene);
    CHECK(built.world.GetJointType(built.joints[0]) == JointType::Weld);
    CHECK(built.world.GetAnchorA(built.joints[0]) == Vec2(1, 2));
    CHECK(built.world.GetAnchorA(built.joints[3]) == Vec2(Real(0.5), 0));

    // A motor without offsets holds the pose the bodies had: alone on a box away from the
    // ground's origin, it keeps the box there against gravity (zero offsets would pull it
    // 3.2 m to the origin and turn it by 0.4 rad; no joint would let it fall).
    const Scene held = ParseScene(R"({ "meff_scene": 1,
        "bodies": [ { "name": "ground", "type": "static" },
                    { "name": "box", "type": "dynamic", "position": [3, 1], "angle": 0.4,
                      "shapes": [ { "type": "circle", "radius": 0.5 } ] } ],
        "joints": [ { "type": "motor", "name": "hold", "body_a": "ground", "body_b": "box",
                      "max_force": 1000, "max_torque": 1000 } ] })",
                                  "x.json");
    BuiltScene heldWorld = BuildWorld(held);
    const BodyId box = heldWorld.bodyByName.at("box");
    for (int i = 0; i < 120; ++i)
    {
        heldWorld.world.Step(Real(1) / 60);
    }
    // The motor's rows take back each step's gravity kick before the position moves, so only
    // round-off remains (measured: 0 m and 6e-9 rad); 1e-5 allows for it.
    CHECK(heldWorld.world.GetPosition(box).x == Approx(3).margin(1e-5));
    CHECK(heldWorld.world.GetPosition(box).y == Approx(1).margin(1e-5));
    CHECK(heldWorld.world.GetAngle(box) == Approx(0.4).margin(1e-5));
}

TEST_CASE("Scene: world.solver chooses the back end; graph_coloring is the older spelling",
          "[scene][solver]")
{
    const auto kindOf = [](const std::string& world)
    {
        return ParseScene(R"({ "meff_scene": 1, "world": )" + world + R"(, "bodies": [] })",
                          "x.json")
            .world.solver.kind;
    };
    CHECK(kindOf("{}") == SolverKind::Box2D);
    CHECK(kindOf(R"({"solver": "box2d"})") == SolverKind::Box2D);
    CHECK(kindOf(R"({"solver": "colour"})") == SolverKind::Colour);
    CHECK(kindOf(R"({"graph_coloring": true})") == SolverKind::Colour);
    CHECK(kindOf(R"({"graph_coloring": false})") == SolverKind::Box2D);
    CHECK(kindOf(R"({"solver": "colour", "graph_coloring": true})") == SolverKind::Colour);

    const auto errorsOf = [](const std::string& world)
    { return ErrorsOf(R"({ "meff_scene": 1, "world": )" + world + R"(, "bodies": [] })"); };
    CHECK(errorsOf(R"({"solver": "colour"})").empty());
    CHECK(
        errorsOf(R"({"solver": "fast"})") ==
        Messages{
            R"(x.json: world.solver: must be one of "box2d", "colour", "soft_step", got "fast")"});
    CHECK(
        errorsOf(R"({"solver": "box2d", "graph_coloring": true})") ==
        Messages{
            R"(x.json: world.graph_coloring: true means "solver": "colour", but "solver" is "box2d", got true)"});
}

TEST_CASE("Scene: world.soft_step sets the sub-stepped solver's settings, each checked",
          "[scene][solver]")
{
    const Scene scene = ParseScene(R"({ "meff_scene": 1, "world": { "solver": "soft_step",
        "soft_step": { "substeps": 8, "relax_iterations": 2, "contacts": "soft",
                       "contact_correction": 0.2, "contact_hertz": 40,
                       "contact_damping_ratio": 5, "joint_hertz": 50, "joint_damping_ratio": 1,
                       "max_push_out_speed": 2, "joint_trees": false } }, "bodies": [] })",
                                   "x.json");
    const SoftStepSettings& soft = scene.world.solver.softStep;
    CHECK(scene.world.solver.kind == SolverKind::SoftStep);
    CHECK(soft.substeps == 8);
    CHECK(soft.relaxIterations == 2);
    CHECK(soft.contacts == SoftContactModel::Soft);
    CHECK(soft.contactCorrection == Approx(0.2));
    CHECK(soft.contactHertz == Approx(40));
    CHECK(soft.contactDampingRatio == Approx(5));
    CHECK(soft.jointHertz == Approx(50));
    CHECK(soft.jointDampingRatio == Approx(1));
    CHECK(soft.maxPushOutSpeed == Approx(2));
    CHECK_FALSE(soft.jointTrees);
    CHECK(ParseScene(R"({ "meff_scene": 1, "bodies": [] })", "x.json")
              .world.solver.softStep.jointTrees); // on by default

    const auto errorsOf = [](const std::string& soft)
    {
        return ErrorsOf(R"({ "meff_scene": 1, "world": { "soft_step": )" + soft +
                        R"( }, "bodies": [] })");
    };
    CHECK(errorsOf(R"({"substeps": 0})") ==
          Messages{"x.json: world.soft_step.substeps: must be an integer in [1, 1000], got 0"});
    CHECK(errorsOf(R"({"contact_correction": 1.5})") ==
          Messages{"x.json: world.soft_step.contact_correction: must be in (0, 1], got 1.5"});
    CHECK(errorsOf(R"({"contacts": "sticky"})") ==
          Messages{
              R"(x.json: world.soft_step.contacts: must be one of "rigid", "soft", got "sticky")"});
    CHECK(errorsOf(R"({"joint_hertz": -1})").size() == 1);
    CHECK(errorsOf(R"({"substep": 4})") ==
          Messages{"x.json: world.soft_step.substep: unknown field (known fields here: substeps, "
                   "relax_iterations, contacts, contact_correction, contact_hertz, "
                   "contact_damping_ratio, joint_hertz, joint_damping_ratio, "
                   "max_push_out_speed, joint_trees)"});
}
