// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SVG frames: the drawing, the caption, the legends and the scale bar of RenderFrame, as vectors
// in output pixels, for figures that scale. The geometry is RenderFrame's: the same projection
// (frame_layout.h), line widths, point sizes and layout.
#include "frame_layout.h"

#include <cstdio>
#include <string>

namespace meff::render
{

namespace
{

std::string Hex(Rgb color)
{
    char text[8];
    std::snprintf(text, sizeof text, "#%02x%02x%02x", color.r, color.g, color.b);
    return text;
}

std::string Number(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.3f", value);
    std::string result = text;
    // Trailing zeros say nothing: 12.500 → 12.5, 3.000 → 3.
    result.erase(result.find_last_not_of('0') + 1);
    if (result.back() == '.')
    {
        result.pop_back();
    }
    return result == "-0" ? "0" : result;
}

/// Text for SVG's character data and attribute values.
std::string Escape(std::string_view text)
{
    std::string result;
    for (const char c : text)
    {
        switch (c)
        {
        case '&':
            result += "&amp;";
            break;
        case '<':
            result += "&lt;";
            break;
        case '>':
            result += "&gt;";
            break;
        case '"':
            result += "&quot;";
            break;
        default:
            result += c;
        }
    }
    return result;
}

/// Writes SVG elements for DebugDraw's calls, in output pixels through `view`.
class SvgDraw final : public DebugDraw
{
  public:
    SvgDraw(std::string& out, const Projection& view)
        : m_out(out), m_view(view), m_lineWidth(LineWidth(view.width, view.height))
    {
    }

    void DrawPolygon(std::span<const Vec2> vertices, const DrawColor& color) override
    {
        m_out +=
            "<polygon points=\"" + Points(vertices) + "\" fill=\"none\"" + Stroke(color) + "/>\n";
    }
    void DrawSolidPolygon(std::span<const Vec2> vertices, const DrawColor& color) override
    {
        m_out +=
            "<polygon points=\"" + Points(vertices) + "\"" + Fill(color) + Stroke(color) + "/>\n";
    }
    void DrawCircle(Vec2 center, Real radius, const DrawColor& color) override
    {
        m_out += Circle(center, radius) + " fill=\"none\"" + Stroke(color) + "/>\n";
    }
    void DrawSolidCircle(Vec2 center, Real radius, Vec2 axis, const DrawColor& color) override
    {
        m_out += Circle(center, radius) + Fill(color) + Stroke(color) + "/>\n";
        DrawSegment(center, center + radius * axis, color);
    }
    void DrawSegment(Vec2 p1, Vec2 p2, const DrawColor& color) override
    {
        const Vec2 a = m_view.ToScreen(p1);
        const Vec2 b = m_view.ToScreen(p2);
        // Square caps, as the image's lines.
        m_out += "<line x1=\"" + Number(double(a.x)) + "\" y1=\"" + Number(double(a.y)) +
                 "\" x2=\"" + Number(double(b.x)) + "\" y2=\"" + Number(double(b.y)) + "\"" +
                 Stroke(color) + " stroke-linecap=\"square\"/>\n";
    }
    void DrawTransform(const Transform& xf) override { DrawAxes(*this, xf); }
    void DrawPoint(Vec2 p, Real size, const DrawColor& color) override
    {
        const Vec2 c = m_view.ToScreen(p);
        m_out += "<circle cx=\"" + Number(double(c.x)) + "\" cy=\"" + Number(double(c.y)) +
                 "\" r=\"" + Number(0.5 * double(size)) + "\" fill=\"" + Hex(ToRgb(color)) + "\"" +
                 Opacity("fill-opacity", color) + "/>\n";
    }

  private:
    std::string Points(std::span<const Vec2> vertices) const
    {
        std::string points;
        for (const Vec2 v : vertices)
        {
            const Vec2 p = m_view.ToScreen(v);
            points += (points.empty() ? "" : " ") + Number(double(p.x)) + "," + Number(double(p.y));
        }
        return points;
    }
    std::string Circle(Vec2 center, Real radius) const
    {
        const Vec2 c = m_view.ToScreen(center);
        return "<circle cx=\"" + Number(double(c.x)) + "\" cy=\"" + Number(double(c.y)) +
               "\" r=\"" + Number(double(radius) / m_view.PixelSize()) + "\"";
    }
    static std::string Opacity(const char* attribute, const DrawColor& color)
    {
        return color.a < 1 ? std::string(" ") + attribute + "=\"" + Number(color.a) + "\"" : "";
    }
    static std::string Fill(const DrawColor& color)
    {
        return " fill=\"" + Hex(FillColor(color)) + "\"" + Opacity("fill-opacity", color);
    }
    std::string Stroke(const DrawColor& color) const
    {
        // Mitred joins, as the image's outlines (which cap a mitre at 4 half-widths).
        return " stroke=\"" + Hex(ToRgb(color)) + "\" stroke-width=\"" + Number(m_lineWidth) +
               "\" stroke-linejoin=\"miter\" stroke-miterlimit=\"4\"" +
               Opacity("stroke-opacity", color);
    }

    std::string& m_out;
    Projection m_view;
    double m_lineWidth;
};

} // namespace

std::string RenderSvg(const DrawList& drawing, const FrameOptions& options, int width, int height)
{
    const Projection view{options.camera, width, height};
    std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" +
                      std::to_string(width) + "\" height=\"" + std::to_string(height) +
                      "\" viewBox=\"0 0 " + std::to_string(width) + " " + std::to_string(height) +
                      "\">\n";
    if (!options.transparent)
    {
        out += "<rect width=\"" + std::to_string(width) + "\" height=\"" + std::to_string(height) +
               "\" fill=\"" + Hex(kBackground) + "\"/>\n";
    }
    SvgDraw svg(out, view);
    ColorNotingDraw draw(svg);
    drawing.Replay(draw);
    const FrameLayout layout = LayOutFrame(options, view, draw);
    DrawLegendArrow(svg, layout, options, view);
    for (const Mark& mark : layout.marks)
    {
        if (mark.kind == Mark::Kind::Rect)
        {
            out += "<rect x=\"" + std::to_string(mark.x) + "\" y=\"" + std::to_string(mark.y) +
                   "\" width=\"" + std::to_string(mark.width) + "\" height=\"" +
                   std::to_string(mark.height) + "\" fill=\"" + Hex(mark.color) + "\"" +
                   (mark.alpha < 1 ? " fill-opacity=\"" + Number(mark.alpha) + "\"" : "") + "/>\n";
        }
        else
        {
            // SVG places text by its baseline; the layout by its line's top.
            out += "<text x=\"" + std::to_string(mark.x) + "\" y=\"" +
                   std::to_string(mark.y + TextAscent(mark.pixelSize)) +
                   "\" font-family=\"DejaVu Sans, sans-serif\" font-size=\"" +
                   std::to_string(mark.pixelSize) + "\" fill=\"" + Hex(mark.color) +
                   "\" xml:space=\"preserve\">" + Escape(mark.text) + "</text>\n";
        }
    }
    out += "</svg>\n";
    return out;
}

} // namespace meff::render
