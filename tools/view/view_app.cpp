// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The `meff view` window (see view_app.h). Everything it decides is in viewer_core.h; this file
// turns GLFW's input into those calls and draws the triangles they give (the render library's
// tessellation, the same as meff render's frames) with OpenGL 3.3, and the panel with Dear
// ImGui.
//
// OpenGL is reached only through pointers from glfwGetProcAddress (and ImGui's backend loads
// its own): the meff executable also links OSMesa, which exports the same gl* names, for
// meff render and for saving frames from here.
#include "view_app.h"

#include "viewer_core.h"

#include "meff/render.h"

#define GLFW_INCLUDE_NONE
#include <GL/glcorearb.h>
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#ifdef MEFF_SANITIZE
#include <dlfcn.h>
#include <link.h>
#endif

namespace meff::view
{

namespace
{

/// The OpenGL 3.3 functions the view draws with.
struct Gl
{
#define MEFF_GL_FUNCTIONS(X)                                                                       \
    X(PFNGLCLEARCOLORPROC, ClearColor, glClearColor)                                               \
    X(PFNGLCLEARPROC, Clear, glClear)                                                              \
    X(PFNGLVIEWPORTPROC, Viewport, glViewport)                                                     \
    X(PFNGLENABLEPROC, Enable, glEnable)                                                           \
    X(PFNGLBLENDFUNCPROC, BlendFunc, glBlendFunc)                                                  \
    X(PFNGLREADPIXELSPROC, ReadPixels, glReadPixels)                                               \
    X(PFNGLPIXELSTOREIPROC, PixelStorei, glPixelStorei)                                            \
    X(PFNGLDRAWARRAYSPROC, DrawArrays, glDrawArrays)                                               \
    X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays, glGenVertexArrays)                                \
    X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray, glBindVertexArray)                                \
    X(PFNGLGENBUFFERSPROC, GenBuffers, glGenBuffers)                                               \
    X(PFNGLBINDBUFFERPROC, BindBuffer, glBindBuffer)                                               \
    X(PFNGLBUFFERDATAPROC, BufferData, glBufferData)                                               \
    X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer, glVertexAttribPointer)                    \
    X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray, glEnableVertexAttribArray)        \
    X(PFNGLCREATESHADERPROC, CreateShader, glCreateShader)                                         \
    X(PFNGLSHADERSOURCEPROC, ShaderSource, glShaderSource)                                         \
    X(PFNGLCOMPILESHADERPROC, CompileShader, glCompileShader)                                      \
    X(PFNGLGETSHADERIVPROC, GetShaderiv, glGetShaderiv)                                            \
    X(PFNGLCREATEPROGRAMPROC, CreateProgram, glCreateProgram)                                      \
    X(PFNGLATTACHSHADERPROC, AttachShader, glAttachShader)                                         \
    X(PFNGLBINDATTRIBLOCATIONPROC, BindAttribLocation, glBindAttribLocation)                       \
    X(PFNGLLINKPROGRAMPROC, LinkProgram, glLinkProgram)                                            \
    X(PFNGLGETPROGRAMIVPROC, GetProgramiv, glGetProgramiv)                                         \
    X(PFNGLUSEPROGRAMPROC, UseProgram, glUseProgram)                                               \
    X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation, glGetUniformLocation)                       \
    X(PFNGLUNIFORM4FPROC, Uniform4f, glUniform4f)                                                  \
    X(PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers, glGenFramebuffers)                                \
    X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer, glBindFramebuffer)                                \
    X(PFNGLDELETEFRAMEBUFFERSPROC, DeleteFramebuffers, glDeleteFramebuffers)                       \
    X(PFNGLGENRENDERBUFFERSPROC, GenRenderbuffers, glGenRenderbuffers)                             \
    X(PFNGLBINDRENDERBUFFERPROC, BindRenderbuffer, glBindRenderbuffer)                             \
    X(PFNGLDELETERENDERBUFFERSPROC, DeleteRenderbuffers, glDeleteRenderbuffers)                    \
    X(PFNGLRENDERBUFFERSTORAGEPROC, RenderbufferStorage, glRenderbufferStorage)                    \
    X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, FramebufferRenderbuffer, glFramebufferRenderbuffer)        \
    X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, CheckFramebufferStatus, glCheckFramebufferStatus)
#define MEFF_GL_MEMBER(type, name, symbol) type name = nullptr;
    MEFF_GL_FUNCTIONS(MEFF_GL_MEMBER)
#undef MEFF_GL_MEMBER

    /// Loads every function from the current context; false (naming the first missing one in
    /// `missing`) when the driver lacks one.
    bool Load(std::string& missing)
    {
#define MEFF_GL_LOAD(type, name, symbol)                                                           \
    name = reinterpret_cast<type>(glfwGetProcAddress(#symbol));                                    \
    if (name == nullptr)                                                                           \
    {                                                                                              \
        missing = #symbol;                                                                         \
        return false;                                                                              \
    }
        MEFF_GL_FUNCTIONS(MEFF_GL_LOAD)
#undef MEFF_GL_LOAD
        return true;
    }
};

constexpr const char* kVertexShader = R"(#version 330 core
in vec2 position; // metres from the camera's centre
in vec4 color;
uniform vec4 view; // 1 / half the view's width and height (m), 0, 0
out vec4 fragmentColor;
void main()
{
    gl_Position = vec4(position * view.xy, 0.0, 1.0);
    fragmentColor = color;
}
)";

constexpr const char* kFragmentShader = R"(#version 330 core
in vec4 fragmentColor;
out vec4 outColor;
void main()
{
    outColor = fragmentColor;
}
)";

/// Draws the session's triangles through a ViewCamera.
class WorldPainter
{
  public:
    explicit WorldPainter(const Gl& gl) : m_gl(gl)
    {
        const auto compile = [&](GLenum type, const char* source)
        {
            const GLuint shader = gl.CreateShader(type);
            gl.ShaderSource(shader, 1, &source, nullptr);
            gl.CompileShader(shader);
            GLint ok = 0;
            gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
            if (!ok)
            {
                throw std::runtime_error("the view's shader does not compile");
            }
            return shader;
        };
        m_program = gl.CreateProgram();
        gl.AttachShader(m_program, compile(GL_VERTEX_SHADER, kVertexShader));
        gl.AttachShader(m_program, compile(GL_FRAGMENT_SHADER, kFragmentShader));
        gl.BindAttribLocation(m_program, 0, "position");
        gl.BindAttribLocation(m_program, 1, "color");
        gl.LinkProgram(m_program);
        GLint ok = 0;
        gl.GetProgramiv(m_program, GL_LINK_STATUS, &ok);
        if (!ok)
        {
            throw std::runtime_error("the view's shader does not link");
        }
        m_view = gl.GetUniformLocation(m_program, "view");
        gl.GenVertexArrays(1, &m_vao);
        gl.GenBuffers(1, &m_buffer);
        gl.BindVertexArray(m_vao);
        gl.BindBuffer(GL_ARRAY_BUFFER, m_buffer);
        gl.VertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 6 * sizeof(float), nullptr);
        gl.VertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, 6 * sizeof(float),
                               reinterpret_cast<const void*>(2 * sizeof(float)));
        gl.EnableVertexAttribArray(0);
        gl.EnableVertexAttribArray(1);
        gl.BindVertexArray(0);
    }

    /// Clears the current framebuffer (`width`×`height`) to meff render's background and draws
    /// the session through `camera`.
    void Paint(const Session& session, const ViewCamera& camera, const DrawFlags& flags)
    {
        const Gl& gl = m_gl;
        gl.Viewport(0, 0, camera.width, camera.heightPixels);
        gl.ClearColor(render::kBackground.r / 255.0f, render::kBackground.g / 255.0f,
                      render::kBackground.b / 255.0f, 1.0f);
        gl.Clear(GL_COLOR_BUFFER_BIT);
        gl.Enable(GL_BLEND);
        gl.BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        Tessellate(session, camera, flags, m_triangles);
        // Relative to the camera's centre in double, then float: no loss far from the origin.
        m_vertices.clear();
        for (const render::ColoredVertex& v : m_triangles.Triangles())
        {
            m_vertices.insert(m_vertices.end(), {float(v.x - double(camera.center.x)),
                                                 float(v.y - double(camera.center.y)), v.color.r,
                                                 v.color.g, v.color.b, v.color.a});
        }
        gl.UseProgram(m_program);
        const double halfHeight = 0.5 * camera.height;
        const double halfWidth = halfHeight * camera.width / camera.heightPixels;
        gl.Uniform4f(m_view, float(1 / halfWidth), float(1 / halfHeight), 0, 0);
        gl.BindVertexArray(m_vao);
        gl.BindBuffer(GL_ARRAY_BUFFER, m_buffer);
        gl.BufferData(GL_ARRAY_BUFFER, GLsizeiptr(m_vertices.size() * sizeof(float)),
                      m_vertices.data(), GL_STREAM_DRAW);
        gl.DrawArrays(GL_TRIANGLES, 0, GLsizei(m_vertices.size() / 6));
        gl.BindVertexArray(0);
        gl.UseProgram(0);
    }

    /// Draws the session into an off-screen framebuffer of the camera's size and returns its
    /// pixels (what a screenshot saves: the world alone, without the panel).
    render::Image Capture(const Session& session, const ViewCamera& camera, const DrawFlags& flags)
    {
        const Gl& gl = m_gl;
        GLuint framebuffer = 0, color = 0;
        gl.GenFramebuffers(1, &framebuffer);
        gl.GenRenderbuffers(1, &color);
        gl.BindRenderbuffer(GL_RENDERBUFFER, color);
        gl.RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, camera.width, camera.heightPixels);
        gl.BindFramebuffer(GL_FRAMEBUFFER, framebuffer);
        gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
        if (gl.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        {
            throw std::runtime_error("cannot make an off-screen framebuffer for the screenshot");
        }
        Paint(session, camera, flags);
        std::vector<std::uint8_t> rgba(std::size_t(camera.width) * camera.heightPixels * 4);
        gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
        gl.ReadPixels(0, 0, camera.width, camera.heightPixels, GL_RGBA, GL_UNSIGNED_BYTE,
                      rgba.data());
        gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
        gl.DeleteFramebuffers(1, &framebuffer);
        gl.DeleteRenderbuffers(1, &color);
        return FromGlRows(rgba, camera.width, camera.heightPixels);
    }

    /// The window's back buffer, top row first.
    render::Image ReadWindow(int width, int height) const
    {
        std::vector<std::uint8_t> rgba(std::size_t(width) * height * 4);
        m_gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
        m_gl.ReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
        return FromGlRows(rgba, width, height);
    }

    /// RGBA rows bottom to top (GL's order) as an image.
    static render::Image FromGlRows(const std::vector<std::uint8_t>& rgba, int width, int height)
    {
        render::Image image(width, height);
        for (int y = 0; y < height; ++y)
        {
            const std::uint8_t* row = rgba.data() + std::size_t(height - 1 - y) * width * 4;
            for (int x = 0; x < width; ++x)
            {
                image.Set(x, y, {row[x * 4], row[x * 4 + 1], row[x * 4 + 2]});
            }
        }
        return image;
    }

  private:
    const Gl& m_gl;
    GLuint m_program = 0;
    GLint m_view = -1;
    GLuint m_vao = 0;
    GLuint m_buffer = 0;
    render::TriangleDraw m_triangles;
    std::vector<float> m_vertices;
};

std::string ReadText(const std::string& path)
{
    std::ifstream file(path, std::ios::binary);
    if (!file)
    {
        throw ScriptError("cannot read the script " + path);
    }
    std::ostringstream text;
    text << file.rdbuf();
    return text.str();
}

/// Saves the session as meff render draws it (OSMesa, supersampled, caption and legend).
void SaveFrame(const Session& session, const ViewCamera& camera, const DrawFlags& flags,
               const std::string& path)
{
    render::OffscreenRenderer renderer(camera.width, camera.heightPixels);
    render::FrameOptions options;
    options.camera = camera.ToRender();
    options.flags = flags;
    char caption[256];
    std::snprintf(caption, sizeof caption, "%s  frame %llu  t = %.3f s",
                  session.GetScene().name.c_str(), static_cast<unsigned long long>(session.Frame()),
                  double(session.Frame()) * session.GetScene().world.dt);
    options.caption = caption;
    render::DrawList drawing;
    session.Draw(drawing, flags);
    render::WritePng(path, render::RenderFrame(renderer, drawing, options));
}

/// The panel: play controls, the back end and its settings, readouts, the selected body.
struct Panel
{
    bool playing = false;
    bool stepOnce = false;
    bool restart = false;
    std::string message;
    int savedFrames = 0;
    std::vector<double> energy; ///< the readout's history, for the plot

    void Draw(Session& session, const ViewCamera& camera, DrawFlags& flags)
    {
        ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
        ImGui::SetNextWindowSize(ImVec2(440, 0), ImGuiCond_FirstUseEver);
        ImGui::Begin("meff view");
        ImGui::PushItemWidth(200);
        ImGui::TextWrapped("%s", session.GetScene().name.c_str());
        if (ImGui::Button(playing ? "Pause (space)" : "Play (space)"))
        {
            playing = !playing;
        }
        ImGui::SameLine();
        if (ImGui::Button("Step (.)"))
        {
            stepOnce = true;
        }
        ImGui::SameLine();
        if (ImGui::Button("Restart (r)"))
        {
            restart = true;
        }
        if (ImGui::Button("Save frame (meff render's PNG)"))
        {
            char name[64];
            std::snprintf(name, sizeof name, "meff_view_%05d.png", savedFrames++);
            try
            {
                SaveFrame(session, camera, flags, name);
                message = std::string("saved ") + name;
            }
            catch (const std::exception& error)
            {
                message = error.what();
            }
        }

        ImGui::Separator();
        SolverSettings solver = session.Solver();
        bool changed = false;
        const char* kinds[] = {"box2d", "colour", "soft_step"};
        int kind = int(solver.kind);
        if (ImGui::Combo("back end", &kind, kinds, 3))
        {
            solver.kind = SolverKind(kind);
            changed = true;
        }
        if (solver.kind == SolverKind::SoftStep)
        {
            changed |= ImGui::SliderInt("substeps", &solver.softStep.substeps, 1, 16);
            changed |= ImGui::SliderInt("relax iterations", &solver.softStep.relaxIterations, 0, 8);
            float hertz = float(solver.softStep.jointHertz);
            if (ImGui::SliderFloat("joint stiffness (Hz)", &hertz, 1, 240))
            {
                solver.softStep.jointHertz = Real(hertz);
                changed = true;
            }
            float contactHertz = float(solver.softStep.contactHertz);
            if (ImGui::SliderFloat("contact stiffness (Hz)", &contactHertz, 1, 240))
            {
                solver.softStep.contactHertz = Real(contactHertz);
                changed = true;
            }
        }
        else
        {
            changed |= ImGui::SliderInt("velocity iterations", &solver.velocityIterations, 1, 50);
            changed |= ImGui::SliderInt("position iterations", &solver.positionIterations, 0, 50);
        }
        changed |= ImGui::Checkbox("warm starting", &solver.warmStarting);
        if (changed)
        {
            try
            {
                session.SetSolver(solver);
            }
            catch (const std::exception& error)
            {
                message = error.what();
            }
        }

        ImGui::Separator();
        const Readouts readouts = session.Measure();
        ImGui::Text("frame %llu  t = %.3f s", static_cast<unsigned long long>(readouts.step),
                    double(readouts.step) * session.GetScene().world.dt);
        ImGui::Text("energy %.6g J", readouts.Energy());
        ImGui::Text("  kinetic %.4g J, potential %.6g J", readouts.kinetic, readouts.potential);
        if (energy.size() >= 600)
        {
            energy.erase(energy.begin());
        }
        energy.push_back(readouts.Energy());
        std::vector<float> plot(energy.begin(), energy.end());
        ImGui::PlotLines("##energy", plot.data(), int(plot.size()), 0, "energy", FLT_MAX, FLT_MAX,
                         ImVec2(-1, 50));
        ImGui::Text("largest joint gap %.3g mm", readouts.jointGap * 1000);
        bool ghost = session.Ghost();
        if (ImGui::Checkbox("Box2D 2.4.1 ghost (blue outlines; restarts)", &ghost))
        {
            std::string why;
            if (!session.SetGhost(ghost, &why))
            {
                message = "no Box2D 2.4.1 ghost: " + why;
            }
            energy.clear();
        }
        if (session.Ghost())
        {
            if (const std::optional<std::uint64_t> detached = session.GhostDetached())
            {
                ImGui::Text("  not compared since the grab at frame %llu",
                            static_cast<unsigned long long>(*detached));
            }
            else if (const std::optional<std::uint64_t> frame = session.GhostDivergence())
            {
                ImGui::TextColored(ImVec4(0.8f, 0.1f, 0.1f, 1), "  first divergence: frame %llu",
                                   static_cast<unsigned long long>(*frame));
            }
            else
            {
                ImGui::Text("  identical to Box2D 2.4.1, bit for bit");
            }
            ImGui::Text("  largest offset %.3g mm", readouts.ghostOffset * 1000);
        }
        ImGui::Text("deepest penetration %.3g mm (%d points)", readouts.penetration * 1000,
                    readouts.contactPoints);
        const StepProfile& profile = session.GetWorld().GetProfile();
        // The profile overlay: where the last step's time went.
        ImGui::Text("step %.3f ms: pairs %.3f, narrow %.3f, solve %.3f,", profile.step,
                    profile.findContacts, profile.collide, profile.solve);
        ImGui::Text("  broad-phase sync %.3f, continuous %.3f", profile.synchronize,
                    profile.continuous);

        ImGui::Separator();
        ImGui::Checkbox("joints", &flags.joints);
        ImGui::SameLine();
        ImGui::Checkbox("contacts", &flags.contacts);
        ImGui::SameLine();
        ImGui::Checkbox("AABBs", &flags.aabbs);
        bool impulses = flags.contactImpulses;
        if (ImGui::Checkbox("impulses", &impulses))
        {
            flags.contactImpulses = flags.jointReactions = impulses;
        }

        ImGui::Separator();
        if (session.selected && session.GetWorld().IsValid(*session.selected))
        {
            for (const std::string& line : session.Report(*session.selected).Lines())
            {
                ImGui::TextUnformatted(line.c_str());
            }
        }
        else
        {
            ImGui::TextWrapped("Click a body to select it; drag it to pull it (a mouse joint), "
                               "let go to throw it. Right or middle drag pans, the wheel zooms.");
        }
        if (!message.empty())
        {
            ImGui::Separator();
            ImGui::TextWrapped("%s", message.c_str());
        }
        ImGui::PopItemWidth();
        ImGui::End();
    }
};

struct App
{
    GLFWwindow* window = nullptr;
    Gl gl;
    std::unique_ptr<WorldPainter> painter;
    std::unique_ptr<Session> session;
    ViewCamera camera;
    DrawFlags flags;
    Panel panel;
    bool panning = false;
    double lastX = 0;
    double lastY = 0;
};

/// One frame of the window without input: the world and the panel, into the back buffer.
void DrawWindow(App& app)
{
    int width = 0, height = 0;
    glfwGetFramebufferSize(app.window, &width, &height);
    const ViewCamera scripted = app.camera;
    app.camera.width = std::max(1, width);
    app.camera.heightPixels = std::max(1, height);
    // The window shows the script's centre at the script's metres per pixel.
    app.camera.height = scripted.height * app.camera.heightPixels / scripted.heightPixels;
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    app.panel.Draw(*app.session, app.camera, app.flags);
    app.painter->Paint(*app.session, app.camera, app.flags);
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    app.camera = scripted;
}

int RunScriptInWindow(App& app, const std::string& scriptPath)
{
    try
    {
        const std::vector<ScriptCommand> commands = ParseScript(ReadText(scriptPath), scriptPath);
        ScriptHost host;
        host.screenshot = [&](const std::string& path)
        {
            render::WritePng(path, app.painter->Capture(*app.session, app.camera, app.flags));
            std::printf("screenshot %s (%dx%d, frame %llu)\n", path.c_str(), app.camera.width,
                        app.camera.heightPixels,
                        static_cast<unsigned long long>(app.session->Frame()));
        };
        host.windowShot = [&](const std::string& path)
        {
            // A whole frame as the person sees it, panel included, read before it is shown.
            // Twice: Dear ImGui lays out a new window on its first frame and shows it from the
            // second.
            DrawWindow(app);
            DrawWindow(app);
            int width = 0, height = 0;
            glfwGetFramebufferSize(app.window, &width, &height);
            render::WritePng(path, app.painter->ReadWindow(width, height));
            glfwSwapBuffers(app.window);
            std::printf("window %s\n", path.c_str());
        };
        host.frame = [&] { glfwPollEvents(); };
        RunScript(commands, scriptPath, *app.session, app.camera, host);
    }
    catch (const ScriptError& error)
    {
        std::fprintf(stderr, "meff view: %s\n", error.what());
        return 1;
    }
    catch (const SimulationError& error)
    {
        std::fprintf(stderr, "meff view: %s: simulation failed: %s\n", scriptPath.c_str(),
                     error.what());
        return 1;
    }
    catch (const render::RenderError& error)
    {
        std::fprintf(stderr, "meff view: %s\n", error.what());
        return 1;
    }
    return 0;
}

void HandleInput(App& app)
{
    ImGuiIO& io = ImGui::GetIO();
    double x = 0, y = 0;
    glfwGetCursorPos(app.window, &x, &y);
    // Window coordinates to framebuffer pixels (they differ on high-DPI screens).
    int windowWidth = 1, windowHeight = 1;
    glfwGetWindowSize(app.window, &windowWidth, &windowHeight);
    x *= double(app.camera.width) / std::max(1, windowWidth);
    y *= double(app.camera.heightPixels) / std::max(1, windowHeight);
    const Vec2 world = app.camera.ScreenToWorld(x, y);
    if (!io.WantCaptureMouse)
    {
        if (ImGui::IsMouseClicked(ImGuiMouseButton_Left))
        {
            app.session->selected = app.session->BodyAt(world);
            app.session->Grab(world);
        }
        if (io.MouseWheel != 0)
        {
            app.camera.ZoomAt(x, y, std::pow(1.1, double(io.MouseWheel)));
        }
        if (ImGui::IsMouseClicked(ImGuiMouseButton_Right) ||
            ImGui::IsMouseClicked(ImGuiMouseButton_Middle))
        {
            app.panning = true;
        }
    }
    if (app.session->Grabbed())
    {
        app.session->MoveGrab(world);
        if (!ImGui::IsMouseDown(ImGuiMouseButton_Left))
        {
            app.session->Release(); // the body keeps its speed: a throw
        }
    }
    if (app.panning)
    {
        app.camera.Pan(x - app.lastX, y - app.lastY);
        if (!ImGui::IsMouseDown(ImGuiMouseButton_Right) &&
            !ImGui::IsMouseDown(ImGuiMouseButton_Middle))
        {
            app.panning = false;
        }
    }
    app.lastX = x;
    app.lastY = y;
    // Dear ImGui 1.86 indexes keys by the backend's codes (GLFW's).
    if (!io.WantCaptureKeyboard)
    {
        if (ImGui::IsKeyPressed(GLFW_KEY_SPACE))
        {
            app.panel.playing = !app.panel.playing;
        }
        if (ImGui::IsKeyPressed(GLFW_KEY_PERIOD))
        {
            app.panel.stepOnce = true;
        }
        if (ImGui::IsKeyPressed(GLFW_KEY_R))
        {
            app.panel.restart = true;
        }
    }
}

int RunInteractive(App& app)
{
    auto lastCheck = std::chrono::steady_clock::now();
    while (!glfwWindowShouldClose(app.window))
    {
        glfwPollEvents();
        int width = 0, height = 0;
        glfwGetFramebufferSize(app.window, &width, &height);
        if (width > 0 && height > 0)
        {
            app.camera.width = width;
            app.camera.heightPixels = height;
        }
        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
        HandleInput(app);
        app.panel.Draw(*app.session, app.camera, app.flags);

        // A level designer's loop: the file saved elsewhere is loaded again.
        const auto now = std::chrono::steady_clock::now();
        if (now - lastCheck > std::chrono::milliseconds(500))
        {
            lastCheck = now;
            if (app.session->FileChanged())
            {
                try
                {
                    app.session->Reload();
                    app.panel.message = "reloaded " + app.session->Path();
                    app.panel.energy.clear();
                }
                catch (const std::exception& error)
                {
                    app.panel.message = error.what(); // keeps the last good scene
                }
            }
        }
        if (app.panel.restart)
        {
            app.session->Restart();
            app.panel.energy.clear();
            app.panel.restart = false;
        }
        if (app.panel.playing || app.panel.stepOnce)
        {
            try
            {
                app.session->Step();
            }
            catch (const SimulationError& error)
            {
                app.panel.playing = false;
                app.panel.message = std::string("simulation failed: ") + error.what();
            }
            app.panel.stepOnce = false;
        }

        app.painter->Paint(*app.session, app.camera, app.flags);
        ImGui::Render();
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
        glfwSwapBuffers(app.window);
    }
    return 0;
}

/// Opens the window and its OpenGL 3.3 context; nullptr (after saying why) when it cannot.
GLFWwindow* OpenWindow(const ViewerOptions& options, const std::string& title)
{
    if (!glfwInit())
    {
        std::fprintf(stderr, "meff view: cannot open a window (no display? under CI, run it "
                             "through xvfb-run)\n");
        return nullptr;
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    GLFWwindow* window =
        glfwCreateWindow(options.width, options.height, title.c_str(), nullptr, nullptr);
    if (window == nullptr)
    {
        std::fprintf(stderr, "meff view: cannot create an OpenGL 3.3 window\n");
        glfwTerminate();
        return nullptr;
    }
    glfwMakeContextCurrent(window);
    glfwSwapInterval(1);
    return window;
}

/// Loads the GL functions and starts Dear ImGui (whose shaders the driver compiles); false, after
/// saying why, when the driver lacks a function.
bool StartGraphics(App& app)
{
    std::string missing;
    if (!app.gl.Load(missing))
    {
        std::fprintf(stderr, "meff view: the OpenGL driver lacks %s\n", missing.c_str());
        return false;
    }
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr; // no imgui.ini left in the working directory
    ImGui::StyleColorsLight();
    ImGui_ImplGlfw_InitForOpenGL(app.window, true);
    ImGui_ImplOpenGL3_Init("#version 330 core");
    return true;
}

/// Frees the painter's and Dear ImGui's GL objects.
void StopGraphics(App& app)
{
    app.painter.reset();
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
}

/// Closes the window. GLFW then unloads the GL stack (libGL, Mesa's driver), which it loaded with
/// dlopen; the driver still holds a few allocations from its globals. Once its module is gone,
/// those globals are too, and LeakSanitizer, which checks at exit, would report the driver's
/// allocations as meff's leaks. Under the sanitizers every library stays loaded to the end.
void CloseWindow(GLFWwindow* window)
{
#ifdef MEFF_SANITIZE
    dl_iterate_phdr(
        [](dl_phdr_info* info, std::size_t, void*) -> int
        {
            if (info->dlpi_name != nullptr && info->dlpi_name[0] != '\0')
            {
                dlopen(info->dlpi_name, RTLD_LAZY | RTLD_NOLOAD | RTLD_NODELETE);
            }
            return 0;
        },
        nullptr);
#endif
    glfwDestroyWindow(window);
    glfwTerminate();
}

} // namespace

int RunViewer(const ViewerOptions& options)
{
    App app;
    try
    {
        app.session = std::make_unique<Session>(options.scenePath);
    }
    catch (const SceneError& error)
    {
        std::fprintf(stderr, "%s\n", error.what());
        return 2;
    }
    app.window = OpenWindow(options, "meff view: " + app.session->GetScene().name);
    if (app.window == nullptr)
    {
        return 2;
    }
    int status = 2;
    if (StartGraphics(app))
    {
        try
        {
            app.painter = std::make_unique<WorldPainter>(app.gl);
            int width = 0, height = 0;
            glfwGetFramebufferSize(app.window, &width, &height);
            app.camera.width = std::max(1, width);
            app.camera.heightPixels = std::max(1, height);
            if (const std::optional<SceneCamera>& scene = app.session->GetScene().camera)
            {
                app.camera.center = Vec2{Real(scene->center.x), Real(scene->center.y)};
                app.camera.height = scene->height;
            }
            else if (const std::optional<AABB> bounds =
                         render::WorldBounds(app.session->GetWorld()))
            {
                app.camera.Fit(*bounds);
            }
            app.flags.pointSize = 5;
            status = options.scriptPath.empty() ? RunInteractive(app)
                                                : RunScriptInWindow(app, options.scriptPath);
        }
        catch (const std::exception& error)
        {
            std::fprintf(stderr, "meff view: %s\n", error.what());
            status = 1;
        }
        StopGraphics(app);
    }
    CloseWindow(app.window);
    return status;
}

} // namespace meff::view
