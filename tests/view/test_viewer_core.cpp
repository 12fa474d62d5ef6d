// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// meff view's logic without a window (tools/view/viewer_core.h): the camera's mapping, the
// session's commands (step, restart, reload, grab and throw, the back end switched), the
// readouts and the script language.
#include "viewer_core.h"

#include <catch2/catch.hpp>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

using namespace meff;
using namespace meff::view;

namespace
{

std::string Sample(const std::string& name)
{
    return (std::filesystem::path(MEFF_SOURCE_DIR) / "samples/scenes" / name).string();
}

/// A ground box and one dynamic 1 m box resting on it at (0, 0.5 + 0.5).
constexpr const char* kBoxScene = R"({
  "meff_scene": 1, "name": "box",
  "world": {"gravity": [0, -10], "dt": 0.016666666666666666, "frames": 60},
  "bodies": [
    {"name": "ground", "type": "static", "position": [0, 0],
     "shapes": [{"type": "box", "half_width": 10, "half_height": 0.5}]},
    {"name": "box", "type": "dynamic", "position": [0, 1],
     "shapes": [{"type": "box", "half_width": 0.5, "half_height": 0.5, "density": 1}]}
  ]
})";

std::string WriteTemp(const std::string& name, const std::string& text)
{
    const std::filesystem::path path = std::filesystem::temp_directory_path() / name;
    std::ofstream(path) << text;
    return path.string();
}

} // namespace

TEST_CASE("The view camera maps pixels to metres as meff render's camera does", "[view]")
{
    ViewCamera camera{.center = {2, 1}, .height = 10, .width = 200, .heightPixels = 100};
    // 10 pixels per metre; the centre pixel boundary (100, 50) is the camera's centre.
    const Vec2 centre = camera.ScreenToWorld(100, 50);
    CHECK(double(centre.x) == Approx(2));
    CHECK(double(centre.y) == Approx(1));
    const Vec2 corner = camera.ScreenToWorld(0, 0);
    CHECK(double(corner.x) == Approx(2 - 10));
    CHECK(double(corner.y) == Approx(1 + 5));
    const Vec2 back = camera.WorldToScreen(Vec2{3, 0});
    CHECK(double(back.x) == Approx(110));
    CHECK(double(back.y) == Approx(60));

    // Panning drags the world with the cursor: 10 pixels right shows what was 1 m to the left.
    camera.Pan(10, 0);
    CHECK(double(camera.center.x) == Approx(1));
    camera.Pan(0, 10);
    CHECK(double(camera.center.y) == Approx(2));

    // Zooming keeps the point under the cursor where it is.
    const Vec2 under = camera.ScreenToWorld(30, 20);
    camera.ZoomAt(30, 20, 2);
    CHECK(camera.height == Approx(5));
    const Vec2 still = camera.ScreenToWorld(30, 20);
    CHECK(double(still.x) == Approx(double(under.x)).margin(1e-5));
    CHECK(double(still.y) == Approx(double(under.y)).margin(1e-5));
    camera.ZoomAt(0, 0, 1e12); // clamped, never zero
    CHECK(camera.height == Approx(1e-3));
}

TEST_CASE("A session steps, restarts and keeps the back end chosen", "[view]")
{
    Session session(WriteTemp("meff_view_box.json", kBoxScene));
    const BodyId box = session.Built().bodyByName.at("box");
    CHECK(session.Frame() == 0);
    for (int i = 0; i < 10; ++i)
    {
        session.Step();
    }
    CHECK(session.Frame() == 10);
    SolverSettings soft = session.Solver();
    soft.kind = SolverKind::SoftStep;
    soft.softStep.substeps = 8;
    session.SetSolver(soft);
    CHECK(session.GetWorld().GetSolverSettings().kind == SolverKind::SoftStep);
    session.Restart();
    CHECK(session.Frame() == 0);
    CHECK(double(session.GetWorld().GetPosition(session.Built().bodyByName.at("box")).y) == 1.0);
    // The choice survives the restart.
    CHECK(session.GetWorld().GetSolverSettings().kind == SolverKind::SoftStep);
    CHECK(session.GetWorld().GetSolverSettings().softStep.substeps == 8);
    (void)box;
}

TEST_CASE("Grabbing a body with the mouse pulls it, and letting go throws it", "[view]")
{
    Session session(WriteTemp("meff_view_grab.json", kBoxScene));
    const BodyId box = session.Built().bodyByName.at("box");
    // Nothing dynamic at an empty point or on the static ground.
    CHECK_FALSE(session.Grab(Vec2{5, 5}));
    CHECK_FALSE(session.Grab(Vec2{5, 0}));
    CHECK_FALSE(session.Grabbed());
    CHECK(session.BodyAt(Vec2{Real(0.2), Real(1.2)}) == box);

    REQUIRE(session.Grab(Vec2{0, 1}));
    CHECK(session.Grabbed() == box);
    CHECK(session.selected == box); // a grab selects, as a click does
    // Pull it up 2 m: the 5 Hz spring gets it most of the way in a second.
    session.MoveGrab(Vec2{0, 3});
    for (int i = 0; i < 60; ++i)
    {
        session.Step();
    }
    CHECK(double(session.GetWorld().GetPosition(box).y) > 2.5);
    // Swing it to the right and let go while it moves: it keeps flying right (a throw).
    session.MoveGrab(Vec2{4, 3});
    for (int i = 0; i < 6; ++i)
    {
        session.Step();
    }
    const double speed = double(session.GetWorld().GetLinearVelocity(box).x);
    CHECK(speed > 1);
    session.Release();
    CHECK_FALSE(session.Grabbed());
    const double before = double(session.GetWorld().GetPosition(box).x);
    session.Step();
    CHECK(double(session.GetWorld().GetPosition(box).x) > before);
}

TEST_CASE("Readouts: energy, joint gaps and penetration, and a selected body's report", "[view]")
{
    // Free fall: the box lifted 10 m falls without touching anything for 1 s.
    std::string lifted = kBoxScene;
    lifted.replace(lifted.find("\"position\": [0, 1]"), 18, "\"position\": [0, 20]");
    Session falling(WriteTemp("meff_view_fall.json", lifted));
    const Readouts start = falling.Measure();
    CHECK(start.kinetic == 0);
    // m g h with m = 1 kg, g = 10, the centre at 20 m.
    CHECK(start.potential == Approx(200));
    for (int i = 0; i < 60; ++i)
    {
        falling.Step();
    }
    const Readouts later = falling.Measure();
    // ½ m (g t)² = 50 J after 1 s. Box2D's symplectic Euler falls g dt² / 2 per step further
    // than the exact parabola, so the energy drifts by about g·(g t)·dt/2·m = 0.8 J: 2 %.
    CHECK(later.kinetic == Approx(50).epsilon(0.01));
    CHECK(later.Energy() == Approx(start.Energy()).margin(0.02 * 50));
    CHECK(later.contactPoints == 0);

    // A resting box: touching, a little overlap (Box2D keeps about linearSlop, 5 mm).
    Session resting(WriteTemp("meff_view_rest.json", kBoxScene));
    for (int i = 0; i < 60; ++i)
    {
        resting.Step();
    }
    const Readouts touching = resting.Measure();
    CHECK(touching.contactPoints == 2);
    CHECK(touching.penetration > 0);
    CHECK(touching.penetration < 0.01);
    const BodyReport report = resting.Report(resting.Built().bodyByName.at("box"));
    CHECK(report.name == "box");
    CHECK(report.contactPoints == 2);
    CHECK(report.mass == Approx(1));
    CHECK(report.Lines().size() == 4);

    // Joints: a chain has gaps under Box2D's step, and the readout follows the back end.
    Session chain(Sample("chain20.json"));
    for (int i = 0; i < 60; ++i)
    {
        chain.Step();
    }
    const double box2dGap = chain.Measure().jointGap;
    CHECK(box2dGap > 0);
    CHECK(box2dGap < 0.5);
    const BodyReport link = chain.Report(chain.Built().bodies[1]);
    CHECK_FALSE(link.joints.empty());
    SolverSettings soft = chain.Solver();
    soft.kind = SolverKind::SoftStep;
    chain.SetSolver(soft);
    chain.Restart();
    for (int i = 0; i < 60; ++i)
    {
        chain.Step();
    }
    CHECK(chain.Measure().jointGap != box2dGap);
}

TEST_CASE("A session reloads its file when it changes, and keeps the last good scene", "[view]")
{
    const std::string path = WriteTemp("meff_view_reload.json", kBoxScene);
    Session session(path);
    session.Step();
    CHECK_FALSE(session.FileChanged());
    std::string moved = kBoxScene;
    moved.replace(moved.find("\"position\": [0, 1]"), 18, "\"position\": [3, 1]");
    // File times can be coarse: make sure the new one differs.
    std::filesystem::last_write_time(path, std::filesystem::last_write_time(path) -
                                               std::chrono::seconds(5));
    CHECK(session.FileChanged());
    std::ofstream(path) << moved;
    CHECK(session.FileChanged());
    session.Reload();
    CHECK_FALSE(session.FileChanged());
    CHECK(session.Frame() == 0);
    CHECK(double(session.GetWorld().GetPosition(session.Built().bodyByName.at("box")).x) == 3.0);
    // A broken file: Reload throws and the session stays as it was.
    std::ofstream(path) << "{ not json";
    CHECK_THROWS_AS(session.Reload(), SceneError);
    CHECK(double(session.GetWorld().GetPosition(session.Built().bodyByName.at("box")).x) == 3.0);
}

TEST_CASE("Scripts parse, run, and name the line of a mistake", "[view]")
{
    const std::vector<ScriptCommand> commands = ParseScript("# a comment\n"
                                                            "size 320 240\n"
                                                            "camera 0 2 8   # trailing comment\n"
                                                            "step 10\n"
                                                            "drag 0 1 0 3 30\n"
                                                            "expect grabbed\n"
                                                            "release\n"
                                                            "expect released\n"
                                                            "solver soft_step\n"
                                                            "substeps 6\n"
                                                            "iterations 10 4\n"
                                                            "screenshot out.png\n",
                                                            "s.txt");
    REQUIRE(commands.size() == 11);
    CHECK(commands[0].kind == ScriptCommand::Kind::Size);
    CHECK(commands[3].numbers == std::vector<double>{0, 1, 0, 3, 30});
    CHECK(commands[10].text == "out.png");
    CHECK(commands[10].line == 12);

    Session session(WriteTemp("meff_view_script.json", kBoxScene));
    ViewCamera camera;
    std::vector<std::string> shots;
    int frames = 0;
    int resized = 0;
    ScriptHost host;
    host.screenshot = [&](const std::string& path) { shots.push_back(path); };
    host.resize = [&](int w, int h) { resized = w * 1000 + h; };
    host.frame = [&] { ++frames; };
    RunScript(commands, "s.txt", session, camera, host);
    CHECK(shots == std::vector<std::string>{"out.png"});
    CHECK(frames == 40);
    CHECK(resized == 320240);
    CHECK(camera.width == 320);
    CHECK(camera.height == 8);
    CHECK(session.Frame() == 40);
    CHECK(session.Solver().kind == SolverKind::SoftStep);
    CHECK(session.Solver().softStep.substeps == 6);
    CHECK(session.Solver().velocityIterations == 10);
    // The drag lifted the box.
    CHECK(double(session.GetWorld().GetPosition(session.Built().bodyByName.at("box")).y) > 2);

    const auto error = [](const std::string& text)
    {
        try
        {
            ParseScript(text, "bad.txt");
        }
        catch (const ScriptError& e)
        {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    CHECK(error("step 1\njump 3\n").find("bad.txt:2: unknown command \"jump\"") == 0);
    CHECK(error("step\n").find("bad.txt:1: step takes 1 number, got 0") == 0);
    CHECK(error("step x\n").find("bad.txt:1: step: \"x\" is not a number") == 0);
    CHECK(error("step 1.5\n").find("bad.txt:1: step: needs a whole number") == 0);
    CHECK(error("camera 0 0 0\n").find("bad.txt:1: camera: the height") == 0);
    CHECK(error("solver fast\n").find("bad.txt:1: solver: unknown back end \"fast\"") == 0);
    CHECK(error("size 10 10\n").find("bad.txt:1: size:") == 0);
    CHECK(error("step nan\n").find("bad.txt:1:") == 0);

    // A grab where there is no body fails the script at that line.
    Session empty(WriteTemp("meff_view_script2.json", kBoxScene));
    CHECK_THROWS_WITH(RunScript(ParseScript("step 1\ngrab 50 50\n", "g.txt"), "g.txt", empty,
                                camera, ScriptHost{}),
                      Catch::Contains("g.txt:2: no dynamic body at (50, 50)"));
    CHECK_THROWS_WITH(
        RunScript(ParseScript("expect grabbed\n", "e.txt"), "e.txt", empty, camera, ScriptHost{}),
        Catch::Contains("e.txt:1: expected the mouse to have a body"));
}

TEST_CASE("The view's triangles are meff render's tessellation at the view's pixel size", "[view]")
{
    Session session(WriteTemp("meff_view_tess.json", kBoxScene));
    ViewCamera camera{.center = {0, 0}, .height = 10, .width = 640, .heightPixels = 480};
    render::TriangleDraw triangles;
    Tessellate(session, camera, DrawFlags{}, triangles);
    render::TriangleDraw expected;
    expected.SetScale(10.0 / 480, 1.0);
    session.GetWorld().Draw(expected, DrawFlags{});
    REQUIRE(triangles.Triangles().size() == expected.Triangles().size());
    CHECK(triangles.Triangles().size() % 3 == 0);
    for (std::size_t i = 0; i < expected.Triangles().size(); ++i)
    {
        CHECK(triangles.Triangles()[i].x == expected.Triangles()[i].x);
        CHECK(triangles.Triangles()[i].y == expected.Triangles()[i].y);
    }
}

TEST_CASE("The Box2D 2.4.1 ghost agrees with the box2d back end and marks where another diverges",
          "[view]")
{
    Session session(Sample("pyramid20.json"));
    std::string why;
    REQUIRE(session.SetGhost(true, &why));
    CHECK(session.Ghost());
    for (int i = 0; i < 60; ++i)
    {
        session.Step();
    }
    // meff's box2d back end is Box2D 2.4.1, bit for bit (meff validate: errors exactly 0).
    CHECK_FALSE(session.GhostDivergence());
    CHECK(session.Measure().ghostOffset == 0);

    // The colour back end solves the same rows in another order: it parts from Box2D at once.
    SolverSettings colour = session.Solver();
    colour.kind = SolverKind::Colour;
    session.SetSolver(colour);
    session.Restart();
    CHECK(session.Ghost()); // kept across the restart
    for (int i = 0; i < 60; ++i)
    {
        session.Step();
    }
    REQUIRE(session.GhostDivergence());
    CHECK(*session.GhostDivergence() >= 1);
    CHECK(*session.GhostDivergence() <= 60);
    CHECK(session.Measure().ghostOffset > 0);

    // The ghost does not feel the mouse: a grab ends the comparison, and says when.
    session.Restart();
    session.Step();
    REQUIRE(session.Grab(Vec2{0, Real(19.8)}));
    CHECK(session.GhostDetached() == std::uint64_t(1));

    // The ghost off; and none for a scene with what only Box2D v3 has.
    CHECK(session.SetGhost(false));
    CHECK_FALSE(session.Ghost());
    Session capsules(
        (std::filesystem::path(MEFF_SOURCE_DIR) / "samples/v3/capsules.json").string());
    CHECK_FALSE(capsules.SetGhost(true, &why));
    CHECK_FALSE(why.empty());
    CHECK_FALSE(capsules.Ghost());

    // From a script.
    Session scripted(Sample("pyramid20.json"));
    ViewCamera camera;
    RunScript(ParseScript("ghost on\nstep 5\nexpect identical\nsolver colour\nrestart\nstep 30\n"
                          "expect diverged\n",
                          "g.txt"),
              "g.txt", scripted, camera, ScriptHost{});
    CHECK_THROWS_WITH(RunScript(ParseScript("expect identical\n", "h.txt"), "h.txt", capsules,
                                camera, ScriptHost{}),
                      Catch::Contains("h.txt:1: expect identical needs the ghost on"));
}
