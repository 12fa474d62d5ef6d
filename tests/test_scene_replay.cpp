// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Saving a live world as a scene file (SceneFromWorld, WriteScene) and replaying it: every
// bundled sample saved as built reads back as the same scene and runs bit for bit as the
// original (state hash every frame); a world saved mid-run at a moment when no contact touches
// replays bit for bit under every back end, its joints' impulses carried in the file; a contact
// touching when saved (whose warm start the file cannot carry) is the measured limit.
#include "sample_scenes.h"
#include "meff/scene.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstring>
#include <limits>
#include <string>
#include <unordered_map>
#include <vector>

using namespace meff;

namespace
{

/// The scene's text read back, its source path set as the saved scene has it.
Scene ReadBack(const Scene& saved)
{
    Scene loaded = ParseScene(WriteScene(saved), "saved.json");
    loaded.sourcePath = saved.sourcePath;
    loaded.warnings = saved.warnings;
    return loaded;
}

template <typename T>
bool SameBits(const T& a, const T& b)
{
    return std::memcmp(&a, &b, sizeof(T)) == 0;
}

/// Steps both worlds `frames` times; the first frame whose state hashes differ, or -1.
int FirstDifferentFrame(World& a, World& b, Real dt, int frames)
{
    if (a.GetStateHash() != b.GetStateHash())
    {
        return 0;
    }
    for (int frame = 1; frame <= frames; ++frame)
    {
        a.Step(dt);
        b.Step(dt);
        if (a.GetStateHash() != b.GetStateHash())
        {
            return frame;
        }
    }
    return -1;
}

} // namespace

TEST_CASE("Every bundled sample saved as built reads back as the same scene and replays bit for "
          "bit",
          "[replay]")
{
    const std::vector<std::string> paths = SampleScenes(
        {"samples/scenes", "samples/extreme", "samples/testbed", "samples/solver2d", "samples/v3"});
    REQUIRE(paths.size() >= 110); // samples/scenes, extreme, testbed, solver2d and v3
    int replayed = 0;
    for (const std::string& path : paths)
    {
        INFO(path);
        const Scene original = LoadScene(path);
        if (!original.characters.empty())
        {
            // The character mover's state lives in BuiltScene, not in the world.
            CHECK_THROWS_AS(SceneFromBuilt(BuildWorld(original), original), SceneError);
            continue;
        }
        BuiltScene built = BuildWorld(original);
        const Scene saved = SceneFromBuilt(built, original);
        CHECK(saved.bodies.size() == original.bodies.size());
        CHECK(saved.joints.size() == original.joints.size());
        // The file reads back as the scene it was written from, field for field.
        const Scene loaded = ReadBack(saved);
        REQUIRE(loaded == saved);
        BuiltScene rebuilt = BuildWorld(loaded);
        // The rebuilt world saves as the same scene again: nothing drifts.
        CHECK(SceneFromBuilt(rebuilt, loaded) == saved);
        // The whole run, bit for bit (BuiltScene::Step is World::Step without characters).
        const int frames = std::min(original.world.frames, 600);
        CHECK(FirstDifferentFrame(built.world, rebuilt.world, Real(original.world.dt), frames) ==
              -1);
        ++replayed;
    }
    CHECK(replayed >= 110);
}

namespace
{

/// Balls, a turned box and a bullet falling towards the ground from different heights, a
/// pendulum and a slider beside them: at frame 20 nothing touches yet.
constexpr const char* kFalling = R"({
  "meff_scene": 1,
  "world": {"continuous": true},
  "bodies": [
    {"name": "ground", "type": "static",
     "shapes": [{"type": "box", "half_width": 20, "half_height": 0.5}]},
    {"name": "ball1", "type": "dynamic", "position": [-4, 6], "linear_velocity": [1, 0],
     "angular_velocity": 2, "shapes": [{"type": "circle", "radius": 0.5, "restitution": 0.5}]},
    {"name": "ball2", "type": "dynamic", "position": [0, 12], "linear_damping": 0.1,
     "shapes": [{"type": "circle", "radius": 0.3, "friction": 0.2}]},
    {"name": "crate", "type": "dynamic", "position": [4, 9], "angle": 0.3,
     "angular_velocity": -1, "shapes": [{"type": "box", "half_width": 0.5, "half_height": 0.25}]},
    {"name": "bullet", "type": "dynamic", "position": [8, 15], "linear_velocity": [0, -20],
     "bullet": true, "shapes": [{"type": "circle", "radius": 0.1}]},
    {"name": "pivot", "type": "static", "position": [-10, 10]},
    {"name": "bob", "type": "dynamic", "position": [-8, 10],
     "shapes": [{"type": "circle", "radius": 0.25}]},
    {"name": "slider", "type": "dynamic", "position": [12, 8],
     "shapes": [{"type": "box", "half_width": 0.4, "half_height": 0.4}]}
  ],
  "joints": [
    {"type": "revolute", "name": "pin", "body_a": "pivot", "body_b": "bob", "anchor": [-10, 10]},
    {"type": "prismatic", "name": "rail", "body_a": "ground", "body_b": "slider",
     "anchor": [12, 8], "axis": [0.6, 0.8], "enable_limit": true, "lower_translation": -2,
     "upper_translation": 3, "enable_motor": true, "motor_speed": 1, "max_motor_force": 50}
  ]
})";

} // namespace

TEST_CASE("A world saved mid-run with nothing touching replays bit for bit, its joints' impulses "
          "carried",
          "[replay]")
{
    const Scene base = ParseScene(kFalling, "falling.json");
    for (const SolverKind kind : {SolverKind::Box2D, SolverKind::Colour, SolverKind::SoftStep})
    {
        INFO(SolverKindName(kind));
        Scene scene = base;
        scene.world.solver.kind = kind;
        BuiltScene original = BuildWorld(scene);
        const Real dt = Real(scene.world.dt);
        for (int frame = 0; frame < 20; ++frame)
        {
            original.Step(dt);
        }
        // No contact touches at this moment; the pendulum's and the rail's joints hold impulses.
        REQUIRE(original.world.GetTouchingContactCount() == 0);

        const Scene saved = SceneFromBuilt(original, scene);
        REQUIRE(saved.joints.size() == 2);
        CHECK(saved.joints[0].impulses.size() == 6);
        CHECK(saved.joints[1].impulses.size() == 6);
        BuiltScene replay = BuildWorld(ReadBack(saved));
        // 300 frames: every ball lands and rests, the crate tumbles, the bullet hits the ground.
        CHECK(FirstDifferentFrame(original.world, replay.world, dt, 300) == -1);
        CHECK(original.world.GetTouchingContactCount() >= 4); // the landings were replayed

        // Without the impulses (what a world saved before them gave), the first step differs:
        // the swinging pendulum's joint starts cold.
        Scene cold = saved;
        for (SceneJoint& joint : cold.joints)
        {
            joint.impulses.clear();
        }
        BuiltScene again = BuildWorld(scene);
        for (int frame = 0; frame < 20; ++frame)
        {
            again.Step(dt);
        }
        BuiltScene coldReplay = BuildWorld(cold);
        CHECK(FirstDifferentFrame(again.world, coldReplay.world, dt, 5) == 1);
    }
}

TEST_CASE("The snapshot of a moment saves as the world of that moment", "[replay]")
{
    const Scene scene = ParseScene(kFalling, "falling.json");
    BuiltScene built = BuildWorld(scene);
    for (int frame = 0; frame < 20; ++frame)
    {
        built.Step(Real(scene.world.dt));
    }
    const Scene saved = SceneFromBuilt(built, scene);
    const WorldSnapshot snapshot = built.world.SaveSnapshot();
    built.Step(Real(scene.world.dt)); // the world moves on; the snapshot does not
    SceneFromWorldOptions options;
    options.name = scene.name;
    const auto index = [&](auto id, const auto& ids)
    { return std::size_t(std::find(ids.begin(), ids.end(), id) - ids.begin()); };
    options.bodyName = [&](BodyId id) { return scene.bodies[index(id, built.bodies)].name; };
    options.jointName = [&](JointId id) { return scene.joints[index(id, built.joints)].name; };
    Scene fromSnapshot = SceneFromSnapshot(snapshot, options);
    fromSnapshot.sourcePath = saved.sourcePath;
    CHECK(fromSnapshot == saved);
    CHECK_THROWS_AS(SceneFromSnapshot(WorldSnapshot{}), InvalidArgument);
}

TEST_CASE("Joint impulses: as many as the type has, finite", "[replay]")
{
    World world;
    const BodyId ground = world.CreateBody({});
    const BodyId bob = world.CreateBody({.type = BodyType::Dynamic, .position = {1, 0}});
    world.CreateShape(bob, {}, Circle{{0, 0}, Real(0.25)});
    const JointId pin = world.CreateJoint(world.MakeRevoluteJointDef(ground, bob, {0, 0}));
    CHECK(world.GetJointImpulses(pin) == std::vector<Real>(6, Real(0)));
    const std::vector<Real> set = {1, 2, 3, 4, 5, 6};
    world.SetJointImpulses(pin, set);
    CHECK(world.GetJointImpulses(pin) == set);
    CHECK_THROWS_AS(world.SetJointImpulses(pin, std::vector<Real>{1, 2}), InvalidArgument);
    CHECK_THROWS_AS(
        world.SetJointImpulses(
            pin, std::vector<Real>{1, 2, 3, 4, 5, std::numeric_limits<Real>::infinity()}),
        InvalidArgument);
    // The file says so too, naming the joint.
    try
    {
        ParseScene(R"({"meff_scene": 1, "bodies": [{"name": "g", "type": "static"},
            {"name": "b", "type": "dynamic", "shapes": [{"type": "circle", "radius": 1}]}],
            "joints": [{"type": "revolute", "name": "pin", "body_a": "g", "body_b": "b",
                        "anchor": [0, 0], "impulses": [1, 2]}]})",
                   "x.json");
        FAIL("two impulses for a revolute joint were accepted");
    }
    catch (const SceneError& error)
    {
        CHECK(std::string(error.what()) ==
              "x.json: joints[0].impulses: a revolute joint has 6 impulses, got [1, 2]");
    }
}

TEST_CASE("What a scene cannot hold is said: warm-start impulses of touching contacts", "[replay]")
{
    // The limit, measured: a box resting on the ground saved mid-run starts its contact without
    // the accumulated impulse, so the first step differs. (docs/api-guide.md says so.)
    const Scene scene = ParseScene(R"({"meff_scene": 1, "bodies": [
        {"name": "ground", "type": "static",
         "shapes": [{"type": "box", "half_width": 5, "half_height": 0.5}]},
        {"name": "box", "type": "dynamic", "position": [0, 1.0],
         "shapes": [{"type": "box", "half_width": 0.5, "half_height": 0.5}]}]})",
                                   "resting.json");
    BuiltScene original = BuildWorld(scene);
    for (int frame = 0; frame < 30; ++frame)
    {
        original.Step(Real(scene.world.dt));
    }
    REQUIRE(original.world.GetTouchingContactCount() == 1);
    BuiltScene replay = BuildWorld(ReadBack(SceneFromWorld(original.world)));
    const BodyId box = original.bodies[1];
    const BodyId replayed = replay.bodies[1];
    // The same pose and velocity, bit for bit ...
    CHECK(SameBits(original.world.GetTransform(box), replay.world.GetTransform(replayed)));
    CHECK(
        SameBits(original.world.GetLinearVelocity(box), replay.world.GetLinearVelocity(replayed)));
    // ... but the contact starts cold in the replay: one step on, the two differ.
    original.Step(Real(scene.world.dt));
    replay.Step(Real(scene.world.dt));
    CHECK_FALSE(SameBits(original.world.GetTransform(box), replay.world.GetTransform(replayed)));
}

TEST_CASE("SceneFromWorld refuses what a scene file cannot say", "[replay]")
{
    WorldDef def;
    def.tolerances = TolerancesForLengthUnits(32);
    const World pixels(def);
    CHECK_THROWS_AS(SceneFromWorld(pixels), SceneError);

    World world;
    world.CreateBody({});
    world.CreateBody({});
    SceneFromWorldOptions options;
    options.bodyName = [](BodyId) { return std::string("same"); };
    try
    {
        SceneFromWorld(world, options);
        FAIL("duplicate names were accepted");
    }
    catch (const SceneError& error)
    {
        CHECK(std::string(error.what()).find("bodies[1].name: given twice") != std::string::npos);
    }
    options.bodyName = [](BodyId) { return std::string("has space"); };
    CHECK_THROWS_AS(SceneFromWorld(world, options), SceneError);
}
