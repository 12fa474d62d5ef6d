// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// b2dJson (R.U.B.E.'s format): the round trip meff → b2dJson → meff gives every sample back
// field for field, the level alone (without meff's authoring forms) builds the same world bit
// for bit, hand-written levels (tests/b2djson/) import to exactly the values they spell in each
// of the format's conventions, and bad levels are refused naming the file and the JSON path.
#include "sample_scenes.h"
#include "meff/b2djson.h"
#include "meff/scene.h"

#include <nlohmann/json.hpp>

#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace meff;

namespace
{

std::string Level(const std::string& name)
{
    return std::string(MEFF_SOURCE_DIR) + "/tests/b2djson/" + name;
}

/// The messages a level is refused with, or none.
std::vector<std::string> ErrorsOf(const std::string& text)
{
    try
    {
        ImportB2dJson(text, "level.json");
    }
    catch (const SceneError& error)
    {
        return error.messages();
    }
    return {};
}

/// Drops the joints' "meff.joint" custom properties: their frames are then only what b2dJson's
/// own fields say (local anchors, reference angles, local axes, offsets).
std::string WithoutAuthoringForms(const std::string& text)
{
    nlohmann::json level = nlohmann::json::parse(text);
    const auto strip = [](nlohmann::json& object)
    {
        if (object.contains("customProperties"))
        {
            object.erase("customProperties");
        }
    };
    for (nlohmann::json& joint : level["joint"])
    {
        strip(joint);
    }
    return level.dump();
}

/// The name of the scene's first joint that b2dJson has no form for (pulley, gear), or "".
std::string UnexportableJoint(const Scene& scene)
{
    for (const SceneJoint& joint : scene.joints)
    {
        if (joint.type == JointType::Pulley || joint.type == JointType::Gear)
        {
            return joint.name;
        }
    }
    return "";
}

/// Such a scene's export is refused with an error naming the joint and its type.
void CheckExportRefused(const Scene& scene, const std::string& joint)
{
    CHECK_THROWS_WITH(ExportB2dJson(scene), Catch::Contains("\"" + joint + "\"") &&
                                                Catch::Contains("cannot be exported") &&
                                                Catch::Contains(scene.sourcePath));
}

float Bits(std::uint32_t bits)
{
    return std::bit_cast<float>(bits);
}

} // namespace

TEST_CASE("b2dJson round trip: every sample comes back as the same scene")
{
    const std::vector<std::string> paths = SampleScenes({"samples/scenes", "samples/extreme"});
    REQUIRE(paths.size() >= 40); // samples/scenes and samples/extreme
    for (const std::string& path : paths)
    {
        INFO(path);
        const Scene original = LoadScene(path);
        if (const std::string joint = UnexportableJoint(original); !joint.empty())
        {
            CheckExportRefused(original, joint); // asserted, not skipped
            continue;
        }
        for (const bool hex : {false, true})
        {
            INFO("hex floats " << hex);
            const std::string level = ExportB2dJson(original, {.hexFloats = hex});
            REQUIRE(LooksLikeB2dJson(level));
            const LoadedScene back = ImportB2dJson(level, path);
            CHECK(back.warnings.empty());
            // Piece by piece first, so that a failure says where.
            CHECK(back.scene.world == original.world);
            REQUIRE(back.scene.bodies.size() == original.bodies.size());
            for (std::size_t i = 0; i < original.bodies.size(); ++i)
            {
                INFO("body " << original.bodies[i].name);
                CHECK(back.scene.bodies[i] == original.bodies[i]);
            }
            REQUIRE(back.scene.joints.size() == original.joints.size());
            for (std::size_t j = 0; j < original.joints.size(); ++j)
            {
                INFO("joint " << original.joints[j].name);
                CHECK(back.scene.joints[j] == original.joints[j]);
            }
            CHECK(back.scene == original);
            // And the level the scene makes again is the same text.
            CHECK(ExportB2dJson(back.scene, {.hexFloats = hex}) == level);
            // The meff file `meff import` writes loads as the same scene.
            CHECK(ParseScene(back.meffText, path) == original);
        }
    }
}

TEST_CASE("b2dJson round trip: the level's joint fields build the same world, bit for bit")
{
    // Without meff.joint, anchors come back in the bodies' frames: a different scene text, but
    // the engine must get the very same numbers, so the two runs agree to the bit, step after
    // step. (A box without meff.box comes back as a polygon, whose centroid and inertia the
    // engine computes by the general formula, as Box2D's b2PolygonShape::Set does: the same
    // to float round-off, not to the bit.)
    for (const std::string& path : SampleScenes({"samples/scenes", "samples/extreme"}))
    {
        INFO(path);
        const Scene original = LoadScene(path);
        if (const std::string joint = UnexportableJoint(original); !joint.empty())
        {
            CheckExportRefused(original, joint);
            continue;
        }
        const Scene imported =
            ImportB2dJson(WithoutAuthoringForms(ExportB2dJson(original)), path).scene;
        BuiltScene a = BuildWorld(original);
        BuiltScene b = BuildWorld(imported);
        for (std::size_t j = 0; j < a.joints.size(); ++j)
        {
            CHECK(a.world.GetAnchorA(a.joints[j]) == b.world.GetAnchorA(b.joints[j]));
            CHECK(a.world.GetAnchorB(a.joints[j]) == b.world.GetAnchorB(b.joints[j]));
        }
        const Real dt = Real(original.world.dt);
        const int frames = std::min(original.world.frames, 120); // enough to collide and swing
        bool same = a.world.GetStateHash() == b.world.GetStateHash();
        for (int frame = 1; frame <= frames && same; ++frame)
        {
            a.world.Step(dt);
            b.world.Step(dt);
            same = a.world.GetStateHash() == b.world.GetStateHash();
            INFO("frame " << frame);
            CHECK(same);
        }
    }
}

TEST_CASE("b2dJson round trip: the soft step's settings travel as meff.soft_step")
{
    // No sample uses the soft step, so a scene is given every member of world.soft_step away
    // from its default (and then only some), and must come back equal.
    Scene original = LoadScene(std::string(MEFF_SOURCE_DIR) + "/samples/scenes/chain20.json");
    original.world.solver.kind = SolverKind::SoftStep;
    SoftStepSettings& soft = original.world.solver.softStep;
    soft.substeps = 8;
    soft.relaxIterations = 2;
    soft.contacts = SoftContactModel::Soft;
    soft.contactCorrection = Real(0.2);
    soft.contactHertz = Real(45.5);
    soft.contactDampingRatio = Real(0.7);
    soft.maxPushOutSpeed = Real(1.25);
    soft.jointHertz = Real(60.1);
    soft.jointDampingRatio = Real(0.3);
    const Scene defaultsOnly = [&]
    {
        Scene scene = original;
        scene.world.solver.softStep = SoftStepSettings{};
        return scene;
    }();
    Scene some = original;
    some.world.solver.softStep = SoftStepSettings{};
    some.world.solver.softStep.substeps = 2;
    some.world.solver.softStep.jointDampingRatio = Real(0.1);
    const Scene* const scenes[] = {&original, &defaultsOnly, &some};
    for (const Scene* scene : scenes)
    {
        for (const bool hex : {false, true})
        {
            INFO("substeps " << scene->world.solver.softStep.substeps << ", hex floats " << hex);
            const std::string level = ExportB2dJson(*scene, {.hexFloats = hex});
            const nlohmann::json parsed = nlohmann::json::parse(level);
            bool named = false;
            for (const nlohmann::json& property : parsed["customProperties"])
            {
                named = named || property["name"] == "meff.soft_step";
            }
            // Written only when it says something.
            CHECK(named == (scene != &defaultsOnly));
            CHECK(level.find("\"soft_step\"") != std::string::npos); // meff.solver
            const LoadedScene back = ImportB2dJson(level, scene->sourcePath);
            CHECK(back.warnings.empty());
            CHECK(back.scene.world.solver.softStep == scene->world.solver.softStep);
            CHECK(back.scene == *scene);
            CHECK(ExportB2dJson(back.scene, {.hexFloats = hex}) == level);
            CHECK(ParseScene(back.meffText, scene->sourcePath) == *scene);
        }
    }

    // A bad value in the property is the loader's message, said about the property.
    using Messages = std::vector<std::string>;
    CHECK(ErrorsOf(R"({"customProperties": [{"name": "meff.solver", "string": "soft_step"},
                       {"name": "meff.soft_step", "string": "{\"substeps\": 0}"}]})") ==
          Messages{"level.json: customProperties[1] (meff.soft_step).substeps: must be an "
                   "integer in [1, 1000], got 0"});
}

TEST_CASE("b2dJson import: world settings and bodies, in every convention")
{
    const LoadedScene loaded = LoadSceneFile(Level("world_and_bodies.json"));
    const Scene& scene = loaded.scene;
    // World: gravity's y as hex bits (C1200000 = -10), step rate and iterations as R.U.B.E.
    // writes them, the flags; meff.frames read back.
    CHECK(scene.world.gravity == SceneVec2{0, -10});
    CHECK(scene.world.dt == 1.0 / 30);
    CHECK(scene.world.solver.velocityIterations == 10);
    CHECK(scene.world.solver.positionIterations == 4);
    CHECK(scene.world.allowSleep);
    CHECK(scene.world.solver.warmStarting);
    CHECK(scene.world.continuous);
    CHECK(scene.world.frames == 90);
    CHECK(scene.name == "world_and_bodies");

    // The inactive body (body[4]) is left out: four bodies.
    REQUIRE(scene.bodies.size() == 4);
    const SceneBody& ground = scene.bodies[0];
    CHECK(ground.name == "ground");
    CHECK(ground.type == BodyType::Static);
    CHECK(ground.position == SceneVec2{0, 0}); // the zero vector written as 0
    REQUIRE(ground.shapes.size() == 1);
    CHECK(ground.shapes[0].type == SceneShapeType::Segment);
    CHECK(ground.shapes[0].friction == 0.5); // "3F000000"
    CHECK(ground.shapes[0].density == 0);    // absent: b2dJson's 0, not meff's default 1

    const SceneBody& crate = scene.bodies[1];
    CHECK(crate.name == "sleepy_crate"); // a space is not allowed in meff's names
    CHECK(crate.type == BodyType::Dynamic);
    CHECK(crate.position == SceneVec2{1.5, 3});     // "3FC00000"
    CHECK(crate.angle == double(Bits(0x3F490FDB))); // π/4 as float bits
    CHECK(crate.linearVelocity == SceneVec2{1, 0});
    CHECK(crate.angularVelocity == 0.5);
    CHECK(crate.linearDamping == 0.1);
    CHECK(crate.angularDamping == 0.25);
    CHECK(crate.gravityScale == 2);
    CHECK(crate.bullet);
    CHECK_FALSE(crate.allowSleep);
    CHECK(crate.fixedRotation);
    CHECK_FALSE(crate.awake); // b2dJson's loader: no "awake" means asleep
    REQUIRE(crate.shapes.size() == 1);
    CHECK(crate.shapes[0].type == SceneShapeType::Polygon);
    CHECK(crate.shapes[0].vertices ==
          std::vector<SceneVec2>{{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}});

    CHECK(scene.bodies[2].name == "sleepy_crate-2"); // the same name twice
    CHECK(scene.bodies[2].awake);
    CHECK(scene.bodies[2].shapes[0].restitution == 0.2);
    CHECK(scene.bodies[3].name == "body3"); // unnamed
    CHECK(scene.bodies[3].type == BodyType::Kinematic);
    CHECK(scene.bodies[3].linearVelocity == SceneVec2{-1, 0});

    // One line for the custom properties (one on the world, one on a body; meff.frames is
    // meff's own), one for the images, and one each for sub-stepping, the inactive body and
    // the changed names.
    const std::vector<std::string> expected = {
        "world_and_bodies.json: warning: subStepping: meff has no sub-stepping (a Box2D "
        "debugging aid); the level is stepped normally",
        "world_and_bodies.json: warning: 2 custom properties left out (meff has no use for "
        "them)",
        "world_and_bodies.json: warning: 1 image left out (meff draws shapes, not images)",
        "world_and_bodies.json: warning: inactive bodies left out (Box2D does not simulate "
        "them), with their fixtures: body[4]",
        "world_and_bodies.json: warning: names changed to meff's (unique; letters, digits, '_', "
        "'-', '.'; at most 64): \"sleepy crate\" -> sleepy_crate, \"sleepy crate\" -> "
        "sleepy_crate-2"};
    REQUIRE(loaded.warnings.size() == expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i)
    {
        // The file is named as given; compare from its base name on.
        const std::string& warning = loaded.warnings[i];
        CHECK(warning.substr(warning.find("world_and_bodies.json")) == expected[i]);
    }
}

TEST_CASE("b2dJson import: circle, polygon, edge, chain and loop fixtures, filters, sensors")
{
    // Read as Box2D 2.4.1 reads them (one-sided chains); the default, two-sided as 2.3, is the
    // next test's.
    B2dJsonImportOptions oneSided;
    oneSided.twoSidedChains = false;
    const LoadedScene loaded =
        LoadSceneFile(Level("fixtures.json"), SceneFormat::Auto, {}, oneSided);
    const std::vector<SceneShape>& terrain = loaded.scene.bodies.at(0).shapes;
    // The open chain, the old-style loop, the edge with ghosts, the chain closed by repeating
    // its first point, the two-point polygon, the sensor.
    REQUIRE(terrain.size() == 6);
    const SceneShape& hills = terrain[0];
    CHECK(hills.type == SceneShapeType::Chain);
    CHECK_FALSE(hills.loop);
    CHECK(hills.points == std::vector<SceneVec2>{{12, 4}, {4, 0}, {-4, 0}, {-12, 4}});
    // No ghosts in the level: the loader continues the end segments straight on.
    CHECK(hills.prev == SceneVec2{20, 8});
    CHECK(hills.next == SceneVec2{-20, 8});
    const SceneShape& box = terrain[1]; // "loop": R.U.B.E. before r197
    CHECK(box.type == SceneShapeType::Chain);
    CHECK(box.loop);
    CHECK(box.points.size() == 4);
    const SceneShape& ledge = terrain[2];
    CHECK(ledge.type == SceneShapeType::Segment);
    CHECK(ledge.oneSided); // ghost vertices: Box2D 2.4's one-sided edge
    CHECK(ledge.point1 == SceneVec2{4, 0});
    CHECK(ledge.prev == SceneVec2{12, 4});
    CHECK(ledge.next == SceneVec2{-12, 4});
    const SceneShape& ring = terrain[3]; // a chain whose last point repeats its first
    CHECK(ring.type == SceneShapeType::Chain);
    CHECK(ring.loop);
    CHECK(ring.points == std::vector<SceneVec2>{{3, 9}, {-3, 9}, {-3, 10}, {3, 10}});
    CHECK(terrain[4].type == SceneShapeType::Segment); // a two-point polygon is an edge
    CHECK_FALSE(terrain[4].oneSided);
    CHECK(terrain[4].point2 == SceneVec2{8, 1});
    CHECK(terrain[5].sensor);
    CHECK(terrain[5].type == SceneShapeType::Polygon);

    const SceneShape& red = loaded.scene.bodies.at(1).shapes.at(0);
    CHECK(red.type == SceneShapeType::Circle);
    CHECK(red.center == SceneVec2{0.1, 0});
    CHECK(red.radius == 0.4);
    CHECK(red.filter.category == 2);
    CHECK(red.filter.mask == 65533);
    CHECK(red.filter.group == -1);
    const SceneShape& blue = loaded.scene.bodies.at(2).shapes.at(0);
    CHECK(blue.filter.category == 4);
    CHECK(blue.filter.mask == 0xFFFF); // absent: Box2D's default
    CHECK(blue.vertices.size() == 3);
    REQUIRE(loaded.warnings.size() == 1);
    CHECK(loaded.warnings[0].find("chains and edges with ghost vertices kept one-sided, as in "
                                  "Box2D 2.4.1") != std::string::npos);
    CHECK(loaded.warnings[0].find("body[0].fixture[0], body[0].fixture[1], body[0].fixture[2]") !=
          std::string::npos);
}

TEST_CASE("b2dJson import: chains and ghosted edges two-sided by default, one segment per edge")
{
    const LoadedScene loaded = LoadSceneFile(Level("fixtures.json"));
    const std::vector<SceneShape>& terrain = loaded.scene.bodies.at(0).shapes;
    // The open chain's 3 edges, the old-style loop's 4, the ghosted edge, the closed chain's 4,
    // the two-point polygon, the sensor.
    REQUIRE(terrain.size() == 14);
    for (std::size_t k = 0; k < 13; ++k)
    {
        CHECK(terrain[k].type == SceneShapeType::Segment);
        CHECK_FALSE(terrain[k].oneSided);
    }
    CHECK(terrain[0].point1 == SceneVec2{12, 4});
    CHECK(terrain[2].point2 == SceneVec2{-12, 4});
    CHECK(terrain[6].point1 == SceneVec2{-1, 7}); // the loop's closing edge
    CHECK(terrain[6].point2 == SceneVec2{-1, 6});
    CHECK(terrain[7].point1 == SceneVec2{4, 0});  // the edge, its ghosts dropped
    CHECK(terrain[11].point2 == SceneVec2{3, 9}); // the closed chain's last edge
    REQUIRE(loaded.warnings.size() == 1);
    CHECK(loaded.warnings[0].find("imported two-sided, as Box2D 2.3") != std::string::npos);
}

TEST_CASE("b2dJson import: every joint kind, anchors in the bodies' frames")
{
    // The springs' numbers as Box2D 2.4.1 reads them; the default keeps 2.3's sizing, which
    // rescales the wheel's (its spring mass is not its bodies' mass): tested below.
    B2dJsonImportOptions as241;
    as241.springsAs23 = false;
    const Scene scene = LoadSceneFile(Level("joints.json"), SceneFormat::Auto, {}, as241).scene;
    REQUIRE(scene.joints.size() == 9);
    const SceneJoint& shoulder = scene.joints[0];
    CHECK(shoulder.type == JointType::Revolute);
    CHECK(shoulder.localAnchors);
    CHECK(shoulder.localAnchorA == SceneVec2{-10, 5});
    CHECK(shoulder.localAnchorB == SceneVec2{-1, 0});
    CHECK(shoulder.referenceAngle == 0.3);
    CHECK(shoulder.enableLimit);
    CHECK(shoulder.lowerAngle == -0.5);
    CHECK(shoulder.upperAngle == 0.5);
    CHECK(shoulder.enableMotor);
    CHECK(shoulder.motorSpeed == 1);
    CHECK(shoulder.maxMotorTorque == 5);

    const SceneJoint& rod = scene.joints[1];
    CHECK(rod.type == JointType::Distance);
    CHECK(rod.length == 3);
    CHECK(rod.minLength == 3); // Box2D 2.3's rod: no spring, so rigid
    CHECK(rod.maxLength == 3);
    const SceneJoint& spring = scene.joints[2];
    CHECK(spring.stiffnessHz == 2);
    CHECK(spring.dampingRatio == 0.3);
    CHECK(spring.minLength == 0); // 2.3's spring has no limits
    CHECK(spring.maxLength == double(std::numeric_limits<float>::max()));

    const SceneJoint& rail = scene.joints[3];
    CHECK(rail.type == JointType::Prismatic);
    REQUIRE(rail.localAxisA);
    CHECK(*rail.localAxisA == SceneVec2{0, 1});
    CHECK(rail.lowerTranslation == -0.5);
    CHECK(rail.upperTranslation == 1);
    CHECK(rail.maxMotorForce == 50);

    const SceneJoint& axle = scene.joints[4];
    CHECK(axle.type == JointType::Wheel);
    CHECK(axle.stiffnessHz == 4);
    CHECK(axle.dampingRatio == 0.7);
    CHECK(axle.motorSpeed == -5);

    const SceneJoint& glue = scene.joints[5];
    CHECK(glue.type == JointType::Weld);
    CHECK(glue.stiffnessHz == 3);
    CHECK(glue.referenceAngle == 0);

    const SceneJoint& carrier = scene.joints[6];
    CHECK(carrier.type == JointType::Motor);
    CHECK(carrier.linearOffset == SceneVec2{12, 5});
    CHECK(carrier.angularOffset == 0.2);
    CHECK(carrier.maxForce == 100);

    const SceneJoint& grab = scene.joints[7];
    CHECK(grab.type == JointType::Mouse);
    CHECK(grab.anchor == SceneVec2{15, 1.2}); // b2dJson's anchorB is a world point
    CHECK(grab.target == SceneVec2{16, 3});
    CHECK(grab.stiffnessHz == 5);

    const SceneJoint& cord = scene.joints[8];
    CHECK(cord.type == JointType::Distance); // a rope: a distance joint with a maximum
    CHECK(cord.minLength == 0);
    CHECK(cord.maxLength == 3.5);
    CHECK(cord.stiffnessHz == 0);

    // The engine gets the level's local anchors as they are: the shoulder's world anchors are
    // where body A's and body B's frames put them.
    BuiltScene built = BuildWorld(scene);
    const Vec2 a = built.world.GetAnchorA(built.joints[0]);
    CHECK(a.x == -10);
    CHECK(a.y == 5);
}

TEST_CASE("b2dJson import: bad levels are refused with the file and the JSON path")
{
    using Messages = std::vector<std::string>;
    CHECK(ErrorsOf(R"({"body": [{"type": 2, "fixture": [{"density": 1,
                       "circle": {"radius": -1}}]}]})") ==
          Messages{"level.json: body[0].fixture[0].circle.radius: must be > 0, got -1.0"});
    CHECK(ErrorsOf(R"({"body": [{"type": 2, "position": {"x": "zz", "y": 0}}]})") ==
          Messages{"level.json: body[0].position: must be a vector {\"x\": X, \"y\": Y}, or 0 "
                   "for the zero vector, got {\"x\": \"zz\", \"y\": 0}"});
    CHECK(ErrorsOf(R"({"body": [{"type": 7}]})") ==
          Messages{"level.json: body[0].type: must be 0 (static), 1 (kinematic) or 2 (dynamic), "
                   "got 7"});
    CHECK(ErrorsOf(R"({"body": [{"type": 0}], "joint": [{"type": "revolute",
                       "bodyA": 0, "bodyB": 3}]})") ==
          Messages{"level.json: joint[0].bodyB: must be the index of a body in \"body\" (0 to "
                   "0), got 3"});
    CHECK(ErrorsOf(R"({"body": [{"type": 0}, {"type": 2, "fixture": [{"density": 1,
                       "circle": {"radius": 1}}]}], "joint": [{"type": "pulley", "bodyA": 0,
                       "bodyB": 1}]})") ==
          Messages{"level.json: joint[0].type: meff does not read b2dJson pulley joints (meff's "
                   "export refuses them too: write the joint in a meff scene), got \"pulley\""});
    CHECK(ErrorsOf(R"({"body": [{"type": 2, "fixture": [{"density": 1, "polygon":
                       {"vertices": {"x": [0, 1], "y": [0, 0, 1]}}}]}]})") ==
          Messages{"level.json: body[0].fixture[0].polygon.vertices: must be {\"x\": [...], "
                   "\"y\": [...]} with as many x as y, got {\"x\": [0, 1], \"y\": [0, 0, 1]}"});
    // meff's own rules, said about the level's fields: a dynamic body needs mass.
    CHECK(ErrorsOf(R"({"body": [{"type": 2, "fixture": [{"circle": {"radius": 1}}]}]})") ==
          Messages{"level.json: body[0].fixture: a dynamic body needs mass: give one of its "
                   "circles, boxes or polygons a density > 0 (segments and chains have none)"});
    CHECK(ErrorsOf(R"({"body": [{"type": 2, "fixture": [{"density": 1, "friction": -1,
                       "circle": {"radius": 1}}]}]})") ==
          Messages{"level.json: body[0].fixture[0].friction: must be >= 0, got -1.0"});
    CHECK(ErrorsOf("{\"body\": [") ==
          Messages{"level.json: line 1, column 11: syntax error while parsing value - unexpected "
                   "end of input; expected '[', '{', or a literal"});
}

TEST_CASE("b2dJson import: a mass set by hand is said, once")
{
    const LoadedScene loaded = ImportB2dJson(R"({"body": [{"name": "crate", "type": 2,
        "massData-mass": 5, "fixture": [{"density": 1, "circle": {"radius": 1}}]}]})",
                                             "level.json");
    REQUIRE(loaded.warnings.size() == 1);
    CHECK(loaded.warnings[0] == "level.json: warning: massData: mass set by hand is not kept "
                                "(meff computes mass from fixture densities): crate: 5 kg set, "
                                "3.14159 kg from its fixtures");
}

TEST_CASE("b2dJson values: hex floats and the zero vector")
{
    // The importer reads "3FC00000" as 1.5f and 0 as the zero vector; the exporter writes
    // them so (ExportB2dJson with hexFloats). Checked through a level.
    const LoadedScene loaded = ImportB2dJson(R"({"gravity": 0, "body": [{"type": 2,
        "position": {"x": "3fc00000", "y": "BF800000"}, "fixture": [{"density": 1,
        "circle": {"radius": "3F000000"}}]}]})",
                                             "level.json");
    CHECK(loaded.scene.world.gravity == SceneVec2{0, 0});
    CHECK(loaded.scene.bodies[0].position == SceneVec2{1.5, -1}); // lower case hex too
    CHECK(loaded.scene.bodies[0].shapes[0].radius == 0.5);
    const std::string level = ExportB2dJson(loaded.scene, {.hexFloats = true});
    CHECK(level.find("\"3FC00000\"") != std::string::npos);
    CHECK(level.find("\"gravity\": 0") != std::string::npos);
    CHECK(ImportB2dJson(level, "level.json").scene == loaded.scene);
}

TEST_CASE("b2dJson and meff files are told apart by their content")
{
    CHECK(LooksLikeB2dJson(R"({"body": []})"));
    CHECK(LooksLikeB2dJson(R"({"gravity": 0})"));
    CHECK_FALSE(LooksLikeB2dJson(R"({"meff_scene": 1, "bodies": []})"));
    CHECK_FALSE(LooksLikeB2dJson(R"({"bodies": []})"));
    CHECK_FALSE(LooksLikeB2dJson("not json"));
    // LoadSceneFile goes by content, or by the format it is told.
    CHECK(LoadSceneFile(Level("joints.json")).scene.joints.size() == 9);
    CHECK_THROWS_AS(LoadSceneFile(Level("joints.json"), SceneFormat::Meff), SceneError);
}

namespace
{

/// The ball of chain_ground.json after `frames` steps of the level read with `options`.
double BallHeightAfter(const B2dJsonImportOptions& options, int frames)
{
    const Scene scene =
        LoadSceneFile(Level("chain_ground.json"), SceneFormat::Auto, {}, options).scene;
    BuiltScene built = BuildWorld(scene);
    for (int frame = 0; frame < frames; ++frame)
    {
        built.Step(Real(scene.world.dt));
    }
    return double(built.world.GetPosition(built.bodyByName.at("ball")).y);
}

} // namespace

TEST_CASE("b2dJson import: a Box2D 2.3 chain is two-sided, so a ball dropped on it stays on it")
{
    // The ground chain runs left to right, so Box2D 2.4.1's one-sided chain is solid below it;
    // R.U.B.E. targets 2.3, whose chains collide on both sides. The ball (radius 0.5 m) starts
    // 3 m up over the chain's flat middle at y = 0.
    const LoadedScene loaded = LoadSceneFile(Level("chain_ground.json"));
    const std::vector<SceneShape>& ground = loaded.scene.bodies.at(0).shapes;
    REQUIRE(ground.size() == 3); // one two-sided segment per edge
    for (const SceneShape& segment : ground)
    {
        CHECK(segment.type == SceneShapeType::Segment);
        CHECK_FALSE(segment.oneSided);
        CHECK(segment.friction == 0.6);
    }
    CHECK(ground[1].point1 == SceneVec2{-2, 0});
    CHECK(ground[1].point2 == SceneVec2{2, 0});
    int chainWarnings = 0;
    for (const std::string& warning : loaded.warnings)
    {
        chainWarnings += warning.find("imported two-sided") != std::string::npos ? 1 : 0;
    }
    CHECK(chainWarnings == 1);
    // At rest on the segment after 3 s: its centre at the radius, within the contact slop the
    // solver leaves (Box2D's linear slop, 0.005 m).
    CHECK(BallHeightAfter({}, 180) == Approx(0.5).margin(0.005));
    // Kept one-sided (2.4.1's chain): the ball falls through, far below the ground.
    B2dJsonImportOptions oneSided;
    oneSided.twoSidedChains = false;
    const Scene kept =
        LoadSceneFile(Level("chain_ground.json"), SceneFormat::Auto, {}, oneSided).scene;
    REQUIRE(kept.bodies.at(0).shapes.size() == 1);
    CHECK(kept.bodies[0].shapes[0].type == SceneShapeType::Chain);
    CHECK(BallHeightAfter(oneSided, 180) < -20);
}

TEST_CASE("b2dJson import: a Box2D 2.3 spring keeps its stiffness from the joint's effective mass")
{
    // The crate (1 m box, 1 kg, I = 1/6 kg·m²) hangs from a static hanger by a spring whose
    // anchor is 0.5 m off its centre, across the spring's line: Box2D 2.3's effective mass is
    // 1/(1/m + 0.5²/I) = 1/(1 + 1.5) = 0.4 kg, 2.4.1's is the crate's mass, 1 kg. So 2.3's
    // 2 Hz, ζ 0.5 spring is 2.4.1's 2·√0.4 Hz, ζ 0.5·√0.4 (same k = m·ω², d = 2·m·ζ·ω).
    const LoadedScene loaded = LoadSceneFile(Level("chain_ground.json"));
    const SceneJoint& spring = loaded.scene.joints.at(0);
    // The masses are float sums of the engine; 1e-6 relative is float round-off.
    CHECK(spring.stiffnessHz == Approx(2 * std::sqrt(0.4)).epsilon(1e-6));
    CHECK(spring.dampingRatio == Approx(0.5 * std::sqrt(0.4)).epsilon(1e-6));
    int springWarnings = 0;
    for (const std::string& warning : loaded.warnings)
    {
        springWarnings += warning.find("keep Box2D 2.3's stiffness") != std::string::npos ? 1 : 0;
    }
    CHECK(springWarnings == 1);
    B2dJsonImportOptions as241;
    as241.springsAs23 = false;
    const Scene kept =
        LoadSceneFile(Level("chain_ground.json"), SceneFormat::Auto, {}, as241).scene;
    CHECK(kept.joints.at(0).stiffnessHz == 2);
    CHECK(kept.joints.at(0).dampingRatio == 0.5);
}
