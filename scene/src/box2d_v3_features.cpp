// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
#include "meff/box2d_v3_features.h"

namespace meff
{

std::vector<std::string> FieldsBox2D241Lacks(const Scene& scene, const std::string& consequence)
{
    std::vector<std::string> messages;
    for (std::size_t i = 0; i < scene.bodies.size(); ++i)
    {
        const std::vector<SceneShape>& shapes = scene.bodies[i].shapes;
        for (std::size_t k = 0; k < shapes.size(); ++k)
        {
            const std::string path = scene.sourcePath + ": bodies[" + std::to_string(i) +
                                     "].shapes[" + std::to_string(k) + "].";
            const SceneShape& shape = shapes[k];
            const bool polygon =
                shape.type == SceneShapeType::Box || shape.type == SceneShapeType::Polygon;
            if (shape.type == SceneShapeType::Capsule)
            {
                messages.push_back(path + "type: \"capsule\" (Box2D v3's), which Box2D 2.4.1 " +
                                   "does not have; " + consequence);
            }
            else if (polygon && shape.rounding > 0)
            {
                messages.push_back(path + "radius: a rounded polygon (Box2D v3's), which Box2D " +
                                   "2.4.1 does not have; " + consequence);
            }
        }
    }
    for (std::size_t j = 0; j < scene.joints.size(); ++j)
    {
        const SceneJoint& joint = scene.joints[j];
        if (joint.enableSpring)
        {
            messages.push_back(scene.sourcePath + ": joints[" + std::to_string(j) +
                               "].enable_spring: a spring on a " +
                               (joint.type == JointType::Revolute ? "revolute" : "prismatic") +
                               " joint (Box2D v3's), which Box2D 2.4.1 does not have; " +
                               consequence);
        }
    }
    for (std::size_t c = 0; c < scene.characters.size(); ++c)
    {
        messages.push_back(scene.sourcePath + ": characters[" + std::to_string(c) +
                           "]: a character moved by the character mover (Box2D v3's), which " +
                           "Box2D 2.4.1 does not have; " + consequence);
    }
    return messages;
}

} // namespace meff
