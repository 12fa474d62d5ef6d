// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// A scene's "characters": kinematic capsules that BuiltScene::Step moves with the character
// mover (World::MoveCharacter) under gravity and scripted inputs. The loader's field-path
// errors; walking, jumping and stopping against analytic answers; the bundled sample's route.
#include "meff/box2d_v3_features.h"
#include "meff/scene.h"

#include <catch2/catch.hpp>

#include "scene_errors.h"

#include <filesystem>
#include <string>
#include <vector>

using namespace meff;
using meff::test::ErrorsOf;

namespace
{

constexpr double kDt = 1.0 / 60.0;
constexpr Real kRadius = Real(0.3);

/// A 30 m floor whose top is y = 0, a wall whose face is x = 5, and a kinematic capsule
/// "hero" (lower cap centre at `start`, radius 0.3, caps 1 m apart) that does not find itself
/// (category 2, its mask everything else); `characters` is the JSON of the "characters"
/// array and `heroFields` extra fields of the hero's body.
std::string CharacterScene(const std::string& characters, const std::string& heroFields = "",
                           const std::string& capsuleFilter = R"("category": 2, "mask": 65533)")
{
    return R"({ "meff_scene": 1, "world": { "dt": 0.016666666666666666 }, "bodies": [
      { "name": "floor", "type": "static", "position": [0, -0.5],
        "shapes": [ { "type": "box", "half_width": 15, "half_height": 0.5 } ] },
      { "name": "wall", "type": "static", "position": [5.5, 2],
        "shapes": [ { "type": "box", "half_width": 0.5, "half_height": 2 } ] },
      { "name": "hero", "type": "kinematic", "position": [0, 0.31])" +
           heroFields + R"(, "shapes": [ { "type": "capsule", "center_a": [0, 0],
          "center_b": [0, 1], "radius": 0.3, "filter": { )" +
           capsuleFilter + R"( } } ] } ],
      "characters": )" +
           characters + " }";
}

/// CharacterScene with one character moving the hero by `inputs` (the JSON array), built.
BuiltScene BuildHero(const std::string& inputs)
{
    return BuildWorld(ParseScene(
        CharacterScene(R"([ { "body": "hero", "inputs": )" + inputs + " } ]"), "x.json"));
}

/// Steps a built scene `steps` frames.
void StepFrames(BuiltScene& built, int steps)
{
    for (int i = 0; i < steps; ++i)
    {
        built.Step(Real(kDt));
    }
}

/// The smallest separation of the character's capsule from any shape it can find but those
/// of `ignored` (m).
Real Clearance(const BuiltScene& built, const BuiltCharacter& character, BodyId ignored = {})
{
    const Transform xf = built.world.GetTransform(character.body);
    const Capsule mover{Mul(xf, character.capsule.center1), Mul(xf, character.capsule.center2),
                        character.capsule.radius};
    Real smallest = kMaxReal;
    built.world.CollideMover(mover, character.filter,
                             [&](ShapeId shape, const CollisionPlane& plane)
                             {
                                 if (built.world.GetBody(shape) == ignored)
                                 {
                                     return true;
                                 }
                                 smallest = Min(smallest, plane.separation);
                                 return true;
                             });
    return smallest;
}

using Messages = std::vector<std::string>;

bool AnyContains(const Messages& messages, const std::string& text)
{
    for (const std::string& message : messages)
    {
        if (message.find(text) != std::string::npos)
        {
            return true;
        }
    }
    return false;
}

} // namespace

TEST_CASE("Scene characters: the loader reads the script", "[scene][character]")
{
    const Scene scene = ParseScene(
        CharacterScene(R"([ { "name": "p", "body": "hero", "inputs": [ { "time": 0, "walk": 2 },
            { "time": 1.5, "jump": 4, "walk": -1 } ] } ])"),
        "x.json");
    REQUIRE(scene.characters.size() == 1);
    const SceneCharacter& character = scene.characters[0];
    CHECK(character.name == "p");
    CHECK(character.body == "hero");
    CHECK(character.bodyIndex == 2);
    REQUIRE(character.inputs.size() == 2);
    CHECK(character.inputs[0].walk == 2.0);
    CHECK_FALSE(character.inputs[0].jump.has_value());
    CHECK(character.inputs[1].time == 1.5);
    CHECK(character.inputs[1].jump == 4.0);
    CHECK(character.inputs[1].walk == -1.0);
    // Box2D 2.4.1 has no mover: validate and export refuse it, naming the character.
    CHECK(AnyContains(FieldsBox2D241Lacks(scene, "refused"),
                      "x.json: characters[0]: a character moved by the character mover"));
}

TEST_CASE("Scene characters: bad scripts are refused with their field paths",
          "[scene][character][errors]")
{
    const std::string walk = R"("inputs": [ { "time": 0, "walk": 1 } ])";
    CHECK(AnyContains(ErrorsOf(CharacterScene(R"([ { "body": "nobody" } ])")),
                      "x.json: characters[0].body: no body has this name"));
    CHECK(AnyContains(ErrorsOf(CharacterScene(R"([ { "body": "floor" } ])")),
                      "x.json: characters[0].body: must name a kinematic body"));
    // Its own category in its own mask: the mover would stand on itself.
    CHECK(AnyContains(
        ErrorsOf(CharacterScene(R"([ { "body": "hero" } ])", "", R"("category": 1)")),
        "x.json: characters[0].body: must name a body whose capsule's filter.category is not in "
        "its own filter.mask (category 1, mask 65535)"));
    CHECK(AnyContains(ErrorsOf(CharacterScene(R"([ { "body": "hero" }, { "body": "hero" } ])")),
                      "x.json: characters[1].body: is already moved by another character"));
    CHECK(AnyContains(
        ErrorsOf(CharacterScene(
            R"([ { "body": "hero", "inputs": [ { "time": 2, "walk": 1 }, { "time": 1, "jump": 3 } ] } ])")),
        "x.json: characters[0].inputs[1].time: must not be before the previous input's (2 s)"));
    CHECK(AnyContains(
        ErrorsOf(CharacterScene(R"([ { "body": "hero", "inputs": [ { "time": 1 } ] } ])")),
        "x.json: characters[0].inputs[0].walk: is required unless \"jump\" is given"));
    CHECK(AnyContains(ErrorsOf(CharacterScene(
                          R"([ { "body": "hero", "inputs": [ { "time": -1, "walk": 1 } ] } ])")),
                      "x.json: characters[0].inputs[0].time:"));
    CHECK(AnyContains(
        ErrorsOf(CharacterScene(R"([ { "body": "hero", "inputs": [ { "walk": 1 } ] } ])")),
        "x.json: characters[0].inputs[0].time: required field is missing"));
    CHECK(
        AnyContains(ErrorsOf(CharacterScene(R"([ { "body": "hero", "speed": 3, )" + walk + " } ]")),
                    "x.json: characters[0].speed:"));
    CHECK(AnyContains(ErrorsOf(CharacterScene(R"([ { "body": "hero", "inputs": 3 } ])")),
                      "x.json: characters[0].inputs:"));
    // A dynamic hero: the mover moves kinematic bodies only.
    const std::string dynamicHero =
        R"({ "meff_scene": 1, "bodies": [ { "name": "hero", "type": "dynamic", "shapes": [
          { "type": "capsule", "center_a": [0, 0], "center_b": [0, 1], "radius": 0.3,
            "filter": { "category": 2, "mask": 1 } } ] } ],
          "characters": [ { "body": "hero" } ] })";
    CHECK(AnyContains(ErrorsOf(dynamicHero),
                      "x.json: characters[0].body: must name a kinematic body"));
}

TEST_CASE("Scene characters: BuildWorld refuses a hand-made character it cannot drive",
          "[scene][character][errors]")
{
    Scene scene = ParseScene(CharacterScene("[]"), "x.json");
    scene.characters.push_back({.name = "p", .body = "floor", .bodyIndex = 0, .inputs = {}});
    CHECK_THROWS_AS(BuildWorld(scene), SceneError);
    scene.characters.back().bodyIndex = 99;
    CHECK_THROWS_AS(BuildWorld(scene), SceneError);
}

TEST_CASE("Scene characters: walking covers speed × time and stops at a wall", "[scene][character]")
{
    BuiltScene built = BuildHero(R"([ { "time": 0, "walk": 2 } ])");
    const BodyId hero = built.characters[0].body;
    const Real skin = built.world.GetTolerances().polygonSkin;
    StepFrames(built, 60);
    // One second at 2 m/s on flat ground: 2 m along, to the rounding of 60 kinematic moves of
    // v·dt (each exact to a few ulps of 2 m), and resting its radius plus the floor's skin
    // above the floor, to the plane solver's tolerance (1e-4 m) plus a step's g·dt² (2.8 mm,
    // taken back by the floor's push every step).
    CHECK(built.world.GetPosition(hero).x == Approx(2).margin(1e-5));
    CHECK(built.world.GetPosition(hero).y == Approx(kRadius + skin).margin(3e-3));
    StepFrames(built, 120);
    // The wall's face is x = 5: the cap stops its radius plus the wall's skin short of it,
    // within the plane solver's tolerance and the linear slop of the cast (5 mm).
    CHECK(built.world.GetPosition(hero).x == Approx(5 - kRadius - skin).margin(5e-3));
    CHECK(Clearance(built, built.characters[0]) > Real(-1e-3));
    // Pressed against the wall, it is given no speed into it.
    CHECK(built.world.GetLinearVelocity(hero).x == Approx(0).margin(1e-3));
}

TEST_CASE("Scene characters: a jump rises to the discrete apex of v·dt under g·dt kicks",
          "[scene][character]")
{
    BuiltScene built = BuildHero(R"([ { "time": 0.5, "jump": 5 } ])");
    const BodyId hero = built.characters[0].body;
    StepFrames(built, 30); // standing still for half a second
    const Real start = built.world.GetPosition(hero).y;
    Real highest = start;
    for (int i = 0; i < 60; ++i)
    {
        built.Step(Real(kDt));
        highest = Max(highest, built.world.GetPosition(hero).y);
    }
    // Step k (from 1) moves by dt·(5 − k·g·dt): gravity first, then the move. The rise ends
    // after K = 30 steps (5 − 30·10/60 = 0), at dt·(30·5 − g·dt·30·31/2) = 1.2083 m; the
    // continuous v²/2g would be 1.25 m. The floor adds no push while the hero leaves it.
    const double apex = kDt * (30 * 5 - 10 * kDt * 30 * 31 / 2);
    CHECK(highest - start == Approx(apex).margin(1e-4));
    // And it lands back where it stood, resting on the floor again.
    StepFrames(built, 60);
    CHECK(built.world.GetPosition(hero).y == Approx(start).margin(3e-3));
}

TEST_CASE("Scene characters: an input acts on the step that starts at its time",
          "[scene][character]")
{
    BuiltScene built = BuildHero(R"([ { "time": 1.5, "walk": 3 } ])");
    const BodyId hero = built.characters[0].body;
    StepFrames(built, 90); // up to t = 1.5 s: standing
    CHECK(built.world.GetPosition(hero).x == Approx(0).margin(1e-6));
    StepFrames(built, 10); // steps 90 to 99 walk: 10 · 3 m/s · dt = 0.5 m
    CHECK(built.world.GetPosition(hero).x == Approx(0.5).margin(1e-5));
}

TEST_CASE("Scene characters: the bundled capsule_character follows its route",
          "[scene][character][sample]")
{
    const std::filesystem::path path =
        std::filesystem::path(MEFF_SOURCE_DIR) / "samples" / "v3" / "capsule_character.json";
    const Scene scene = LoadScene(path.string());
    BuiltScene built = BuildWorld(scene);
    const BuiltCharacter& player = built.characters.at(0);
    const Real skin = built.world.GetTolerances().polygonSkin;
    const auto at = [&] { return built.world.GetPosition(player.body); };
    const BodyId crate = built.bodyByName.at("crate");
    const Vec2 crateStart = built.world.GetPosition(crate);

    // The static route (ground, ramp, platform, ledge, wall) is where the mover's planes are
    // exact; the crate is dynamic and moves during the step after the mover has looked at it.
    Real lowest = kMaxReal;
    const auto stepTo = [&](int last)
    {
        for (int frame = int(built.world.GetStepCount()) + 1; frame <= last; ++frame)
        {
            built.Step(Real(kDt));
            lowest = Min(lowest, Clearance(built, player, crate));
        }
    };
    stepTo(180); // t = 3 s: over the crate, at the foot of the ramp
    // It went over the crate and shoved it along to the right, landing past it.
    CHECK(built.world.GetPosition(crate).x > crateStart.x + Real(0.5));
    CHECK(at().x > built.world.GetPosition(crate).x);
    stepTo(480); // t = 8 s
    // On the ledge (top 2.2 m) against the wall (face x = 12), within the plane solver's
    // tolerance and a step's g·dt² (height) and the cast's linear slop (5 mm, along).
    CHECK(at().y == Approx(2.2 + kRadius + skin).margin(3e-3));
    CHECK(at().x == Approx(12 - kRadius - skin).margin(5e-3));
    stepTo(690); // t = 11.5 s: from 9 s it walked back 5 m at 2 m/s, down onto the platform
    CHECK(at().x == Approx(12 - kRadius - skin - 5).margin(5e-3));
    CHECK(at().y == Approx(1.4559 + kRadius + skin).margin(3e-3));
    stepTo(scene.world.frames);
    // Never into the route by more than a millimetre (the planes' linear model over one
    // step's move; the plane solver's tolerance is 0.1 mm).
    CHECK(lowest > Real(-1e-3));
}
