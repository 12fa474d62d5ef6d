// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Debug drawing: World::Draw describes the world as polygons, circles, segments and points
// through this interface, as Box2D's b2Draw does, and a renderer (meff's off-screen PNG renderer
// in render/, or a game's own) implements it. The engine itself draws nothing and depends on no
// graphics library.
#pragma once

#include "meff/math.h"

#include <span>

namespace meff
{

/// A colour with components in [0, 1].
struct DrawColor
{
    float r = 1; ///< red
    float g = 1; ///< green
    float b = 1; ///< blue
    float a = 1; ///< opacity

    constexpr DrawColor() = default;
    /// The colour (r_, g_, b_) with opacity a_.
    constexpr DrawColor(float r_, float g_, float b_, float a_ = 1) : r(r_), g(g_), b(b_), a(a_) {}
};

/// The colours World::Draw uses. Defaults follow Box2D's testbed, darkened a little so that
/// they read on a light background.
struct DrawPalette
{
    DrawColor staticBody{0.35f, 0.65f, 0.35f};    ///< static bodies' shapes
    DrawColor kinematicBody{0.40f, 0.45f, 0.85f}; ///< kinematic bodies' shapes
    DrawColor dynamicBody{0.90f, 0.55f, 0.45f};   ///< awake dynamic bodies' shapes
    /// Dynamic bodies that are asleep.
    DrawColor sleepingBody{0.60f, 0.60f, 0.60f};
    DrawColor joint{0.25f, 0.60f, 0.75f};          ///< joints, anchors and their lines
    DrawColor contactPoint{0.85f, 0.10f, 0.10f};   ///< contact points
    DrawColor contactNormal{0.10f, 0.55f, 0.15f};  ///< contact normals
    DrawColor contactImpulse{0.80f, 0.15f, 0.60f}; ///< contact impulse arrows
    DrawColor jointReaction{0.95f, 0.55f, 0.00f};  ///< joint reaction arrows
    DrawColor aabb{0.80f, 0.40f, 0.85f};           ///< broad-phase boxes
};

/// What World::Draw draws, and how big. Designated initializers read well here:
/// `world.Draw(draw, {.contacts = true})`.
struct DrawFlags
{
    bool shapes = true;           ///< every shape, coloured by its body's type
    bool joints = true;           ///< joints: their anchors and what links them
    bool contacts = false;        ///< contact points of the last step, with their normals
    bool contactImpulses = false; ///< arrows: each contact point's normal impulse
    bool jointReactions = false;  ///< arrows: each joint's reaction impulse on body B
    bool aabbs = false;           ///< every shape's broad-phase box
    bool centersOfMass = false;   ///< each body's centre of mass and axes (DrawTransform)

    /// Length of an impulse arrow per unit impulse (m per N·s). Contact and joint impulses
    /// share it, so their arrows compare directly; a joint's reaction is drawn as an impulse
    /// (force × dt of the last step), in the same unit as the contacts'.
    Real impulseScale = Real(0.1);
    Real normalLength = Real(0.3); ///< length of a contact normal (m)
    Real arrowHead = Real(0.1);    ///< length of an arrow's head (m)
    Real pointSize = 4;            ///< contact and anchor points, in pixels (as b2Draw)
    DrawPalette colors{};          ///< the colours of everything drawn
};

/// Implement this to see a world: World::Draw calls it once per primitive, in a fixed order
/// (bodies in creation order, each body's shapes, then joints, contacts and arrows), so the
/// same world always produces the same calls.
class DebugDraw
{
  public:
    virtual ~DebugDraw() = default;

    /// A closed outline through the vertices, in order.
    virtual void DrawPolygon(std::span<const Vec2> vertices, const DrawColor& color) = 0;
    /// A filled convex polygon (counter-clockwise vertices) with its outline.
    virtual void DrawSolidPolygon(std::span<const Vec2> vertices, const DrawColor& color) = 0;
    /// A circle's outline (centre and radius in m).
    virtual void DrawCircle(Vec2 center, Real radius, const DrawColor& color) = 0;
    /// A filled circle with its outline and a line from the centre along `axis` (a unit
    /// vector), which shows how the body has turned.
    virtual void DrawSolidCircle(Vec2 center, Real radius, Vec2 axis, const DrawColor& color) = 0;
    /// A line from p1 to p2 (m).
    virtual void DrawSegment(Vec2 p1, Vec2 p2, const DrawColor& color) = 0;
    /// A frame: its x axis in red and y axis in green (Box2D's convention).
    virtual void DrawTransform(const Transform& xf) = 0;
    /// A dot `size` pixels across, whatever the zoom.
    virtual void DrawPoint(Vec2 p, Real size, const DrawColor& color) = 0;
};

/// Draws a segment from `tail` to `tip` with a two-stroke head of length `head` at the tip;
/// nothing for a zero-length arrow. What World::Draw uses for impulses; exposed so that other
/// drawings (a legend, an overlay) can match it.
void DrawArrow(DebugDraw& draw, Vec2 tail, Vec2 tip, Real head, const DrawColor& color);

} // namespace meff
