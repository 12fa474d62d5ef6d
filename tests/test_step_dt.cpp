// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The step's length (issue 36): World::Step takes dt from kMinStepDt (1e-9 s) to kMaxStepDt
// (1 s), the scene loader the same for world.dt.
#include <catch2/catch.hpp>

#include "world_fixtures.h"
#include "meff/scene.h"
#include "meff/world.h"

#include <limits>
#include <string>

using namespace meff;

TEST_CASE("World::Step refuses a dt beyond a second or below a nanosecond", "[world][step]")
{
    World world = test::MakePile(4, 2, 1, 0);
    const std::uint64_t before = world.GetStateHash();
    // Step(1e30) froze every body; a denormal dt passed the check, then stopped the step with
    // a non-finite state.
    for (const Real dt :
         {Real(1e30), Real(1.5), std::numeric_limits<Real>::denorm_min(), Real(1e-10), Real(0),
          Real(-1), std::numeric_limits<Real>::infinity(), std::numeric_limits<Real>::quiet_NaN()})
    {
        CAPTURE(dt);
        CHECK_THROWS_WITH(world.Step(dt),
                          Catch::StartsWith("World::Step: dt must be finite, from 1e-09 to 1 s"));
    }
    CHECK(world.GetStateHash() == before); // nothing stepped
    // Both ends are steps (kMaxStepDt, kMinStepDt).
    world.Step(Real(1));
    world.Step(Real(1e-9));
    world.Step(Real(1) / 60);
}

TEST_CASE("A scene's world.dt is refused outside World::Step's range, naming the field",
          "[scene][step]")
{
    const auto errors = [](const std::string& dt)
    {
        try
        {
            ParseScene(R"({"meff_scene": 1, "world": {"dt": )" + dt + R"(}, "bodies": []})",
                       "s.json");
        }
        catch (const SceneError& error)
        {
            return error.messages();
        }
        return std::vector<std::string>{};
    };
    CHECK(errors("2") ==
          std::vector<std::string>{"s.json: world.dt: must be in [1e-09, 1], got 2"});
    CHECK(errors("1e-12") ==
          std::vector<std::string>{"s.json: world.dt: must be in [1e-09, 1], got 1e-12"});
    CHECK(errors("1").empty());
    CHECK(errors("0.016666666666666666").empty());
}
