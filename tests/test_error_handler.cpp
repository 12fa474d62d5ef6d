// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Errors with and without exceptions (meff/error.h): a refused call reports once, with the
// message that names the argument, and changes nothing; without exceptions (MEFF_EXCEPTIONS=0)
// it returns a null or empty result, and with them the error handler is never called.
#include "error_checks.h"
#include "meff/task_system.h"
#include "meff/world.h"

#include <catch2/catch.hpp>

#include <limits>
#include <vector>

using namespace meff;
using meff::test::CapturedErrors;
using meff::test::ErrorMessageOf;

namespace
{

constexpr Real kNaN = std::numeric_limits<Real>::quiet_NaN();

} // namespace

TEST_CASE("A refused call reports its error once and changes nothing", "[errors]")
{
    World world(WorldDef{});
    const BodyId body = world.CreateBody(BodyDef{.type = BodyType::Dynamic});
    world.CreateShape(body, ShapeDef{.density = 1}, MakeBox(1, 1));
    const std::vector<BodyId> bodies = world.GetBodies();

    CHECK_THAT(ErrorMessageOf(
                   [&] {
                       world.CreateBody(BodyDef{.position = {kNaN, 0}});
                   }),
               Catch::Contains("BodyDef::position"));
    CHECK(world.GetBodies() == bodies);
    CHECK_THAT(
        ErrorMessageOf([&] { world.CreateShape(body, ShapeDef{.density = -1}, MakeBox(1, 1)); }),
        Catch::Contains("density"));
    CHECK(world.GetShapes(body).size() == 1);
    CHECK_THAT(ErrorMessageOf([&] { world.CreateJoint(RevoluteJointDef{.bodyA = body}); }),
               Catch::Contains("invalid body id"));
    CHECK(world.GetJoints().empty());
    CHECK_THAT(ErrorMessageOf([&] { world.Step(-1); }), Catch::Contains("World::Step: dt"));
    CHECK(world.GetStepCount() == 0);

    // Each rule of a check is applied, not only its first (a segment's length after its finite
    // points, the soft step's settings after its substeps).
    CHECK_THAT(ErrorMessageOf(
                   [&] {
                       world.CreateShape(body, ShapeDef{}, Segment{{0, 0}, {0, 0}});
                   }),
               Catch::Contains("points must be further apart"));
    CHECK(world.GetShapes(body).size() == 1);
    SolverSettings settings = world.GetSolverSettings();
    settings.softStep.relaxIterations = -1;
    CHECK_THAT(ErrorMessageOf([&] { world.SetSolverSettings(settings); }),
               Catch::Contains("relaxIterations"));
    CHECK(world.GetSolverSettings().softStep.relaxIterations != -1);

    world.DestroyBody(body);
    CHECK_THAT(ErrorMessageOf([&] { world.DestroyBody(body); }),
               Catch::Contains("invalid body id"));
    CHECK(world.GetBodies().empty());
    world.Step(Real(1) / 60); // the world steps on
    CHECK(world.GetStepCount() == 1);
}

#if MEFF_EXCEPTIONS

TEST_CASE("With exceptions the error handler is not called", "[errors]")
{
    const CapturedErrors captured;
    CHECK_THROWS_AS(MakeBox(-1, 1), InvalidArgument);
    CHECK(captured.messages.empty());
}

#else

TEST_CASE("Without exceptions a refused call returns a null or empty result", "[errors]")
{
    const CapturedErrors captured;
    World world(WorldDef{});
    const BodyId body = world.CreateBody(BodyDef{.type = BodyType::Dynamic});
    CHECK(world.CreateBody(BodyDef{.angle = kNaN}).IsNull());
    CHECK(world.CreateShape(body, ShapeDef{}, Circle{{0, 0}, -1}).IsNull());
    CHECK(MakeBox(-1, 1).count == 0);
    CHECK(MakeThreadPool(0) == nullptr);
    world.DestroyBody(body);
    CHECK(world.GetPosition(body) == Vec2{});
    CHECK(world.GetShapes(body).empty());
    // A refused definition builds the world from the default one.
    const World defaulted(WorldDef{.gravity = {kNaN, 0}});
    CHECK(defaulted.GetGravity() == WorldDef{}.gravity);
    CHECK(captured.messages.size() == 7);
}

#endif
