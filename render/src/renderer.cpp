// The OSMesa context, the OpenGL DebugDraw, and a whole frame.
//
// Legacy fixed-function OpenGL is all this needs: a few thousand flat-coloured triangles per
// frame, which Mesa's software rasterizer draws in milliseconds. Lines are drawn as triangles
// (not GL lines) so that their width is exact and the same on every Mesa driver; edges are
// smoothed by drawing at `supersample`× the size and averaging down on the CPU, which, unlike
// GL multisampling, gives the same bytes whatever the driver's sample pattern.
#include "meff/render.h"

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
#endif

namespace meff::render
{

namespace
{

/// Past this many supersampled pixels, supersampling is lowered: a 8192² image at 3× would
/// need 2.4 GB of colour buffer.
constexpr long long kMaxBufferPixels = 64LL * 1024 * 1024;

/// A line is one output pixel wide; a shape's outline too.
constexpr double kLineWidth = 1.0;

std::uint8_t ToByte(float component)
{
    return std::uint8_t(std::lround(std::clamp(component, 0.0f, 1.0f) * 255.0f));
}

void SetColor(const DrawColor& color)
{
    glColor4f(color.r, color.g, color.b, color.a);
}

void Vertex(Vec2 p)
{
    glVertex2d(double(p.x), double(p.y));
}

/// Draws through the current GL context in world coordinates. Sizes given in pixels are
/// converted with `pixel`, the metres per output pixel.
class GLDebugDraw final : public DebugDraw
{
  public:
    void SetPixelSize(double pixel) { m_pixel = pixel; }

    void DrawPolygon(std::span<const Vec2> vertices, const DrawColor& color) override
    {
        StrokeLoop(vertices, color);
    }

    void DrawSolidPolygon(std::span<const Vec2> vertices, const DrawColor& color) override
    {
        Fill(vertices, FillOf(color));
        StrokeLoop(vertices, color);
    }

    void DrawCircle(Vec2 center, Real radius, const DrawColor& color) override
    {
        const std::vector<Vec2> loop = CirclePoints(center, double(radius));
        StrokeLoop(loop, color);
    }

    void DrawSolidCircle(Vec2 center, Real radius, Vec2 axis, const DrawColor& color) override
    {
        const std::vector<Vec2> loop = CirclePoints(center, double(radius));
        Fill(loop, FillOf(color));
        StrokeLoop(loop, color);
        DrawSegment(center, center + radius * axis, color);
    }

    void DrawSegment(Vec2 p1, Vec2 p2, const DrawColor& color) override
    {
        const double dx = double(p2.x) - double(p1.x);
        const double dy = double(p2.y) - double(p1.y);
        const double length = std::sqrt(dx * dx + dy * dy);
        const double half = 0.5 * kLineWidth * m_pixel;
        // Square caps (the line extended by half its width): joins of separate segments, such
        // as an arrow's head, then close without notches.
        const double ux = length > 0 ? dx / length * half : half;
        const double uy = length > 0 ? dy / length * half : 0;
        const double ax = double(p1.x) - ux, ay = double(p1.y) - uy;
        const double bx = double(p2.x) + ux, by = double(p2.y) + uy;
        SetColor(color);
        glBegin(GL_TRIANGLE_STRIP);
        glVertex2d(ax - uy, ay + ux);
        glVertex2d(ax + uy, ay - ux);
        glVertex2d(bx - uy, by + ux);
        glVertex2d(bx + uy, by - ux);
        glEnd();
    }

    void DrawTransform(const Transform& xf) override
    {
        // Box2D's testbed axis length.
        const Real axisLength = Real(0.4);
        DrawSegment(xf.p, xf.p + axisLength * xf.q.GetXAxis(), DrawColor{1, 0, 0});
        DrawSegment(xf.p, xf.p + axisLength * xf.q.GetYAxis(), DrawColor{0, 1, 0});
    }

    void DrawPoint(Vec2 p, Real size, const DrawColor& color) override
    {
        Fill(CirclePoints(p, 0.5 * double(size) * m_pixel), color);
    }

  private:
    static DrawColor FillOf(const DrawColor& color)
    {
        const Rgb fill = FillColor(color);
        return {fill.r / 255.0f, fill.g / 255.0f, fill.b / 255.0f, color.a};
    }

    /// A circle as a polygon fine enough that its facets vanish at output resolution.
    std::vector<Vec2> CirclePoints(Vec2 center, double radius) const
    {
        const double radiusPixels = radius / m_pixel;
        const int count = std::clamp(int(std::ceil(radiusPixels)) + 16, 16, 128);
        std::vector<Vec2> points(static_cast<std::size_t>(count));
        for (int i = 0; i < count; ++i)
        {
            const double angle = 2.0 * 3.14159265358979323846 * i / count;
            points[std::size_t(i)] = Vec2{Real(double(center.x) + radius * std::cos(angle)),
                                          Real(double(center.y) + radius * std::sin(angle))};
        }
        return points;
    }

    static void Fill(std::span<const Vec2> vertices, const DrawColor& color)
    {
        SetColor(color);
        glBegin(GL_TRIANGLE_FAN);
        for (const Vec2 v : vertices)
        {
            Vertex(v);
        }
        glEnd();
    }

    /// A closed outline as one band of triangles between the loop offset inwards and
    /// outwards by half the line width, mitred at the corners: exact width, no gaps or
    /// overlaps at the joins (which would show with translucent colours).
    void StrokeLoop(std::span<const Vec2> vertices, const DrawColor& color) const
    {
        const std::size_t n = vertices.size();
        if (n < 2)
        {
            return;
        }
        double area = 0;
        for (std::size_t i = 0; i < n; ++i)
        {
            const Vec2 a = vertices[i], b = vertices[(i + 1) % n];
            area += double(a.x) * double(b.y) - double(b.x) * double(a.y);
        }
        // Outward is to the right of the edges of a counter-clockwise loop.
        const double side = area >= 0 ? 1.0 : -1.0;
        const double half = 0.5 * kLineWidth * m_pixel;
        const auto normal = [&](std::size_t i, double& nx, double& ny)
        {
            const Vec2 a = vertices[i % n], b = vertices[(i + 1) % n];
            const double dx = double(b.x) - double(a.x), dy = double(b.y) - double(a.y);
            const double length = std::sqrt(dx * dx + dy * dy);
            nx = length > 0 ? side * dy / length : 0;
            ny = length > 0 ? -side * dx / length : 0;
        };
        SetColor(color);
        glBegin(GL_TRIANGLE_STRIP);
        for (std::size_t i = 0; i <= n; ++i)
        {
            double n0x, n0y, n1x, n1y;
            normal(i + n - 1, n0x, n0y);
            normal(i, n1x, n1y);
            double mx = n0x + n1x, my = n0y + n1y;
            const double m = std::sqrt(mx * mx + my * my);
            // The mitre is 1/cos(half the turn) long; capped so a needle-sharp corner does not
            // shoot a spike across the image.
            double scale = half;
            if (m > 1e-9)
            {
                mx /= m;
                my /= m;
                scale = half / std::max(mx * n1x + my * n1y, 0.25);
            }
            else
            {
                mx = n1x;
                my = n1y;
            }
            const Vec2 v = vertices[i % n];
            glVertex2d(double(v.x) + mx * scale, double(v.y) + my * scale);
            glVertex2d(double(v.x) - mx * scale, double(v.y) - my * scale);
        }
        glEnd();
    }

    double m_pixel = 0.01;
};

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

Camera FitCamera(const World& world, int width, int height)
{
    bool any = false;
    AABB bounds;
    for (const BodyId body : world.GetBodies())
    {
        const Transform xf = world.GetTransform(body);
        for (const ShapeId shape : world.GetShapes(body))
        {
            AABB box;
            switch (world.GetShapeType(shape))
            {
            case ShapeType::Circle:
                box = ComputeAABB(world.GetCircle(shape), xf);
                break;
            case ShapeType::Polygon:
                box = ComputeAABB(world.GetPolygon(shape), xf);
                break;
            case ShapeType::Segment:
                box = ComputeAABB(world.GetSegment(shape), xf);
                break;
            case ShapeType::ChainSegment:
                box = ComputeAABB(world.GetChainSegment(shape), xf);
                break;
            case ShapeType::Capsule:
                box = ComputeAABB(world.GetCapsule(shape), xf);
                break;
            }
            bounds = any ? Combine(bounds, box) : box;
            any = true;
        }
    }
    if (!any)
    {
        return Camera{};
    }
    const double aspect = double(width) / double(height);
    const double boundsWidth = double(bounds.upperBound.x) - double(bounds.lowerBound.x);
    const double boundsHeight = double(bounds.upperBound.y) - double(bounds.lowerBound.y);
    // A margin of 10% of the view on every side (room for the caption at the top), and at
    // least a metre so that a lone point still shows something.
    const double view = std::max({boundsHeight, boundsWidth / aspect, 1.0}) / 0.8;
    return Camera{bounds.GetCenter(), Real(view)};
}

struct OffscreenRenderer::Impl
{
    OSMesaContext context = nullptr;
    int width = 0;
    int height = 0;
    int supersample = 1;
    std::vector<std::uint8_t> buffer; ///< RGBA, bottom row first (OSMesa's default)
    Camera camera;
    GLDebugDraw draw;

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

DebugDraw& OffscreenRenderer::BeginFrame(const Camera& camera)
{
    Impl& impl = *m_impl;
    impl.MakeCurrent();
    impl.camera = camera;
    impl.draw.SetPixelSize(double(PixelSize()));

    glViewport(0, 0, impl.BufferWidth(), impl.BufferHeight());
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_DITHER); // dithering would make colours depend on the pixel's position
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glShadeModel(GL_FLAT);
    glClearColor(kBackground.r / 255.0f, kBackground.g / 255.0f, kBackground.b / 255.0f, 1.0f);
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
    const Impl& impl = *m_impl;
    const double pixel = double(impl.camera.height) / impl.height;
    return Vec2{Real(double(impl.camera.center.x) + (x - 0.5 * impl.width) * pixel),
                Real(double(impl.camera.center.y) + (0.5 * impl.height - y) * pixel)};
}

Image OffscreenRenderer::EndFrame()
{
    Impl& impl = *m_impl;
    glFinish(); // the buffer then holds the whole frame, and is ours alone
    Impl::Release();
    const int s = impl.supersample;
    const int bufferWidth = impl.BufferWidth();
    const int bufferHeight = impl.BufferHeight();
    const int samples = s * s;
    Image image(impl.width, impl.height);
    // A box filter over each s×s block, in integers (rounded): the same sums on every machine.
    std::vector<int> sums(std::size_t(impl.width) * 3);
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
                int* sum = &sums[std::size_t(x / s) * 3];
                sum[0] += source[x * 4];
                sum[1] += source[x * 4 + 1];
                sum[2] += source[x * 4 + 2];
            }
        }
        std::uint8_t* target = image.pixels.data() + std::size_t(y) * impl.width * 3;
        for (std::size_t i = 0; i < sums.size(); ++i)
        {
            target[i] = std::uint8_t((sums[i] + samples / 2) / samples);
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

namespace
{

bool SameColor(const DrawColor& a, const DrawColor& b)
{
    return a.r == b.r && a.g == b.g && a.b == b.b;
}

/// Passes every call on, noting which colours were drawn.
class ColorNotingDraw final : public DebugDraw
{
  public:
    explicit ColorNotingDraw(DebugDraw& target) : m_target(target) {}

    void DrawPolygon(std::span<const Vec2> vertices, const DrawColor& color) override
    {
        Note(color);
        m_target.DrawPolygon(vertices, color);
    }
    void DrawSolidPolygon(std::span<const Vec2> vertices, const DrawColor& color) override
    {
        Note(color);
        m_target.DrawSolidPolygon(vertices, color);
    }
    void DrawCircle(Vec2 center, Real radius, const DrawColor& color) override
    {
        Note(color);
        m_target.DrawCircle(center, radius, color);
    }
    void DrawSolidCircle(Vec2 center, Real radius, Vec2 axis, const DrawColor& color) override
    {
        Note(color);
        m_target.DrawSolidCircle(center, radius, axis, color);
    }
    void DrawSegment(Vec2 p1, Vec2 p2, const DrawColor& color) override
    {
        Note(color);
        m_target.DrawSegment(p1, p2, color);
    }
    void DrawTransform(const Transform& xf) override
    {
        Note(DrawColor{1, 0, 0});
        Note(DrawColor{0, 1, 0});
        m_target.DrawTransform(xf);
    }
    void DrawPoint(Vec2 p, Real size, const DrawColor& color) override
    {
        Note(color);
        m_target.DrawPoint(p, size, color);
    }

    bool Used(const DrawColor& color) const
    {
        return std::any_of(m_used.begin(), m_used.end(),
                           [&](const DrawColor& used) { return SameColor(used, color); });
    }

  private:
    void Note(const DrawColor& color)
    {
        if (!Used(color))
        {
            m_used.push_back(color);
        }
    }

    DebugDraw& m_target;
    std::vector<DrawColor> m_used;
};

/// Swatches and labels along the bottom edge, wrapping onto more rows when they do not fit,
/// on a translucent backing.
void DrawColorLegend(Image& image, const std::vector<LegendEntry>& entries, int pixelSize,
                     int margin)
{
    if (entries.empty())
    {
        return;
    }
    const int lineHeight = TextHeight(pixelSize);
    const int swatch = std::max(6, lineHeight * 2 / 3);
    const int rowHeight = lineHeight + margin;
    // Lay out first, to know how many rows there are.
    std::vector<std::pair<int, int>> places; // x, row
    int x = margin;
    int row = 0;
    int widest = 0;
    for (const LegendEntry& entry : entries)
    {
        const int width = swatch + margin + TextWidth(entry.label, pixelSize);
        if (x > margin && x + width > image.width - margin)
        {
            x = margin;
            ++row;
        }
        places.emplace_back(x, row);
        x += width + 3 * margin;
        widest = std::max(widest, x - 2 * margin);
    }
    const int rows = row + 1;
    const int top = image.height - rows * rowHeight - margin;
    FillRect(image, 0, top - margin, std::min(image.width, widest + margin),
             rows * rowHeight + 2 * margin, kBackground, 0.75);
    for (std::size_t i = 0; i < entries.size(); ++i)
    {
        const auto [left, r] = places[i];
        const int y = top + r * rowHeight;
        const int swatchTop = y + (lineHeight - swatch) / 2;
        const Rgb outline = ToRgb(entries[i].color);
        FillRect(image, left, swatchTop, swatch, swatch, outline, 1.0);
        FillRect(image, left + 1, swatchTop + 1, swatch - 2, swatch - 2,
                 FillColor(entries[i].color), 1.0);
        DrawText(image, left + swatch + margin, y, entries[i].label, kTextColor, pixelSize);
    }
}

} // namespace

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
    DebugDraw& gl = renderer.BeginFrame(options.camera);
    ColorNotingDraw draw(gl);
    drawing.Replay(draw);

    // Text is about 1/34 of the image's height (at least 9 pixels, legible), ...
    int pixelSize = std::clamp(renderer.Height() / 34, 9, 48);
    // ...but the caption never wider than the image, if a smaller size fits.
    while (pixelSize > 9 && TextWidth(options.caption, pixelSize) + pixelSize > renderer.Width())
    {
        --pixelSize;
    }
    const int margin = std::max(2, pixelSize / 4);
    const int lineHeight = TextHeight(pixelSize) + 2 * margin;
    const int legendTop = lineHeight;
    std::string legendLabel;
    int arrowLeft = 0;
    int arrowLength = 0;
    if (options.legendImpulse)
    {
        const std::string prefix = "impulse";
        arrowLeft = margin + TextWidth(prefix, pixelSize) + 2 * margin;
        arrowLength = int(std::lround(*options.legendImpulse * double(options.flags.impulseScale) /
                                      double(renderer.PixelSize())));
        char value[64];
        std::snprintf(value, sizeof value, "= %g N\xC2\xB7s", *options.legendImpulse);
        legendLabel = value;
        const double y = legendTop + margin + 0.5 * TextHeight(pixelSize);
        DrawArrow(gl, renderer.ScreenToWorld(arrowLeft, y),
                  renderer.ScreenToWorld(arrowLeft + arrowLength, y), options.flags.arrowHead,
                  DrawColor{kTextColor.r / 255.0f, kTextColor.g / 255.0f, kTextColor.b / 255.0f});
    }

    Image image = renderer.EndFrame();
    if (!options.caption.empty())
    {
        FillRect(image, 0, 0, TextWidth(options.caption, pixelSize) + 2 * margin, lineHeight,
                 kBackground, 0.75);
        DrawText(image, margin, margin, options.caption, kTextColor, pixelSize);
    }
    if (options.legendImpulse)
    {
        DrawText(image, margin, legendTop + margin, "impulse", kTextColor, pixelSize);
        DrawText(image, arrowLeft + arrowLength + 2 * margin, legendTop + margin, legendLabel,
                 kTextColor, pixelSize);
    }
    // Every colour the frame used, said once: the palette's, then the overlay's.
    std::vector<LegendEntry> used;
    std::vector<LegendEntry> candidates = PaletteLegend(options.flags);
    candidates.insert(candidates.end(), options.overlayLegend.begin(), options.overlayLegend.end());
    for (const LegendEntry& entry : candidates)
    {
        const bool listed =
            std::any_of(used.begin(), used.end(),
                        [&](const LegendEntry& e) { return SameColor(e.color, entry.color); });
        if (draw.Used(entry.color) && !listed)
        {
            used.push_back(entry);
        }
    }
    DrawColorLegend(image, used, pixelSize, margin);
    return image;
}

} // namespace meff::render
