// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// What a frame draws besides the world, laid out once in output pixels and painted either
// into an image (renderer.cpp) or as SVG (svg.cpp), so that both show the same frame.
#pragma once

#include "meff/render.h"

#include <string>
#include <vector>

namespace meff::render
{

/// The camera's mapping between world points and output pixels (x from the left, y from the
/// top, pixel centres at half-integers).
struct Projection
{
    Camera camera;
    int width = 1;
    int height = 1;

    double PixelSize() const { return double(camera.height) / height; }
    Vec2 ToWorld(double x, double y) const
    {
        const double pixel = PixelSize();
        return Vec2{Real(double(camera.center.x) + (x - 0.5 * width) * pixel),
                    Real(double(camera.center.y) + (0.5 * height - y) * pixel)};
    }
    Vec2 ToScreen(Vec2 p) const
    {
        const double pixel = PixelSize();
        return Vec2{Real(0.5 * width + (double(p.x) - double(camera.center.x)) / pixel),
                    Real(0.5 * height - (double(p.y) - double(camera.center.y)) / pixel)};
    }
};

/// DrawTransform's picture: the x axis in red and the y axis in green, 0.4 m long (Box2D's
/// testbed).
void DrawAxes(DebugDraw& draw, const Transform& xf);

/// A rectangle blended over the frame, or a line of text (top-left corner at x, y).
struct Mark
{
    enum class Kind
    {
        Rect,
        Text,
    };
    Kind kind = Kind::Rect;
    int x = 0;
    int y = 0;
    int width = 0;  ///< Rect
    int height = 0; ///< Rect
    Rgb color{};
    double alpha = 1;  ///< Rect
    std::string text;  ///< Text, UTF-8
    int pixelSize = 9; ///< Text
};

/// Everything drawn over the world: the impulse arrow (in pixels, drawn with the world's lines)
/// and the marks, in painting order.
struct FrameLayout
{
    bool arrow = false;
    double arrowY = 0;
    double arrowLeft = 0;
    double arrowLength = 0;
    std::vector<Mark> marks;
};

/// Passes every call on, noting which colours were drawn.
class ColorNotingDraw final : public DebugDraw
{
  public:
    explicit ColorNotingDraw(DebugDraw& target) : m_target(target) {}

    void DrawPolygon(std::span<const Vec2> vertices, const DrawColor& color) override;
    void DrawSolidPolygon(std::span<const Vec2> vertices, const DrawColor& color) override;
    void DrawCircle(Vec2 center, Real radius, const DrawColor& color) override;
    void DrawSolidCircle(Vec2 center, Real radius, Vec2 axis, const DrawColor& color) override;
    void DrawSegment(Vec2 p1, Vec2 p2, const DrawColor& color) override;
    void DrawTransform(const Transform& xf) override;
    void DrawPoint(Vec2 p, Real size, const DrawColor& color) override;

    bool Used(const DrawColor& color) const;

  private:
    void Note(const DrawColor& color);

    DebugDraw& m_target;
    std::vector<DrawColor> m_used;
};

/// Lays out the caption, the impulse legend, the colour legend (the entries `drawn` used) and
/// the scale bar of a frame of `view`'s size, as options asks.
FrameLayout LayOutFrame(const FrameOptions& options, const Projection& view,
                        const ColorNotingDraw& drawn);

/// Paints the marks into the image.
void PaintMarks(Image& image, const std::vector<Mark>& marks);

/// Draws the layout's impulse arrow through `draw` (world coordinates).
void DrawLegendArrow(DebugDraw& draw, const FrameLayout& layout, const FrameOptions& options,
                     const Projection& view);

} // namespace meff::render
