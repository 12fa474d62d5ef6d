// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Plausibility checks (meff/plausibility.h): one run of a scene in one back end, sampled after
// every step, and the invariants docs/validation.md describes.
#include "meff/plausibility.h"

#include "meff/error.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace meff::validation
{

namespace
{

constexpr double kTwoPi = 6.283185307179586;

/// How long after a hit its rebound is watched (s): long enough for a joint or a spring
/// compressed by the hit to give its energy back, short enough not to see the next swing.
constexpr double kReboundWindow = 0.5;

struct Vec
{
    double x = 0;
    double y = 0;
};

Vec ToVec(Vec2 v)
{
    return {double(v.x), double(v.y)};
}

double Dot(Vec a, Vec b)
{
    return a.x * b.x + a.y * b.y;
}

double Length(Vec a)
{
    return std::sqrt(Dot(a, a));
}

Vec Minus(Vec a, Vec b)
{
    return {a.x - b.x, a.y - b.y};
}

Vec Rotate(Vec v, double angle)
{
    const double c = std::cos(angle);
    const double s = std::sin(angle);
    return {c * v.x - s * v.y, s * v.x + c * v.y};
}

/// What the checks read of one dynamic body, fixed for the run.
struct BodyInfo
{
    std::size_t scene = 0; ///< index into scene.bodies
    BodyId id{};
    double mass = 0;
    double inertia = 0;       ///< about the centre of mass
    double originInertia = 0; ///< about the body origin (b2Body::GetInertia, for weld springs)
    double gyration = 0;      ///< sqrt(inertia / mass): |ω|·gyration is its turning speed
    double gravityScale = 1;
};

/// b2LinearStiffness's mass: the reduced mass of two dynamic bodies, else the one that moves.
double SpringMass(double massA, double massB)
{
    if (massA > 0 && massB > 0)
    {
        return massA * massB / (massA + massB);
    }
    return massA > 0 ? massA : massB;
}

class Run
{
  public:
    Run(const Scene& scene, std::optional<SolverKind> solver)
        : m_scene(scene), m_built(BuildWorld(WithSolver(scene, solver)))
    {
        m_gravity = {scene.world.gravity.x, scene.world.gravity.y};
        for (std::size_t i = 0; i < scene.bodies.size(); ++i)
        {
            const BodyId id = m_built.bodies[i];
            if (scene.bodies[i].type != BodyType::Dynamic)
            {
                continue;
            }
            BodyInfo info;
            info.scene = i;
            info.id = id;
            info.mass = double(m_built.world.GetMass(id));
            info.inertia = double(m_built.world.GetRotationalInertia(id));
            const Vec local = ToVec(m_built.world.GetLocalCenter(id));
            info.originInertia = info.inertia + info.mass * Dot(local, local);
            info.gyration = info.mass > 0 ? std::sqrt(info.inertia / info.mass) : 0;
            info.gravityScale = scene.bodies[i].gravityScale;
            m_bodies.push_back(info);
        }
        for (std::size_t j = 0; j < scene.joints.size(); ++j)
        {
            m_referenceAngles.push_back(ReferenceAngle(scene.joints[j]));
        }
    }

    World& world() { return m_built.world; }
    BuiltScene& built() { return m_built; }
    const std::vector<BodyInfo>& bodies() const { return m_bodies; }
    const std::string& BodyName(std::size_t sceneIndex) const
    {
        return m_scene.bodies[sceneIndex].name;
    }
    std::optional<std::size_t> SceneIndexOf(BodyId id) const { return m_built.SceneIndexOf(id); }

    /// Kinetic energy of every dynamic body (J).
    double Kinetic() const
    {
        double energy = 0;
        for (const BodyInfo& body : m_bodies)
        {
            const Vec v = ToVec(m_built.world.GetLinearVelocity(body.id));
            const double w = double(m_built.world.GetAngularVelocity(body.id));
            energy += 0.5 * body.mass * Dot(v, v) + 0.5 * body.inertia * w * w;
        }
        return energy;
    }

    /// Kinetic + gravitational potential + the energy of the springs it knows (J).
    double Energy() const
    {
        double energy = Kinetic();
        for (const BodyInfo& body : m_bodies)
        {
            const Vec c = ToVec(m_built.world.GetWorldCenter(body.id));
            energy -= body.mass * body.gravityScale * Dot(m_gravity, c);
        }
        return energy + SpringEnergy();
    }

    /// Why the scene is not a closed system (a motor, a driven body, a belt), or "".
    std::string EnergySource() const
    {
        for (const SceneJoint& joint : m_scene.joints)
        {
            switch (joint.type)
            {
            case JointType::Motor:
            case JointType::Mouse:
                return "joint " + joint.name + " drives its body";
            case JointType::Revolute:
            case JointType::Prismatic:
            case JointType::Wheel:
            {
                const double most =
                    joint.type == JointType::Prismatic ? joint.maxMotorForce : joint.maxMotorTorque;
                // A motor held at speed 0 only brakes: it takes energy, never gives it.
                if (joint.enableMotor && joint.motorSpeed != 0 && most > 0)
                {
                    return "joint " + joint.name + "'s motor does work";
                }
                if (joint.enableSpring && joint.stiffnessHz > 0)
                {
                    return "joint " + joint.name + "'s spring (Box2D v3's) is not counted";
                }
                break;
            }
            default:
                break;
            }
        }
        for (const SceneBody& body : m_scene.bodies)
        {
            if (body.type == BodyType::Kinematic &&
                (body.linearVelocity.x != 0 || body.linearVelocity.y != 0 ||
                 body.angularVelocity != 0))
            {
                return "kinematic body " + body.name + " moves";
            }
            for (const SceneShape& shape : body.shapes)
            {
                if (shape.tangentSpeed != 0)
                {
                    return "body " + body.name + " has a conveyor (tangent_speed)";
                }
            }
        }
        if (!m_scene.characters.empty())
        {
            return "characters are moved by their inputs";
        }
        return "";
    }

    /// The largest gap of any joint now (m), and which.
    std::pair<double, int> JointGap() const
    {
        double largest = 0;
        int which = -1;
        for (std::size_t j = 0; j < m_scene.joints.size(); ++j)
        {
            const double gap = Gap(j);
            if (gap > largest)
            {
                largest = gap;
                which = int(j);
            }
        }
        return {largest, which};
    }

    /// |v| + |ω|·gyration: how fast the body's mass moves, translation and turning together.
    double Speed(const BodyInfo& body) const
    {
        return Length(ToVec(m_built.world.GetLinearVelocity(body.id))) +
               std::abs(double(m_built.world.GetAngularVelocity(body.id))) * body.gyration;
    }

  private:
    static Scene WithSolver(const Scene& scene, std::optional<SolverKind> solver)
    {
        Scene copy = scene;
        if (solver)
        {
            copy.world.solver.kind = *solver;
        }
        return copy;
    }

    double ReferenceAngle(const SceneJoint& joint) const
    {
        if (joint.referenceAngle)
        {
            return *joint.referenceAngle;
        }
        return m_scene.bodies[joint.bodyIndexB].angle - m_scene.bodies[joint.bodyIndexA].angle;
    }

    double Mass(std::size_t sceneIndex) const
    {
        return m_scene.bodies[sceneIndex].type == BodyType::Dynamic
                   ? double(m_built.world.GetMass(m_built.bodies[sceneIndex]))
                   : 0.0;
    }

    double OriginInertia(std::size_t sceneIndex) const
    {
        for (const BodyInfo& body : m_bodies)
        {
            if (body.scene == sceneIndex)
            {
                return body.originInertia;
            }
        }
        return 0;
    }

    double Angle(std::size_t sceneIndex) const
    {
        return double(m_built.world.GetAngle(m_built.bodies[sceneIndex]));
    }

    /// Distance, wheel and weld springs (stiffness_hz > 0), with the stiffness the engine
    /// derives from the file (b2LinearStiffness, b2AngularStiffness).
    double SpringEnergy() const
    {
        double energy = 0;
        for (std::size_t j = 0; j < m_scene.joints.size(); ++j)
        {
            const SceneJoint& joint = m_scene.joints[j];
            if (joint.stiffnessHz <= 0)
            {
                continue;
            }
            const double omega = kTwoPi * joint.stiffnessHz;
            const JointId id = m_built.joints[j];
            if (joint.type == JointType::Distance && joint.minLength < joint.maxLength)
            {
                const double k =
                    SpringMass(Mass(joint.bodyIndexA), Mass(joint.bodyIndexB)) * omega * omega;
                const double length = Length(Minus(ToVec(m_built.world.GetAnchorB(id)),
                                                   ToVec(m_built.world.GetAnchorA(id))));
                energy += 0.5 * k * (length - joint.length) * (length - joint.length);
            }
            else if (joint.type == JointType::Wheel)
            {
                const double k =
                    SpringMass(Mass(joint.bodyIndexA), Mass(joint.bodyIndexB)) * omega * omega;
                const double t = double(m_built.world.GetJointTranslation(id));
                energy += 0.5 * k * t * t;
            }
            else if (joint.type == JointType::Weld)
            {
                const double k =
                    SpringMass(OriginInertia(joint.bodyIndexA), OriginInertia(joint.bodyIndexB)) *
                    omega * omega;
                const double angle =
                    Angle(joint.bodyIndexB) - Angle(joint.bodyIndexA) - m_referenceAngles[j];
                energy += 0.5 * k * angle * angle;
            }
        }
        return energy;
    }

    /// How far joint j is from holding (m): pins and welds, their anchors apart; rods, off
    /// [min, max]; slides and wheels, off their axis (and a slide beyond its enabled limits);
    /// pulleys, the rope's length changed. Gears, motors, mice and friction have no gap.
    double Gap(std::size_t j) const
    {
        const SceneJoint& joint = m_scene.joints[j];
        const JointId id = m_built.joints[j];
        const Vec a = ToVec(m_built.world.GetAnchorA(id));
        const Vec b = ToVec(m_built.world.GetAnchorB(id));
        const Vec d = Minus(b, a);
        switch (joint.type)
        {
        case JointType::Revolute:
        case JointType::Weld:
            return Length(d);
        case JointType::Distance:
        {
            // Box2D keeps every length at least the linear slop.
            const double slop = 0.005;
            const double length = Length(d);
            return std::max({0.0, std::max(joint.minLength, slop) - length,
                             length - std::max(joint.maxLength, slop)});
        }
        case JointType::Prismatic:
        case JointType::Wheel:
        {
            Vec localAxis = joint.localAxisA ? Vec{joint.localAxisA->x, joint.localAxisA->y}
                                             : Rotate({joint.axis.x, joint.axis.y},
                                                      -m_scene.bodies[joint.bodyIndexA].angle);
            const double norm = Length(localAxis);
            localAxis = {localAxis.x / norm, localAxis.y / norm};
            const Vec axis = Rotate(localAxis, Angle(joint.bodyIndexA));
            const double off = std::abs(axis.x * d.y - axis.y * d.x);
            double beyond = 0;
            if (joint.type == JointType::Prismatic && joint.enableLimit)
            {
                const double t = Dot(axis, d);
                beyond = std::max({0.0, joint.lowerTranslation - t, t - joint.upperTranslation});
            }
            return std::max(off, beyond);
        }
        case JointType::Pulley:
        {
            const auto ropeLength = [&](Vec anchorA, Vec anchorB)
            {
                return Length(Minus(anchorA, {joint.groundAnchorA.x, joint.groundAnchorA.y})) +
                       joint.ratio *
                           Length(Minus(anchorB, {joint.groundAnchorB.x, joint.groundAnchorB.y}));
            };
            const double start =
                ropeLength({joint.anchorA.x, joint.anchorA.y}, {joint.anchorB.x, joint.anchorB.y});
            return std::abs(ropeLength(a, b) - start);
        }
        default:
            return 0;
        }
    }

    const Scene& m_scene;
    BuiltScene m_built;
    Vec m_gravity;
    std::vector<BodyInfo> m_bodies;
    std::vector<double> m_referenceAngles;
};

bool Finite(Vec2 v)
{
    return std::isfinite(v.x) && std::isfinite(v.y);
}

/// A hit of a dynamic body on a static one without restitution, watched for its rebound.
struct Hit
{
    std::size_t body = 0; ///< index into Run::bodies()
    Vec away;             ///< the contact normal, from the static body into the dynamic one
    int frame = 0;
    double spin = 0; ///< the largest |ω| from the step of the hit on (rad/s)
    std::string where;
};

PlausibilityCheck NewCheck(const char* name, const char* unit)
{
    PlausibilityCheck check;
    check.name = name;
    check.unit = unit;
    return check;
}

std::string Format(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", value);
    return text;
}

} // namespace

std::string DescribeCheck(const PlausibilityCheck& check)
{
    if (!check.applies || check.passed)
    {
        return "";
    }
    std::string text = check.name + " " + Format(check.value) + " " + check.unit + " > " +
                       Format(check.limit) + " " + check.unit;
    if (check.frame >= 0)
    {
        text += " at frame " + std::to_string(check.frame);
    }
    if (!check.where.empty())
    {
        text += " (" + check.where + ")";
    }
    return text;
}

PlausibilityResult CheckPlausibility(const Scene& scene, std::optional<SolverKind> solver,
                                     std::optional<int> frames)
{
    const ScenePlausibility& limits = scene.plausibility;
    PlausibilityResult result;
    result.scene = scene.name;
    result.solver = SolverKindName(solver.value_or(scene.world.solver.kind));
    result.frames = frames.value_or(scene.world.frames);

    Run run(scene, solver);
    const double dt = scene.world.dt;
    const double gravity = std::hypot(scene.world.gravity.x, scene.world.gravity.y);
    const std::vector<BodyInfo>& bodies = run.bodies();

    PlausibilityCheck finite = NewCheck("finite", "");
    PlausibilityCheck energy = NewCheck("energy", "J");
    PlausibilityCheck rebound = NewCheck("rebound", "m/s");
    PlausibilityCheck jointGap = NewCheck("joint_gap", "m");
    PlausibilityCheck penetration = NewCheck("penetration", "m");
    PlausibilityCheck maxSpeed = NewCheck("max_speed", "m/s");
    PlausibilityCheck rise = NewCheck("rise", "m");
    PlausibilityCheck rest = NewCheck("rest", "m/s");
    PlausibilityCheck hold = NewCheck("hold", "m");

    // Energy: E(t) - E(0) may not exceed a fraction of the largest kinetic energy of the run
    // (the integrator's own error, symplectic Euler's O(h) wobble of a swinging body, scales
    // with it) plus, per dynamic body, a lift of energy_lift against gravity (position
    // correction pushes overlapping bodies apart by up to a skin and a slop: 0.01 + 0.005 m)
    // and a speed of energy_speed (what a resting contact's correction may leave).
    const std::string source = run.EnergySource();
    energy.applies = source.empty();
    energy.note = source;
    // What drives a scene (a motor) may also lift a body off what it hit.
    rebound.applies = source.empty();
    rebound.note = source;
    double floor = 0;
    for (const BodyInfo& body : bodies)
    {
        floor += body.mass * (std::abs(body.gravityScale) * gravity * limits.energyLift +
                              0.5 * limits.energySpeed * limits.energySpeed);
    }
    const double startEnergy = run.Energy();
    double largestKinetic = run.Kinetic();
    double largestGain = 0;
    int gainFrame = -1;

    rebound.limit = limits.reboundSpeed;
    penetration.limit = limits.penetration;
    jointGap.limit = limits.jointGap;
    maxSpeed.applies = limits.maxSpeed.has_value();
    maxSpeed.limit = limits.maxSpeed.value_or(0);
    rise.applies = limits.maxRise.has_value();
    rise.limit = limits.maxRise.value_or(0);
    const Vec up = gravity > 0
                       ? Vec{-scene.world.gravity.x / gravity, -scene.world.gravity.y / gravity}
                       : Vec{0, 1};
    std::vector<Vec> startCenters;
    for (const BodyInfo& body : bodies)
    {
        startCenters.push_back(ToVec(run.world().GetWorldCenter(body.id)));
    }
    rest.applies = limits.rest.has_value();
    if (limits.rest)
    {
        rest.limit = limits.rest->speed;
        rest.note = "from " + Format(limits.rest->after) + " s";
    }
    // Hold: where each dynamic body's centre of mass is at hold.after is its place; the
    // furthest any of them is from it later. A structure that falls or slides apart moves its
    // bodies by their own size; one that stands, by what settling moves it (the scene's limit
    // says how much, docs/validation.md).
    hold.applies = limits.hold.has_value();
    std::vector<Vec> places; // empty until hold.after
    if (limits.hold)
    {
        hold.limit = limits.hold->distance;
        hold.note = "from the places at " + Format(limits.hold->after) + " s";
        if (limits.hold->after <= 0)
        {
            places = startCenters;
        }
    }

    const auto [startGap, startGapJoint] = run.JointGap();
    if (startGap > 0)
    {
        jointGap.note = "starts at " + Format(startGap) + " m" +
                        (startGapJoint >= 0 ? " (" + scene.joints[startGapJoint].name + ")" : "");
    }
    const int lastSecond = result.frames - int(std::lround(1.0 / dt));
    const int reboundFrames = std::max(1, int(std::lround(kReboundWindow / dt)));

    using ShapePair = std::pair<std::int32_t, std::int32_t>;
    std::vector<ShapePair> touching;      // the shape pairs reported after this step
    std::vector<ShapePair> touchedBefore; // after the step before, sorted
    std::vector<Vec> previousVelocity(bodies.size());
    std::vector<double> previousAngular(bodies.size());
    double reboundExcess = -1; // the worst hit's leaving speed beyond its allowance (m/s)
    std::vector<Hit> hits;
    std::vector<int> bodyByScene(scene.bodies.size(), -1);
    for (std::size_t i = 0; i < bodies.size(); ++i)
    {
        bodyByScene[bodies[i].scene] = int(i);
    }

    for (int frame = 1; frame <= result.frames; ++frame)
    {
        for (std::size_t i = 0; i < bodies.size(); ++i)
        {
            previousVelocity[i] = ToVec(run.world().GetLinearVelocity(bodies[i].id));
            previousAngular[i] = double(run.world().GetAngularVelocity(bodies[i].id));
        }
        try
        {
            run.built().Step(Real(dt));
        }
        catch (const SimulationError& error)
        {
            finite.passed = false;
            finite.value = 1;
            finite.frame = frame;
            finite.where = error.what();
            break;
        }
        // No NaN or infinity anywhere.
        for (const BodyInfo& body : bodies)
        {
            World& world = run.world();
            if (!Finite(world.GetPosition(body.id)) || !std::isfinite(world.GetAngle(body.id)) ||
                !Finite(world.GetLinearVelocity(body.id)) ||
                !std::isfinite(world.GetAngularVelocity(body.id)))
            {
                finite.passed = false;
                finite.value += 1;
                if (finite.frame < 0)
                {
                    finite.frame = frame;
                    finite.where = run.BodyName(body.scene);
                }
            }
        }
        if (!finite.passed)
        {
            break;
        }

        const double kinetic = run.Kinetic();
        largestKinetic = std::max(largestKinetic, kinetic);
        const double gain = run.Energy() - startEnergy;
        if (gain > largestGain)
        {
            largestGain = gain;
            gainFrame = frame;
        }

        // Contacts: the deepest overlap, and hits on static bodies without restitution.
        touchedBefore.swap(touching);
        std::sort(touchedBefore.begin(), touchedBefore.end());
        touching.clear();
        for (const ContactPointReport& report : run.world().GetContactReports())
        {
            const BodyType typeA = run.world().GetType(report.bodyA);
            const BodyType typeB = run.world().GetType(report.bodyB);
            // Sinking and tunnelling are measured against what cannot move: a dynamic body's
            // overlap with a static one, in a contact that already touched the step before.
            // Two dynamic bodies meeting fast without continuous collision (which Box2D gives
            // only bullets) may overlap deeply, a kinematic body crushes what it meets, and
            // any arrival overlaps in the step it lands (by up to its speed times the step,
            // continuous collision off): those are the step's, and every back end pushes them
            // apart.
            const bool fixedPair = (typeA == BodyType::Static && typeB == BodyType::Dynamic) ||
                                   (typeB == BodyType::Static && typeA == BodyType::Dynamic);
            const ShapePair pair{report.shapeA.index, report.shapeB.index};
            touching.push_back(pair);
            if (fixedPair && std::binary_search(touchedBefore.begin(), touchedBefore.end(), pair) &&
                -double(report.separation) > penetration.value)
            {
                penetration.value = -double(report.separation);
                penetration.frame = frame;
                const auto a = run.SceneIndexOf(report.bodyA);
                const auto b = run.SceneIndexOf(report.bodyB);
                penetration.where =
                    (a ? run.BodyName(*a) : "?") + "/" + (b ? run.BodyName(*b) : "?");
            }
            const bool staticA = typeA == BodyType::Static && typeB == BodyType::Dynamic;
            const bool staticB = typeB == BodyType::Static && typeA == BodyType::Dynamic;
            if (!rebound.applies || (!staticA && !staticB))
            {
                continue;
            }
            const double restitution =
                std::max(double(run.world().GetShapeDef(report.shapeA).restitution),
                         double(run.world().GetShapeDef(report.shapeB).restitution));
            if (restitution != 0)
            {
                continue;
            }
            const auto sceneIndex = run.SceneIndexOf(staticA ? report.bodyB : report.bodyA);
            if (!sceneIndex || bodyByScene[*sceneIndex] < 0)
            {
                continue;
            }
            const std::size_t body = std::size_t(bodyByScene[*sceneIndex]);
            const Vec normal = ToVec(report.normal);
            const Vec away = staticA ? normal : Vec{-normal.x, -normal.y};
            if (Dot(previousVelocity[body], away) < -limits.reboundApproach)
            {
                const auto other = run.SceneIndexOf(staticA ? report.bodyA : report.bodyB);
                hits.push_back(
                    {body, away, frame, std::abs(previousAngular[body]),
                     run.BodyName(*sceneIndex) + " off " + (other ? run.BodyName(*other) : "?")});
            }
        }
        std::erase_if(hits, [&](const Hit& hit) { return frame - hit.frame >= reboundFrames; });
        for (Hit& hit : hits)
        {
            // A spinning body may turn its rotation into a jump (a stick landing on its end, a
            // box tipping onto its face from a corner): all its rotational energy ½mρ²ω² as
            // speed is ρ|ω|, allowed on top, with the fastest spin it had since the hit.
            hit.spin = std::max(hit.spin, std::abs(previousAngular[hit.body]));
            const double allowance = limits.reboundSpeed + bodies[hit.body].gyration * hit.spin;
            const double leaving =
                Dot(ToVec(run.world().GetLinearVelocity(bodies[hit.body].id)), hit.away);
            if (leaving - allowance > reboundExcess)
            {
                reboundExcess = leaving - allowance;
                rebound.value = leaving;
                rebound.limit = allowance;
                rebound.frame = frame;
                rebound.where = hit.where + ", hit at frame " + std::to_string(hit.frame);
            }
        }

        if (frame > lastSecond)
        {
            const auto [gap, joint] = run.JointGap();
            if (gap > jointGap.value)
            {
                jointGap.value = gap;
                jointGap.frame = frame;
                jointGap.where = joint >= 0 ? scene.joints[joint].name : "";
            }
        }

        const bool resting = limits.rest && frame * dt >= limits.rest->after - 1e-9;
        const bool holding = !places.empty();
        if (limits.hold && !holding && frame * dt >= limits.hold->after - 1e-9)
        {
            for (const BodyInfo& body : bodies)
            {
                places.push_back(ToVec(run.world().GetWorldCenter(body.id)));
            }
        }
        for (std::size_t i = 0; i < bodies.size(); ++i)
        {
            const BodyInfo& body = bodies[i];
            const Vec center = ToVec(run.world().GetWorldCenter(body.id));
            const double height = Dot(up, Minus(center, startCenters[i]));
            if (height > rise.value)
            {
                rise.value = height;
                rise.frame = frame;
                rise.where = run.BodyName(body.scene);
            }
            const double speed = run.Speed(body);
            if (speed > maxSpeed.value)
            {
                maxSpeed.value = speed;
                maxSpeed.frame = frame;
                maxSpeed.where = run.BodyName(body.scene);
            }
            if (resting && speed > rest.value)
            {
                rest.value = speed;
                rest.frame = frame;
                rest.where = run.BodyName(body.scene);
            }
            const double moved = holding ? Length(Minus(center, places[i])) : 0.0;
            if (moved > hold.value)
            {
                hold.value = moved;
                hold.frame = frame;
                hold.where = run.BodyName(body.scene);
            }
        }
    }

    energy.value = largestGain;
    energy.frame = gainFrame;
    energy.limit = limits.energyGain * largestKinetic + floor;
    if (energy.applies)
    {
        energy.note = Format(limits.energyGain) + " x largest kinetic energy " +
                      Format(largestKinetic) + " J + " + Format(floor) + " J (lift " +
                      Format(limits.energyLift) + " m, speed " + Format(limits.energySpeed) +
                      " m/s per body)";
    }
    if (scene.joints.empty())
    {
        jointGap.applies = false;
        jointGap.note = "no joints";
    }
    for (PlausibilityCheck* check :
         {&energy, &rebound, &jointGap, &penetration, &maxSpeed, &rise, &rest, &hold})
    {
        check->passed = !check->applies || check->value <= check->limit;
    }
    result.checks = {finite, energy, rebound, jointGap, penetration, maxSpeed, rise, rest, hold};
    result.passed = std::all_of(result.checks.begin(), result.checks.end(),
                                [](const PlausibilityCheck& check) { return check.passed; });
    return result;
}

} // namespace meff::validation
