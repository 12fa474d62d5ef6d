// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// meff view's logic without a window (see viewer_core.h).
#include "viewer_core.h"

#include "meff/b2djson.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace meff::view
{

Vec2 ViewCamera::ScreenToWorld(double x, double y) const
{
    const double pixel = PixelSize();
    return Vec2{Real(double(center.x) + (x - 0.5 * width) * pixel),
                Real(double(center.y) + (0.5 * heightPixels - y) * pixel)};
}

Vec2 ViewCamera::WorldToScreen(Vec2 point) const
{
    const double pixel = PixelSize();
    return Vec2{Real(0.5 * width + (double(point.x) - double(center.x)) / pixel),
                Real(0.5 * heightPixels - (double(point.y) - double(center.y)) / pixel)};
}

void ViewCamera::Pan(double dx, double dy)
{
    const double pixel = PixelSize();
    center = Vec2{Real(double(center.x) - dx * pixel), Real(double(center.y) + dy * pixel)};
}

void ViewCamera::ZoomAt(double x, double y, double factor)
{
    const Vec2 before = ScreenToWorld(x, y);
    height = std::clamp(height / factor, 1e-3, 1e5);
    const Vec2 after = ScreenToWorld(x, y);
    center = center + (before - after);
}

void ViewCamera::Fit(const AABB& bounds)
{
    const render::Camera fitted = render::FitCamera(bounds, width, heightPixels);
    center = fitted.center;
    height = double(fitted.height);
}

std::vector<std::string> BodyReport::Lines() const
{
    char line[160];
    std::vector<std::string> lines{name};
    std::snprintf(line, sizeof line, "position (%.3f, %.3f) m, angle %.3f rad", double(position.x),
                  double(position.y), angle);
    lines.emplace_back(line);
    std::snprintf(line, sizeof line, "velocity (%.3f, %.3f) m/s, %.3f rad/s", double(velocity.x),
                  double(velocity.y), angularVelocity);
    lines.emplace_back(line);
    std::snprintf(line, sizeof line, "mass %.3f kg, %d contact point%s", mass, contactPoints,
                  contactPoints == 1 ? "" : "s");
    lines.emplace_back(line);
    lines.insert(lines.end(), joints.begin(), joints.end());
    return lines;
}

namespace
{

std::filesystem::file_time_type WriteTime(const std::string& path)
{
    std::error_code error;
    const auto time = std::filesystem::last_write_time(path, error);
    return error ? std::filesystem::file_time_type{} : time;
}

} // namespace

Session::Session(std::string path) : m_path(std::move(path))
{
    m_loadedTime = WriteTime(m_path);
    m_scene = LoadSceneFile(m_path).scene;
    m_solver = m_scene.world.solver;
    Build();
}

void Session::Build()
{
    auto built = std::make_unique<BuiltScene>(BuildWorld(m_scene));
    built->world.SetSolverSettings(m_solver);
    m_built = std::move(built);
    m_frame = 0;
    m_grabbed.reset();
    m_mouse.reset();
    m_anchor.reset();
    m_mirror.reset();
    m_divergedAt.reset();
    m_detachedAt.reset();
    if (m_ghostWanted)
    {
        try
        {
            m_mirror = std::make_unique<validation::Box2DMirror>(m_scene);
        }
        catch (const SceneError&)
        {
            m_ghostWanted = false; // Box2D 2.4.1 cannot run this scene (SetGhost says why)
        }
    }
    if (selected && !m_built->world.IsValid(*selected))
    {
        selected.reset();
    }
}

void Session::Restart()
{
    Build();
}

void Session::Reload()
{
    const auto time = WriteTime(m_path);
    Scene scene = LoadSceneFile(m_path).scene; // throws, leaving everything as it was
    m_scene = std::move(scene);
    m_loadedTime = time;
    m_solver = m_scene.world.solver;
    Build();
}

bool Session::FileChanged() const
{
    return WriteTime(m_path) != m_loadedTime;
}

void Session::Step()
{
    m_built->Step(Real(m_scene.world.dt));
    ++m_frame;
    if (m_mirror)
    {
        m_mirror->Step();
        CompareWithGhost();
    }
}

bool Session::SetGhost(bool on, std::string* why)
{
    if (on)
    {
        try
        {
            validation::Box2DMirror trial(m_scene);
        }
        catch (const SceneError& error)
        {
            if (why != nullptr)
            {
                *why = error.what();
            }
            return false;
        }
    }
    m_ghostWanted = on;
    Build();
    return true;
}

void Session::CompareWithGhost()
{
    if (m_divergedAt || m_detachedAt)
    {
        return;
    }
    const World& world = GetWorld();
    for (std::size_t i = 0; i < m_scene.bodies.size(); ++i)
    {
        const b2Body* ghost = m_mirror->Body(i);
        const BodyId body = m_built->bodies[i];
        const Vec2 p = world.GetPosition(body);
        if (double(ghost->GetPosition().x) != double(p.x) ||
            double(ghost->GetPosition().y) != double(p.y) ||
            double(ghost->GetAngle()) != double(world.GetAngle(body)))
        {
            m_divergedAt = m_frame;
            return;
        }
    }
}

void Session::SetSolver(const SolverSettings& settings)
{
    m_built->world.SetSolverSettings(settings); // throws on settings the engine refuses
    m_solver = settings;
}

std::optional<BodyId> Session::BodyAt(Vec2 point) const
{
    std::optional<BodyId> found;
    const World& world = GetWorld();
    world.OverlapPoint(point, QueryFilter{},
                       [&](ShapeId shape)
                       {
                           const BodyId body = world.GetBody(shape);
                           if (world.GetType(body) == BodyType::Dynamic &&
                               (!found || body.index > found->index))
                           {
                               found = body;
                           }
                           return true;
                       });
    return found;
}

bool Session::Grab(Vec2 point)
{
    Release();
    const std::optional<BodyId> body = BodyAt(point);
    if (!body)
    {
        return false;
    }
    World& world = GetWorld();
    if (!m_anchor)
    {
        m_anchor = world.CreateBody(BodyDef{});
    }
    const double gravity = std::max(double(world.GetGravity().Length()), 9.8);
    MouseJointDef def;
    def.bodyA = *m_anchor;
    def.bodyB = *body;
    def.target = point;
    def.maxForce = Real(1000 * double(world.GetMass(*body)) * gravity);
    m_mouse = world.CreateJoint(def);
    m_grabbed = body;
    if (m_mirror && !m_detachedAt)
    {
        m_detachedAt = m_frame;
    }
    selected = body;
    world.SetAwake(*body, true);
    return true;
}

void Session::MoveGrab(Vec2 target)
{
    if (m_mouse)
    {
        GetWorld().SetMouseTarget(*m_mouse, target);
        GetWorld().SetAwake(*m_grabbed, true);
    }
}

void Session::Release()
{
    if (m_mouse)
    {
        GetWorld().DestroyJoint(*m_mouse);
    }
    m_mouse.reset();
    m_grabbed.reset();
}

std::optional<Vec2> Session::GrabTarget() const
{
    if (!m_mouse)
    {
        return std::nullopt;
    }
    return GetWorld().GetAnchorA(*m_mouse);
}

Readouts Session::Measure() const
{
    const World& world = GetWorld();
    Readouts readouts;
    readouts.step = m_frame;
    const Vec2 gravity = world.GetGravity();
    for (const BodyId body : world.GetBodies())
    {
        if (world.GetType(body) != BodyType::Dynamic)
        {
            continue;
        }
        const double mass = double(world.GetMass(body));
        const Vec2 v = world.GetLinearVelocity(body);
        const double w = double(world.GetAngularVelocity(body));
        readouts.kinetic +=
            0.5 * mass * double(Dot(v, v)) + 0.5 * double(world.GetRotationalInertia(body)) * w * w;
        readouts.potential -= mass * double(Dot(gravity, world.GetWorldCenter(body)));
    }
    for (const JointId joint : world.GetJoints())
    {
        const JointType type = world.GetJointType(joint);
        if (type == JointType::Revolute || type == JointType::Weld)
        {
            readouts.jointGap =
                std::max(readouts.jointGap,
                         double((world.GetAnchorB(joint) - world.GetAnchorA(joint)).Length()));
        }
    }
    for (const ContactPointReport& point : world.GetContactReports())
    {
        readouts.penetration = std::max(readouts.penetration, -double(point.separation));
        ++readouts.contactPoints;
    }
    if (m_mirror)
    {
        for (std::size_t i = 0; i < m_scene.bodies.size(); ++i)
        {
            const b2Vec2 ghost = m_mirror->Body(i)->GetPosition();
            const Vec2 p = world.GetPosition(m_built->bodies[i]);
            readouts.ghostOffset =
                std::max(readouts.ghostOffset,
                         std::hypot(double(ghost.x) - double(p.x), double(ghost.y) - double(p.y)));
        }
    }
    return readouts;
}

BodyReport Session::Report(BodyId body) const
{
    const World& world = GetWorld();
    BodyReport report;
    const std::optional<std::size_t> index = m_built->SceneIndexOf(body);
    report.name = index ? m_scene.bodies[*index].name : "";
    if (report.name.empty())
    {
        report.name = "#" + std::to_string(index ? *index : std::size_t(body.index));
    }
    report.position = world.GetPosition(body);
    report.angle = double(world.GetAngle(body));
    report.velocity = world.GetLinearVelocity(body);
    report.angularVelocity = double(world.GetAngularVelocity(body));
    report.mass = double(world.GetMass(body));
    for (const ContactPointReport& point : world.GetContactReports())
    {
        report.contactPoints += (point.bodyA == body || point.bodyB == body) ? 1 : 0;
    }
    const Real invDt = Real(1 / m_scene.world.dt);
    for (std::size_t j = 0; j < m_built->joints.size(); ++j)
    {
        const JointId joint = m_built->joints[j];
        if (!world.IsValid(joint) ||
            (world.GetBodyA(joint) != body && world.GetBodyB(joint) != body))
        {
            continue;
        }
        const JointReaction reaction = world.GetReaction(joint, invDt);
        char line[160];
        std::snprintf(line, sizeof line, "%s: reaction %.3f N, %.3f N\xC2\xB7m",
                      m_scene.joints[j].name.empty() ? ("joint " + std::to_string(j)).c_str()
                                                     : m_scene.joints[j].name.c_str(),
                      double(reaction.force.Length()), double(reaction.torque));
        report.joints.emplace_back(line);
    }
    return report;
}

void Session::Draw(DebugDraw& draw, const DrawFlags& flags) const
{
    GetWorld().Draw(draw, flags);
    if (m_mouse)
    {
        const DrawColor color{0.2f, 0.2f, 0.2f};
        const Vec2 target = GetWorld().GetAnchorA(*m_mouse);
        draw.DrawSegment(GetWorld().GetAnchorB(*m_mouse), target, color);
        draw.DrawPoint(target, flags.pointSize, color);
    }
    if (m_mirror)
    {
        m_mirror->Draw(draw, validation::kBox2DColor);
    }
}

namespace
{

struct CommandSpec
{
    const char* name;
    ScriptCommand::Kind kind;
    int numbers; ///< how many numbers follow
    bool word;   ///< one word follows instead
};

constexpr CommandSpec kCommands[] = {
    {"size", ScriptCommand::Kind::Size, 2, false},
    {"camera", ScriptCommand::Kind::Camera, 3, false},
    {"step", ScriptCommand::Kind::Step, 1, false},
    {"grab", ScriptCommand::Kind::Grab, 2, false},
    {"move", ScriptCommand::Kind::Move, 2, false},
    {"release", ScriptCommand::Kind::Release, 0, false},
    {"drag", ScriptCommand::Kind::Drag, 5, false},
    {"solver", ScriptCommand::Kind::Solver, 0, true},
    {"iterations", ScriptCommand::Kind::Iterations, 2, false},
    {"substeps", ScriptCommand::Kind::Substeps, 1, false},
    {"restart", ScriptCommand::Kind::Restart, 0, false},
    {"screenshot", ScriptCommand::Kind::Screenshot, 0, true},
    {"screenshot_window", ScriptCommand::Kind::WindowShot, 0, true},
    {"ghost", ScriptCommand::Kind::Ghost, 0, true},
    {"expect", ScriptCommand::Kind::Expect, 0, true},
};

std::optional<SolverKind> SolverByName(const std::string& name)
{
    for (const SolverKind kind : {SolverKind::Box2D, SolverKind::Colour, SolverKind::SoftStep})
    {
        if (name == SolverKindName(kind))
        {
            return kind;
        }
    }
    return std::nullopt;
}

/// A whole number in [low, high] from a script's number.
bool Whole(double value, double low, double high)
{
    return value == std::floor(value) && value >= low && value <= high;
}

} // namespace

std::vector<ScriptCommand> ParseScript(std::string_view text, const std::string& path)
{
    std::vector<ScriptCommand> commands;
    std::istringstream lines{std::string(text)};
    std::string line;
    int number = 0;
    while (std::getline(lines, line))
    {
        ++number;
        const std::string where = path + ":" + std::to_string(number) + ": ";
        line = line.substr(0, line.find('#'));
        std::istringstream words(line);
        std::vector<std::string> tokens;
        for (std::string word; words >> word;)
        {
            tokens.push_back(word);
        }
        if (tokens.empty())
        {
            continue;
        }
        const auto spec = std::find_if(std::begin(kCommands), std::end(kCommands),
                                       [&](const CommandSpec& s) { return tokens[0] == s.name; });
        if (spec == std::end(kCommands))
        {
            throw ScriptError(
                where + "unknown command \"" + tokens[0] +
                "\" (size, camera, step, grab, move, release, drag, solver, "
                "iterations, substeps, restart, screenshot, screenshot_window, ghost, expect)");
        }
        const std::size_t wanted = spec->word ? 1 : std::size_t(spec->numbers);
        if (tokens.size() - 1 != wanted)
        {
            throw ScriptError(where + tokens[0] + " takes " + std::to_string(wanted) +
                              (spec->word ? " word" : " number") + (wanted == 1 ? "" : "s") +
                              ", got " + std::to_string(tokens.size() - 1));
        }
        ScriptCommand command;
        command.kind = spec->kind;
        command.line = number;
        if (spec->word)
        {
            command.text = tokens[1];
        }
        for (int i = 0; i < spec->numbers; ++i)
        {
            const std::string& token = tokens[std::size_t(i) + 1];
            char* end = nullptr;
            const double value = std::strtod(token.c_str(), &end);
            if (end != token.c_str() + token.size() || !std::isfinite(value) ||
                std::abs(value) > 1e7)
            {
                throw ScriptError(where + tokens[0] + ": \"" + token +
                                  "\" is not a number within ±1e7");
            }
            command.numbers.push_back(value);
        }
        const std::vector<double>& n = command.numbers;
        const auto refuse = [&](const std::string& why)
        { throw ScriptError(where + tokens[0] + ": " + why); };
        switch (command.kind)
        {
        case ScriptCommand::Kind::Size:
            if (!Whole(n[0], 16, render::kMaxImageSize) || !Whole(n[1], 16, render::kMaxImageSize))
            {
                refuse("width and height must be whole numbers from 16 to 8192");
            }
            break;
        case ScriptCommand::Kind::Camera:
            if (!(n[2] >= 1e-3 && n[2] <= 1e5))
            {
                refuse("the height must be from 0.001 to 100000 m");
            }
            break;
        case ScriptCommand::Kind::Step:
        case ScriptCommand::Kind::Substeps:
            if (!Whole(n[0], command.kind == ScriptCommand::Kind::Step ? 0 : 1, 1e6))
            {
                refuse("needs a whole number from " +
                       std::string(command.kind == ScriptCommand::Kind::Step ? "0" : "1") +
                       " to 1000000");
            }
            break;
        case ScriptCommand::Kind::Drag:
            if (!Whole(n[4], 1, 1e6))
            {
                refuse("the step count must be a whole number from 1 to 1000000");
            }
            break;
        case ScriptCommand::Kind::Iterations:
            if (!Whole(n[0], 1, 1000) || !Whole(n[1], 0, 1000))
            {
                refuse("velocity iterations 1..1000, position iterations 0..1000");
            }
            break;
        case ScriptCommand::Kind::Solver:
            if (!SolverByName(command.text))
            {
                refuse("unknown back end \"" + command.text + "\" (box2d, colour, soft_step)");
            }
            break;
        case ScriptCommand::Kind::Ghost:
            if (command.text != "on" && command.text != "off")
            {
                refuse("takes \"on\" or \"off\", got \"" + command.text + "\"");
            }
            break;
        case ScriptCommand::Kind::Expect:
            if (command.text != "grabbed" && command.text != "released" &&
                command.text != "identical" && command.text != "diverged")
            {
                refuse("expects grabbed, released, identical or diverged, got \"" + command.text +
                       "\"");
            }
            break;
        default:
            break;
        }
        commands.push_back(std::move(command));
    }
    return commands;
}

void RunScript(const std::vector<ScriptCommand>& commands, const std::string& path,
               Session& session, ViewCamera& camera, const ScriptHost& host)
{
    const auto step = [&]
    {
        session.Step();
        if (host.frame)
        {
            host.frame();
        }
    };
    for (const ScriptCommand& command : commands)
    {
        const std::string where = path + ":" + std::to_string(command.line) + ": ";
        const std::vector<double>& n = command.numbers;
        const auto point = [&](std::size_t i) { return Vec2{Real(n[i]), Real(n[i + 1])}; };
        switch (command.kind)
        {
        case ScriptCommand::Kind::Size:
            camera.width = int(n[0]);
            camera.heightPixels = int(n[1]);
            if (host.resize)
            {
                host.resize(camera.width, camera.heightPixels);
            }
            break;
        case ScriptCommand::Kind::Camera:
            camera.center = point(0);
            camera.height = n[2];
            break;
        case ScriptCommand::Kind::Step:
            for (int i = 0; i < int(n[0]); ++i)
            {
                step();
            }
            break;
        case ScriptCommand::Kind::Grab:
        case ScriptCommand::Kind::Drag:
            if (!session.Grab(point(0)))
            {
                char text[96];
                std::snprintf(text, sizeof text, "no dynamic body at (%g, %g)", n[0], n[1]);
                throw ScriptError(where + text);
            }
            if (command.kind == ScriptCommand::Kind::Drag)
            {
                const int steps = int(n[4]);
                for (int i = 1; i <= steps; ++i)
                {
                    const double t = double(i) / steps;
                    session.MoveGrab(
                        Vec2{Real(n[0] + (n[2] - n[0]) * t), Real(n[1] + (n[3] - n[1]) * t)});
                    step();
                }
            }
            break;
        case ScriptCommand::Kind::Move:
            session.MoveGrab(point(0));
            break;
        case ScriptCommand::Kind::Release:
            session.Release();
            break;
        case ScriptCommand::Kind::Solver:
        {
            SolverSettings settings = session.Solver();
            settings.kind = *SolverByName(command.text);
            session.SetSolver(settings);
            break;
        }
        case ScriptCommand::Kind::Iterations:
        {
            SolverSettings settings = session.Solver();
            settings.velocityIterations = int(n[0]);
            settings.positionIterations = int(n[1]);
            session.SetSolver(settings);
            break;
        }
        case ScriptCommand::Kind::Substeps:
        {
            SolverSettings settings = session.Solver();
            settings.softStep.substeps = int(n[0]);
            session.SetSolver(settings);
            break;
        }
        case ScriptCommand::Kind::Restart:
            session.Restart();
            break;
        case ScriptCommand::Kind::Screenshot:
            if (host.screenshot)
            {
                host.screenshot(command.text);
            }
            break;
        case ScriptCommand::Kind::WindowShot:
            if (host.windowShot)
            {
                host.windowShot(command.text);
            }
            break;
        case ScriptCommand::Kind::Ghost:
        {
            std::string why;
            if (!session.SetGhost(command.text == "on", &why))
            {
                throw ScriptError(where + "no Box2D 2.4.1 ghost: " + why);
            }
            break;
        }
        case ScriptCommand::Kind::Expect:
            if (command.text == "identical" || command.text == "diverged")
            {
                if (!session.Ghost())
                {
                    throw ScriptError(where + "expect " + command.text + " needs the ghost on");
                }
                const bool diverged = session.GhostDivergence().has_value();
                if (diverged != (command.text == "diverged"))
                {
                    throw ScriptError(where + "expected meff and Box2D 2.4.1 to be " +
                                      command.text + ", " +
                                      (diverged ? "they diverged at frame " +
                                                      std::to_string(*session.GhostDivergence())
                                                : std::string("they agree bit for bit")));
                }
            }
            else if ((command.text == "grabbed") != session.Grabbed().has_value())
            {
                throw ScriptError(where + "expected the mouse to have " +
                                  (command.text == "grabbed" ? "a body" : "no body") + ", it has " +
                                  (session.Grabbed() ? "one" : "none"));
            }
            break;
        }
    }
}

void Tessellate(const Session& session, const ViewCamera& camera, const DrawFlags& flags,
                render::TriangleDraw& triangles)
{
    triangles.Clear();
    triangles.SetScale(camera.PixelSize(), render::LineWidth(camera.width, camera.heightPixels));
    session.Draw(triangles, flags);
}

} // namespace meff::view
