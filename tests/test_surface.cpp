// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Surface motion of shapes: conveyor belts (ShapeDef::tangentSpeed), in every back end.
//
// Oracle: a box at rest on a belt whose surface moves at s is dragged by kinetic friction,
// m·a = μ·m·g, until it moves with the surface, then rides at s with no slip: v(t) = min(μ·g·t, s).
// The contact's target is the two shapes' speeds summed, each clockwise round its own shape.
#include "analytic_support.h"
#include "scene_errors.h"
#include "meff/b2djson.h"
#include "meff/validation.h"

#include <nlohmann/json.hpp>

#include <catch2/catch.hpp>

using namespace meff;
using namespace meff::analytic;

namespace
{

constexpr Real kMu = Real(0.5);
constexpr double kG = 10;

/// A 0.5 m box resting on a 40 m static belt (both friction μ), with the solver's equilibrium
/// gap so nothing is pushed apart.
struct Belt
{
    World world;
    BodyId box;

    Belt(SolverKind kind, Real beltSpeed, Real boxSpeed = 0)
    {
        WorldDef def;
        def.gravity = {0, Real(-kG)};
        def.solver.kind = kind;
        world = World{def};
        ShapeDef belt = Material(1, kMu);
        belt.tangentSpeed = beltSpeed;
        AddBox(world, BodyType::Static, {0, 0}, 0, 20, Real(0.25), belt);
        const Tolerances& tol = world.GetTolerances();
        const Real gap = 2 * tol.polygonSkin - tol.linearSlop;
        ShapeDef crate = Material(1, kMu);
        crate.tangentSpeed = boxSpeed;
        box = AddBox(world, BodyType::Dynamic, {-10, Real(0.5) + gap}, 0, Real(0.25), Real(0.25),
                     crate);
    }

    double Vx() const { return double(world.GetLinearVelocity(box).x); }
    void Run(int steps)
    {
        for (int i = 0; i < steps; ++i)
        {
            world.Step(kDt);
        }
    }
};

const char* Name(SolverKind kind)
{
    return kind == SolverKind::Box2D ? "box2d" : kind == SolverKind::Colour ? "colour" : "soft";
}

} // namespace

TEST_CASE("Conveyor: a box on a belt accelerates at mu*g, then rides at the belt's speed",
          "[surface][conveyor][analytic]")
{
    for (const SolverKind kind : {SolverKind::Box2D, SolverKind::Colour, SolverKind::SoftStep})
    {
        for (const Real s : {Real(2), Real(-3)})
        {
            INFO(Name(kind) << " belt speed " << s);
            Belt belt(kind, s);
            const double sign = s > 0 ? 1 : -1;
            // Acceleration measured over steps 6..18 (0.2 s, well before v reaches |s| at
            // |s|/(μg) ≥ 0.4 s): the first steps are left out while the normal impulse that
            // bounds friction is still being found (no warm start yet). Once it is m·g·dt, each
            // step's friction impulse is exactly μ·m·g·dt, so the slope is μ·g to round-off and
            // the iterations' residue in the normal impulse: 1% leaves room for that residue.
            belt.Run(6);
            const double v6 = belt.Vx();
            belt.Run(12);
            const double v18 = belt.Vx();
            const double a = (v18 - v6) / (12 * double(kDt));
            CHECK(sign * a == Approx(double(kMu) * kG).epsilon(0.01));
            CHECK(sign * v18 < std::abs(double(s)));
            // After 1.5 s it has long caught up (0.6 s at most): the friction row holds the
            // relative tangential speed at zero, up to the rows' round-off (1e-4 m/s, many ulps of
            // 3 m/s but far below what one step of μ·g·dt = 0.083 m/s of slip would show).
            belt.Run(72);
            CHECK(belt.Vx() == Approx(double(s)).margin(1e-4));
            CHECK(std::abs(double(belt.world.GetAngularVelocity(belt.box))) < 1e-4);
        }
    }
}

TEST_CASE("Conveyor: two surfaces' speeds add, each turning clockwise round its own shape",
          "[surface][conveyor][analytic]")
{
    // The box's own surface turns clockwise too: its bottom face (outward normal −y) moves
    // towards −x at 1 m/s over the box, so to be at rest against the belt's +2 m/s surface the
    // box itself moves at 3 m/s. Tolerance as above.
    for (const SolverKind kind : {SolverKind::Box2D, SolverKind::Colour, SolverKind::SoftStep})
    {
        INFO(Name(kind));
        Belt belt(kind, 2, 1);
        belt.Run(120);
        CHECK(belt.Vx() == Approx(3.0).margin(1e-4));
    }
}

TEST_CASE("Conveyor: without friction a belt moves nothing; a belt of speed 0 is a plain box",
          "[surface][conveyor]")
{
    WorldDef def;
    def.gravity = {0, -10};
    World world{def};
    ShapeDef slick = Material(1, 0);
    slick.tangentSpeed = 5;
    AddBox(world, BodyType::Static, {0, 0}, 0, 20, Real(0.25), slick);
    const BodyId box = AddBox(world, BodyType::Dynamic, {0, Real(0.515)}, 0, Real(0.25), Real(0.25),
                              Material(1, 0));
    for (int i = 0; i < 60; ++i)
    {
        world.Step(kDt);
    }
    CHECK(world.GetLinearVelocity(box).x == 0);
}

TEST_CASE("Conveyor: a non-finite tangent speed is refused", "[surface][conveyor][errors]")
{
    World world;
    const BodyId body = world.CreateBody({});
    ShapeDef def;
    def.tangentSpeed = std::numeric_limits<Real>::infinity();
    CHECK_THROWS_WITH(world.CreateShape(body, def, Circle{{0, 0}, 1}),
                      Catch::Contains("ShapeDef::tangentSpeed") && Catch::Contains("finite"));
    def.tangentSpeed = std::numeric_limits<Real>::quiet_NaN();
    CHECK_THROWS_WITH(world.CreateShape(body, def, Circle{{0, 0}, 1}),
                      Catch::Contains("ShapeDef::tangentSpeed"));
}

TEST_CASE("Scene errors: tangent_speed must be a finite number", "[surface][scene][errors]")
{
    const auto scene = [](const std::string& value)
    {
        return R"({ "meff_scene": 1, "bodies": [ { "name": "b", "type": "static", "shapes": [
            { "type": "box", "half_width": 1, "half_height": 1, "tangent_speed": )" +
               value + " } ] } ] }";
    };
    CHECK(test::ErrorsOf(scene("-2.5")).empty());
    CHECK(test::ErrorsOf(scene("\"fast\"")) ==
          std::vector<std::string>{
              "x.json: bodies[0].shapes[0].tangent_speed: must be a number, got \"fast\""});
    if constexpr (sizeof(Real) == sizeof(float))
    {
        CHECK(test::ErrorsOf(scene("1e39")) ==
              std::vector<std::string>{"x.json: bodies[0].shapes[0].tangent_speed: must be a "
                                       "finite number (at most 3.40282347e+38 in magnitude), "
                                       "got 1e+39"});
    }
}

TEST_CASE("b2dJson: a conveyor's tangent speed travels as the fixture's meff.tangent_speed",
          "[surface][conveyor][b2djson]")
{
    // R.U.B.E. has no tangent speed: the export writes it as a meff.* custom property of the
    // fixture (float), which the import reads back; a fixture of speed 0 has none.
    const Scene scene = LoadScene(std::string(MEFF_SOURCE_DIR) + "/samples/scenes/conveyor.json");
    nlohmann::json level = nlohmann::json::parse(ExportB2dJson(scene, {}));
    const nlohmann::json& belt = level["body"][0]["fixture"][0];
    REQUIRE(belt.contains("customProperties"));
    CHECK(belt["customProperties"][0] ==
          nlohmann::json{{"name", "meff.tangent_speed"}, {"float", 2.0}});
    const nlohmann::json& wall = level["body"][2]["fixture"][0];
    for (const nlohmann::json& property : wall.value("customProperties", nlohmann::json::array()))
    {
        CHECK(property["name"] != "meff.tangent_speed");
    }
    CHECK(ImportB2dJson(level.dump(), "level.json").scene.bodies[0].shapes[0].tangentSpeed == 2);

    // A bad value is refused naming the property's path.
    level["body"][0]["fixture"][0]["customProperties"][0]["float"] = "fast";
    try
    {
        ImportB2dJson(level.dump(), "level.json");
        FAIL("imported");
    }
    catch (const SceneError& error)
    {
        REQUIRE(error.messages().size() == 1);
        CHECK_THAT(error.messages()[0],
                   Catch::StartsWith("level.json: body[0].fixture[0].customProperties[0]"));
    }
}

// Rolling resistance (ShapeDef::rollingResistance). Oracle: a solid disc (I = m·r²/2) rolling
// without slipping on flat ground under a resisting torque τ = c·r·N, N = m·g: from
// m·dv/dt = f and I·dω/dt = f·r + τ with v = −ω·r (rolling towards +x),
//   dv/dt = −τ·r / (m·r² + I) = −(2/3)·c·g,
// so it stops after t = 3·v0 / (2·c·g), and without resistance it keeps rolling.

namespace
{

struct Roller
{
    World world;
    BodyId ball;

    /// A disc of `radius`; with `segment` > 0, a capsule of that radius whose caps' centres are
    /// `segment` apart (lying along x).
    Roller(SolverKind kind, Real resistance, Real v0, Real radius, Real segment = 0)
    {
        WorldDef def;
        def.gravity = {0, Real(-kG)};
        def.solver.kind = kind;
        world = World{def};
        AddBox(world, BodyType::Static, {0, 0}, 0, 50, Real(0.25), Material(1, Real(0.6)));
        ShapeDef disc = Material(1, Real(0.6));
        disc.rollingResistance = resistance;
        BodyDef body;
        body.type = BodyType::Dynamic;
        // Resting at the solver's equilibrium: the ground's skin less the slop into the circle.
        const Tolerances& tol = world.GetTolerances();
        body.position = {-20, Real(0.25) + radius + tol.polygonSkin - tol.linearSlop};
        body.linearVelocity = {v0, 0};
        body.angularVelocity = -v0 / radius;
        ball = world.CreateBody(body);
        if (segment > 0)
        {
            world.CreateShape(ball, disc, Capsule{{-segment / 2, 0}, {segment / 2, 0}, radius});
        }
        else
        {
            world.CreateShape(ball, disc, Circle{{0, 0}, radius});
        }
    }

    double Vx() const { return double(world.GetLinearVelocity(ball).x); }
    void Run(int steps)
    {
        for (int i = 0; i < steps; ++i)
        {
            world.Step(kDt);
        }
    }
};

} // namespace

TEST_CASE("Rolling resistance: a rolling disc slows at (2/3)*c*g and stops; with none it rolls on",
          "[surface][rolling][analytic]")
{
    const Real c = Real(0.15), v0 = 3, r = Real(0.5);
    const double a = 2.0 / 3.0 * double(c) * kG; // 1 m/s²: stops after 3 s
    for (const SolverKind kind : {SolverKind::Box2D, SolverKind::Colour, SolverKind::SoftStep})
    {
        INFO(Name(kind));
        Roller roller(kind, c, v0, r);
        // Deceleration over 0.1..1.1 s (the first steps find the normal impulse the torque
        // limit is made of): each step then takes exactly c·r·m·g·dt of spin impulse, so the
        // slope is (2/3)·c·g up to the iterations' residue in the normal and friction rows;
        // 1% is far tighter than a wrong inertia or radius (a hoop's 1/2 would be 25% off).
        roller.Run(6);
        const double v6 = roller.Vx();
        roller.Run(60);
        const double v66 = roller.Vx();
        CHECK((v6 - v66) / (60 * double(kDt)) == Approx(a).epsilon(0.01));
        // Still rolling without slip: v = −ω·ρ, ρ the centre's height over the contact point,
        // which lies midway into the overlap of the circle and the ground's skin: 2.5 mm
        // inside the 0.5 m radius, so 1% (not round-off) separates v from −ω·r.
        CHECK(v66 ==
              Approx(-double(roller.world.GetAngularVelocity(roller.ball)) * r).epsilon(0.01));
        // Stopped by 3.5 s (at rest: the spin row now holds ω at 0 below its limit, friction
        // holds v at 0): within the rows' round-off of zero, and it stays there.
        roller.Run(144);
        CHECK(std::abs(roller.Vx()) < 1e-4);
        CHECK(std::abs(double(roller.world.GetAngularVelocity(roller.ball))) < 1e-4);
        const double x = double(roller.world.GetPosition(roller.ball).x);
        // Distance v0²/(2a) = 4.5 m from x = −20 (5%: the first steps' start-up and the stop
        // falling between steps move it by centimetres).
        CHECK(x + 20 == Approx(double(v0) * double(v0) / (2 * a)).epsilon(0.05));
        roller.Run(60);
        CHECK(double(roller.world.GetPosition(roller.ball).x) == Approx(x).margin(1e-4));

        // Without resistance it rolls on: after the first steps (which trade 5 mm/s of speed
        // for spin to roll on the contact point's slightly shorter lever, see above) the speed
        // stays, to the rows' round-off over 200 steps.
        Roller free(kind, 0, v0, r);
        free.Run(6);
        const double rolling = free.Vx();
        CHECK(rolling == Approx(double(v0)).epsilon(0.005));
        free.Run(204);
        CHECK(free.Vx() == Approx(rolling).margin(1e-4));
    }
}

TEST_CASE("Rolling resistance: a capsule rolls on its radius, as a disc does",
          "[surface][rolling][capsule][analytic]")
{
    // A capsule whose caps' centres are 2 cm apart rolls almost as a disc of its radius: its
    // rolling radius is the capsule's (Box2D v3's shape radius). Its centre rises and falls by
    // at most 1 cm per half turn and its inertia differs from a disc's by under 1% (a 2 cm by
    // 1 m box of mass inside), so the deceleration is (2/3)·c·g within 3%; with a rolling
    // radius of 0 (the old rule) there would be no deceleration at all.
    const Real c = Real(0.15), v0 = 3, r = Real(0.5);
    const double a = 2.0 / 3.0 * double(c) * kG;
    for (const SolverKind kind : {SolverKind::Box2D, SolverKind::Colour, SolverKind::SoftStep})
    {
        INFO(Name(kind));
        Roller roller(kind, c, v0, r, Real(0.02));
        roller.Run(6);
        const double v6 = roller.Vx();
        roller.Run(60);
        CHECK((v6 - roller.Vx()) / (60 * double(kDt)) == Approx(a).epsilon(0.03));
    }
}

TEST_CASE("rolling_resistance.json: every back end stops the resisted disc and capsule where "
          "its description says",
          "[surface][rolling][scene][analytic]")
{
    const SolverKind kind = GENERATE(SolverKind::Box2D, SolverKind::Colour, SolverKind::SoftStep);
    INFO(Name(kind));
    Scene scene = LoadScene(std::string(MEFF_SOURCE_DIR) + "/samples/v3/rolling_resistance.json");
    scene.world.solver.kind = kind;
    BuiltScene built = BuildWorld(scene);
    for (int i = 0; i < scene.world.frames; ++i)
    {
        built.world.Step(Real(scene.world.dt));
    }
    const auto body = [&](const char* name)
    {
        for (std::size_t b = 0; b < scene.bodies.size(); ++b)
        {
            if (scene.bodies[b].name == name)
            {
                return built.bodies[b];
            }
        }
        FAIL("no body " << name);
        return BodyId{};
    };
    // (2/3)·c·g = 1 m/s² from 3 m/s: stopped after 3 s (the scene runs 5), 4.5 m on. 5% for
    // the disc, as the analytic test above (start-up and a stop between steps); 6% for the
    // capsule, whose deceleration is the disc's within 3% (see above) and whose distance is
    // then within 3% more.
    const World& world = built.world;
    CHECK(double(world.GetPosition(body("resisted_disc")).x) ==
          Approx(-10 + 4.5).margin(0.05 * 4.5));
    CHECK(std::abs(double(world.GetLinearVelocity(body("resisted_disc")).x)) < 1e-3);
    CHECK(double(world.GetPosition(body("resisted_capsule")).x) ==
          Approx(-14 + 4.5).margin(0.06 * 4.5));
    CHECK(std::abs(double(world.GetLinearVelocity(body("resisted_capsule")).x)) < 1e-3);
    // Without resistance: 3 m/s, less the first steps' 5 mm/s (see above), to 0.5%.
    CHECK(double(world.GetLinearVelocity(body("free_disc")).x) == Approx(3).epsilon(0.005));
}

TEST_CASE("Rolling resistance: boxes do not roll, so it leaves them alone; bad values refused",
          "[surface][rolling]")
{
    // A polygon's rolling radius is 0: a box with resistance slides exactly as one without.
    const auto slide = [](Real resistance)
    {
        World world = MakeWorld({0, -10});
        AddBox(world, BodyType::Static, {0, 0}, 0, 50, Real(0.25), Material(1, Real(0.3)));
        ShapeDef crate = Material(1, Real(0.3));
        crate.rollingResistance = resistance;
        const BodyId box =
            AddBox(world, BodyType::Dynamic, {0, Real(0.515)}, 0, Real(0.25), Real(0.25), crate);
        world.SetLinearVelocity(box, {2, 0});
        for (int i = 0; i < 60; ++i)
        {
            world.Step(kDt);
        }
        return world.GetStateHash();
    };
    CHECK(slide(Real(0.5)) == slide(0));

    World world;
    const BodyId body = world.CreateBody({});
    ShapeDef def;
    def.rollingResistance = -1;
    CHECK_THROWS_WITH(world.CreateShape(body, def, Circle{{0, 0}, 1}),
                      Catch::Contains("ShapeDef::rollingResistance"));
    CHECK(test::ErrorsOf(R"({ "meff_scene": 1, "bodies": [ { "name": "b", "type": "static",
        "shapes": [ { "type": "circle", "radius": 1, "rolling_resistance": -0.5 } ] } ] })") ==
          std::vector<std::string>{
              "x.json: bodies[0].shapes[0].rolling_resistance: must be >= 0, got -0.5"});
}

TEST_CASE("Rolling resistance: meff validate refuses it, naming the field (2.4.1 has none)",
          "[surface][rolling][validation]")
{
    Scene scene = ParseScene(R"({ "meff_scene": 1, "bodies": [
        { "name": "ground", "type": "static",
          "shapes": [ { "type": "box", "half_width": 5, "half_height": 0.5 } ] },
        { "name": "ball", "type": "dynamic", "position": [0, 1],
          "shapes": [ { "type": "circle", "radius": 0.5, "rolling_resistance": 0.2 } ] } ] })",
                             "roll.json");
    try
    {
        validation::Validate(scene, {});
        FAIL("validated");
    }
    catch (const SceneError& error)
    {
        REQUIRE(error.messages().size() == 1);
        CHECK_THAT(error.messages()[0],
                   Catch::StartsWith("roll.json: bodies[1].shapes[0].rolling_resistance: Box2D "
                                     "2.4.1 has no rolling resistance"));
    }
    // At 0 the same scene validates.
    scene.bodies[1].shapes[0].rollingResistance = 0;
    CHECK(validation::Validate(scene, {}).passed);
}

// Explosions (World::Explode). Oracle: a body takes J = p·w·s along the line from the centre
// to its closest point, w its width across that line, s = 1 inside the radius and
// (radius + falloff − d)/falloff in the falloff band; v = J/m, no spin when the line passes
// through the centre of mass.

namespace
{

World ZeroGravity()
{
    WorldDef def;
    def.gravity = {0, 0};
    return World{def};
}

} // namespace

TEST_CASE("Explosion: impulse per width, along the line from the centre, fading over the falloff",
          "[surface][explosion][analytic]")
{
    World world = ZeroGravity();
    // A 1 m box (1 kg at density 1) 3 m to the right: its face 2.5 m away, width 1 m across.
    const BodyId near =
        AddBox(world, BodyType::Dynamic, {3, 0}, 0, Real(0.5), Real(0.5), Material(1, 0));
    // A disc of radius 0.5 (π/4 kg) straight up at 4.5 m: 4 m from its surface, in the falloff
    // band (radius 3, falloff 2): scale (5 − 4)/2 = 1/2, width 2r = 1.
    const BodyId up = AddBall(world, {0, Real(4.5)}, {0, 0}, Real(0.5), Material(1, 0));
    // Beyond radius + falloff: 5.5 m from its surface.
    const BodyId far = AddBall(world, {-6, 0}, {0, 0}, Real(0.5), Material(1, 0));
    // Inside the radius but its category is not in the mask.
    ShapeDef hidden = Material(1, 0);
    hidden.filter.categoryBits = 0x0002;
    const BodyId masked = AddBall(world, {0, -2}, {0, 0}, Real(0.5), hidden);

    ExplosionDef def;
    def.position = {0, 0};
    def.radius = 3;
    def.falloff = 2;
    def.impulsePerLength = 4; // N·s per metre of width
    def.maskBits = 0x0001;
    world.Explode(def);

    // v = J/m: the box 4·1/1 ≈ 4 m/s along +x; the disc 4·1·(1/2)/(π/4) along +y. Round-off
    // only: GJK's closest point and a width of exact corners (1e-5 relative).
    // The box's width counts its skin (Tolerances::polygonSkin on each side), as its surface
    // does in every contact: 1 + 2·skin.
    const double width = 1 + 2 * double(world.GetTolerances().polygonSkin);
    const Vec2 vNear = world.GetLinearVelocity(near);
    CHECK(vNear.x == Approx(4.0 * width).epsilon(1e-5));
    CHECK(std::abs(double(vNear.y)) < 1e-5);
    CHECK(std::abs(double(world.GetAngularVelocity(near))) < 1e-5);
    const Vec2 vUp = world.GetLinearVelocity(up);
    CHECK(vUp.y == Approx(2.0 / (kPiD / 4)).epsilon(1e-5));
    CHECK(std::abs(double(vUp.x)) < 1e-5);
    CHECK(world.GetLinearVelocity(far) == Vec2{0, 0});
    CHECK(world.GetLinearVelocity(masked) == Vec2{0, 0});

    // A negative impulse pulls in, and the mask now takes every category.
    def.impulsePerLength = -4;
    def.maskBits = 0xFFFF;
    world.Explode(def);
    CHECK(world.GetLinearVelocity(near).x == Approx(0.0).margin(1e-5));
    CHECK(world.GetLinearVelocity(masked).y == Approx(4.0 / (kPiD / 4)).epsilon(1e-5));
}

TEST_CASE("Explosion: a capsule takes the impulse of its width across the line",
          "[surface][explosion][capsule][analytic]")
{
    World world = ZeroGravity();
    // A capsule lying along x, 3 m straight up: caps 1 m apart, radius 0.25. Its surface is
    // 2.75 m from the centre (inside the 3 m radius: full strength); across the vertical line
    // it is 1 + 2·0.25 = 1.5 m wide. Mass at density 1: the 1 × 0.5 m box plus the two half
    // discs, 0.5 + π/16 kg.
    BodyDef body;
    body.type = BodyType::Dynamic;
    body.position = {0, 3};
    const BodyId capsule = world.CreateBody(body);
    world.CreateShape(capsule, Material(1, 0),
                      Capsule{{Real(-0.5), 0}, {Real(0.5), 0}, Real(0.25)});

    ExplosionDef def;
    def.radius = 3;
    def.falloff = 2;
    def.impulsePerLength = 4;
    world.Explode(def);
    // v = J/m = 4·1.5/(0.5 + π/16), straight up through the centre of mass: no spin. Round-off
    // only (GJK's closest point, the width's two end points).
    const double mass = 0.5 + kPiD / 16;
    CHECK(double(world.GetMass(capsule)) == Approx(mass).epsilon(1e-6));
    CHECK(double(world.GetLinearVelocity(capsule).y) == Approx(6 / mass).epsilon(1e-5));
    CHECK(std::abs(double(world.GetLinearVelocity(capsule).x)) < 1e-5);
    CHECK(std::abs(double(world.GetAngularVelocity(capsule))) < 1e-5);
}

TEST_CASE("Explosion: a sleeping body is woken; static bodies and sensors are left alone; bad "
          "arguments refused",
          "[surface][explosion]")
{
    World world = ZeroGravity();
    BodyDef sleeper;
    sleeper.type = BodyType::Dynamic;
    sleeper.position = {2, 0};
    sleeper.awake = false;
    const BodyId body = world.CreateBody(sleeper);
    world.CreateShape(body, Material(1, 0), Circle{{0, 0}, Real(0.5)});
    REQUIRE(!world.IsAwake(body));
    const BodyId wall = AddBox(world, BodyType::Static, {-2, 0}, 0, 1, 1, Material(1, 0));
    ShapeDef sensor = Material(1, 0);
    sensor.isSensor = true;
    const BodyId ghost = AddBall(world, {0, 2}, {0, 0}, Real(0.5), sensor);

    ExplosionDef def;
    def.radius = 5;
    world.Explode(def);
    CHECK(world.IsAwake(body));
    CHECK(world.GetLinearVelocity(body).x > 0);
    CHECK(world.GetLinearVelocity(wall) == Vec2{0, 0});
    CHECK(world.GetLinearVelocity(ghost) == Vec2{0, 0});

    const auto refused = [&](ExplosionDef bad, const char* field)
    { CHECK_THROWS_WITH(world.Explode(bad), Catch::Contains(field)); };
    ExplosionDef bad;
    bad.radius = -1;
    refused(bad, "ExplosionDef::radius");
    bad = {};
    bad.falloff = std::numeric_limits<Real>::quiet_NaN();
    refused(bad, "ExplosionDef::falloff");
    bad = {};
    bad.impulsePerLength = std::numeric_limits<Real>::infinity();
    refused(bad, "ExplosionDef::impulsePerLength");
    bad = {};
    bad.position = {std::numeric_limits<Real>::infinity(), 0};
    refused(bad, "ExplosionDef::position");
}
