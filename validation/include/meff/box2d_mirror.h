// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The Box2D 2.4.1 mirror of a scene: the same bodies, shapes, materials, filters and joints,
// created in the same order as meff::BuildWorld creates them (creation order fixes Box2D's
// body, fixture, contact and joint lists and so the order the solver visits them).
//
// Nothing is left to Box2D's defaults: every definition field is set from the scene.
#pragma once

#include "meff/debug_draw.h"
#include "meff/scene.h"
#include "meff/validation.h"

#include <box2d/box2d.h>

#include <memory>
#include <unordered_map>
#include <vector>

namespace meff::validation
{

/// The colour Box2D's bodies are drawn in over meff's (meff render --overlay-box2d, meff
/// view's ghost).
inline constexpr DrawColor kBox2DColor{0.0f, 0.40f, 1.0f};

class Box2DMirror
{
  public:
    /// Builds the world. `blockSolver` is used for g_blockSolve during Step (default: the
    /// scene's "block_solver"). Throws SceneError, naming each field, for a scene with what
    /// Box2D 2.4.1 does not have (FieldsBox2D241Lacks).
    explicit Box2DMirror(const Scene& scene, std::optional<bool> blockSolver = std::nullopt);
    ~Box2DMirror();
    Box2DMirror(const Box2DMirror&) = delete;
    Box2DMirror& operator=(const Box2DMirror&) = delete;

    /// One b2World::Step with the scene's dt and iteration counts. Box2D's block-solver switch
    /// is a process-wide global: it is set for the step and restored afterwards, and mirrors
    /// on other threads step at the same time only while they want the same value.
    void Step();
    /// The state after the last step: bodies, PostSolve impulses, joint reactions.
    FrameSample Sample() const;

    /// Box2D's bodies as outlines (every fixture's shape, a circle's angle line): what the
    /// mirror computed for the same frame, to draw over meff's. Where they hide exactly behind
    /// meff's outlines, the engines agree.
    void Draw(DebugDraw& draw, const DrawColor& color) const;

    b2World& World() { return *m_world; }
    b2Body* Body(std::size_t sceneIndex) const { return m_bodies.at(sceneIndex); }
    b2Joint* Joint(std::size_t sceneIndex) const { return m_joints.at(sceneIndex); }

  private:
    class Listener;

    const Scene& m_scene;
    float m_dt = 0;
    bool m_blockSolve = true;
    long long m_steps = 0; ///< steps taken
    std::unique_ptr<b2World> m_world;
    std::unique_ptr<Listener> m_listener;
    std::vector<b2Body*> m_bodies;
    std::vector<b2Joint*> m_joints;
    /// Scene body and shape index of every fixture.
    std::unordered_map<const b2Fixture*, std::pair<std::size_t, std::size_t>> m_shapeOf;
};

} // namespace meff::validation
