// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// A scene's shapes as the engine's: one conversion for the loader (which checks them against
// the engine's rules, meff/validity.h) and for BuildWorld (which creates them).
#pragma once

#include "json_document.h"
#include "meff/collision.h"
#include "meff/scene.h"
#include "meff/shape.h"

#include <string>
#include <variant>
#include <vector>

namespace meff::scene_detail
{

inline Vec2 ToEngine(SceneVec2 v)
{
    return {Real(v.x), Real(v.y)};
}

using EngineShape = std::variant<Circle, Polygon, Segment, ChainSegment, Capsule>;

/// The engine's geometry for a shape other than a chain (which World::CreateChain makes):
/// boxes through MakeOffsetBox and polygons through MakePolygon, which throw InvalidArgument
/// (RefusedArgument for the rules of meff/validity.h) for what the engine cannot take; a
/// one-sided segment is a ChainSegment.
EngineShape ToEngineShape(const SceneShape& shape);

/// The definition (material, filter, sensor) of a shape.
ShapeDef ToShapeDef(const SceneShape& shape);

/// Whether a shape gives its body mass, as the engine decides (World::CreateShape, Box2D's
/// ResetMassData): a density > 0, and not a segment.
bool HasMass(const SceneShape& shape);

/// The scene field behind an engine refusal's field: "Circle::radius" is "radius", a box's
/// "Polygon::vertices" its more extreme half extent, "body" the shape itself (empty).
std::string SceneField(const SceneShape& shape, const std::string& engineField);

/// Applies the engine's rules (meff/validity.h) to a body's shapes in file order, as
/// World::CreateShape will when the scene is built: each shape's geometry, and on a dynamic body
/// its mass and the body's mass with it. Reports every refusal at the scene field behind it
/// (`shapesPath` is "bodies[i].shapes"); shapes with `checked[k]` false had errors already.
void CheckShapesAsTheEngine(Diagnostics& diagnostics, const std::string& shapesPath,
                            const SceneBody& body, const std::vector<bool>& checked);

} // namespace meff::scene_detail
