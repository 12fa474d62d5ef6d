// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The frame's caption, legends and scale bar, laid out in output pixels (see frame_layout.h).
#include "frame_layout.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace meff::render
{

namespace
{

bool SameColor(const DrawColor& a, const DrawColor& b)
{
    return a.r == b.r && a.g == b.g && a.b == b.b;
}

constexpr DrawColor kRedAxis{1, 0, 0};
constexpr DrawColor kGreenAxis{0, 1, 0};

Mark Rect(int x, int y, int width, int height, Rgb color, double alpha)
{
    Mark mark;
    mark.kind = Mark::Kind::Rect;
    mark.x = x;
    mark.y = y;
    mark.width = width;
    mark.height = height;
    mark.color = color;
    mark.alpha = alpha;
    return mark;
}

Mark Text(int x, int y, std::string text, Rgb color, int pixelSize)
{
    Mark mark;
    mark.kind = Mark::Kind::Text;
    mark.x = x;
    mark.y = y;
    mark.color = color;
    mark.text = std::move(text);
    mark.pixelSize = pixelSize;
    return mark;
}

/// The entries of the colour legend: every colour the frame used, said once, the palette's
/// then the overlay's.
std::vector<LegendEntry> UsedEntries(const FrameOptions& options, const ColorNotingDraw& drawn)
{
    std::vector<LegendEntry> used;
    std::vector<LegendEntry> candidates = PaletteLegend(options.flags);
    candidates.insert(candidates.end(), options.overlayLegend.begin(), options.overlayLegend.end());
    for (const LegendEntry& entry : candidates)
    {
        const bool listed =
            std::any_of(used.begin(), used.end(),
                        [&](const LegendEntry& e) { return SameColor(e.color, entry.color); });
        if (drawn.Used(entry.color) && !listed)
        {
            used.push_back(entry);
        }
    }
    return used;
}

/// Swatches and labels along the bottom edge, left of `right`, wrapping onto more rows when
/// they do not fit, on a translucent backing.
void LayOutColorLegend(std::vector<Mark>& marks, const std::vector<LegendEntry>& entries,
                       int height, int right, int pixelSize, int margin)
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
        if (x > margin && x + width > right - margin)
        {
            x = margin;
            ++row;
        }
        places.emplace_back(x, row);
        x += width + 3 * margin;
        widest = std::max(widest, x - 2 * margin);
    }
    const int rows = row + 1;
    const int top = height - rows * rowHeight - margin;
    marks.push_back(Rect(0, top - margin, std::min(right, widest + margin),
                         rows * rowHeight + 2 * margin, kBackground, 0.75));
    for (std::size_t i = 0; i < entries.size(); ++i)
    {
        const auto [left, r] = places[i];
        const int y = top + r * rowHeight;
        const int swatchTop = y + (lineHeight - swatch) / 2;
        marks.push_back(Rect(left, swatchTop, swatch, swatch, ToRgb(entries[i].color), 1.0));
        marks.push_back(Rect(left + 1, swatchTop + 1, swatch - 2, swatch - 2,
                             FillColor(entries[i].color), 1.0));
        marks.push_back(Text(left + swatch + margin, y, entries[i].label, kTextColor, pixelSize));
    }
}

/// A bar of a round length near a fifth of the image's width at the bottom right, ticked at
/// both ends, its length written to its right; returns its left edge (the image's width when
/// there is no room for one).
int LayOutScaleBar(std::vector<Mark>& marks, const Projection& view, int pixelSize, int margin)
{
    const double pixel = view.PixelSize();
    const double metres = NiceFloor(view.width / 5.0 * pixel);
    const int length = int(std::lround(metres / pixel));
    char label[48];
    std::snprintf(label, sizeof label, "%g m", metres);
    const int lineHeight = TextHeight(pixelSize);
    const int blockWidth = length + margin + TextWidth(label, pixelSize);
    if (length < 2 || blockWidth + 2 * margin > view.width / 2)
    {
        return view.width;
    }
    const int thickness = std::max(2, int(std::lround(2 * LineWidth(view.width, view.height))));
    const int left = view.width - margin - blockWidth;
    const int top = view.height - (lineHeight + margin) - margin;
    marks.push_back(Rect(left - margin, top - margin, blockWidth + 2 * margin,
                         lineHeight + 3 * margin, kBackground, 0.75));
    marks.push_back(
        Rect(left, top + (lineHeight - thickness) / 2, length, thickness, kTextColor, 1));
    for (const int x : {left, left + length - thickness})
    {
        marks.push_back(Rect(x, top + lineHeight / 4, thickness, lineHeight / 2, kTextColor, 1));
    }
    marks.push_back(Text(left + length + margin, top, label, kTextColor, pixelSize));
    return left - margin;
}

} // namespace

void DrawAxes(DebugDraw& draw, const Transform& xf)
{
    const Real axisLength = Real(0.4);
    draw.DrawSegment(xf.p, xf.p + axisLength * xf.q.GetXAxis(), kRedAxis);
    draw.DrawSegment(xf.p, xf.p + axisLength * xf.q.GetYAxis(), kGreenAxis);
}

void ColorNotingDraw::DrawPolygon(std::span<const Vec2> vertices, const DrawColor& color)
{
    Note(color);
    m_target.DrawPolygon(vertices, color);
}
void ColorNotingDraw::DrawSolidPolygon(std::span<const Vec2> vertices, const DrawColor& color)
{
    Note(color);
    m_target.DrawSolidPolygon(vertices, color);
}
void ColorNotingDraw::DrawCircle(Vec2 center, Real radius, const DrawColor& color)
{
    Note(color);
    m_target.DrawCircle(center, radius, color);
}
void ColorNotingDraw::DrawSolidCircle(Vec2 center, Real radius, Vec2 axis, const DrawColor& color)
{
    Note(color);
    m_target.DrawSolidCircle(center, radius, axis, color);
}
void ColorNotingDraw::DrawSegment(Vec2 p1, Vec2 p2, const DrawColor& color)
{
    Note(color);
    m_target.DrawSegment(p1, p2, color);
}
void ColorNotingDraw::DrawTransform(const Transform& xf)
{
    Note(kRedAxis);
    Note(kGreenAxis);
    m_target.DrawTransform(xf);
}
void ColorNotingDraw::DrawPoint(Vec2 p, Real size, const DrawColor& color)
{
    Note(color);
    m_target.DrawPoint(p, size, color);
}

bool ColorNotingDraw::Used(const DrawColor& color) const
{
    return std::any_of(m_used.begin(), m_used.end(),
                       [&](const DrawColor& used) { return SameColor(used, color); });
}

void ColorNotingDraw::Note(const DrawColor& color)
{
    if (!Used(color))
    {
        m_used.push_back(color);
    }
}

FrameLayout LayOutFrame(const FrameOptions& options, const Projection& view,
                        const ColorNotingDraw& drawn)
{
    FrameLayout layout;
    // Text is about 1/34 of the image's height (at least 9 pixels, legible), ...
    int pixelSize = std::clamp(view.height / 34, 9, 48);
    // ...but the caption never wider than the image, if a smaller size fits.
    while (pixelSize > 9 && TextWidth(options.caption, pixelSize) + pixelSize > view.width)
    {
        --pixelSize;
    }
    const int margin = std::max(2, pixelSize / 4);
    const int lineHeight = TextHeight(pixelSize) + 2 * margin;
    if (!options.caption.empty())
    {
        layout.marks.push_back(Rect(0, 0, TextWidth(options.caption, pixelSize) + 2 * margin,
                                    lineHeight, kBackground, 0.75));
        layout.marks.push_back(Text(margin, margin, options.caption, kTextColor, pixelSize));
    }
    if (!options.legend)
    {
        return layout;
    }
    if (options.legendImpulse)
    {
        // Under the caption: "impulse", an arrow standing for the impulse, "= value N·s".
        const int top = options.caption.empty() ? 0 : lineHeight;
        const std::string prefix = "impulse";
        layout.arrow = true;
        layout.arrowLeft = margin + TextWidth(prefix, pixelSize) + 2 * margin;
        layout.arrowLength = double(std::lround(
            *options.legendImpulse * double(options.flags.impulseScale) / view.PixelSize()));
        layout.arrowY = top + margin + 0.5 * TextHeight(pixelSize);
        char value[64];
        std::snprintf(value, sizeof value, "= %g N\xC2\xB7s", *options.legendImpulse);
        layout.marks.push_back(Text(margin, top + margin, prefix, kTextColor, pixelSize));
        layout.marks.push_back(Text(int(layout.arrowLeft + layout.arrowLength) + 2 * margin,
                                    top + margin, value, kTextColor, pixelSize));
    }
    std::vector<Mark> scaleBar;
    const int right = LayOutScaleBar(scaleBar, view, pixelSize, margin);
    LayOutColorLegend(layout.marks, UsedEntries(options, drawn), view.height, right, pixelSize,
                      margin);
    layout.marks.insert(layout.marks.end(), scaleBar.begin(), scaleBar.end());
    return layout;
}

void PaintMarks(Image& image, const std::vector<Mark>& marks)
{
    for (const Mark& mark : marks)
    {
        if (mark.kind == Mark::Kind::Rect)
        {
            FillRect(image, mark.x, mark.y, mark.width, mark.height, mark.color, mark.alpha);
        }
        else
        {
            DrawText(image, mark.x, mark.y, mark.text, mark.color, mark.pixelSize);
        }
    }
}

void DrawLegendArrow(DebugDraw& draw, const FrameLayout& layout, const FrameOptions& options,
                     const Projection& view)
{
    if (!layout.arrow)
    {
        return;
    }
    DrawArrow(draw, view.ToWorld(layout.arrowLeft, layout.arrowY),
              view.ToWorld(layout.arrowLeft + layout.arrowLength, layout.arrowY),
              options.flags.arrowHead,
              DrawColor{kTextColor.r / 255.0f, kTextColor.g / 255.0f, kTextColor.b / 255.0f});
}

} // namespace meff::render
