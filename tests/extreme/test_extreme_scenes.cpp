// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The extreme scenes of samples/extreme/ (issue 7): each scene, what must hold for meff, and
// Box2D 2.4.1's result on the same scene through the validation mirror. docs/stability.md's
// stability table is made from the STABILITY lines these tests print (`ctest -R extreme -V`).
//
// Tolerances are argued next to each check. Three lengths recur:
//   linear slop 0.005 m — the overlap the position solver leaves at rest (Box2D's constant);
//   g·dt = 0.167 m/s — the speed gravity adds in one step at 60 Hz, the scale of "moving";
//   a box's half-size 0.5 m — the scale of "fell over".
#include "extreme_support.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <limits>

using namespace meff;
using namespace meff::extreme;

namespace
{

constexpr double kPiD = 3.14159265358979323846;

/// How a set of bodies held still over a run, measured on the dynamic bodies.
struct Stand
{
    double deepest = 0;    ///< deepest contact overlap at any step (m)
    double shift = 0;      ///< largest |x − x₀| at any step (m)
    double drop = 0;       ///< largest y₀ − y at any step (m)
    double rise = 0;       ///< largest y − y₀ at any step (m)
    double turn = 0;       ///< largest |θ − θ₀| at any step (rad)
    double maxSpeed = 0;   ///< largest speed at any step (m/s)
    double finalSpeed = 0; ///< largest speed after the last step (m/s)
    int steps = 0;         ///< steps taken

    std::string Describe() const
    {
        return Format("max overlap %.3g m, max shift %.3g m, max drop %.3g m, ", deepest, shift,
                      drop) +
               Format("max turn %.3g deg, final speed %.2g m/s", turn * 180 / kPiD, finalSpeed);
    }
};

Stand RunStand(Engine& engine, const Scene& scene, int steps,
               const std::function<void(int)>& perStep = {})
{
    const std::vector<std::size_t> bodies = DynamicBodies(scene);
    std::vector<BodyState> start;
    for (const std::size_t i : bodies)
    {
        start.push_back(engine.Body(i));
    }
    Stand s;
    for (int n = 1; n <= steps; ++n)
    {
        if (!engine.Step())
        {
            break;
        }
        s.steps = n;
        s.deepest = std::max(s.deepest, engine.DeepestPenetration());
        s.finalSpeed = 0;
        for (std::size_t k = 0; k < bodies.size(); ++k)
        {
            const BodyState b = engine.Body(bodies[k]);
            s.shift = std::max(s.shift, std::abs(b.x - start[k].x));
            s.drop = std::max(s.drop, start[k].y - b.y);
            s.rise = std::max(s.rise, b.y - start[k].y);
            s.turn = std::max(s.turn, std::abs(b.angle - start[k].angle));
            s.maxSpeed = std::max(s.maxSpeed, b.Speed());
            s.finalSpeed = std::max(s.finalSpeed, b.Speed());
        }
        if (perStep)
        {
            perStep(n);
        }
    }
    return s;
}

/// A scene that must stand for its 30 s: runs both engines, reports both, and returns meff's
/// and Box2D's measurements.
std::pair<Stand, Stand> StandBoth(const Scene& scene, const std::string& label)
{
    std::pair<Stand, Stand> result;
    auto engines = BothEngines(scene);
    result.first = RunStand(*engines[0], scene, scene.world.frames);
    result.second = RunStand(*engines[1], scene, scene.world.frames);
    Report(label, *engines[0], result.first.Describe());
    Report(label, *engines[1], result.second.Describe());
    REQUIRE(engines[0]->failure.empty());
    return result;
}

} // namespace

// --- High mass ratio -------------------------------------------------------------------------

namespace
{

Scene WithIterations(Scene scene, int velocityIterations)
{
    scene.world.solver.velocityIterations = velocityIterations;
    return scene;
}

std::string Label(const Scene& scene)
{
    return scene.name + " (" + std::to_string(scene.world.solver.velocityIterations) +
           " iterations)";
}

/// Box on box: the smallest distance between the two centres over the run (1.015 m as built).
struct BoxOnBox
{
    Stand stand;
    double closest = 1e9;
    double lightY = 0; ///< the light box's centre at the end (0.515 m as built)
};

BoxOnBox RunBoxOnBox(Engine& engine, const Scene& scene)
{
    const std::size_t light = *scene.FindBody("light");
    const std::size_t heavy = *scene.FindBody("heavy");
    BoxOnBox r;
    r.stand = RunStand(
        engine, scene, scene.world.frames,
        [&](int) { r.closest = std::min(r.closest, engine.Body(heavy).y - engine.Body(light).y); });
    r.lightY = engine.Body(light).y;
    Report(Label(scene), engine,
           r.stand.Describe() + Format(", closest centres %.4g m (1.015 at rest)", r.closest));
    return r;
}

/// What must hold for a box on a box: nothing passes through anything, and it stands.
void CheckBoxOnBoxStands(const BoxOnBox& r)
{
    INFO(r.stand.Describe() << ", closest centres " << r.closest);
    // Nothing passes through anything: the centres never come closer than a box (1 m) less
    // the measured overlap, and the light box stays on the ground.
    CHECK(r.closest > 1.0 - r.stand.deepest - 1e-3);
    CHECK(r.lightY > 0.5 - r.stand.deepest - 1e-3);
    // The overlap itself: the heavy box sinks into the light one because the iterations
    // cannot carry its load through the light box in one step; position correction (at most
    // 0.2 m per iteration, Baumgarte 0.2) then pushes it back. Bound: a tenth of a box's size,
    // far below "passing through" (1 m).
    CHECK(r.stand.deepest < 0.1);
    // It stands: no sideways force acts on a column, so sideways motion is solver asymmetry;
    // 5 cm is a tenth of the half-width. At rest at the end: well below g·dt.
    CHECK(r.stand.shift < 0.05);
    CHECK(r.stand.turn < 2 * kPiD / 180);
    CHECK(r.stand.finalSpeed < 0.01);
}

} // namespace

TEST_CASE("mass ratio 100:1: the heavy box stays on the light box for 30 s (8 iterations)",
          "[extreme][mass_ratio]")
{
    const Scene scene = LoadExtreme("mass_ratio_100");
    REQUIRE(scene.world.solver.velocityIterations == 8);
    MeffEngine meff(scene);
    Box2DEngine box2d(scene);
    const BoxOnBox m = RunBoxOnBox(meff, scene);
    const BoxOnBox b = RunBoxOnBox(box2d, scene);
    REQUIRE(meff.failure.empty());
    CheckBoxOnBoxStands(m);
    CheckBoxOnBoxStands(b); // docs/stability.md says Box2D holds too
}

TEST_CASE("mass ratio 1000:1: crushed through the ground at 8 iterations (known limit, as "
          "Box2D), stands at 200",
          "[extreme][mass_ratio]")
{
    const Scene scene = LoadExtreme("mass_ratio_1000");
    {
        // Known limit of sequential impulses with Box2D's default 8 iterations, stated so that
        // a change of behaviour is noticed: the light box is driven into the ground and both
        // fall through it (both engines: they agree bit for bit here).
        MeffEngine meff(scene);
        Box2DEngine box2d(scene);
        const BoxOnBox m = RunBoxOnBox(meff, scene);
        const BoxOnBox b = RunBoxOnBox(box2d, scene);
        CHECK(m.lightY < 0);
        CHECK(b.lightY < 0);
    }
    // Iterations are the remedy the solver has: 200 carry a 1000:1 load.
    const Scene more = WithIterations(scene, 200);
    MeffEngine meff(more);
    Box2DEngine box2d(more);
    const BoxOnBox m = RunBoxOnBox(meff, more);
    const BoxOnBox b = RunBoxOnBox(box2d, more);
    REQUIRE(meff.failure.empty());
    CheckBoxOnBoxStands(m);
    CheckBoxOnBoxStands(b);
}

TEST_CASE("heavy box (100:1) on a pyramid of light boxes: does not settle at 8 iterations, "
          "stands for 30 s at 20",
          "[extreme][mass_ratio]")
{
    const Scene scene = LoadExtreme("heavy_on_pyramid");
    {
        // Known limit at 8 iterations (both engines): the pyramid squirms under the load and is
        // still moving after 30 s, though nothing passes through anything.
        const auto [meff, box2d] = StandBoth(scene, Label(scene));
        CHECK(meff.deepest < 0.5);
        CHECK(meff.finalSpeed > 0.01);
        CHECK(box2d.finalSpeed > 0.01);
    }
    const Scene more = WithIterations(scene, 20);
    const auto [meff, box2d] = StandBoth(more, Label(more));
    INFO(meff.Describe());
    // Nothing passes through anything: overlap below a tenth of a box. It stands: no box
    // moves sideways by a tenth of its half-width or turns by 2 degrees; the column under the
    // heavy box sinks past the slop under its load (6 contacts; bound 0.02 m each); at rest.
    CHECK(meff.deepest < 0.1);
    CHECK(meff.shift < 0.05);
    CHECK(meff.turn < 2 * kPiD / 180);
    CHECK(meff.drop < 0.12);
    CHECK(meff.finalSpeed < 0.01);
    CHECK(box2d.finalSpeed < 0.01);
}

namespace
{

/// The chain's stretch: the sum of the 21 joints' gaps (anchor A to anchor B), i.e. how much
/// longer the chain is than its 10 m of links; the worst step and the state after 30 s.
struct Stretch
{
    double worst = 0;
    double final = 0;
};

Stretch RunChain(Engine& engine, const Scene& scene)
{
    Stretch r;
    RunStand(engine, scene, scene.world.frames,
             [&](int)
             {
                 r.final = 0;
                 for (std::size_t j = 0; j < scene.joints.size(); ++j)
                 {
                     r.final += engine.JointGap(j);
                 }
                 r.worst = std::max(r.worst, r.final);
             });
    Report(Label(scene), engine,
           Format("joint gaps summed: worst %.3g m (%.2g %% of the 10.25 m chain), after 30 s "
                  "%.3g m",
                  r.worst, 100 * r.worst / 10.25, r.final));
    return r;
}

} // namespace

TEST_CASE("chain of 20 light links holding a 100x weight: stretch bounded", "[extreme][chain]")
{
    const Scene scene = LoadExtreme("chain_heavy_weight");
    {
        // 8 iterations: the weight falls before the links take up its pull (each iteration
        // carries it one link further). Stated bounds, from the measured run
        // (docs/stability.md: 5.46 m and 0.296 m): worst stretch below 6 m (60 % of the chain!) in
        // the first second, below 0.5 m after 30 s.
        MeffEngine meff(scene);
        Box2DEngine box2d(scene);
        const Stretch m = RunChain(meff, scene);
        RunChain(box2d, scene);
        REQUIRE(meff.failure.empty());
        CHECK(m.worst < 6.0);
        CHECK(m.final < 0.5);
    }
    // 100 iterations: worst below 0.5 m (5 %), hanging after 30 s below 0.15 m (measured
    // 0.415 m and 0.117 m).
    const Scene more = WithIterations(scene, 100);
    MeffEngine meff(more);
    Box2DEngine box2d(more);
    const Stretch m = RunChain(meff, more);
    RunChain(box2d, more);
    REQUIRE(meff.failure.empty());
    CHECK(m.worst < 0.5);
    CHECK(m.final < 0.15);
}

// --- Stacks that stand 30 s ------------------------------------------------------------------

TEST_CASE("stack of 15 boxes with slight offsets stands for 30 s", "[extreme][stand]")
{
    const Scene scene = LoadExtreme("stack15_offset");
    const auto [meff, box2d] = StandBoth(scene, scene.name);
    INFO(meff.Describe());
    // Stands: no box moves sideways by a fifth of its half-width (a falling box moves by its
    // whole width) or turns by a degree; the top sinks by at most one slop per contact
    // (15 × 0.005 m). The offset column never quite comes to rest: it sways by a few
    // centimetres at a few mm/s (both engines), so "at the end" is bounded at 2 cm/s, an eighth
    // of g·dt, not at zero.
    CHECK(meff.shift < 0.1);
    CHECK(meff.turn < kPiD / 180);
    CHECK(meff.drop < 15 * 0.005);
    CHECK(meff.deepest < 0.02);
    CHECK(meff.finalSpeed < 0.02);
}

TEST_CASE("card house stands for 30 s", "[extreme][stand]")
{
    const Scene scene = LoadExtreme("card_house");
    const auto [meff, box2d] = StandBoth(scene, scene.name);
    INFO(meff.Describe());
    // A card that falls turns by tens of degrees and drops by decimetres. Standing: no card
    // turns by more than 2 degrees, drops by more than 2 cm or slides by more than 2 cm.
    CHECK(meff.turn < 2 * kPiD / 180);
    CHECK(meff.drop < 0.02);
    CHECK(meff.shift < 0.02);
    CHECK(meff.finalSpeed < 0.01);
}

TEST_CASE("arch of voussoirs stands by friction for 30 s", "[extreme][stand]")
{
    const Scene scene = LoadExtreme("arch");
    const auto [meff, box2d] = StandBoth(scene, scene.name);
    INFO(meff.Describe());
    // Standing: the keystone (and every block) sags less than 2 cm of a 3 m span's radius and
    // no block turns by a degree; a collapsing arch drops by metres.
    CHECK(meff.drop < 0.02);
    CHECK(meff.shift < 0.02);
    CHECK(meff.turn < kPiD / 180);
    CHECK(meff.finalSpeed < 0.01);
}

// --- Overlap recovery ------------------------------------------------------------------------

TEST_CASE("boxes created 25 % overlapped separate without exploding", "[extreme][overlap]")
{
    const Scene scene = LoadExtreme("overlap_recovery");
    auto engines = BothEngines(scene);
    Stand meff;
    for (auto& engine : engines)
    {
        const Stand s = RunStand(*engine, scene, scene.world.frames);
        double finalDeepest = engine->DeepestPenetration();
        Report(
            scene.name, *engine,
            Format("max speed %.3g m/s, highest rise %.3g m, ", s.maxSpeed, s.rise) +
                Format("final overlap %.3g m, final speed %.2g m/s", finalDeepest, s.finalSpeed));
        if (engine == engines.front())
        {
            REQUIRE(engine->failure.empty());
            meff = s;
            // Separated: only the slop's overlap (plus the load's sinking, 2 slops) is left.
            CHECK(finalDeepest < 3 * 0.005);
        }
    }
    INFO(meff.Describe());
    // Not exploding: position correction moves bodies without giving them velocity, so speed
    // comes only from gravity and the settling. A box falling its own height (1 m) reaches
    // sqrt(2 g h) = 4.5 m/s; bound 2 m/s is less than that, far below an explosion.
    CHECK(meff.maxSpeed < 2.0);
    // Nothing flew away: the top box must rise by the overlap below it, 4 × 0.25 m, plus the
    // four resting gaps (4 × 0.015 m) = 1.06 m, and by no more than a slop per contact beyond.
    CHECK(meff.rise < 1.06 + 4 * 0.005);
    CHECK(meff.finalSpeed < 0.01);
}

// --- Friction ramp ---------------------------------------------------------------------------

TEST_CASE("friction ramp: each box slides or stays as tan(theta) versus mu says",
          "[extreme][friction]")
{
    const Scene scene = LoadExtreme("friction_ramp");
    const double tanTheta = 0.4;
    const double theta = std::atan(tanTheta);
    const double g = 10;
    const double dt = scene.world.dt;
    const std::vector<double> mus = {0, 0.25, 0.375, 0.45, 0.75};
    auto engines = BothEngines(scene);
    for (auto& engine : engines)
    {
        std::vector<std::size_t> boxes;
        std::vector<BodyState> start;
        for (std::size_t i = 0; i < scene.bodies.size(); ++i)
        {
            if (scene.bodies[i].type == BodyType::Dynamic)
            {
                boxes.push_back(i);
                start.push_back(engine->Body(i));
            }
        }
        REQUIRE(boxes.size() == mus.size());
        // Speed along the slope (downhill positive) at 0.5 s (settled) and at the end, 2 s.
        const auto along = [&](const BodyState& b)
        { return b.vx * std::cos(theta) - b.vy * std::sin(theta); };
        std::vector<double> v05(boxes.size());
        const int steps = scene.world.frames;
        const int early = 30;
        RunStand(*engine, scene, steps,
                 [&](int n)
                 {
                     if (n == early)
                     {
                         for (std::size_t k = 0; k < boxes.size(); ++k)
                         {
                             v05[k] = along(engine->Body(boxes[k]));
                         }
                     }
                 });
        std::string line;
        for (std::size_t k = 0; k < boxes.size(); ++k)
        {
            const BodyState b = engine->Body(boxes[k]);
            const double a = (along(b) - v05[k]) / ((steps - early) * dt);
            const double expected =
                mus[k] < tanTheta ? g * (std::sin(theta) - mus[k] * std::cos(theta)) : 0.0;
            const double moved = std::hypot(b.x - start[k].x, b.y - start[k].y);
            line += Format("mu %.3g: a = %.4g m/s^2 (Coulomb %.4g), moved %.3g m; ", mus[k], a,
                           expected, moved);
            if (engine != engines.front())
            {
                continue;
            }
            INFO("mu " << mus[k] << ": a " << a << " expected " << expected << " moved " << moved);
            if (mus[k] < tanTheta)
            {
                // Sliding: once sliding, the friction row is clamped at μ·normal impulse every
                // step, so the acceleration is Coulomb's to solver precision; 1 % allows the
                // slop-level normal bounce of the box on the segment.
                CHECK(a == Approx(expected).epsilon(0.01));
            }
            else
            {
                // Sticking: friction holds a box below its limit exactly (the friction row
                // drives the sliding speed to zero each step); moved < 1 mm over 2 s.
                CHECK(moved < 1e-3);
            }
        }
        Report(scene.name, *engine, line);
    }
}

// --- Far from the origin ---------------------------------------------------------------------

namespace
{

/// The far scene moved back to the origin, where float spacing is fine.
Scene AtOrigin(Scene scene, double x0)
{
    for (SceneBody& body : scene.bodies)
    {
        body.position.x -= x0;
    }
    return scene;
}

struct FarResult
{
    Stand column;               ///< the 10 boxes
    double worstDifference = 0; ///< largest |Δposition| of a column box vs at the origin (m)
    double slide = 0;           ///< how far the slider went (m)
    double slideAtOrigin = 0;   ///< the same at the origin (m)
};

FarResult RunFar(Engine& far, Engine& near, const Scene& scene, double x0)
{
    FarResult r;
    const std::size_t slider = *scene.FindBody("slider");
    std::vector<std::size_t> column = DynamicBodies(scene);
    std::erase(column, slider);
    const double start = far.Body(slider).x - x0;
    const double startNear = near.Body(slider).x;
    Scene columnOnly = scene; // RunStand measures the dynamic bodies: the column alone
    columnOnly.bodies[slider].type = BodyType::Static;
    r.column = RunStand(far, columnOnly, scene.world.frames,
                        [&](int)
                        {
                            near.Step();
                            for (const std::size_t i : column)
                            {
                                const BodyState a = far.Body(i);
                                const BodyState b = near.Body(i);
                                r.worstDifference = std::max(r.worstDifference,
                                                             std::hypot(a.x - x0 - b.x, a.y - b.y));
                            }
                        });
    r.slide = far.Body(slider).x - x0 - start;
    r.slideAtOrigin = near.Body(slider).x - startNear;
    return r;
}

} // namespace

TEST_CASE("far from the origin: the column and a sliding box at x = 1e3 ... 1e7 m",
          "[extreme][far]")
{
    // The offsets, 1e3 to 1e5 m (scene files), and beyond, 1e6 and 1e7 m (the 1e5 m
    // scene moved further), to show where precision ends.
    const int exponent = GENERATE(3, 4, 5, 6, 7);
    const double x0 = std::pow(10.0, exponent);
    Scene scene = LoadExtreme("far_stack_1e" + std::to_string(std::min(exponent, 5)));
    for (SceneBody& body : scene.bodies)
    {
        body.position.x += x0 - std::pow(10.0, std::min(exponent, 5));
    }
    scene.name = "far_stack_1e" + std::to_string(exponent);
    const Scene origin = AtOrigin(scene, x0);
    // The spacing of float values near x0: the position resolution of both engines there. A
    // step moves a body only when h·v exceeds half of it: below ulp/(2h) the body stands still.
    const double ulp = double(std::nextafter(float(x0), 2 * float(x0))) - double(float(x0));
    const double stuckBelow = ulp / (2 * scene.world.dt);

    MeffEngine meffFar(scene), meffNear(origin);
    Box2DEngine boxFar(scene), boxNear(origin);
    const FarResult meff = RunFar(meffFar, meffNear, scene, x0);
    const FarResult box2d = RunFar(boxFar, boxNear, scene, x0);
    for (const FarResult* r : {&meff, &box2d})
    {
        Report(scene.name, r == &meff ? static_cast<Engine&>(meffFar) : boxFar,
               Format("float spacing %.3g m (slower than %.3g m/s does not move); column: ", ulp,
                      stuckBelow) +
                   r->column.Describe() +
                   Format(", worst difference from the origin %.3g m; slider went %.4g m "
                          "(%.4g m at the origin)",
                          r->worstDifference, r->slide, r->slideAtOrigin));
    }
    REQUIRE(meffFar.failure.empty());
    INFO("x0 = " << x0 << ", float spacing " << ulp << " m: " << meff.column.Describe()
                 << ", worst difference " << meff.worstDifference << ", slide " << meff.slide
                 << " vs " << meff.slideAtOrigin);
    // The column stands at every offset: it is symmetric about its own x, so rounding x to the
    // float grid moves nothing sideways (same bounds as at the origin, stack10).
    CHECK(meff.column.shift < 0.05);
    CHECK(meff.column.turn < kPiD / 180);
    CHECK(meff.column.finalSpeed < 0.01);
    CHECK(meff.worstDifference < 0.05);
    // The slider shows where precision ends: its stopping distance (0.33 m at the origin) is
    // wrong by about the distance it covers below `stuckBelow` plus a rounding per step.
    const double error = std::abs(meff.slide - meff.slideAtOrigin);
    switch (exponent)
    {
    case 3:
    case 4:
    case 5:
        // Up to 1e5 m the slide is right to within one float spacing (6e-5, 1e-3, 7.8e-3 m):
        // the body's last few steps are rounded, no more.
        CHECK(error < ulp);
        break;
    case 6:
        // 1e6 m: spacing 0.0625 m, and a body slower than 1.9 m/s cannot move at all: the
        // slider makes one 0.0625 m jump and stops, 80 % short. Precision has ended for
        // anything that moves slowly; stacks still stand.
        CHECK(error > 0.2);
        break;
    default:
        // 1e7 m: spacing 1 m. Nothing moves sideways at any speed below 30 m/s; the slider
        // keeps a velocity it never acts on.
        CHECK(meff.slide == 0);
        break;
    }
}

// --- Speed -----------------------------------------------------------------------------------

TEST_CASE("a small fast ball at a thin wall: stopped with continuous collision, tunnels without",
          "[extreme][speed]")
{
    const int speed = GENERATE(100, 1000);
    const bool continuous = GENERATE(true, false);
    Scene scene = LoadExtreme("bullet_" + std::to_string(speed));
    scene.world.continuous = continuous;
    const std::size_t ball = *scene.FindBody("ball");
    auto engines = BothEngines(scene);
    std::vector<double> finalX;
    for (auto& engine : engines)
    {
        double firstSpeed = 0;
        RunStand(*engine, scene, scene.world.frames,
                 [&](int n)
                 {
                     if (n == 1)
                     {
                         firstSpeed = engine->Body(ball).Speed();
                     }
                 });
        const BodyState b = engine->Body(ball);
        finalX.push_back(b.x);
        Report(scene.name + (continuous ? " continuous on" : " continuous off"), *engine,
               Format("speed after step 1 %.4g m/s; after 1 s the ball is at x = %.4g m, "
                      "speed %.4g m/s: ",
                      firstSpeed, b.x, b.Speed()) +
                   (b.x > 0 ? "TUNNELLED through the wall" : "stopped by the wall"));
        REQUIRE(engine->failure.empty());
        // Both engines clamp a step's motion to maxTranslation = 2 m by scaling the velocity
        // itself: 1000 m/s leaves the first step as 2 m × 60 Hz = 120 m/s.
        CHECK(firstSpeed == Approx(std::min(double(speed), 120.0)).epsilon(1e-5));
    }
    // With continuous collision the ball never passes the wall (its face is at x = −0.06 m
    // with the skin; the ball's centre stops a radius before it); without it, the ball jumps
    // the 0.12 m wall in one 1.7 m (or 2 m) step: tunnelling, in both engines.
    for (std::size_t e = 0; e < engines.size(); ++e)
    {
        INFO(engines[e]->Name() << ": ball ends at x = " << finalX[e]);
        if (continuous)
        {
            CHECK(finalX[e] < -0.06);
        }
        else
        {
            CHECK(finalX[e] > 0);
        }
    }
}

// --- Long runs -------------------------------------------------------------------------------

namespace
{

/// The energy that semi-implicit Euler (v += h·a, then x += h·v) conserves exactly in free
/// flight: kinetic energy plus potential energy at the middle of the last position step,
/// y − h·v_y/2. The plain m·g·y + ½m·v² of a free-flying body falls by ½m·g²·h² every step
/// (0.0139 J per kg at 60 Hz), which would read as drift though nothing was lost.
double StepEnergy(const BodyState& b, double g, double h)
{
    BodyState mid = b;
    mid.cy = b.cy - 0.5 * h * b.vy;
    return mid.Energy(g);
}

} // namespace

TEST_CASE("long run: over 10^5 steps a pendulum loses energy at a bounded rate, never gains",
          "[extreme][long]")
{
    const Scene scene = LoadExtreme("long_pendulum");
    const std::size_t bob = *scene.FindBody("bob");
    const double g = 10, h = scene.world.dt;
    const double length = 2; // pivot to the bob's centre
    auto engines = BothEngines(scene);
    double meffEarly = 0, meffLast = 0, meffRise = 0;
    for (auto& engine : engines)
    {
        const double e0 = StepEnergy(engine->Body(bob), g, h);
        // The change after 1000 steps too (16.7 s, about 6 swings): the early rate of loss.
        double lowest = 0, highest = 0, last = 0, early = 0;
        RunStand(*engine, scene, scene.world.frames,
                 [&](int n)
                 {
                     last = StepEnergy(engine->Body(bob), g, h) - e0;
                     lowest = std::min(lowest, last);
                     highest = std::max(highest, last);
                     if (n == 1000)
                     {
                         early = last;
                     }
                 });
        // Relative to m·g·L = 20 J, the energy of the full swing.
        const double scale = engine->Body(bob).mass * g * length;
        Report(scene.name, *engine,
               Format("energy change: after 1e3 steps %+.3g %%, after 1e5 steps %+.3g %%, "
                      "highest %+.3g %% of m g L",
                      100 * early / scale, 100 * last / scale, 100 * highest / scale));
        if (engine == engines.front())
        {
            REQUIRE(engine->failure.empty());
            meffEarly = early / scale;
            meffLast = last / scale;
            meffRise = highest / scale;
        }
    }
    // Nothing may add energy: never more than 0.1 % of m·g·L above the start (float rounding of
    // a 10 m height over 1e5 steps is far below that).
    CHECK(meffRise < 1e-3);
    // The drift is a loss, and large: Box2D 2.4.1's revolute joint removes the radial velocity
    // that each step's straight-line motion creates (an inelastic projection, O(h²) per step)
    // and its position correction moves the bob back onto the circle without velocity, so the
    // pendulum slowly comes to rest. Measured (both engines, identical): it loses about 99 %
    // of m·g·L over 1e5 steps, half of it in the first 1e3 steps (the loss per step grows with
    // speed, (v²h/L)², so it slows as the swing dies down). Bounds on the measured rate
    // (49.5 %, 99 %): at most 60 % after 1e3 steps, and not all of it by the end.
    CHECK(meffEarly > -0.6);
    CHECK(meffLast > -0.995);
}

// Restitution must never add energy. Box2D 2.4.1's rule — and meff's Box2D profile, the default
// — drives the normal velocity to −e·vn with vn measured after this step's gravity was added, so
// each bounce returns g·h more speed than the ball arrived with and e = 1 gains energy at every
// bounce. meff's SolverSettings::restitutionFromStepStart measures vn at the start of the step
// instead; with it the property holds. Both facts are asserted.
TEST_CASE("long run: a ball with restitution 1 never gains energy over 10^5 steps",
          "[extreme][long]")
{
    const Scene scene = LoadExtreme("long_bounce");
    const std::size_t ball = *scene.FindBody("ball");
    const double g = 10, h = scene.world.dt;
    // The largest energy rise over the run, as a fraction of the initial energy.
    const auto largestRise = [&](Engine& engine, const Scene& run)
    {
        const double e0 = StepEnergy(engine.Body(ball), g, h);
        double lowest = 0, highest = 0, last = 0;
        RunStand(engine, run, run.world.frames,
                 [&](int)
                 {
                     last = StepEnergy(engine.Body(ball), g, h) - e0;
                     lowest = std::min(lowest, last);
                     highest = std::max(highest, last);
                 });
        Report(run.name, engine,
               std::string(run.world.solver.restitutionFromStepStart
                               ? "restitution from step start: "
                               : "Box2D profile: ") +
                   Format("energy change over 1e5 steps: final %+.3g %%, range [%+.3g %%, "
                          "%+.3g %%] of the initial energy",
                          100 * last / e0, 100 * lowest / e0, 100 * highest / e0));
        REQUIRE(engine.failure.empty());
        return highest / e0;
    };

    Scene fromStepStart = scene;
    fromStepStart.world.solver.restitutionFromStepStart = true;
    MeffEngine meff(fromStepStart);
    // Float rounding of a 5 m height and a 10 m/s speed is ~1e-6 of the energy per step; 1e-4
    // allows that to accumulate over a bounce.
    CHECK(largestRise(meff, fromStepStart) < 1e-4);

    // The Box2D profile gains energy exactly as Box2D does (+3 % per bounce at first, so far more
    // than 1 % over the run), the same in both engines.
    auto engines = BothEngines(scene);
    const double meffBox2DProfile = largestRise(*engines[0], scene);
    const double box2d = largestRise(*engines[1], scene);
    CHECK(meffBox2DProfile > 0.01);
    CHECK(meffBox2DProfile == box2d);
}

// --- Tiny and large bodies, time steps -------------------------------------------------------

TEST_CASE("tiny (1 cm) bodies: nothing falls through, the 3-box column topples (known limit)",
          "[extreme][scale]")
{
    const Scene scene = LoadExtreme("tiny_bodies");
    auto engines = BothEngines(scene);
    std::vector<Stand> stands;
    std::vector<double> lowest;
    for (auto& engine : engines)
    {
        stands.push_back(RunStand(*engine, scene, scene.world.frames));
        double low = 1e9;
        for (const std::size_t i : DynamicBodies(scene))
        {
            low = std::min(low, engine->Body(i).y);
        }
        lowest.push_back(low);
        Report(scene.name, *engine,
               stands.back().Describe() + Format(", lowest centre at the end %.4g m", low));
    }
    REQUIRE(engines[0]->failure.empty());
    const Stand& meff = stands[0];
    INFO(meff.Describe());
    // Nothing passes through the ground: every centre ends above it by at least its half-size
    // (0.005 m) less the slop, and overlaps stay near the slop (skin 0.01 m, slop 0.005 m).
    CHECK(lowest[0] > 0.005 - 0.005);
    CHECK(meff.deepest < 0.01);
    // At rest at the end, and nothing thrown away (the ball rolls a little when hit).
    CHECK(meff.finalSpeed < 0.01);
    CHECK(meff.shift < 0.25);
    // Known limit, both engines: the skin is twice a box's half-size, so the boxes collide as
    // rounded blobs and a column of three falls over (its top box ends on the ground). Box2D's
    // constants are for 0.1 m to 10 m bodies.
    CHECK(meff.drop > 0.02);
    CHECK(stands[1].drop > 0.02);
}

TEST_CASE("large (100 m) bodies stand for 30 s", "[extreme][scale]")
{
    const Scene scene = LoadExtreme("large_bodies");
    const auto [meff, box2d] = StandBoth(scene, scene.name);
    INFO(meff.Describe());
    // A 100 m box that fell would move by tens of metres. Standing: 1 % of the half-size.
    CHECK(meff.drop < 0.5);
    CHECK(meff.shift < 0.5);
    CHECK(meff.turn < kPiD / 180);
    CHECK(meff.finalSpeed < 0.05);
}

TEST_CASE("the 10-box column stands for 30 s at time steps from 1/40 s to 1/1000 s",
          "[extreme][dt]")
{
    const int hz = GENERATE(40, 60, 120, 240, 1000);
    Scene scene = LoadExtreme("dt_sweep_stack");
    scene.world.dt = 1.0 / hz;
    scene.world.frames = 30 * hz;
    const auto [meff, box2d] = StandBoth(scene, scene.name + " dt=1/" + std::to_string(hz));
    INFO("dt = 1/" << hz << ": " << meff.Describe());
    // Same bounds as stack10 at 60 Hz: sideways a tenth of the half-width, a slop per contact.
    CHECK(meff.shift < 0.05);
    CHECK(meff.turn < kPiD / 180);
    CHECK(meff.drop < 10 * 0.005 + 0.02);
    CHECK(meff.finalSpeed < 0.01);
}

TEST_CASE("at dt = 1/30 s the 10-box column collapses (known limit, as Box2D)", "[extreme][dt]")
{
    // 8 iterations at 30 Hz cannot hold 10 boxes: the first steps sink the column by more
    // than position correction recovers and it bursts. Stated so a change is noticed; a
    // column of 8 stands at 30 Hz (docs/stability.md).
    Scene scene = LoadExtreme("dt_sweep_stack");
    scene.world.dt = 1.0 / 30;
    scene.world.frames = 30 * 30;
    const auto [meff, box2d] = StandBoth(scene, scene.name + " dt=1/30");
    CHECK(meff.drop > 1.0);
    CHECK(box2d.drop > 1.0);
    scene.bodies.resize(9); // ground and 8 boxes
    const auto [meff8, box2d8] = StandBoth(scene, scene.name + " dt=1/30, 8 boxes");
    CHECK(meff8.shift < 0.05);
    CHECK(meff8.drop < 8 * 0.005 + 0.03);
    CHECK(meff8.finalSpeed < 0.01);
}
