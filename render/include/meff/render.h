// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Off-screen rendering of a World to images and PNG files, with no display and no GPU: OpenGL
// through OSMesa (Mesa's software rasterizer) into memory, drawn through the engine's DebugDraw
// interface, supersampled and averaged down on the CPU for anti-aliasing. Everything here is
// deterministic: the same world, camera and options give the same bytes.
#pragma once

#include "meff/debug_draw.h"
#include "meff/error.h"
#include "meff/world.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace meff::render
{

/// Rendering could not be done: no OSMesa context, a size it cannot handle, a PNG that cannot
/// be written or read.
class RenderError : public Error
{
  public:
    using Error::Error;
};

/// The largest width or height of an image (pixels).
inline constexpr int kMaxImageSize = 8192;

struct Rgb
{
    std::uint8_t r = 0;
    std::uint8_t g = 0;
    std::uint8_t b = 0;
    friend bool operator==(Rgb, Rgb) = default;
};

/// The colour behind everything.
inline constexpr Rgb kBackground{248, 248, 245};
/// The caption and legend text.
inline constexpr Rgb kTextColor{40, 40, 40};

/// An 8-bit RGB image, rows top to bottom (as PNG stores them), opaque or with an alpha plane
/// (a frame drawn with FrameOptions::transparent).
struct Image
{
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> pixels; ///< width·height·3 bytes
    /// Empty: every pixel opaque. Else width·height opacities (0 transparent, 255 opaque), the
    /// colours in `pixels` not premultiplied by them (as PNG stores them).
    std::vector<std::uint8_t> alpha;

    Image() = default;
    Image(int width_, int height_, Rgb fill = kBackground);
    Rgb At(int x, int y) const;
    void Set(int x, int y, Rgb color);
    bool HasAlpha() const { return !alpha.empty(); }
    /// 255 for an opaque image.
    std::uint8_t AlphaAt(int x, int y) const;
    /// Lays `color` over pixel (x, y) at opacity weight/scale (0 ≤ weight ≤ scale): a plain
    /// mix for an opaque image, Porter-Duff "over" with an alpha plane.
    void Blend(int x, int y, Rgb color, int weight, int scale);
};

/// The colour a filled shape of DebugDraw colour `color` gets: half way to white, opaque, so
/// that the outline (drawn in `color` itself) and the angle line stand out against the fill.
Rgb FillColor(const DrawColor& color);
/// `color` as 8-bit RGB (rounded), ignoring its opacity.
Rgb ToRgb(const DrawColor& color);

/// What the image shows: a world rectangle `height` metres tall centred on `center`; its width
/// follows from the image's aspect ratio.
struct Camera
{
    Vec2 center{};
    Real height = 10; ///< m, > 0
};

/// The box around every shape of `body` (World::GetShapeAABB: skin included), or nullopt for a
/// body without shapes.
std::optional<AABB> BodyBounds(const World& world, BodyId body);
/// The box around every shape of the world as it is now, or nullopt for a world without shapes.
std::optional<AABB> WorldBounds(const World& world);
/// A camera that shows `bounds` whole, centred, with a margin of a tenth of the view on every
/// side (and at least 1.25 m tall, so that a lone point still shows something).
Camera FitCamera(const AABB& bounds, int width, int height);
/// A camera that shows every shape of the world as it is now, with a margin.
Camera FitCamera(const World& world, int width, int height);

/// A camera that follows one body: its centre eases towards the body's (a first-order lag of
/// `timeConstant` seconds, so that the picture does not jitter with the body), but never so far
/// behind that the body's box leaves the middle 80 % of the view on either axis; a body too big
/// for that is centred. The height stays as given.
class FollowCamera
{
  public:
    /// Starts centred on `body` (which must have a shape), showing `height` metres at
    /// `aspect` (image width / height).
    FollowCamera(const World& world, BodyId body, Real height, double aspect,
                 double timeConstant = 0.3);
    /// The camera after `dt` seconds more of the body's motion (the world as it is now).
    const Camera& Update(const World& world, double dt);
    const Camera& Current() const { return m_camera; }

  private:
    void KeepInside(const AABB& box);

    BodyId m_body;
    Camera m_camera;
    double m_aspect;
    double m_timeConstant;
};

/// Lines (outlines, segments, arrows' shafts) in an image of this size are this many pixels
/// wide: 1 up to 480 pixels (the shorter side), growing in proportion beyond, so that a
/// 1080p frame reads like a 480p one.
double LineWidth(int width, int height);

/// A corner of a triangle: a world point and its colour.
struct ColoredVertex
{
    double x = 0;
    double y = 0;
    DrawColor color{};
};

/// DebugDraw as coloured triangles in world coordinates, three vertices each, in drawing order:
/// fills as fans, outlines and segments as bands `lineWidth` output pixels wide (mitred corners,
/// square caps), circles with facets too fine to see, points `size` output pixels across. What
/// OffscreenRenderer draws, and what a window (meff view) uploads, so that both show the same
/// geometry.
class TriangleDraw final : public DebugDraw
{
  public:
    /// `pixel`: metres per output pixel; `lineWidth`: output pixels.
    void SetScale(double pixel, double lineWidth);
    const std::vector<ColoredVertex>& Triangles() const { return m_vertices; }
    void Clear();

    void DrawPolygon(std::span<const Vec2> vertices, const DrawColor& color) override;
    void DrawSolidPolygon(std::span<const Vec2> vertices, const DrawColor& color) override;
    void DrawCircle(Vec2 center, Real radius, const DrawColor& color) override;
    void DrawSolidCircle(Vec2 center, Real radius, Vec2 axis, const DrawColor& color) override;
    void DrawSegment(Vec2 p1, Vec2 p2, const DrawColor& color) override;
    void DrawTransform(const Transform& xf) override;
    void DrawPoint(Vec2 p, Real size, const DrawColor& color) override;

  private:
    static DrawColor FillOf(const DrawColor& color);
    std::vector<Vec2> CirclePoints(Vec2 center, double radius) const;
    void Fill(std::span<const Vec2> vertices, const DrawColor& color);
    void Strip(std::span<const ColoredVertex> strip);
    void StrokeLoop(std::span<const Vec2> vertices, const DrawColor& color);

    std::vector<ColoredVertex> m_vertices;
    double m_pixel = 0.01;
    double m_lineWidth = 1;
};

/// An OSMesa context and its colour buffer, `width`×`height` output pixels drawn at
/// `supersample`× that size. Makes itself current when a frame begins.
class OffscreenRenderer
{
  public:
    /// Throws RenderError if the size is out of range or no OSMesa context can be made.
    /// `supersample` is lowered (down to 1) if the larger buffer would exceed OSMesa's limits
    /// or a sensible amount of memory.
    OffscreenRenderer(int width, int height, int supersample = 3);
    ~OffscreenRenderer();
    OffscreenRenderer(const OffscreenRenderer&) = delete;
    OffscreenRenderer& operator=(const OffscreenRenderer&) = delete;

    int Width() const;
    int Height() const;
    int Supersample() const;

    /// Clears to kBackground (to nothing with `transparent`) and returns a DebugDraw that
    /// draws in world coordinates through `camera`. Lines are LineWidth output pixels wide,
    /// points `size` output pixels across.
    DebugDraw& BeginFrame(const Camera& camera, bool transparent = false);
    /// Metres per output pixel under the current camera.
    Real PixelSize() const;
    /// The world point under output pixel (x, y), counted from the top-left corner.
    Vec2 ScreenToWorld(double x, double y) const;
    /// The output pixel (x from the left, y from the top) of a world point.
    Vec2 WorldToScreen(Vec2 point) const;
    /// Finishes drawing and returns the image, averaged down from the supersampled buffer;
    /// with an alpha plane when the frame began transparent.
    Image EndFrame();

  private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

/// A frame's drawing recorded (World::Draw, overlays) to be drawn later, on another thread or
/// more than once: Replay makes the same calls, with the same numbers, in the same order, so
/// an image drawn from it is the image drawn from the world itself.
class DrawList final : public DebugDraw
{
  public:
    void DrawPolygon(std::span<const Vec2> vertices, const DrawColor& color) override;
    void DrawSolidPolygon(std::span<const Vec2> vertices, const DrawColor& color) override;
    void DrawCircle(Vec2 center, Real radius, const DrawColor& color) override;
    void DrawSolidCircle(Vec2 center, Real radius, Vec2 axis, const DrawColor& color) override;
    void DrawSegment(Vec2 p1, Vec2 p2, const DrawColor& color) override;
    void DrawTransform(const Transform& xf) override;
    void DrawPoint(Vec2 p, Real size, const DrawColor& color) override;

    void Replay(DebugDraw& draw) const;
    std::size_t Size() const { return m_commands.size(); }

  private:
    enum class Kind
    {
        Polygon,
        SolidPolygon,
        Circle,
        SolidCircle,
        Segment,
        Transform,
        Point,
    };
    struct Command
    {
        Kind kind = Kind::Segment;
        DrawColor color{};
        Vec2 a{};              ///< centre, first point, or the transform's position
        Vec2 b{};              ///< axis, second point, or the transform's (cos, sin)
        Real value = 0;        ///< radius or point size
        std::size_t first = 0; ///< polygons: their vertices in m_points
        std::size_t count = 0;
    };
    void Add(Kind kind, std::span<const Vec2> vertices, const DrawColor& color);

    std::vector<Command> m_commands;
    std::vector<Vec2> m_points;
};

/// A colour the legend may explain, and what it stands for.
struct LegendEntry
{
    DrawColor color{};
    std::string label{};
};

/// The legend entries of `flags.colors`: body types, sleeping bodies, joints, contact points
/// and normals, impulses, reactions, AABBs and the centre-of-mass axes.
std::vector<LegendEntry> PaletteLegend(const DrawFlags& flags);

/// One frame: what to draw on top of the world and the text to print.
struct FrameOptions
{
    Camera camera{};
    DrawFlags flags{};
    /// Drawn after the world, through the same DebugDraw (e.g. another engine's bodies).
    std::function<void(DebugDraw&)> overlay{};
    std::string caption{}; ///< the text line at the top left; UTF-8
    /// With a value: a legend under the caption, an arrow standing for this impulse (N·s)
    /// drawn at flags.impulseScale, so arrows in the image can be read off against it.
    std::optional<double> legendImpulse{};
    /// Colours the overlay draws, for the legend (PaletteLegend(flags) covers World::Draw's).
    std::vector<LegendEntry> overlayLegend{};
    /// The colour legend, the impulse arrow's legend and the scale bar (bottom right: a bar of
    /// a round length near a fifth of the image's width, with its length written beside it).
    bool legend = true;
    /// No background: pixels nothing was drawn on are fully transparent (an RGBA PNG).
    bool transparent = false;
};

/// Draws `world` (World::Draw), the overlay, the legend arrow and the text into one image:
/// records the drawing into a DrawList and renders that.
Image RenderFrame(OffscreenRenderer& renderer, const World& world, const FrameOptions& options);
/// Draws a recorded frame (`drawing`: the world and its overlay; options.overlay is not
/// called), then the caption, the impulse arrow and the colour legend: a swatch and a label for
/// every legend colour (PaletteLegend(options.flags), then options.overlayLegend) that the
/// drawing used, in that order, along the bottom edge.
Image RenderFrame(OffscreenRenderer& renderer, const DrawList& drawing,
                  const FrameOptions& options);

/// The same frame as SVG (for figures): the same camera, shapes, lines and text as
/// RenderFrame's image of `width`×`height` pixels, as vectors in pixel coordinates (origin top
/// left). Deterministic: the same drawing gives the same text.
std::string RenderSvg(const DrawList& drawing, const FrameOptions& options, int width, int height);
/// Writes `text` to `path` whole or not at all (a temporary file renamed into place). Throws
/// RenderError.
void WriteFileAtomically(const std::string& path, std::string_view text);

/// A "nice" value (1, 2 or 5 times a power of ten) at least `value` (> 0).
double NiceCeil(double value);
/// A "nice" value (1, 2 or 5 times a power of ten) at most `value` (> 0).
double NiceFloor(double value);

// Text: DejaVu Sans (Debian's fonts-dejavu-core, the file CMake found when meff was built,
// FontPath()) drawn through FreeType, anti-aliased, at `pixelSize` pixels per em. Text is UTF-8.
// Safe to call from several threads (one FreeType face, behind a lock). Throws RenderError when
// the font cannot be loaded.
/// Width in pixels of `text` at `pixelSize` (the pen's advance, whole pixels per glyph).
int TextWidth(std::string_view text, int pixelSize);
/// Height in pixels of a line of text at `pixelSize`: the font's ascender to its descender.
int TextHeight(int pixelSize);
/// Pixels from the top of a line of text at `pixelSize` to its baseline (the font's ascender).
int TextAscent(int pixelSize);
/// Draws `text` with the top-left corner of its line at (x, y), blending the glyphs' coverage
/// over the image; pixels outside the image are skipped.
void DrawText(Image& image, int x, int y, std::string_view text, Rgb color, int pixelSize);
/// The font file text is drawn with.
const std::string& FontPath();
/// Blends `color` over a rectangle at opacity `alpha` in [0, 1] (a backing for text).
void FillRect(Image& image, int x, int y, int width, int height, Rgb color, double alpha);

// PNG files (libpng), 8-bit RGB (RGBA for an image with alpha), no time stamp or other varying
// chunk: the same image always encodes to the same bytes.
std::vector<std::uint8_t> EncodePng(const Image& image);
/// Throws RenderError with libpng's reason.
Image DecodePng(std::span<const std::uint8_t> bytes);
Image ReadPng(const std::string& path);
/// Writes to a temporary file beside `path` and renames it into place: the file appears whole
/// or not at all. Throws RenderError.
void WritePng(const std::string& path, const Image& image);

/// The colour between stitched frames: darker than kBackground, so frames stay apart.
inline constexpr Rgb kGapColor{200, 200, 200};
/// Places images side by side, top-aligned, `gap` pixels apart, on `gapColor`.
Image StitchHorizontally(std::span<const Image> images, int gap, Rgb gapColor = kGapColor);

} // namespace meff::render
