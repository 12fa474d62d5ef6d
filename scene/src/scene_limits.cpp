// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SceneLimits: how much a scene may hold, checked before the memory for it is taken.
#include "json_document.h"

#include <string>

namespace meff::scene_detail
{

namespace
{

/// "N THINGS, more than the limit of M (raise it with --max-THINGS)".
std::string OverLimit(std::size_t count, std::size_t limit, const std::string& things)
{
    return std::to_string(count) + " " + things + ", more than the limit of " +
           std::to_string(limit) + " (raise it with --max-" + things + ")";
}

} // namespace

bool CheckCounts(const Json& document, const char* bodiesKey, const char* shapesKey,
                 const char* jointsKey, const SceneLimits& limits, Diagnostics& diagnostics)
{
    if (!document.is_object())
    {
        return true; // the reader says what is wrong with it
    }
    bool within = true;
    const auto bodies = document.find(bodiesKey);
    if (bodies != document.end() && bodies->is_array())
    {
        if (bodies->size() > limits.bodies)
        {
            diagnostics.Report(bodiesKey, OverLimit(bodies->size(), limits.bodies, "bodies"));
            within = false;
        }
        std::size_t shapes = 0;
        for (const Json& body : *bodies)
        {
            const auto list = body.is_object() ? body.find(shapesKey) : body.end();
            if (list != body.end() && list->is_array())
            {
                shapes += list->size();
            }
        }
        if (shapes > limits.shapes)
        {
            diagnostics.Report(bodiesKey, OverLimit(shapes, limits.shapes, "shapes"));
            within = false;
        }
    }
    const auto joints = document.find(jointsKey);
    if (joints != document.end() && joints->is_array() && joints->size() > limits.joints)
    {
        diagnostics.Report(jointsKey, OverLimit(joints->size(), limits.joints, "joints"));
        within = false;
    }
    return within;
}

void CheckPairs(const BuiltScene& built, const SceneLimits& limits, const std::string& sourcePath)
{
    const World& world = built.world;
    std::size_t pairs = 0;
    for (const BodyId body : world.GetBodies())
    {
        if (world.GetType(body) != BodyType::Dynamic)
        {
            continue; // counted from the dynamic side
        }
        for (const ShapeId shape : world.GetShapes(body))
        {
            world.OverlapAABB(world.GetShapeAABB(shape), QueryFilter{},
                              [&](ShapeId other)
                              {
                                  const BodyId otherBody = world.GetBody(other);
                                  // A pair of two dynamic bodies is counted from one of them.
                                  const bool counted =
                                      otherBody != body &&
                                      (world.GetType(otherBody) != BodyType::Dynamic ||
                                       otherBody.index > body.index);
                                  pairs += counted ? 1 : 0;
                                  return pairs <= limits.pairs;
                              });
            if (pairs > limits.pairs)
            {
                throw SceneError({sourcePath + ": bodies: more than " +
                                  std::to_string(limits.pairs) +
                                  " pairs of shapes overlap at the start, the limit (raise it "
                                  "with --max-pairs)"});
            }
        }
    }
}

} // namespace meff::scene_detail
