// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Running one extreme scene (samples/extreme/) in meff and, through the validation mirror, in
// Box2D 2.4.1, and measuring both the same way. The tests assert what must hold for meff; they
// also measure Box2D on the same scene, so docs/stability.md's table states both engines'
// results from one place, and where a claim about Box2D is made, a CHECK pins it.
//
// The two engines are not compared frame by frame here (these scenes are chaotic or long, and
// that is validation's job); each is judged against the physics on its own.
#pragma once

#include "meff/box2d_mirror.h"
#include "meff/scene.h"

#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#ifndef MEFF_SOURCE_DIR
#error "MEFF_SOURCE_DIR must name the repository root"
#endif

namespace meff::extreme
{

inline Scene LoadExtreme(const std::string& name)
{
    return LoadScene(std::string(MEFF_SOURCE_DIR) + "/samples/extreme/" + name + ".json");
}

/// One body after a step, in double, from either engine.
struct BodyState
{
    double x = 0; ///< body origin (m)
    double y = 0;
    double angle = 0;
    double vx = 0; ///< centre of mass (m/s)
    double vy = 0;
    double w = 0;
    double cx = 0; ///< centre of mass (m)
    double cy = 0;
    double mass = 0;    ///< kg
    double inertia = 0; ///< about the centre of mass (kg·m²)

    double Speed() const { return std::hypot(vx, vy); }
    /// Kinetic plus potential energy in gravity g pointing down (J).
    double Energy(double g) const
    {
        return 0.5 * mass * (vx * vx + vy * vy) + 0.5 * inertia * w * w + mass * g * cy;
    }
};

/// One engine stepping one scene. Step() returns false once the engine refused to go on
/// (meff's SimulationError); `failure` then says why.
class Engine
{
  public:
    virtual ~Engine() = default;
    virtual const char* Name() const = 0;
    virtual bool Step() = 0;
    virtual BodyState Body(std::size_t sceneIndex) const = 0;
    /// Deepest overlap of any touching contact point after the last step (m, ≥ 0).
    virtual double DeepestPenetration() const = 0;
    /// Largest distance between a joint's two anchors (m): how far joint j has come apart.
    virtual double JointGap(std::size_t sceneIndex) const = 0;
    std::string failure;
};

class MeffEngine final : public Engine
{
  public:
    explicit MeffEngine(const Scene& scene) : m_built(BuildWorld(scene)), m_dt(Real(scene.world.dt))
    {
    }
    const char* Name() const override { return "meff"; }
    bool Step() override
    {
        if (!failure.empty())
        {
            return false;
        }
        try
        {
            m_built.world.Step(m_dt);
            return true;
        }
        catch (const SimulationError& error)
        {
            failure = error.what();
            return false;
        }
    }
    BodyState Body(std::size_t i) const override
    {
        const World& w = m_built.world;
        const BodyId id = m_built.bodies.at(i);
        const Vec2 p = w.GetPosition(id);
        const Vec2 v = w.GetLinearVelocity(id);
        const Vec2 c = w.GetWorldCenter(id);
        return {p.x,
                p.y,
                w.GetAngle(id),
                v.x,
                v.y,
                w.GetAngularVelocity(id),
                c.x,
                c.y,
                w.GetMass(id),
                w.GetRotationalInertia(id)};
    }
    double DeepestPenetration() const override
    {
        double deepest = 0;
        for (const ContactPointReport& report : m_built.world.GetContactReports())
        {
            deepest = std::max(deepest, -double(report.separation));
        }
        return deepest;
    }
    double JointGap(std::size_t j) const override
    {
        const JointId id = m_built.joints.at(j);
        const Vec2 a = m_built.world.GetAnchorA(id);
        const Vec2 b = m_built.world.GetAnchorB(id);
        return std::hypot(double(a.x) - b.x, double(a.y) - b.y);
    }
    World& world() { return m_built.world; }

  private:
    BuiltScene m_built;
    Real m_dt;
};

class Box2DEngine final : public Engine
{
  public:
    explicit Box2DEngine(const Scene& scene) : m_mirror(scene) {}
    const char* Name() const override { return "Box2D 2.4.1"; }
    bool Step() override
    {
        m_mirror.Step();
        return true; // Box2D has no such check: non-finite values show in the states
    }
    BodyState Body(std::size_t i) const override
    {
        const b2Body* b = m_mirror.Body(i);
        const b2Vec2 p = b->GetPosition();
        const b2Vec2 v = b->GetLinearVelocity();
        const b2Vec2 c = b->GetWorldCenter();
        const b2Vec2 lc = b->GetLocalCenter();
        // Box2D's GetInertia is about the body origin; move it to the centre of mass.
        const double inertia = b->GetInertia() - b->GetMass() * (double(lc.x) * lc.x + lc.y * lc.y);
        return {p.x, p.y, b->GetAngle(), v.x,    v.y, b->GetAngularVelocity(),
                c.x, c.y, b->GetMass(),  inertia};
    }
    double DeepestPenetration() const override
    {
        double deepest = 0;
        for (b2Contact* c = const_cast<b2World&>(World()).GetContactList(); c; c = c->GetNext())
        {
            if (!c->IsTouching() || !c->IsEnabled())
            {
                continue;
            }
            b2WorldManifold wm;
            c->GetWorldManifold(&wm);
            for (int k = 0; k < c->GetManifold()->pointCount; ++k)
            {
                deepest = std::max(deepest, -double(wm.separations[k]));
            }
        }
        return deepest;
    }
    double JointGap(std::size_t j) const override
    {
        const b2Joint* joint = m_mirror.Joint(j);
        const b2Vec2 a = joint->GetAnchorA();
        const b2Vec2 b = joint->GetAnchorB();
        return std::hypot(double(a.x) - b.x, double(a.y) - b.y);
    }

  private:
    const b2World& World() const { return const_cast<validation::Box2DMirror&>(m_mirror).World(); }
    validation::Box2DMirror m_mirror;
};

/// Both engines on one scene; the scene must outlive them.
inline std::vector<std::unique_ptr<Engine>> BothEngines(const Scene& scene)
{
    std::vector<std::unique_ptr<Engine>> engines;
    engines.push_back(std::make_unique<MeffEngine>(scene));
    engines.push_back(std::make_unique<Box2DEngine>(scene));
    return engines;
}

/// Indices of the scene's dynamic bodies.
inline std::vector<std::size_t> DynamicBodies(const Scene& scene)
{
    std::vector<std::size_t> indices;
    for (std::size_t i = 0; i < scene.bodies.size(); ++i)
    {
        if (scene.bodies[i].type == BodyType::Dynamic)
        {
            indices.push_back(i);
        }
    }
    return indices;
}

/// A line for docs/stability.md's table, printed with the test's output (ctest -V).
inline void Report(const std::string& scene, const Engine& engine, const std::string& result)
{
    std::printf("STABILITY | %s | %s | %s%s%s\n", scene.c_str(), engine.Name(), result.c_str(),
                engine.failure.empty() ? "" : " | stopped: ", engine.failure.c_str());
    std::fflush(stdout);
}

inline std::string Format(const char* format, double a, double b = 0, double c = 0, double d = 0)
{
    char text[256];
    std::snprintf(text, sizeof text, format, a, b, c, d);
    return text;
}

} // namespace meff::extreme
