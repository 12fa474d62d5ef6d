// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// meff view's logic, apart from any window: the camera, the session (a scene stepped, restarted,
// reloaded, dragged by a mouse joint, its solver switched), the readouts, and the scripts that
// drive it. The window (view_app.cpp) turns input into these calls and draws what they say;
// this part is tested without one (tests/view).
#pragma once

#include "meff/box2d_mirror.h"
#include "meff/error.h"
#include "meff/render.h"
#include "meff/scene.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace meff::view
{

/// What the window shows: a world rectangle `height` metres tall centred on `center`, in a
/// framebuffer of `width`×`heightPixels` pixels. The same mapping as meff render's camera.
struct ViewCamera
{
    Vec2 center{};
    double height = 10; ///< m, > 0
    int width = 640;
    int heightPixels = 480;

    render::Camera ToRender() const { return {center, Real(height)}; }
    /// Metres per pixel.
    double PixelSize() const { return height / heightPixels; }
    /// The world point under pixel (x, y), counted from the top-left corner.
    Vec2 ScreenToWorld(double x, double y) const;
    Vec2 WorldToScreen(Vec2 point) const;
    /// Moves the view so that what was under the cursor follows it by (dx, dy) pixels.
    void Pan(double dx, double dy);
    /// Zooms by `factor` (> 1: closer) keeping the world point under pixel (x, y) there.
    /// The height stays within 1 mm and 100 km.
    void ZoomAt(double x, double y, double factor);
    /// Shows `bounds` whole with a margin (render::FitCamera).
    void Fit(const AABB& bounds);
};

/// The errors the viewer's panel shows beside the picture: what a back end trades for speed.
struct Readouts
{
    std::uint64_t step = 0;
    double kinetic = 0;   ///< J: ½mv² + ½Iω² over every dynamic body
    double potential = 0; ///< J: −m g·x of each dynamic body's centre of mass
    double Energy() const { return kinetic + potential; }
    /// m: the largest distance between a point-like joint's two anchors (revolute, weld;
    /// which a rigid solve would keep together).
    double jointGap = 0;
    /// m: the deepest overlap of any contact point (0 when none overlaps).
    double penetration = 0;
    int contactPoints = 0;
    /// m: with the ghost on, the largest distance between a body's position in meff and in
    /// Box2D 2.4.1 (0 while they agree bit for bit).
    double ghostOffset = 0;
};

/// The state of one body, as the panel lists it.
struct BodyReport
{
    std::string name; ///< the scene's name, or "#index"
    Vec2 position{};
    double angle = 0;
    Vec2 velocity{};
    double angularVelocity = 0;
    double mass = 0;
    int contactPoints = 0;           ///< touching points of the last step
    std::vector<std::string> joints; ///< "name: reaction force F N, torque T N·m"
    /// The lines of the whole report, for a panel or a log.
    std::vector<std::string> Lines() const;
};

/// A scene loaded from its file and stepped by the viewer.
class Session
{
  public:
    /// Loads `path` (a meff scene or a b2dJson level). Throws SceneError.
    explicit Session(std::string path);
    /// Not copied or moved: the ghost refers to the session's scene.
    Session(const Session&) = delete;
    Session& operator=(const Session&) = delete;

    const std::string& Path() const { return m_path; }
    const Scene& GetScene() const { return m_scene; }
    const World& GetWorld() const { return m_built->world; }
    World& GetWorld() { return m_built->world; }
    const BuiltScene& Built() const { return *m_built; }

    /// Back to frame 0 of the scene as loaded, keeping the solver chosen here.
    void Restart();
    /// Loads the file again (it changed on disk) and restarts; a file that no longer loads
    /// throws SceneError and leaves the session as it was.
    void Reload();
    /// Whether the file was written since it was loaded.
    bool FileChanged() const;
    /// One frame: the scene's dt (characters moved as in meff run). Throws SimulationError.
    void Step();
    std::uint64_t Frame() const { return m_frame; }

    const SolverSettings& Solver() const { return m_solver; }
    /// The back end and its settings, from the next step on (and after restarts).
    void SetSolver(const SolverSettings& settings);

    /// The dynamic body with a shape containing `point`, if any (the topmost: last created).
    std::optional<BodyId> BodyAt(Vec2 point) const;
    /// Grabs the dynamic body under `point` with a mouse joint (Box2D testbed's: 1000 × its
    /// mass × g of force, 5 Hz, ζ 0.7) and selects it; false when there is none.
    bool Grab(Vec2 point);
    /// The grabbed point's target.
    void MoveGrab(Vec2 target);
    /// Lets go: the body keeps its velocity (a throw).
    void Release();
    std::optional<BodyId> Grabbed() const { return m_grabbed; }
    std::optional<Vec2> GrabTarget() const;

    std::optional<BodyId> selected; ///< the body whose report the panel shows

    Readouts Measure() const;
    BodyReport Report(BodyId body) const;

    /// The Box2D 2.4.1 ghost: the scene stepped by libbox2d (the validation library's mirror)
    /// in lockstep with meff, drawn as outlines over it. False, with the reason in `why`, for a
    /// scene Box2D 2.4.1 cannot run (Box2D v3's features). Starts again from frame 0.
    bool SetGhost(bool on, std::string* why = nullptr);
    bool Ghost() const { return m_mirror != nullptr; }
    /// The first frame at which a body's position or angle in meff differs from Box2D's, bit
    /// for bit; none while they agree (the box2d back end at the scene's settings always does).
    std::optional<std::uint64_t> GhostDivergence() const { return m_divergedAt; }
    /// Since a grab (which the ghost does not feel) the two are no longer compared; the frame.
    std::optional<std::uint64_t> GhostDetached() const { return m_detachedAt; }

    /// World::Draw, the grab's line from the body to the target, and the ghost's outlines.
    void Draw(DebugDraw& draw, const DrawFlags& flags) const;

  private:
    void Build();
    void CompareWithGhost();

    std::string m_path;
    Scene m_scene;
    std::unique_ptr<BuiltScene> m_built;
    SolverSettings m_solver;
    std::uint64_t m_frame = 0;
    std::filesystem::file_time_type m_loadedTime{};
    std::optional<BodyId> m_grabbed;
    std::optional<JointId> m_mouse;
    std::optional<BodyId> m_anchor; ///< a static body without shapes for the mouse joint
    bool m_ghostWanted = false;
    std::unique_ptr<validation::Box2DMirror> m_mirror;
    std::optional<std::uint64_t> m_divergedAt;
    std::optional<std::uint64_t> m_detachedAt;
};

/// A mistake in a script: "FILE:LINE: what".
class ScriptError : public Error
{
  public:
    using Error::Error;
};

/// One line of a `meff view --script` file.
struct ScriptCommand
{
    enum class Kind
    {
        Size,       ///< size W H: the window's framebuffer
        Camera,     ///< camera X Y HEIGHT
        Step,       ///< step N
        Grab,       ///< grab X Y (world point)
        Move,       ///< move X Y
        Release,    ///< release
        Drag,       ///< drag X1 Y1 X2 Y2 N: grab, move in a straight line over N steps, hold
        Solver,     ///< solver box2d|colour|soft_step
        Iterations, ///< iterations VELOCITY POSITION
        Substeps,   ///< substeps N
        Restart,    ///< restart
        Screenshot, ///< screenshot FILE.png: the world as the window draws it, without the panel
        WindowShot, ///< screenshot_window FILE.png: the whole window, panel included
        Ghost,      ///< ghost on|off: the Box2D 2.4.1 ghost
        Expect,     ///< expect grabbed|released|identical|diverged: a check, failing the
                    ///< script when wrong (identical, diverged: the ghost against meff)
    };
    Kind kind = Kind::Step;
    std::vector<double> numbers;
    std::string text;
    int line = 0;
};

/// Parses a script: one command a line, `#` starts a comment. Throws ScriptError naming
/// `path`, the line and what is wrong.
std::vector<ScriptCommand> ParseScript(std::string_view text, const std::string& path);

/// Runs a parsed script's commands against a session and camera; `screenshot(path)` saves the
/// window's pixels (the window's part), `resize(w, h)` sizes its framebuffer. Throws
/// ScriptError when a command cannot be done (an expectation fails, a grab finds no body).
struct ScriptHost
{
    std::function<void(const std::string& path)> screenshot;
    std::function<void(const std::string& path)> windowShot;
    std::function<void(int width, int height)> resize;
    std::function<void()> frame; ///< after every step, so the window can draw it
};
void RunScript(const std::vector<ScriptCommand>& commands, const std::string& path,
               Session& session, ViewCamera& camera, const ScriptHost& host);

/// The triangles (world coordinates) of the session's drawing as the window shows it through
/// `camera`: the same tessellation as meff render's frames.
void Tessellate(const Session& session, const ViewCamera& camera, const DrawFlags& flags,
                render::TriangleDraw& triangles);

} // namespace meff::view
