// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Recording DebugDraw calls to replay them later (meff render --jobs draws frames on several
// threads while one thread steps the world).
#include "meff/render.h"

namespace meff::render
{

void DrawList::Add(Kind kind, std::span<const Vec2> vertices, const DrawColor& color)
{
    Command command;
    command.kind = kind;
    command.color = color;
    command.first = m_points.size();
    command.count = vertices.size();
    m_points.insert(m_points.end(), vertices.begin(), vertices.end());
    m_commands.push_back(command);
}

void DrawList::DrawPolygon(std::span<const Vec2> vertices, const DrawColor& color)
{
    Add(Kind::Polygon, vertices, color);
}

void DrawList::DrawSolidPolygon(std::span<const Vec2> vertices, const DrawColor& color)
{
    Add(Kind::SolidPolygon, vertices, color);
}

void DrawList::DrawCircle(Vec2 center, Real radius, const DrawColor& color)
{
    m_commands.push_back({Kind::Circle, color, center, {}, radius, 0, 0});
}

void DrawList::DrawSolidCircle(Vec2 center, Real radius, Vec2 axis, const DrawColor& color)
{
    m_commands.push_back({Kind::SolidCircle, color, center, axis, radius, 0, 0});
}

void DrawList::DrawSegment(Vec2 p1, Vec2 p2, const DrawColor& color)
{
    m_commands.push_back({Kind::Segment, color, p1, p2, 0, 0, 0});
}

void DrawList::DrawTransform(const Transform& xf)
{
    m_commands.push_back({Kind::Transform, {}, xf.p, {xf.q.c, xf.q.s}, 0, 0, 0});
}

void DrawList::DrawPoint(Vec2 p, Real size, const DrawColor& color)
{
    m_commands.push_back({Kind::Point, color, p, {}, size, 0, 0});
}

void DrawList::Replay(DebugDraw& draw) const
{
    for (const Command& command : m_commands)
    {
        const std::span<const Vec2> vertices(m_points.data() + command.first, command.count);
        switch (command.kind)
        {
        case Kind::Polygon:
            draw.DrawPolygon(vertices, command.color);
            break;
        case Kind::SolidPolygon:
            draw.DrawSolidPolygon(vertices, command.color);
            break;
        case Kind::Circle:
            draw.DrawCircle(command.a, command.value, command.color);
            break;
        case Kind::SolidCircle:
            draw.DrawSolidCircle(command.a, command.value, command.b, command.color);
            break;
        case Kind::Segment:
            draw.DrawSegment(command.a, command.b, command.color);
            break;
        case Kind::Transform:
        {
            Transform xf;
            xf.p = command.a;
            xf.q.c = command.b.x;
            xf.q.s = command.b.y;
            draw.DrawTransform(xf);
            break;
        }
        case Kind::Point:
            draw.DrawPoint(command.a, command.value, command.color);
            break;
        }
    }
}

} // namespace meff::render
