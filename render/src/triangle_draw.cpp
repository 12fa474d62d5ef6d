// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// DebugDraw as coloured triangles (see TriangleDraw in meff/render.h).
//
// Lines are triangles, not GL lines, so that their width is exact and the same on every
// driver; a closed outline is one band between the loop offset inwards and outwards by half the
// line width, mitred at the corners: exact width, no gaps or overlaps at the joins (which would
// show with translucent colours).
#include "meff/render.h"

#include "frame_layout.h"

#include <algorithm>
#include <cmath>

namespace meff::render
{

void TriangleDraw::SetScale(double pixel, double lineWidth)
{
    m_pixel = pixel;
    m_lineWidth = lineWidth;
}

void TriangleDraw::Clear()
{
    m_vertices.clear();
}

void TriangleDraw::DrawPolygon(std::span<const Vec2> vertices, const DrawColor& color)
{
    StrokeLoop(vertices, color);
}

void TriangleDraw::DrawSolidPolygon(std::span<const Vec2> vertices, const DrawColor& color)
{
    Fill(vertices, FillOf(color));
    StrokeLoop(vertices, color);
}

void TriangleDraw::DrawCircle(Vec2 center, Real radius, const DrawColor& color)
{
    const std::vector<Vec2> loop = CirclePoints(center, double(radius));
    StrokeLoop(loop, color);
}

void TriangleDraw::DrawSolidCircle(Vec2 center, Real radius, Vec2 axis, const DrawColor& color)
{
    const std::vector<Vec2> loop = CirclePoints(center, double(radius));
    Fill(loop, FillOf(color));
    StrokeLoop(loop, color);
    DrawSegment(center, center + radius * axis, color);
}

void TriangleDraw::DrawSegment(Vec2 p1, Vec2 p2, const DrawColor& color)
{
    const double dx = double(p2.x) - double(p1.x);
    const double dy = double(p2.y) - double(p1.y);
    const double length = std::sqrt(dx * dx + dy * dy);
    const double half = 0.5 * m_lineWidth * m_pixel;
    // Square caps (the line extended by half its width): joins of separate segments, such
    // as an arrow's head, then close without notches.
    const double ux = length > 0 ? dx / length * half : half;
    const double uy = length > 0 ? dy / length * half : 0;
    const double ax = double(p1.x) - ux, ay = double(p1.y) - uy;
    const double bx = double(p2.x) + ux, by = double(p2.y) + uy;
    const ColoredVertex corners[4] = {{ax - uy, ay + ux, color},
                                      {ax + uy, ay - ux, color},
                                      {bx - uy, by + ux, color},
                                      {bx + uy, by - ux, color}};
    Strip(corners);
}

void TriangleDraw::DrawTransform(const Transform& xf)
{
    DrawAxes(*this, xf);
}

void TriangleDraw::DrawPoint(Vec2 p, Real size, const DrawColor& color)
{
    Fill(CirclePoints(p, 0.5 * double(size) * m_pixel), color);
}

DrawColor TriangleDraw::FillOf(const DrawColor& color)
{
    const Rgb fill = FillColor(color);
    return {fill.r / 255.0f, fill.g / 255.0f, fill.b / 255.0f, color.a};
}

std::vector<Vec2> TriangleDraw::CirclePoints(Vec2 center, double radius) const
{
    // Fine enough that its facets vanish at output resolution.
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

void TriangleDraw::Fill(std::span<const Vec2> vertices, const DrawColor& color)
{
    // A fan from the first vertex.
    for (std::size_t i = 1; i + 1 < vertices.size(); ++i)
    {
        for (const Vec2 v : {vertices[0], vertices[i], vertices[i + 1]})
        {
            m_vertices.push_back({double(v.x), double(v.y), color});
        }
    }
}

void TriangleDraw::Strip(std::span<const ColoredVertex> strip)
{
    for (std::size_t i = 0; i + 2 < strip.size(); ++i)
    {
        m_vertices.insert(m_vertices.end(), {strip[i], strip[i + 1], strip[i + 2]});
    }
}

void TriangleDraw::StrokeLoop(std::span<const Vec2> vertices, const DrawColor& color)
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
    const double half = 0.5 * m_lineWidth * m_pixel;
    const auto normal = [&](std::size_t i, double& nx, double& ny)
    {
        const Vec2 a = vertices[i % n], b = vertices[(i + 1) % n];
        const double dx = double(b.x) - double(a.x), dy = double(b.y) - double(a.y);
        const double length = std::sqrt(dx * dx + dy * dy);
        nx = length > 0 ? side * dy / length : 0;
        ny = length > 0 ? -side * dx / length : 0;
    };
    std::vector<ColoredVertex> band;
    band.reserve(2 * (n + 1));
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
        band.push_back({double(v.x) + mx * scale, double(v.y) + my * scale, color});
        band.push_back({double(v.x) - mx * scale, double(v.y) - my * scale, color});
    }
    Strip(band);
}

} // namespace meff::render
