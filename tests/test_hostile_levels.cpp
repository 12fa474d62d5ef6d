// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Hostile levels (issue 36): what a crafted b2dJson level or scene file could do to the
// importer and the loader, each refused in words naming the file and the JSON path.
#include "meff/b2djson.h"
#include "meff/scene.h"

#include <nlohmann/json.hpp>

#include <catch2/catch.hpp>

#include <string>
#include <vector>

using namespace meff;

namespace
{

/// The messages a level is refused with, or none.
std::vector<std::string> ImportErrors(const std::string& text)
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

/// `levels` nested arrays.
std::string Nested(std::size_t levels)
{
    return std::string(levels, '[') + std::string(levels, ']');
}

/// A one-body level whose world has the custom property `name` holding the string `text`.
std::string LevelWithProperty(const std::string& name, const std::string& text)
{
    nlohmann::json level = {
        {"gravity", {{"x", 0}, {"y", -10}}},
        {"body", nlohmann::json::array({{{"type", 2},
                                         {"position", {{"x", 0}, {"y", 0}}},
                                         {"fixture", nlohmann::json::array({{
                                                         {"density", 1},
                                                         {"circle", {{"radius", 0.5}}},
                                                     }})}}})},
        {"customProperties", nlohmann::json::array({{{"name", name}, {"string", text}}})}};
    return level.dump();
}

} // namespace

TEST_CASE("b2dJson: JSON embedded in a meff.* property is nested no deeper than the cap",
          "[b2djson][hostile]")
{
    // 70,000 levels (140 KB) were parsed without a cap and copied recursively: SIGSEGV.
    for (const char* name : {"meff.soft_step", "meff.validate", "meff.render", "meff.analytic"})
    {
        CAPTURE(name);
        const std::vector<std::string> errors =
            ImportErrors(LevelWithProperty(name, Nested(70000)));
        REQUIRE(errors.size() == 1);
        CHECK_THAT(errors[0], Catch::StartsWith("level.json: customProperties[0].string: "
                                                "must hold JSON (" +
                                                std::string(name) + " is a section"));
        CHECK_THAT(errors[0], Catch::Contains("nested deeper than 64 levels"));
    }
    // One cap for the scene the level becomes: meff.validate lands inside the scene's root, so
    // 63 levels of its own are the most it may have (64 in all); meff.soft_step lands in
    // world, so 62.
    CHECK(ImportErrors(LevelWithProperty("meff.validate", Nested(64))).size() == 1);
    CHECK_THAT(ImportErrors(LevelWithProperty("meff.validate", Nested(64)))[0],
               Catch::Contains("inside its 1 outer levels"));
    CHECK_THAT(ImportErrors(LevelWithProperty("meff.soft_step", Nested(63)))[0],
               Catch::Contains("inside its 2 outer levels"));
    // Within the cap the section is read, and the loader says what is wrong with it.
    const std::vector<std::string> shallow =
        ImportErrors(LevelWithProperty("meff.validate", Nested(63)));
    REQUIRE_FALSE(shallow.empty());
    CHECK_THAT(shallow[0], !Catch::Contains("nested deeper"));
}

TEST_CASE("b2dJson: a NaN or negative massData-mass is refused at its field", "[b2djson][hostile]")
{
    nlohmann::json level = nlohmann::json::parse(LevelWithProperty("meff.name", "x"));
    level.erase("customProperties");
    for (const nlohmann::json& mass : {nlohmann::json("7FC00000"), nlohmann::json(-2.0)})
    {
        CAPTURE(mass);
        level["body"][0]["massData-mass"] = mass;
        const std::vector<std::string> errors = ImportErrors(level.dump());
        // A NaN once passed unsaid: no warning, no error (NaN compares unequal to nothing).
        REQUIRE(errors.size() == 1);
        CHECK_THAT(errors[0], Catch::StartsWith("level.json: body[0].massData-mass: must be "
                                                "finite and >= 0, got "));
    }
}

TEST_CASE("b2dJson: a number beyond a float's range is refused in the level's terms",
          "[b2djson][hostile]")
{
    nlohmann::json level = nlohmann::json::parse(LevelWithProperty("meff.name", "x"));
    level.erase("customProperties");
    level["body"][0]["position"] = {{"x", 1e39}, {"y", 0}};
    std::vector<std::string> errors = ImportErrors(level.dump());
    REQUIRE(errors.size() == 1);
    // It was refused as the scene's "[x, y]".
    CHECK(errors[0] == "level.json: body[0].position.x: must be within a float's range "
                       "(b2dJson's numbers are floats, at most 3.4028235e+38), got 1e+39");
    level["body"][0]["position"] = {{"x", 0}, {"y", 0}};
    level["body"][0]["angularDamping"] = -1e39;
    errors = ImportErrors(level.dump());
    REQUIRE(errors.size() == 1);
    CHECK_THAT(errors[0], Catch::StartsWith("level.json: body[0].angularDamping: must be within "
                                            "a float's range"));
}

TEST_CASE("A distance joint's length is refused at load when the solvers cannot square it",
          "[scene][hostile]")
{
    // 3.4e38 loaded, then every back end stopped step 0 with a non-finite state; 1e20 too
    // (box2d and colour); 1e19 steps (the bound is sqrt(FLT_MAX), about 1.8e19).
    const auto errors = [](const std::string& fields)
    {
        try
        {
            ParseScene(R"({"meff_scene": 1, "bodies": [{"name": "g", "type": "static"},
                {"name": "b", "type": "dynamic", "shapes": [{"type": "circle", "radius": 0.5}]}],
                "joints": [{"name": "d", "type": "distance", "body_a": "g", "body_b": "b",
                "anchor_a": [0, 1], "anchor_b": [0, 0], )" +
                           fields + "}]}",
                       "s.json");
        }
        catch (const SceneError& error)
        {
            return error.messages();
        }
        return std::vector<std::string>{};
    };
    std::vector<std::string> refused = errors(R"("length": 3.4e38)");
    REQUIRE(refused.size() == 1);
    CHECK_THAT(refused[0], Catch::StartsWith("s.json: joints[0].length: must be at most 1.8"));
    refused = errors(R"("length": 1, "min_length": 1e20, "max_length": 1e21)");
    REQUIRE(refused.size() == 1);
    CHECK_THAT(refused[0], Catch::StartsWith("s.json: joints[0].min_length: must be at most"));
    CHECK(errors(R"("length": 1e19)").empty());
    CHECK(errors(R"("length": 1, "min_length": 0, "max_length": 3.4e38)").empty()); // a rope
}
