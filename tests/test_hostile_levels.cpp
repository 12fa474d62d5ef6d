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
