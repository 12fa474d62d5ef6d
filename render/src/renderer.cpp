// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The OSMesa context, the OpenGL DebugDraw, and a whole frame.
//
// Legacy fixed-function OpenGL is all this needs: a few thousand flat-coloured triangles per
// frame, which Mesa's software rasterizer draws in milliseconds. Lines are drawn as triangles
// (not GL lines) so that their width is exact and the same on every Mesa driver; edges are
// smoothed by drawing at `supersample`× the size and averaging down on the CPU, which, unlike
// GL multisampling, gives the same bytes whatever the driver's sample pattern.
#include "meff/render.h"

#include "frame_layout.h"

// glBlendFuncSeparate (OpenGL 1.4), which libOSMesa exports.
#define GL_GLEXT_PROTOTYPES 1
#include <GL/osmesa.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#ifdef MEFF_SANITIZE
// Mesa's OSMesa keeps the framebuffers OSMesaMakeCurrent creates in a global list it never frees
// (not ours to fix); LeakSanitizer would fail every program that renders. Hide only those.
extern "C" const char* __lsan_default_suppressions()
{
    return "leak:libOSMesa.so\n";
}
// Without this LeakSanitizer lists the suppressions it used on stderr at exit, after the one-line
// error a refused render prints (render.bad_input.follow_unknown_body reads stderr whole).
extern "C" const char* __lsan_default_options()
{
    return "print_suppressions=0";
}
#endif

namespace meff::render
{

namespace
{

/// Past this many supersampled pixels, supersampling is lowered: a 8192² image at 3× would
/// need 2.4 GB of colour buffer.
constexpr long long kMaxBufferPixels = 64LL * 1024 * 1024;

std::uint8_t ToByte(float component)
{
    return std::uint8_t(std::lround(std::clamp(component, 0.0f, 1.0f) * 255.0f));
}

/// Draws a frame's triangles through the current GL context, in world coordinates.
void DrawTriangles(std::span<const ColoredVertex> vertices)
{
    glBegin(GL_TRIANGLES);
    for (const ColoredVertex& v : vertices)
    {
        glColor4f(v.color.r, v.color.g, v.color.b, v.color.a);
        glVertex2d(v.x, v.y);
    }
    glEnd();
}

} // namespace

Rgb ToRgb(const DrawColor& color)
{
    return {ToByte(color.r), ToByte(color.g), ToByte(color.b)};
}

Rgb FillColor(const DrawColor& color)
{
    const auto lighten = [](float c) { return ToByte(0.5f * c + 0.5f); };
    return {lighten(color.r), lighten(color.g), lighten(color.b)};
}

std::optional<AABB> BodyBounds(const World& world, BodyId body)
{
    std::optional<AABB> bounds;
    for (const ShapeId shape : world.GetShapes(body))
    {
        const AABB box = world.GetShapeAABB(shape);
        bounds = bounds ? Combine(*bounds, box) : box;
    }
    return bounds;
}

std::optional<AABB> WorldBounds(const World& world)
{
    std::optional<AABB> bounds;
    for (const BodyId body : world.GetBodies())
    {
        if (const std::optional<AABB> box = BodyBounds(world, body))
        {
            bounds = bounds ? Combine(*bounds, *box) : *box;
        }
    }
    return bounds;
}

Camera FitCamera(const AABB& bounds, int width, int height)
{
    const double aspect = double(width) / double(height);
    const double boundsWidth = double(bounds.upperBound.x) - double(bounds.lowerBound.x);
    const double boundsHeight = double(bounds.upperBound.y) - double(bounds.lowerBound.y);
    // A margin of 10% of the view on every side (room for the caption at the top), and at
    // least a metre so that a lone point still shows something.
    const double view = std::max({boundsHeight, boundsWidth / aspect, 1.0}) / 0.8;
    return Camera{bounds.GetCenter(), Real(view)};
}

Camera FitCamera(const World& world, int width, int height)
{
    const std::optional<AABB> bounds = WorldBounds(world);
    return bounds ? FitCamera(*bounds, width, height) : Camera{};
}

FollowCamera::FollowCamera(const World& world, BodyId body, Real height, double aspect,
                           double timeConstant)
    : m_body(body), m_aspect(aspect), m_timeConstant(timeConstant)
{
    const std::optional<AABB> box = BodyBounds(world, body);
    m_camera = Camera{box ? box->GetCenter() : world.GetPosition(body), height};
}

const Camera& FollowCamera::Update(const World& world, double dt)
{
    const std::optional<AABB> box = BodyBounds(world, m_body);
    if (!box)
    {
        return m_camera;
    }
    // Exact exponential easing over dt: the same motion whatever the step.
    const double keep = m_timeConstant > 0 ? std::exp(-dt / m_timeConstant) : 0.0;
    const Vec2 target = box->GetCenter();
    m_camera.center =
        Vec2{Real(double(target.x) + (double(m_camera.center.x) - double(target.x)) * keep),
             Real(double(target.y) + (double(m_camera.center.y) - double(target.y)) * keep)};
    KeepInside(*box);
    return m_camera;
}

void FollowCamera::KeepInside(const AABB& box)
{
    // On each axis, the box must stay within the middle 80 % of the view.
    const auto keep = [](double center, double half, double low, double high)
    {
        const double inner = 0.8 * half;
        if (high - low >= 2 * inner)
        {
            return 0.5 * (low + high);
        }
        center = std::max(center, high - inner);
        return std::min(center, low + inner);
    };
    const double halfHeight = 0.5 * double(m_camera.height);
    m_camera.center.x = Real(keep(double(m_camera.center.x), halfHeight * m_aspect,
                                  double(box.lowerBound.x), double(box.upperBound.x)));
    m_camera.center.y = Real(keep(double(m_camera.center.y), halfHeight, double(box.lowerBound.y),
                                  double(box.upperBound.y)));
}

double LineWidth(int width, int height)
{
    return std::max(1.0, std::min(width, height) / 480.0);
}

struct OffscreenRenderer::Impl
{
    OSMesaContext context = nullptr;
    int width = 0;
    int height = 0;
    int supersample = 1;
    std::vector<std::uint8_t> buffer; ///< RGBA, bottom row first (OSMesa's default)
    Camera camera;
    bool transparent = false;
    TriangleDraw draw;

    Projection View() const { return Projection{camera, width, height}; }

    int BufferWidth() const { return width * supersample; }
    int BufferHeight() const { return height * supersample; }

    void MakeCurrent()
    {
        if (!OSMesaMakeCurrent(context, buffer.data(), GL_UNSIGNED_BYTE, BufferWidth(),
                               BufferHeight()))
        {
            throw RenderError("cannot make the OSMesa context current (" +
                              std::to_string(BufferWidth()) + "×" + std::to_string(BufferHeight()) +
                              " pixels)");
        }
    }

    /// Leaves this thread with no current context. A context may be current on one thread at a
    /// time, and render's threads take turns with the renderers (a frame may be drawn on another
    /// thread than the last): a context still current on the thread that drew the last frame
    /// while another thread makes it current crashed or hung OSMesa 22 (llvmpipe), about one
    /// render in 30 with two threads.
    static void Release() { OSMesaMakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0); }
};

OffscreenRenderer::OffscreenRenderer(int width, int height, int supersample)
    : m_impl(std::make_unique<Impl>())
{
    if (width < 1 || height < 1 || width > kMaxImageSize || height > kMaxImageSize)
    {
        throw RenderError("image size must be between 1 and " + std::to_string(kMaxImageSize) +
                          " pixels each way, got " + std::to_string(width) + "x" +
                          std::to_string(height));
    }
    Impl& impl = *m_impl;
    impl.width = width;
    impl.height = height;
    // RGBA, no depth, stencil or accumulation buffer: everything is drawn in painter's order.
    impl.context = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, nullptr);
    if (impl.context == nullptr)
    {
        throw RenderError("cannot create an OSMesa context (is Mesa's libOSMesa working?)");
    }
    // The largest buffer OSMesa accepts is only known once a context is current, so start at
    // 1× to ask, then settle on the supersampling factor.
    impl.supersample = 1;
    impl.buffer.resize(std::size_t(width) * std::size_t(height) * 4);
    try
    {
        impl.MakeCurrent();
    }
    catch (...)
    {
        OSMesaDestroyContext(impl.context);
        throw;
    }
    GLint maxWidth = 0, maxHeight = 0;
    OSMesaGetIntegerv(OSMESA_MAX_WIDTH, &maxWidth);
    OSMesaGetIntegerv(OSMESA_MAX_HEIGHT, &maxHeight);
    GLint viewport[2] = {0, 0};
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
    maxWidth = std::min(maxWidth, viewport[0]);
    maxHeight = std::min(maxHeight, viewport[1]);
    if (width > maxWidth || height > maxHeight)
    {
        Impl::Release();
        OSMesaDestroyContext(impl.context);
        throw RenderError("OSMesa cannot draw " + std::to_string(width) + "x" +
                          std::to_string(height) + " pixels (its limit is " +
                          std::to_string(maxWidth) + "x" + std::to_string(maxHeight) + ")");
    }
    int factor = std::max(1, supersample);
    while (factor > 1 && (width * factor > maxWidth || height * factor > maxHeight ||
                          (long long)width * height * factor * factor > kMaxBufferPixels))
    {
        --factor;
    }
    impl.supersample = factor;
    impl.buffer.assign(std::size_t(impl.BufferWidth()) * std::size_t(impl.BufferHeight()) * 4, 0);
    Impl::Release(); // BeginFrame makes it current on the thread that draws
}

OffscreenRenderer::~OffscreenRenderer()
{
    OSMesaDestroyContext(m_impl->context);
}

int OffscreenRenderer::Width() const
{
    return m_impl->width;
}
int OffscreenRenderer::Height() const
{
    return m_impl->height;
}
int OffscreenRenderer::Supersample() const
{
    return m_impl->supersample;
}

DebugDraw& OffscreenRenderer::BeginFrame(const Camera& camera, bool transparent)
{
    Impl& impl = *m_impl;
    impl.MakeCurrent();
    impl.camera = camera;
    impl.transparent = transparent;
    impl.draw.Clear();
    impl.draw.SetScale(double(PixelSize()), LineWidth(impl.width, impl.height));

    glViewport(0, 0, impl.BufferWidth(), impl.BufferHeight());
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_DITHER); // dithering would make colours depend on the pixel's position
    glEnable(GL_BLEND);
    // Colours blend by their opacity; the buffer's alpha accumulates coverage, so that with a
    // transparent background (cleared to zero) it holds premultiplied colours and their
    // opacity, which EndFrame averages down and divides out.
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glShadeModel(GL_FLAT);
    if (transparent)
    {
        glClearColor(0, 0, 0, 0);
    }
    else
    {
        glClearColor(kBackground.r / 255.0f, kBackground.g / 255.0f, kBackground.b / 255.0f, 1.0f);
    }
    glClear(GL_COLOR_BUFFER_BIT);

    const double halfHeight = 0.5 * double(camera.height);
    const double halfWidth = halfHeight * impl.width / impl.height;
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(double(camera.center.x) - halfWidth, double(camera.center.x) + halfWidth,
            double(camera.center.y) - halfHeight, double(camera.center.y) + halfHeight, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    return impl.draw;
}

Real OffscreenRenderer::PixelSize() const
{
    return Real(double(m_impl->camera.height) / m_impl->height);
}

Vec2 OffscreenRenderer::ScreenToWorld(double x, double y) const
{
    return m_impl->View().ToWorld(x, y);
}

Vec2 OffscreenRenderer::WorldToScreen(Vec2 point) const
{
    return m_impl->View().ToScreen(point);
}

Image OffscreenRenderer::EndFrame()
{
    Impl& impl = *m_impl;
    DrawTriangles(impl.draw.Triangles());
    impl.draw.Clear();
    glFinish(); // the buffer then holds the whole frame, and is ours alone
    Impl::Release();
    const int s = impl.supersample;
    const int bufferWidth = impl.BufferWidth();
    const int bufferHeight = impl.BufferHeight();
    const int samples = s * s;
    Image image(impl.width, impl.height);
    if (impl.transparent)
    {
        image.alpha.assign(std::size_t(impl.width) * std::size_t(impl.height), 0);
    }
    // A box filter over each s×s block, in integers (rounded): the same sums on every machine.
    std::vector<int> sums(std::size_t(impl.width) * 4);
    for (int y = 0; y < impl.height; ++y)
    {
        std::fill(sums.begin(), sums.end(), 0);
        // Image row y (from the top) comes from buffer rows counted from the bottom.
        const int firstRow = bufferHeight - (y + 1) * s;
        for (int row = firstRow; row < firstRow + s; ++row)
        {
            const std::uint8_t* source = impl.buffer.data() + std::size_t(row) * bufferWidth * 4;
            for (int x = 0; x < bufferWidth; ++x)
            {
                int* sum = &sums[std::size_t(x / s) * 4];
                for (int c = 0; c < 4; ++c)
                {
                    sum[c] += source[x * 4 + c];
                }
            }
        }
        const std::size_t rowStart = std::size_t(y) * std::size_t(impl.width);
        for (std::size_t x = 0; x < std::size_t(impl.width); ++x)
        {
            const int* sum = &sums[x * 4];
            std::uint8_t* target = image.pixels.data() + (rowStart + x) * 3;
            if (!impl.transparent)
            {
                for (int c = 0; c < 3; ++c)
                {
                    target[c] = std::uint8_t((sum[c] + samples / 2) / samples);
                }
                continue;
            }
            // Premultiplied sums: the colour is their ratio to the summed opacity.
            image.alpha[rowStart + x] = std::uint8_t((sum[3] + samples / 2) / samples);
            for (int c = 0; c < 3; ++c)
            {
                target[c] = sum[3] > 0
                                ? std::uint8_t(std::min(255, (sum[c] * 255 + sum[3] / 2) / sum[3]))
                                : std::uint8_t(0);
            }
        }
    }
    return image;
}

double NiceCeil(double value)
{
    const double power = std::pow(10.0, std::floor(std::log10(value)));
    for (const double step : {1.0, 2.0, 5.0, 10.0})
    {
        if (step * power >= value * (1 - 1e-9))
        {
            return step * power;
        }
    }
    return 10.0 * power;
}

std::vector<LegendEntry> PaletteLegend(const DrawFlags& flags)
{
    const DrawPalette& colors = flags.colors;
    return {{colors.staticBody, "static"},
            {colors.kinematicBody, "kinematic"},
            {colors.dynamicBody, "dynamic"},
            {colors.sleepingBody, "sleeping"},
            {colors.joint, "joint"},
            {colors.contactPoint, "contact point"},
            {colors.contactNormal, "contact normal"},
            {colors.contactImpulse, "contact impulse"},
            {colors.jointReaction, "joint reaction"},
            {colors.aabb, "AABB"},
            // DrawTransform's axes (Box2D's convention), which the GL draw colours itself.
            {DrawColor{1, 0, 0}, "x axis"},
            {DrawColor{0, 1, 0}, "y axis"}};
}

Image RenderFrame(OffscreenRenderer& renderer, const World& world, const FrameOptions& options)
{
    DrawList drawing;
    world.Draw(drawing, options.flags);
    if (options.overlay)
    {
        options.overlay(drawing);
    }
    return RenderFrame(renderer, drawing, options);
}

Image RenderFrame(OffscreenRenderer& renderer, const DrawList& drawing, const FrameOptions& options)
{
    DebugDraw& gl = renderer.BeginFrame(options.camera, options.transparent);
    ColorNotingDraw draw(gl);
    drawing.Replay(draw);
    const Projection view{options.camera, renderer.Width(), renderer.Height()};
    const FrameLayout layout = LayOutFrame(options, view, draw);
    DrawLegendArrow(gl, layout, options, view);
    Image image = renderer.EndFrame();
    PaintMarks(image, layout.marks);
    return image;
}

double NiceFloor(double value)
{
    const double ceil = NiceCeil(value);
    if (ceil <= value * (1 + 1e-9))
    {
        return ceil;
    }
    // One nice step down: 10 → 5, 5 → 2, 2 → 1 (times the power of ten).
    const double power = std::pow(10.0, std::floor(std::log10(ceil) + 1e-9));
    const double mantissa = ceil / power;
    return mantissa > 4.5 ? 2 * power : mantissa > 1.5 ? power : 0.5 * power;
}

} // namespace meff::render
