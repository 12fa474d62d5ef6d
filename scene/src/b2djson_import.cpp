// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// b2dJson → meff scene. The level is converted into a meff scene document, field by field,
// remembering which level field each scene field came from; the scene loader then checks the
// document with every rule a meff scene obeys, and its messages are given back with the
// level's JSON paths. docs/b2djson.md lists the mapping.
#include "b2djson_values.h"
#include "joint_frame.h"
#include "json_document.h"

#include "meff/b2djson.h"
#include "meff/collision.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <set>

namespace meff
{

using b2djson_detail::FormatJson;
using b2djson_detail::Json;
using Out = b2djson_detail::OrderedJson;
using b2djson_detail::ReadNumber;
using b2djson_detail::ReadVector;
using scene_detail::Describe;
using scene_detail::Diagnostics;
using scene_detail::IndexPath;
using scene_detail::JoinPath;

namespace
{

constexpr std::size_t kMaxNameLength = 64;
constexpr const char* kMeffPrefix = "meff.";

Out Pair(SceneVec2 v)
{
    return Out::array({v.x, v.y});
}

/// A name as meff's format allows it: plain characters only (others become '_'), at most 64.
std::string PlainName(const std::string& name)
{
    std::string plain;
    for (const char c : name)
    {
        const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                        (c >= '0' && c <= '9') || c == '_' || c == '-' || c == '.';
        plain += ok ? c : '_';
    }
    if (plain.size() > kMaxNameLength)
    {
        plain.resize(kMaxNameLength);
    }
    return plain;
}

/// Unique plain names for bodies or joints: a level's names may be missing, repeated or hold
/// any character; meff's are unique and plain. Kept as written when they already are.
class NameTable
{
  public:
    explicit NameTable(std::string fallbackPrefix) : m_prefix(std::move(fallbackPrefix)) {}

    /// The scene name for the level's `written` name (empty: none) of item `index`.
    std::string Add(const std::string& written, std::size_t index)
    {
        std::string base = written.empty() ? m_prefix + std::to_string(index) : PlainName(written);
        if (base.empty())
        {
            base = m_prefix + std::to_string(index);
        }
        std::string name = base;
        for (int n = 2; m_used.count(name) != 0; ++n)
        {
            const std::string suffix = "-" + std::to_string(n);
            name = base.substr(0, kMaxNameLength - suffix.size()) + suffix;
        }
        m_used.insert(name);
        if (!written.empty() && name != written)
        {
            m_changed.push_back("\"" + written + "\" -> " + name);
        }
        return name;
    }

    const std::vector<std::string>& Changed() const { return m_changed; }

  private:
    std::string m_prefix;
    std::set<std::string> m_used;
    std::vector<std::string> m_changed;
};

/// The level's custom properties of one object: meff's own ("meff.*") by name, the others
/// counted for the warning.
struct CustomProperties
{
    std::map<std::string, std::pair<const Json*, std::string>> meff; ///< value and its path
    std::size_t foreign = 0;
};

/// Everything the conversion produces: the scene document, where its fields came from, the
/// problems and the warnings.
class Converter
{
  public:
    explicit Converter(std::string file) : m_file(std::move(file)), m_diagnostics(m_file) {}

    const std::string& File() const { return m_file; }
    Diagnostics& Diag() { return m_diagnostics; }

    void Error(const std::string& levelPath, const std::string& message, const Json* got = nullptr)
    {
        if (got != nullptr)
        {
            m_diagnostics.Report(levelPath, message, *got);
        }
        else
        {
            m_diagnostics.Report(levelPath, message);
        }
    }

    /// Records that scene field `scenePath` comes from level field `levelPath`.
    void From(const std::string& scenePath, const std::string& levelPath)
    {
        m_origin[scenePath] = levelPath;
    }

    /// The level path of a scene path: the nearest recorded ancestor, with the rest appended.
    std::string LevelPath(const std::string& scenePath) const
    {
        std::string path = scenePath;
        std::string rest;
        for (;;)
        {
            const auto found = m_origin.find(path);
            if (found != m_origin.end())
            {
                return found->second + rest;
            }
            const std::size_t cut = path.find_last_of(".[");
            if (cut == std::string::npos || cut == 0)
            {
                return scenePath;
            }
            rest = path.substr(cut) + rest;
            path = path.substr(0, cut);
        }
    }

    void Warn(const std::string& message)
    {
        m_warnings.push_back(m_file + ": warning: " + message);
    }
    std::vector<std::string>& Warnings() { return m_warnings; }

  private:
    std::string m_file;
    Diagnostics m_diagnostics;
    std::map<std::string, std::string> m_origin;
    std::vector<std::string> m_warnings;
};

/// Typed reading of one level object by b2dJson's conventions (a float may be a hex string, a
/// zero vector may be 0), reporting at the level's path. Absent fields take b2dJson's loader's
/// defaults, which the caller passes.
class LevelObject
{
  public:
    LevelObject(Converter& converter, const Json& object, std::string path)
        : m_converter(converter), m_object(object), m_path(std::move(path))
    {
    }

    const std::string& Path() const { return m_path; }
    std::string PathOf(std::string_view key) const { return JoinPath(m_path, key); }
    Converter& Conv() { return m_converter; }

    const Json* Find(std::string_view key) const
    {
        const auto found = m_object.find(std::string(key));
        return found == m_object.end() || found->is_null() ? nullptr : &*found;
    }

    std::optional<double> Number(std::string_view key, std::optional<double> fallback)
    {
        const Json* value = Find(key);
        if (value == nullptr)
        {
            if (!fallback)
            {
                m_converter.Error(PathOf(key), "required field is missing");
            }
            return fallback;
        }
        const std::optional<double> number = ReadNumber(*value);
        if (!number)
        {
            m_converter.Error(PathOf(key), "must be a number or a float's bits as 8 hex digits",
                              value);
        }
        else if (!InFloatRange(*number))
        {
            FloatRangeError(PathOf(key), *number);
            return std::nullopt;
        }
        return number;
    }

    std::optional<SceneVec2> Vector(std::string_view key, std::optional<SceneVec2> fallback)
    {
        const Json* value = Find(key);
        if (value == nullptr)
        {
            if (!fallback)
            {
                m_converter.Error(PathOf(key), "required field is missing");
            }
            return fallback;
        }
        const std::optional<SceneVec2> vector = ReadVector(*value);
        if (!vector)
        {
            m_converter.Error(PathOf(key),
                              "must be a vector {\"x\": X, \"y\": Y}, or 0 for the zero vector",
                              value);
        }
        else if (!InFloatRange(vector->x) || !InFloatRange(vector->y))
        {
            const bool x = !InFloatRange(vector->x);
            FloatRangeError(JoinPath(PathOf(key), x ? "x" : "y"), x ? vector->x : vector->y);
            return std::nullopt;
        }
        return vector;
    }

    /// b2dJson's numbers are floats: a finite number beyond the largest float is refused here,
    /// in the level's terms (it was refused later as the scene's "[x, y]"). NaN and infinities
    /// go on to the checks of the field they are in.
    static bool InFloatRange(double value)
    {
        return !std::isfinite(value) ||
               std::abs(value) <= double(std::numeric_limits<float>::max());
    }
    void FloatRangeError(const std::string& path, double value)
    {
        m_converter.Error(path, "must be within a float's range (b2dJson's numbers are floats, "
                                "at most 3.4028235e+38), got " +
                                    scene_detail::FormatNumber(value));
    }

    bool Boolean(std::string_view key, bool fallback)
    {
        const Json* value = Find(key);
        if (value == nullptr)
        {
            return fallback;
        }
        if (!value->is_boolean())
        {
            m_converter.Error(PathOf(key), "must be true or false", value);
            return fallback;
        }
        return value->get<bool>();
    }

    std::optional<long long> Integer(std::string_view key, long long fallback, long long minimum,
                                     long long maximum)
    {
        const Json* value = Find(key);
        if (value == nullptr)
        {
            return fallback;
        }
        if (!value->is_number_integer() || value->get<long long>() < minimum ||
            value->get<long long>() > maximum)
        {
            m_converter.Error(PathOf(key),
                              "must be a whole number from " + std::to_string(minimum) + " to " +
                                  std::to_string(maximum),
                              value);
            return std::nullopt;
        }
        return value->get<long long>();
    }

    std::string String(std::string_view key)
    {
        const Json* value = Find(key);
        if (value == nullptr)
        {
            return {};
        }
        if (!value->is_string())
        {
            m_converter.Error(PathOf(key), "must be a string", value);
            return {};
        }
        return value->get<std::string>();
    }

    /// b2dJson's point lists: {"x": [x0, x1, ...], "y": [y0, y1, ...]}.
    std::optional<std::vector<SceneVec2>> Points(std::string_view key)
    {
        const Json* value = Find(key);
        const std::string path = PathOf(key);
        if (value == nullptr)
        {
            m_converter.Error(path, "required field is missing");
            return std::nullopt;
        }
        const auto xs = value->is_object() ? value->find("x") : value->end();
        const auto ys = value->is_object() ? value->find("y") : value->end();
        if (xs == value->end() || ys == value->end() || !xs->is_array() || !ys->is_array() ||
            xs->size() != ys->size())
        {
            m_converter.Error(path, "must be {\"x\": [...], \"y\": [...]} with as many x as y",
                              value);
            return std::nullopt;
        }
        std::vector<SceneVec2> points;
        for (std::size_t i = 0; i < xs->size(); ++i)
        {
            const std::optional<double> x = ReadNumber((*xs)[i]);
            const std::optional<double> y = ReadNumber((*ys)[i]);
            if (!x || !y)
            {
                m_converter.Error(IndexPath(JoinPath(path, x ? "y" : "x"), i),
                                  "must be a number or a float's bits as 8 hex digits",
                                  &(x ? (*ys)[i] : (*xs)[i]));
                return std::nullopt;
            }
            points.push_back({*x, *y});
        }
        return points;
    }

    /// The "customProperties" list: meff's own by name; the others counted.
    CustomProperties Custom()
    {
        CustomProperties properties;
        const Json* list = Find("customProperties");
        if (list == nullptr)
        {
            return properties;
        }
        if (!list->is_array())
        {
            m_converter.Error(PathOf("customProperties"), "must be an array", list);
            return properties;
        }
        for (std::size_t i = 0; i < list->size(); ++i)
        {
            const Json& property = (*list)[i];
            const std::string path = IndexPath(PathOf("customProperties"), i);
            const auto name = property.is_object() ? property.find("name") : property.end();
            if (name != property.end() && name->is_string() &&
                name->get<std::string>().rfind(kMeffPrefix, 0) == 0)
            {
                properties.meff[name->get<std::string>()] = {&property, path};
            }
            else
            {
                ++properties.foreign;
            }
        }
        return properties;
    }

  private:
    Converter& m_converter;
    const Json& m_object;
    std::string m_path;
};

/// The value of a meff.* custom property of the given type ("string", "int", "float", "bool"),
/// or nullptr (after reporting) when it has another.
const Json* PropertyValue(Converter& converter, const CustomProperties& properties,
                          const std::string& name, const char* type)
{
    const auto found = properties.meff.find(name);
    if (found == properties.meff.end())
    {
        return nullptr;
    }
    const auto& [property, path] = found->second;
    const auto value = property->find(type);
    if (value == property->end())
    {
        converter.Error(path,
                        std::string("the custom property ") + name + " must hold a \"" + type +
                            "\" value",
                        property);
        return nullptr;
    }
    return &*value;
}

/// A meff.* string property holding JSON (a section of a meff scene), parsed; nullptr when
/// absent or bad (reported). `outerDepth`: the containers the section lands in within the
/// scene, so that the scene's nesting cap holds for the embedded text as it is read (a
/// property nested 70,000 levels deep was once parsed without a cap and copied recursively
/// until the stack overflowed).
std::optional<Json> PropertyJson(Converter& converter, const CustomProperties& properties,
                                 const std::string& name, std::size_t outerDepth)
{
    const Json* text = PropertyValue(converter, properties, name, "string");
    if (text == nullptr)
    {
        return std::nullopt;
    }
    if (!text->is_string())
    {
        converter.Error(properties.meff.at(name).second, "must be a string", text);
        return std::nullopt;
    }
    Diagnostics embedded(name);
    std::optional<Json> parsed =
        scene_detail::ParseDocument(text->get<std::string>(), embedded, outerDepth);
    for (const std::string& message : embedded.Messages())
    {
        converter.Error(properties.meff.at(name).second + ".string",
                        "must hold JSON (" + name + " is a section of a meff scene): " + message);
    }
    return embedded.HasErrors() ? std::nullopt : std::move(parsed);
}

/// The conversion of one level.
class Importer
{
  public:
    Importer(Converter& converter, const B2dJsonImportOptions& options)
        : m_converter(converter), m_options(options)
    {
    }

    Out Convert(const Json& level)
    {
        Out scene = Out::object();
        scene["meff_scene"] = kSceneFormatVersion;
        LevelObject world(m_converter, level, "");
        const CustomProperties custom = world.Custom();
        m_foreignProperties += custom.foreign;
        // A level meff wrote (it names its scene) means Box2D 2.4 by its ghost vertices.
        m_writtenByMeff = custom.meff.count("meff.name") != 0;
        ConvertScene(world, custom, scene);
        ConvertBodies(world, scene);
        ConvertJoints(world, scene);
        if (const Json* images = world.Find("image"); images != nullptr && images->is_array())
        {
            m_images = images->size();
        }
        Warnings();
        return scene;
    }

  private:
    // ---- world and scene ----------------------------------------------------------------

    void ConvertScene(LevelObject& world, const CustomProperties& custom, Out& scene)
    {
        for (const char* key : {"name", "description"})
        {
            if (const Json* text =
                    PropertyValue(m_converter, custom, kMeffPrefix + std::string(key), "string"))
            {
                scene[key] = *text;
                m_converter.From(key, custom.meff.at(kMeffPrefix + std::string(key)).second);
            }
        }
        Out settings = Out::object();
        const auto put = [&](const char* key, const Out& value, const std::string& levelPath)
        {
            settings[key] = value;
            m_converter.From(std::string("world.") + key, levelPath);
        };
        if (const std::optional<SceneVec2> gravity = world.Vector("gravity", SceneVec2{0, -10}))
        {
            put("gravity", Pair(*gravity), world.PathOf("gravity"));
        }
        // R.U.B.E. writes the step rate and iterations; b2dJson's own loader leaves them to
        // the game (60 Hz, 8 and 3 are the testbed's).
        const std::optional<double> rate = world.Number("stepsPerSecond", 60.0);
        if (rate && !(*rate > 0))
        {
            m_converter.Error(world.PathOf("stepsPerSecond"), "must be > 0",
                              world.Find("stepsPerSecond"));
        }
        else if (rate)
        {
            // meff.dt is the exact step the scene was exported with; it stands while the
            // level's rate is still its inverse (an edited rate wins).
            double dt = 1.0 / *rate;
            if (const Json* exact = PropertyValue(m_converter, custom, "meff.dt", "float"))
            {
                const std::optional<double> value = ReadNumber(*exact);
                if (value && *value > 0 && 1.0 / *value == *rate)
                {
                    dt = *value;
                }
            }
            put("dt", dt, world.PathOf("stepsPerSecond"));
        }
        if (const std::optional<long long> v = world.Integer("velocityIterations", 8, 1, 1000))
        {
            put("velocity_iterations", *v, world.PathOf("velocityIterations"));
        }
        if (const std::optional<long long> p = world.Integer("positionIterations", 3, 0, 1000))
        {
            put("position_iterations", *p, world.PathOf("positionIterations"));
        }
        // b2dJson's loader reads a missing flag as false.
        put("warm_starting", world.Boolean("warmStarting", false), world.PathOf("warmStarting"));
        put("continuous", world.Boolean("continuousPhysics", false),
            world.PathOf("continuousPhysics"));
        put("allow_sleep", world.Boolean("allowSleep", false), world.PathOf("allowSleep"));
        if (world.Boolean("subStepping", false))
        {
            m_converter.Warn("subStepping: meff has no sub-stepping (a Box2D debugging aid); "
                             "the level is stepped normally");
        }
        if (const Json* frames = PropertyValue(m_converter, custom, "meff.frames", "int"))
        {
            put("frames", *frames, custom.meff.at("meff.frames").second);
        }
        if (const Json* kind = PropertyValue(m_converter, custom, "meff.solver", "string"))
        {
            put("solver", *kind, custom.meff.at("meff.solver").second);
        }
        for (const char* key : {"block_solver", "block_joints", "restitution_from_step_start"})
        {
            const std::string name = kMeffPrefix + std::string(key);
            if (const Json* flag = PropertyValue(m_converter, custom, name, "bool"))
            {
                put(key, *flag, custom.meff.at(name).second);
            }
        }
        // world.soft_step is a section of its own: the loader checks each member, its
        // messages naming the property.
        if (std::optional<Json> soft =
                PropertyJson(m_converter, custom, "meff.soft_step", 2 /* root, world */))
        {
            put("soft_step", std::move(*soft),
                custom.meff.at("meff.soft_step").second + " (meff.soft_step)");
        }
        scene["world"] = settings;
        m_converter.From("world", "");
        for (const char* section : {"validate", "render", "analytic", "plausibility"})
        {
            const std::string name = kMeffPrefix + std::string(section);
            if (std::optional<Json> value = PropertyJson(m_converter, custom, name, 1 /* root */))
            {
                scene[section] = std::move(*value);
                m_converter.From(section, custom.meff.at(name).second + " (" + name + ")");
            }
        }
    }

    // ---- bodies and fixtures -------------------------------------------------------------

    void ConvertBodies(LevelObject& world, Out& scene)
    {
        scene["bodies"] = Out::array();
        m_converter.From("bodies", "body");
        const Json* bodies = world.Find("body");
        if (bodies == nullptr)
        {
            return;
        }
        if (!bodies->is_array())
        {
            m_converter.Error("body", "must be an array", bodies);
            return;
        }
        for (std::size_t i = 0; i < bodies->size(); ++i)
        {
            const std::string path = IndexPath("body", i);
            if (!(*bodies)[i].is_object())
            {
                m_converter.Error(path, "must be an object", &(*bodies)[i]);
                m_sceneBody.push_back(-1);
                continue;
            }
            LevelObject body(m_converter, (*bodies)[i], path);
            if (!body.Boolean("active", true))
            {
                // Box2D never simulates an inactive body nor a joint on it.
                m_inactive.push_back(path);
                m_sceneBody.push_back(-1);
                continue;
            }
            m_sceneBody.push_back(std::ptrdiff_t(scene["bodies"].size()));
            scene["bodies"].push_back(ConvertBody(body, scene["bodies"].size()));
        }
    }

    Out ConvertBody(LevelObject& body, std::size_t index)
    {
        const std::string scenePath = IndexPath("bodies", index);
        m_converter.From(scenePath, body.Path());
        const CustomProperties custom = body.Custom();
        m_foreignProperties += custom.foreign;
        Out out = Out::object();
        const auto put = [&](const char* key, const Out& value, std::string_view levelKey)
        {
            out[key] = value;
            m_converter.From(JoinPath(scenePath, key), body.PathOf(levelKey));
        };
        const std::string name = m_bodyNames.Add(body.String("name"), index);
        m_bodyName.push_back(name);
        put("name", name, "name");
        int type = 0;
        if (const Json* written = body.Find("type"))
        {
            // b2dJson writes b2BodyType's number; a few exporters write the word.
            static const char* const kWords[] = {"static", "kinematic", "dynamic"};
            if (written->is_number_integer() && written->get<long long>() >= 0 &&
                written->get<long long>() <= 2)
            {
                type = int(written->get<long long>());
            }
            else if (written->is_string() &&
                     std::find(std::begin(kWords), std::end(kWords), written->get<std::string>()) !=
                         std::end(kWords))
            {
                type = int(
                    std::find(std::begin(kWords), std::end(kWords), written->get<std::string>()) -
                    std::begin(kWords));
            }
            else
            {
                m_converter.Error(body.PathOf("type"),
                                  "must be 0 (static), 1 (kinematic) or 2 (dynamic)", written);
            }
        }
        static const char* const kTypes[] = {"static", "kinematic", "dynamic"};
        put("type", kTypes[type], "type");
        m_bodyTypes.push_back(type);
        const std::optional<SceneVec2> position = body.Vector("position", SceneVec2{});
        const std::optional<double> angle = body.Number("angle", 0.0);
        if (position)
        {
            put("position", Pair(*position), "position");
        }
        if (angle)
        {
            put("angle", *angle, "angle");
        }
        m_bodyPose.push_back({position.value_or(SceneVec2{}), angle.value_or(0.0)});
        // A static body never moves in Box2D whatever velocity it was given; meff's format
        // refuses one, so it is left out.
        if (type != 0)
        {
            if (const std::optional<SceneVec2> v = body.Vector("linearVelocity", SceneVec2{}))
            {
                put("linear_velocity", Pair(*v), "linearVelocity");
            }
            if (const std::optional<double> w = body.Number("angularVelocity", 0.0))
            {
                put("angular_velocity", *w, "angularVelocity");
            }
        }
        if (const std::optional<double> c = body.Number("linearDamping", 0.0))
        {
            put("linear_damping", *c, "linearDamping");
        }
        if (const std::optional<double> c = body.Number("angularDamping", 0.0))
        {
            put("angular_damping", *c, "angularDamping");
        }
        if (const std::optional<double> g = body.Number("gravityScale", 1.0))
        {
            put("gravity_scale", *g, "gravityScale");
        }
        put("fixed_rotation", body.Boolean("fixedRotation", false), "fixedRotation");
        put("bullet", body.Boolean("bullet", false), "bullet");
        put("allow_sleep", body.Boolean("allowSleep", true), "allowSleep");
        // b2dJson's loader creates a body asleep unless the level says "awake": true.
        put("awake", body.Boolean("awake", false), "awake");
        if (const Json* given = body.Find("massData-mass"))
        {
            // Not kept (meff computes mass), but a NaN or a negative mass is a broken level,
            // not a mass set by hand: said, as every other field's (it once passed unsaid).
            if (const std::optional<double> mass = body.Number("massData-mass", 0.0))
            {
                if (std::isfinite(*mass) && *mass >= 0)
                {
                    m_handMass.emplace_back(index, *mass);
                }
                else
                {
                    m_converter.Error(body.PathOf("massData-mass"), "must be finite and >= 0",
                                      given);
                }
            }
        }
        out["shapes"] = Out::array();
        m_converter.From(JoinPath(scenePath, "shapes"), body.PathOf("fixture"));
        if (const Json* fixtures = body.Find("fixture"))
        {
            if (!fixtures->is_array())
            {
                m_converter.Error(body.PathOf("fixture"), "must be an array", fixtures);
                return out;
            }
            for (std::size_t k = 0; k < fixtures->size(); ++k)
            {
                const std::string path = IndexPath(body.PathOf("fixture"), k);
                if (!(*fixtures)[k].is_object())
                {
                    m_converter.Error(path, "must be an object", &(*fixtures)[k]);
                    continue;
                }
                LevelObject fixture(m_converter, (*fixtures)[k], path);
                ConvertFixture(fixture, scenePath, out["shapes"]);
            }
        }
        return out;
    }

    /// Appends the fixture's shape.
    void ConvertFixture(LevelObject& fixture, const std::string& bodyPath, Out& shapes)
    {
        const CustomProperties custom = fixture.Custom();
        m_foreignProperties += custom.foreign;
        Out material = Out::object();
        std::map<std::string, std::string> materialFrom;
        const auto material_put = [&](const char* key, const Out& value, std::string_view from)
        {
            material[key] = value;
            materialFrom[key] = fixture.PathOf(from);
        };
        // b2dJson leaves out zeros: a missing friction, restitution or density is 0.
        for (const auto& [key, levelKey] :
             {std::pair{"density", "density"}, std::pair{"friction", "friction"},
              std::pair{"restitution", "restitution"}})
        {
            if (const std::optional<double> value = fixture.Number(levelKey, 0.0))
            {
                material_put(key, *value, levelKey);
            }
        }
        // Box2D 2.4's restitution threshold, which b2dJson (2.3) does not have: meff's export
        // writes it when it is not the default 1 m/s.
        if (const std::optional<double> threshold = fixture.Number("restitutionThreshold", 1.0))
        {
            material_put("restitution_threshold", *threshold, "restitutionThreshold");
        }
        material_put("sensor", fixture.Boolean("sensor", false), "sensor");
        // meff's surface fields, which R.U.B.E. has no place for, travel as meff.* properties.
        for (const auto& [key, name] : {std::pair{"tangent_speed", "meff.tangent_speed"},
                                        std::pair{"rolling_resistance", "meff.rolling_resistance"}})
        {
            if (const Json* value = PropertyValue(m_converter, custom, name, "float"))
            {
                const std::string& path = custom.meff.at(name).second;
                if (const std::optional<double> number = ReadNumber(*value))
                {
                    material[key] = *number;
                    materialFrom[key] = path;
                }
                else
                {
                    m_converter.Error(path, "must hold a number in \"float\"", value);
                }
            }
        }
        Out filter = Out::object();
        const auto filterPut = [&](const char* key, const char* levelKey, long long fallback,
                                   long long low, long long high)
        {
            if (const std::optional<long long> bits =
                    fixture.Integer(levelKey, fallback, low, high))
            {
                filter[key] = *bits;
                materialFrom[std::string("filter.") + key] = fixture.PathOf(levelKey);
            }
        };
        filterPut("category", "filter-categoryBits", 1, 0, 0xFFFF);
        filterPut("mask", "filter-maskBits", 0xFFFF, 0, 0xFFFF);
        filterPut("group", "filter-groupIndex", 0, INT16_MIN, INT16_MAX);
        material["filter"] = filter;
        materialFrom["filter"] = fixture.Path();

        const auto add = [&](Out shape, const std::map<std::string, std::string>& geometryFrom)
        {
            const std::string path = IndexPath(JoinPath(bodyPath, "shapes"), shapes.size());
            m_converter.From(path, fixture.Path());
            for (const auto& [key, from] : geometryFrom)
            {
                m_converter.From(JoinPath(path, key), from);
            }
            for (const auto& [key, from] : materialFrom)
            {
                m_converter.From(JoinPath(path, key), from);
            }
            shape.update(material);
            shapes.push_back(std::move(shape));
        };

        if (const Json* circle = fixture.Find("circle"))
        {
            LevelObject geometry(m_converter, *circle, fixture.PathOf("circle"));
            Out shape = {{"type", "circle"}};
            if (const std::optional<double> radius = geometry.Number("radius", 0.0))
            {
                shape["radius"] = *radius;
            }
            if (const std::optional<SceneVec2> center = geometry.Vector("center", SceneVec2{}))
            {
                shape["center"] = Pair(*center);
            }
            add(shape, {{"type", fixture.PathOf("circle")},
                        {"radius", geometry.PathOf("radius")},
                        {"center", geometry.PathOf("center")}});
        }
        else if (const Json* polygon = fixture.Find("polygon"))
        {
            ConvertPolygon(fixture, *polygon, custom, add);
        }
        else if (const Json* edge = fixture.Find("edge"))
        {
            LevelObject geometry(m_converter, *edge, fixture.PathOf("edge"));
            const std::optional<SceneVec2> a = geometry.Vector("vertex1", std::nullopt);
            const std::optional<SceneVec2> b = geometry.Vector("vertex2", std::nullopt);
            if (!a || !b)
            {
                return;
            }
            Out shape = {{"type", "segment"}, {"points", {Pair(*a), Pair(*b)}}};
            std::map<std::string, std::string> from = {{"type", fixture.PathOf("edge")},
                                                       {"points", fixture.PathOf("edge")}};
            // Ghost vertices make Box2D 2.4's edge one-sided (b2EdgeShape::SetOneSided); a
            // missing one is the end segment continued, as the scene loader fills it in.
            const bool before = geometry.Boolean("hasVertex0", false);
            const bool after = geometry.Boolean("hasVertex3", false);
            if ((before || after) && TwoSidedChains())
            {
                m_twoSidedChains.push_back(fixture.Path()); // Box2D 2.3's edge: two-sided
            }
            else if (before || after)
            {
                shape["one_sided"] = true;
                Ghost(geometry, before, "vertex0", "prev", shape, from);
                Ghost(geometry, after, "vertex3", "next", shape, from);
                m_oneSidedEdges.push_back(fixture.Path());
            }
            add(shape, from);
        }
        else if (fixture.Find("chain") != nullptr || fixture.Find("loop") != nullptr)
        {
            ConvertChain(fixture, add);
        }
        else
        {
            m_converter.Error(fixture.Path(),
                              "has no shape (one of circle, polygon, edge, chain, loop)");
        }
    }

    /// A ghost vertex the level gives (`has`) as `levelKey`, into the shape's `key`.
    void Ghost(LevelObject& geometry, bool has, const char* levelKey, const char* key, Out& shape,
               std::map<std::string, std::string>& from)
    {
        if (!has)
        {
            return;
        }
        if (const std::optional<SceneVec2> ghost = geometry.Vector(levelKey, std::nullopt))
        {
            shape[key] = Pair(*ghost);
            from[key] = geometry.PathOf(levelKey);
        }
    }

    /// A chain, or a loop: R.U.B.E.'s "loop" (before r197), or a chain whose last point
    /// repeats its first (how Box2D 2.3's CreateLoop stores one, and b2dJson writes it).
    template <typename Add>
    void ConvertChain(LevelObject& fixture, const Add& add)
    {
        const bool oldLoop = fixture.Find("chain") == nullptr;
        const char* key = oldLoop ? "loop" : "chain";
        LevelObject geometry(m_converter, *fixture.Find(key), fixture.PathOf(key));
        std::optional<std::vector<SceneVec2>> points = geometry.Points("vertices");
        if (!points)
        {
            return;
        }
        const bool closed = points->size() >= 4 && points->front() == points->back() && !oldLoop;
        Out shape = {{"type", "chain"}};
        std::map<std::string, std::string> from = {{"type", fixture.PathOf(key)},
                                                   {"points", geometry.PathOf("vertices")}};
        if (oldLoop || closed)
        {
            if (closed)
            {
                points->pop_back();
            }
            shape["loop"] = true;
            from["loop"] = fixture.PathOf(key);
        }
        Out list = Out::array();
        for (const SceneVec2& point : *points)
        {
            list.push_back(Pair(point));
        }
        if (TwoSidedChains())
        {
            // Box2D 2.3's chain: each edge collides on both sides, as a two-sided segment.
            const std::size_t edges = shape.contains("loop") ? points->size() : points->size() - 1;
            for (std::size_t i = 0; i < edges; ++i)
            {
                add(Out{{"type", "segment"},
                        {"points",
                         {Pair((*points)[i]), Pair((*points)[(i + 1) % points->size()])}}},
                    {{"type", fixture.PathOf(key)}, {"points", geometry.PathOf("vertices")}});
            }
            m_twoSidedChains.push_back(fixture.Path());
            return;
        }
        shape["points"] = list;
        m_oneSidedEdges.push_back(fixture.Path());
        if (!oldLoop && !closed)
        {
            Ghost(geometry, geometry.Boolean("hasPrevVertex", false), "prevVertex", "prev", shape,
                  from);
            Ghost(geometry, geometry.Boolean("hasNextVertex", false), "nextVertex", "next", shape,
                  from);
        }
        add(shape, from);
    }

    template <typename Add>
    void ConvertPolygon(LevelObject& fixture, const Json& polygon, const CustomProperties& custom,
                        const Add& add)
    {
        LevelObject geometry(m_converter, polygon, fixture.PathOf("polygon"));
        const std::optional<std::vector<SceneVec2>> points = geometry.Points("vertices");
        if (!points)
        {
            return;
        }
        const std::string from = geometry.PathOf("vertices");
        if (points->size() == 2)
        {
            // As b2dJson's loader does: a two-point polygon is an edge.
            add({{"type", "segment"}, {"points", {Pair((*points)[0]), Pair((*points)[1])}}},
                {{"type", fixture.PathOf("polygon")}, {"points", from}});
            return;
        }
        if (std::optional<Json> box =
                PropertyJson(m_converter, custom, "meff.box", 4 /* root, bodies, [i], shapes */))
        {
            if (IsBoxOf(*box, *points))
            {
                Out shape = {{"type", "box"}};
                shape.update(Out(*box));
                add(shape, {{"type", fixture.PathOf("polygon")},
                            {"half_width", from},
                            {"half_height", from},
                            {"center", from},
                            {"angle", from}});
                return;
            }
        }
        Out vertices = Out::array();
        for (const SceneVec2& point : *points)
        {
            vertices.push_back(Pair(point));
        }
        add({{"type", "polygon"}, {"vertices", vertices}},
            {{"type", fixture.PathOf("polygon")}, {"vertices", from}});
    }

    /// Whether meff's box `box` ({half_width, half_height, center, angle}) has exactly these
    /// corners, in this order, in the engine's precision: then the box is what was drawn.
    static bool IsBoxOf(const Json& box, const std::vector<SceneVec2>& points)
    {
        if (!box.is_object() || points.size() != 4)
        {
            return false;
        }
        const auto number = [&](const char* key, double fallback)
        {
            const auto found = box.find(key);
            return found == box.end() || !found->is_number() ? fallback : found->get<double>();
        };
        SceneVec2 center;
        if (const auto found = box.find("center"); found != box.end() && found->is_array() &&
                                                   found->size() == 2 && (*found)[0].is_number() &&
                                                   (*found)[1].is_number())
        {
            center = {(*found)[0].get<double>(), (*found)[1].get<double>()};
        }
        const double halfWidth = number("half_width", 0);
        const double halfHeight = number("half_height", 0);
        if (!(halfWidth > 0) || !(halfHeight > 0))
        {
            return false;
        }
        try
        {
            const Polygon corners =
                MakeOffsetBox(Real(halfWidth), Real(halfHeight), scene_detail::ToEngine(center),
                              Real(number("angle", 0)));
            for (std::size_t i = 0; i < 4; ++i)
            {
                if (corners.vertices[i].x != Real(points[i].x) ||
                    corners.vertices[i].y != Real(points[i].y))
                {
                    return false;
                }
            }
        }
        catch (const Error&)
        {
            return false;
        }
        return true;
    }

    // ---- joints ------------------------------------------------------------------------------

    void ConvertJoints(LevelObject& world, Out& scene)
    {
        scene["joints"] = Out::array();
        m_converter.From("joints", "joint");
        const Json* joints = world.Find("joint");
        if (joints == nullptr)
        {
            return;
        }
        if (!joints->is_array())
        {
            m_converter.Error("joint", "must be an array", joints);
            return;
        }
        MakePoseWorld();
        for (std::size_t j = 0; j < joints->size(); ++j)
        {
            const std::string path = IndexPath("joint", j);
            if (!(*joints)[j].is_object())
            {
                m_converter.Error(path, "must be an object", &(*joints)[j]);
                continue;
            }
            LevelObject joint(m_converter, (*joints)[j], path);
            std::optional<Out> converted = ConvertJoint(joint, j, scene["joints"].size());
            if (converted)
            {
                scene["joints"].push_back(std::move(*converted));
            }
        }
    }

    /// The scene body index of the level body `key` names; nullopt (reported, or the joint
    /// left out with its inactive body) otherwise.
    std::optional<std::size_t> JointBody(LevelObject& joint, const char* key, bool& dropped)
    {
        const Json* index = joint.Find(key);
        if (index == nullptr || !index->is_number_integer() || index->get<long long>() < 0 ||
            index->get<long long>() >= (long long)m_sceneBody.size())
        {
            m_converter.Error(joint.PathOf(key),
                              "must be the index of a body in \"body\" (0 to " +
                                  std::to_string(long(m_sceneBody.size()) - 1) + ")",
                              index);
            return std::nullopt;
        }
        const std::ptrdiff_t scene = m_sceneBody[std::size_t(index->get<long long>())];
        if (scene < 0)
        {
            dropped = true;
            return std::nullopt;
        }
        return std::size_t(scene);
    }

    std::optional<Out> ConvertJoint(LevelObject& joint, std::size_t levelIndex,
                                    std::size_t sceneIndex)
    {
        const std::string type = joint.String("type");
        bool dropped = false;
        const std::optional<std::size_t> a = JointBody(joint, "bodyA", dropped);
        const std::optional<std::size_t> b = JointBody(joint, "bodyB", dropped);
        if (dropped)
        {
            m_inactiveJoints.push_back(joint.Path());
            return std::nullopt;
        }
        static const std::set<std::string> kMissing = {"pulley", "gear"};
        if (kMissing.count(type) != 0)
        {
            m_converter.Error(joint.PathOf("type"),
                              "meff does not read b2dJson " + type +
                                  " joints (meff's export refuses them too: write the joint in "
                                  "a meff scene)",
                              joint.Find("type"));
            return std::nullopt;
        }
        static const std::set<std::string> kKnown = {"revolute", "distance", "prismatic",
                                                     "wheel",    "weld",     "motor",
                                                     "mouse",    "rope",     "friction"};
        if (kKnown.count(type) == 0)
        {
            m_converter.Error(joint.PathOf("type"),
                              "must be one of \"revolute\", \"distance\", \"prismatic\", "
                              "\"wheel\", \"weld\", \"friction\", \"motor\", \"mouse\", "
                              "\"pulley\", \"gear\", \"rope\"",
                              joint.Find("type"));
            return std::nullopt;
        }
        if (!a || !b)
        {
            return std::nullopt;
        }
        // Box2D never solves a joint between two bodies that cannot move; meff's format
        // refuses one, so it is left out (the simulation is the same).
        if (m_bodyTypes[*a] != 2 && m_bodyTypes[*b] != 2)
        {
            m_immovableJoints.push_back(joint.Path());
            return std::nullopt;
        }
        const std::string scenePath = IndexPath("joints", sceneIndex);
        m_converter.From(scenePath, joint.Path());
        const CustomProperties custom = joint.Custom();
        m_foreignProperties += custom.foreign;
        Out out = Out::object();
        const auto put = [&](const char* key, const Out& value, const std::string& from)
        {
            out[key] = value;
            m_converter.From(JoinPath(scenePath, key), from);
        };
        put("type", type == "rope" ? "distance" : type, joint.PathOf("type"));
        put("name", m_jointNames.Add(joint.String("name"), levelIndex), joint.PathOf("name"));
        put("body_a", m_bodyName[*a], joint.PathOf("bodyA"));
        put("body_b", m_bodyName[*b], joint.PathOf("bodyB"));
        put("collide_connected", joint.Boolean("collideConnected", false),
            joint.PathOf("collideConnected"));
        const auto number = [&](const char* key, const char* levelKey, double fallback = 0)
        {
            if (const std::optional<double> value = joint.Number(levelKey, fallback))
            {
                put(key, *value, joint.PathOf(levelKey));
            }
        };
        const auto flag = [&](const char* key, const char* levelKey)
        { put(key, joint.Boolean(levelKey, false), joint.PathOf(levelKey)); };
        const auto localAnchors = [&]
        {
            for (const auto& [key, levelKey] :
                 {std::pair{"local_anchor_a", "anchorA"}, std::pair{"local_anchor_b", "anchorB"}})
            {
                if (const std::optional<SceneVec2> anchor = joint.Vector(levelKey, SceneVec2{}))
                {
                    put(key, Pair(*anchor), joint.PathOf(levelKey));
                }
            }
        };
        if (type == "revolute" || type == "weld" || type == "prismatic" || type == "wheel" ||
            type == "distance" || type == "rope" || type == "friction")
        {
            localAnchors();
        }
        if (type == "revolute" || type == "weld" || type == "prismatic")
        {
            number("reference_angle", "refAngle");
        }
        if (type == "revolute" || type == "prismatic" || type == "wheel")
        {
            flag("enable_limit", "enableLimit");
            flag("enable_motor", "enableMotor");
            number("motor_speed", "motorSpeed");
        }
        if (type == "revolute")
        {
            number("lower_angle", "lowerLimit");
            number("upper_angle", "upperLimit");
            number("max_motor_torque", "maxMotorTorque");
        }
        if (type == "prismatic" || type == "wheel")
        {
            const char* axisKey =
                joint.Find("localAxisA") == nullptr && joint.Find("localAxis1") != nullptr
                    ? "localAxis1" // before R.U.B.E. 1.3
                    : "localAxisA";
            if (const std::optional<SceneVec2> axis = joint.Vector(axisKey, SceneVec2{1, 0}))
            {
                put("local_axis_a", Pair(*axis), joint.PathOf(axisKey));
            }
            number("lower_translation", "lowerLimit");
            number("upper_translation", "upperLimit");
        }
        if (type == "prismatic")
        {
            number("max_motor_force", "maxMotorForce");
        }
        if (type == "wheel")
        {
            number("max_motor_torque", "maxMotorTorque");
            number("stiffness_hz", "springFrequency");
            number("damping_ratio", "springDampingRatio");
        }
        if (type == "weld" || type == "mouse")
        {
            number("stiffness_hz", "frequency");
            number("damping_ratio", "dampingRatio");
        }
        if (type == "distance")
        {
            ConvertDistance(joint, put);
        }
        if (type == "rope")
        {
            // Box2D 2.4 has no rope joint: a distance joint that only stops the bodies going
            // further apart than maxLength, with no spring, is what it was.
            // (meff's export also writes the rest length and a minimum, which it reads back.)
            if (const std::optional<double> maxLength = joint.Number("maxLength", 0.0))
            {
                put("max_length", *maxLength, joint.PathOf("maxLength"));
                if (const std::optional<double> length = joint.Number("length", *maxLength))
                {
                    put("length", *length,
                        joint.PathOf(joint.Find("length") ? "length" : "maxLength"));
                }
                if (const std::optional<double> minLength = joint.Number("minLength", 0.0))
                {
                    put("min_length", *minLength,
                        joint.PathOf(joint.Find("minLength") ? "minLength" : "maxLength"));
                }
            }
        }
        if (type == "motor")
        {
            const char* offsetKey =
                joint.Find("linearOffset") == nullptr && joint.Find("anchorA") != nullptr
                    ? "anchorA" // R.U.B.E. before 1.7
                    : "linearOffset";
            if (const std::optional<SceneVec2> offset = joint.Vector(offsetKey, SceneVec2{}))
            {
                put("linear_offset", Pair(*offset), joint.PathOf(offsetKey));
            }
            number("angular_offset", "refAngle");
            number("max_force", "maxForce");
            number("max_torque", "maxTorque");
            number("correction_factor", "correctionFactor");
        }
        if (type == "friction")
        {
            number("max_force", "maxForce");
            number("max_torque", "maxTorque");
        }
        if (type == "mouse")
        {
            // b2dJson writes the grabbed point (anchorB) and the target as world points.
            if (const std::optional<SceneVec2> anchor = joint.Vector("anchorB", SceneVec2{}))
            {
                put("anchor", Pair(*anchor), joint.PathOf("anchorB"));
            }
            if (const std::optional<SceneVec2> target = joint.Vector("target", SceneVec2{}))
            {
                put("target", Pair(*target), joint.PathOf("target"));
            }
            number("max_force", "maxForce");
        }
        if (std::optional<Json> form =
                PropertyJson(m_converter, custom, "meff.joint", 2 /* root, joints */))
        {
            UseAuthoringForm(*form, *a, *b, out);
        }
        // 2.3 sizes these springs from the joint's effective mass (Importer::Springs23).
        if ((type == "distance" || type == "wheel" || type == "weld") &&
            out.contains("stiffness_hz") && out["stiffness_hz"].get<double>() > 0)
        {
            m_springs23.emplace_back(sceneIndex, joint.Path());
        }
        return out;
    }

    template <typename Put>
    void ConvertDistance(LevelObject& joint, const Put& put)
    {
        const std::optional<double> length = joint.Number("length", 0.0);
        const std::optional<double> frequency = joint.Number("frequency", 0.0);
        if (length)
        {
            put("length", *length, joint.PathOf("length"));
        }
        if (frequency)
        {
            put("stiffness_hz", *frequency, joint.PathOf("frequency"));
        }
        if (const std::optional<double> ratio = joint.Number("dampingRatio", 0.0))
        {
            put("damping_ratio", *ratio, joint.PathOf("dampingRatio"));
        }
        // Box2D 2.3's distance joint (what R.U.B.E. writes) is a rigid rod without a spring
        // and a spring with no limits with one; 2.4's limits say which. A level from a 2.4
        // exporter may give them.
        const bool spring = frequency && *frequency > 0;
        const double huge = double(std::numeric_limits<float>::max());
        if (const std::optional<double> minLength =
                joint.Number("minLength", spring ? 0.0 : length.value_or(0.0)))
        {
            put("min_length", *minLength,
                joint.PathOf(joint.Find("minLength") ? "minLength" : "length"));
        }
        if (const std::optional<double> maxLength =
                joint.Number("maxLength", spring ? huge : length.value_or(0.0)))
        {
            put("max_length", *maxLength,
                joint.PathOf(joint.Find("maxLength") ? "maxLength" : "length"));
        }
    }

    /// A bodies-only world with the level's poses, for the engine's joint-frame arithmetic.
    void MakePoseWorld()
    {
        try
        {
            for (const auto& [position, angle] : m_bodyPose)
            {
                BodyDef def;
                def.position = scene_detail::ToEngine(position);
                def.angle = Real(angle);
                m_poseBodies.push_back(m_poseWorld.CreateBody(def));
            }
        }
        catch (const Error&)
        {
            m_poseBodies.clear(); // a bad pose is reported by the loader; no authoring forms
        }
    }

    /// meff's export records how a joint was written in the scene (world-point anchors, a
    /// world axis, offsets left to their defaults) as "meff.joint". It replaces the level's
    /// local fields when it gives the engine exactly the same joint frame, float for float; an
    /// edit in the editor makes them differ, and then the level's fields stand.
    void UseAuthoringForm(const Json& form, std::size_t a, std::size_t b, Out& joint)
    {
        if (!form.is_object() || m_poseBodies.empty())
        {
            return;
        }
        const std::optional<SceneJoint> local = FrameFields(joint);
        // Each authored key replaces the local fields it stands for (null: "as created", the
        // field left out); only these keys are taken from the form.
        static const std::pair<const char*, std::vector<const char*>> kReplaces[] = {
            {"anchor", {"local_anchor_a", "local_anchor_b"}},
            {"anchor_a", {"local_anchor_a", "local_anchor_b"}},
            {"anchor_b", {"local_anchor_a", "local_anchor_b"}},
            {"axis", {"local_axis_a"}},
            {"reference_angle", {"reference_angle"}},
            {"linear_offset", {"linear_offset"}},
            {"angular_offset", {"angular_offset"}}};
        Out candidate = joint;
        for (const auto& [key, replaced] : kReplaces)
        {
            if (!form.contains(key))
            {
                continue;
            }
            for (const char* local : replaced)
            {
                candidate.erase(local);
            }
        }
        for (const auto& [key, replaced] : kReplaces)
        {
            if (form.contains(key) && !form[key].is_null())
            {
                candidate[key] = form[key];
            }
        }
        const std::optional<SceneJoint> authored = FrameFields(candidate);
        if (!local || !authored)
        {
            return;
        }
        try
        {
            const scene_detail::JointFrame x = scene_detail::ComputeJointFrame(
                m_poseWorld, m_poseBodies[a], m_poseBodies[b], *local);
            const scene_detail::JointFrame y = scene_detail::ComputeJointFrame(
                m_poseWorld, m_poseBodies[a], m_poseBodies[b], *authored);
            const auto same = [](Vec2 p, Vec2 q) { return p.x == q.x && p.y == q.y; };
            if (same(x.localAnchorA, y.localAnchorA) && same(x.localAnchorB, y.localAnchorB) &&
                x.referenceAngle == y.referenceAngle && same(x.localAxisA, y.localAxisA) &&
                same(x.linearOffset, y.linearOffset) && x.angularOffset == y.angularOffset)
            {
                joint = std::move(candidate);
            }
        }
        catch (const Error&)
        {
        }
    }

    /// The frame-defining fields of a converted joint, as a SceneJoint; nullopt when one is
    /// malformed (the loader will say so).
    static std::optional<SceneJoint> FrameFields(const Out& joint)
    {
        static const std::map<std::string, JointType> kTypes = {
            {"revolute", JointType::Revolute},   {"distance", JointType::Distance},
            {"prismatic", JointType::Prismatic}, {"wheel", JointType::Wheel},
            {"weld", JointType::Weld},           {"motor", JointType::Motor},
            {"mouse", JointType::Mouse},         {"friction", JointType::Friction}};
        SceneJoint frame;
        const auto type = kTypes.find(joint.value("type", ""));
        if (type == kTypes.end())
        {
            return std::nullopt;
        }
        frame.type = type->second;
        bool ok = true;
        const auto vector = [&](const char* key) -> std::optional<SceneVec2>
        {
            const auto found = joint.find(key);
            if (found == joint.end())
            {
                return std::nullopt;
            }
            if (!found->is_array() || found->size() != 2 || !(*found)[0].is_number() ||
                !(*found)[1].is_number())
            {
                ok = false;
                return std::nullopt;
            }
            return SceneVec2{(*found)[0].get<double>(), (*found)[1].get<double>()};
        };
        const auto number = [&](const char* key) -> std::optional<double>
        {
            const auto found = joint.find(key);
            if (found == joint.end())
            {
                return std::nullopt;
            }
            ok = ok && found->is_number();
            return found->is_number() ? std::optional(found->get<double>()) : std::nullopt;
        };
        if (const auto v = vector("anchor"))
        {
            frame.anchor = *v;
        }
        if (const auto v = vector("anchor_a"))
        {
            frame.anchorA = *v;
        }
        if (const auto v = vector("anchor_b"))
        {
            frame.anchorB = *v;
        }
        if (const auto v = vector("axis"))
        {
            frame.axis = *v;
        }
        const std::optional<SceneVec2> localA = vector("local_anchor_a");
        const std::optional<SceneVec2> localB = vector("local_anchor_b");
        if (localA || localB)
        {
            frame.localAnchors = true;
            frame.localAnchorA = localA.value_or(SceneVec2{});
            frame.localAnchorB = localB.value_or(SceneVec2{});
        }
        frame.localAxisA = vector("local_axis_a");
        frame.referenceAngle = number("reference_angle");
        frame.linearOffset = vector("linear_offset");
        frame.angularOffset = number("angular_offset");
        if (!ok)
        {
            return std::nullopt;
        }
        return frame;
    }

    // ---- what was left out -----------------------------------------------------------------

  public:
    /// "body[1], body[4], ... (7 in all)"
    static std::string List(const std::vector<std::string>& items)
    {
        std::string text;
        for (std::size_t i = 0; i < items.size() && i < 4; ++i)
        {
            text += (i == 0 ? "" : ", ") + items[i];
        }
        if (items.size() > 4)
        {
            text += ", ... (" + std::to_string(items.size()) + " in all)";
        }
        return text;
    }

  private:
    static std::string Count(std::size_t n, const char* one, const char* many)
    {
        return std::to_string(n) + " " + (n == 1 ? one : many);
    }

    void Warnings()
    {
        if (m_foreignProperties > 0)
        {
            m_converter.Warn(Count(m_foreignProperties, "custom property", "custom properties") +
                             " left out (meff has no use for them)");
        }
        if (m_images > 0)
        {
            m_converter.Warn(Count(m_images, "image", "images") +
                             " left out (meff draws shapes, not images)");
        }
        if (!m_inactive.empty())
        {
            m_converter.Warn("inactive bodies left out (Box2D does not simulate them), with "
                             "their fixtures: " +
                             List(m_inactive) +
                             (m_inactiveJoints.empty()
                                  ? ""
                                  : "; and the joints on them: " + List(m_inactiveJoints)));
        }
        if (!m_immovableJoints.empty())
        {
            m_converter.Warn("joints between two bodies that cannot move left out (Box2D never "
                             "solves them): " +
                             List(m_immovableJoints));
        }
        if (!m_oneSidedEdges.empty() && !m_writtenByMeff)
        {
            m_converter.Warn("chains and edges with ghost vertices kept one-sided, as in Box2D "
                             "2.4.1 (two-sided in 2.3, which R.U.B.E. targets; without "
                             "--b2djson-chains one_sided they import two-sided): " +
                             List(m_oneSidedEdges));
        }
        if (!m_twoSidedChains.empty())
        {
            m_converter.Warn("chains and edges with ghost vertices imported two-sided, as Box2D "
                             "2.3 (which R.U.B.E. targets) collides them: one two-sided segment "
                             "per edge (--b2djson-chains one_sided keeps 2.4.1's one-sided "
                             "chains): " +
                             List(m_twoSidedChains));
        }
        std::vector<std::string> renamed = m_bodyNames.Changed();
        for (const std::string& name : m_jointNames.Changed())
        {
            renamed.push_back(name);
        }
        if (!renamed.empty())
        {
            m_converter.Warn("names changed to meff's (unique; letters, digits, '_', '-', "
                             "'.'; at most 64): " +
                             List(renamed));
        }
    }

  public:
    /// Bodies whose level gave "massData-mass": scene index and that mass.
    const std::vector<std::pair<std::size_t, double>>& HandMass() const { return m_handMass; }

  private:
    Converter& m_converter;
    NameTable m_bodyNames{"body"};
    NameTable m_jointNames{"joint"};
    std::vector<std::ptrdiff_t> m_sceneBody; ///< by level body index: scene index or -1
    std::vector<std::string> m_bodyName;     ///< by scene body index
    std::vector<int> m_bodyTypes;            ///< by scene body index: 0 static .. 2 dynamic
    std::vector<std::pair<SceneVec2, double>> m_bodyPose;
    World m_poseWorld;
    std::vector<BodyId> m_poseBodies;
    std::vector<std::pair<std::size_t, double>> m_handMass;
    std::size_t m_foreignProperties = 0;
    std::size_t m_images = 0;
    std::vector<std::string> m_inactive;
    std::vector<std::string> m_inactiveJoints;
    std::vector<std::string> m_immovableJoints;
    std::vector<std::string> m_oneSidedEdges;
    std::vector<std::string> m_twoSidedChains;
    /// Scene index and level path of each spring joint (distance frequency, wheel
    /// springFrequency, weld frequency > 0) whose 2.3 sizing is to be kept.
    std::vector<std::pair<std::size_t, std::string>> m_springs23;
    bool m_writtenByMeff = false;
    B2dJsonImportOptions m_options;

  public:
    /// Spring joints to resize as Box2D 2.3 (see ResizeSprings23): scene index, level path.
    const std::vector<std::pair<std::size_t, std::string>>& Springs23() const
    {
        return m_springs23;
    }
    /// Whether the level is read as Box2D 2.3 authored it (not a level meff exported).
    bool As23() const { return !m_writtenByMeff; }

  private:
    bool TwoSidedChains() const { return m_options.twoSidedChains && !m_writtenByMeff; }
};

/// The loader's messages, "FILE: SCENE.PATH: MESSAGE", said about the level's paths.
std::vector<std::string> InLevelTerms(const Converter& converter, const SceneError& error)
{
    std::vector<std::string> messages;
    const std::string prefix = converter.File() + ": ";
    for (const std::string& message : error.messages())
    {
        if (message.rfind(prefix, 0) != 0)
        {
            messages.push_back(message);
            continue;
        }
        const std::size_t end = message.find(": ", prefix.size());
        if (end == std::string::npos)
        {
            messages.push_back(message);
            continue;
        }
        const std::string path = message.substr(prefix.size(), end - prefix.size());
        std::string rest = message.substr(end);
        // A list or object after "got" would be the converted scene's, not the level's: the
        // path says where to look.
        const std::size_t got = rest.rfind(", got ");
        if (got != std::string::npos && (rest[got + 6] == '[' || rest[got + 6] == '{'))
        {
            rest.resize(got);
        }
        messages.push_back(prefix + converter.LevelPath(path) + rest);
    }
    return messages;
}

/// One warning for bodies whose level set their mass by hand (massData-mass differs from what
/// their fixtures' densities give): meff computes mass from densities only.
void CheckHandMass(Converter& converter, const BuiltScene& built, const Scene& scene,
                   const std::vector<std::pair<std::size_t, double>>& handMass)
{
    if (handMass.empty())
    {
        return;
    }
    std::vector<std::string> differing;
    for (const auto& [index, mass] : handMass)
    {
        const double computed = double(built.world.GetMass(built.bodies[index]));
        // Box2D and meff compute a body's mass with the same float operations, so an
        // unedited level matches to the bit; a relative 1e-6 only absorbs a decimal export.
        if (std::abs(computed - mass) > 1e-6 * std::max(1.0, std::abs(mass)))
        {
            char text[160];
            std::snprintf(text, sizeof text, "%s: %g kg set, %g kg from its fixtures",
                          scene.bodies[index].name.c_str(), mass, computed);
            differing.push_back(text);
        }
    }
    if (!differing.empty())
    {
        std::string list;
        for (std::size_t i = 0; i < differing.size() && i < 3; ++i)
        {
            list += (i == 0 ? "" : "; ") + differing[i];
        }
        if (differing.size() > 3)
        {
            list += "; ... (" + std::to_string(differing.size()) + " bodies)";
        }
        converter.Warn("massData: mass set by hand is not kept (meff computes mass from "
                       "fixture densities): " +
                       list);
    }
}

/// The joint's effective mass on its spring's row as Box2D 2.3 computes it (the inverse of
/// invMass in b2DistanceJoint's, b2WheelJoint's and b2WeldJoint's InitVelocityConstraints), over
/// the mass Box2D 2.4.1's b2LinearStiffness or b2AngularStiffness takes from the bodies; 0
/// when either is 0 (then nothing is resized).
double SpringMassRatio23(const World& world, const SceneJoint& joint, JointId id)
{
    const BodyId a = world.GetBodyA(id);
    const BodyId b = world.GetBodyB(id);
    const auto inverse = [](double value) { return value > 0 ? 1 / value : 0.0; };
    const double mA = world.GetType(a) == BodyType::Dynamic ? double(world.GetMass(a)) : 0;
    const double mB = world.GetType(b) == BodyType::Dynamic ? double(world.GetMass(b)) : 0;
    const double iA =
        world.GetType(a) == BodyType::Dynamic ? double(world.GetRotationalInertia(a)) : 0;
    const double iB =
        world.GetType(b) == BodyType::Dynamic ? double(world.GetRotationalInertia(b)) : 0;
    const auto cross = [](double ax, double ay, double bx, double by) { return ax * by - ay * bx; };
    double invMass23 = 0;
    double mass241 = 0;
    if (joint.type == JointType::Weld)
    {
        // 2.3: the angular row's inertia 1/(1/IA + 1/IB), about the centres of mass; 2.4.1:
        // b2AngularStiffness on b2Body::GetInertia, about the body origins.
        invMass23 = inverse(iA) + inverse(iB);
        const auto aboutOrigin = [&](BodyId body, double mass, double inertia)
        {
            const Vec2 c = world.GetLocalCenter(body);
            return inertia + mass * (double(c.x) * c.x + double(c.y) * c.y);
        };
        const double IA = mA > 0 ? aboutOrigin(a, mA, iA) : 0;
        const double IB = mB > 0 ? aboutOrigin(b, mB, iB) : 0;
        mass241 = IA > 0 && IB > 0 ? IA * IB / (IA + IB) : (IA > 0 ? IA : IB);
    }
    else
    {
        const Vec2 pA = world.GetAnchorA(id);
        const Vec2 pB = world.GetAnchorB(id);
        const Vec2 cA = world.GetWorldCenter(a);
        const Vec2 cB = world.GetWorldCenter(b);
        const double rAx = double(pA.x) - cA.x;
        const double rAy = double(pA.y) - cA.y;
        const double rBx = double(pB.x) - cB.x;
        const double rBy = double(pB.y) - cB.y;
        double ux = 0;
        double uy = 0;
        double sA = 0; // the arm of body A's row
        if (joint.type == JointType::Distance)
        {
            ux = double(pB.x) - pA.x;
            uy = double(pB.y) - pA.y;
            const double length = std::hypot(ux, uy);
            if (length <= 0)
            {
                return 0;
            }
            ux /= length;
            uy /= length;
            sA = cross(rAx, rAy, ux, uy);
        }
        else // wheel: the axis in body A's frame, and d + rA from A's centre to B's anchor
        {
            const SceneVec2 local = joint.localAxisA.value_or(joint.axis);
            Vec2 axis{Real(local.x), Real(local.y)};
            if (joint.localAxisA)
            {
                const Vec2 origin = world.GetWorldPoint(a, Vec2{});
                const Vec2 tip = world.GetWorldPoint(a, axis);
                axis = Vec2{tip.x - origin.x, tip.y - origin.y};
            }
            const double length = std::hypot(double(axis.x), double(axis.y));
            ux = axis.x / length;
            uy = axis.y / length;
            sA = cross(double(pB.x) - cA.x, double(pB.y) - cA.y, ux, uy);
        }
        const double sB = cross(rBx, rBy, ux, uy);
        invMass23 = inverse(mA) + inverse(mB) + inverse(iA) * sA * sA + inverse(iB) * sB * sB;
        mass241 = mA > 0 && mB > 0 ? mA * mB / (mA + mB) : (mA > 0 ? mA : mB);
    }
    if (!(invMass23 > 0) || !(mass241 > 0))
    {
        return 0;
    }
    return 1 / invMass23 / mass241;
}

/// Keeps Box2D 2.3's spring sizing (ImportB2dJson's springsAs23): 2.3 takes stiffness m·ω² and
/// damping 2·m·ζ·ω on the joint's effective mass m, 2.4.1 (and meff's box2d back end) on the
/// bodies' mass M; with r = m/M at the level's pose, frequency·√r and ratio·√r give 2.4.1 the
/// same stiffness and damping. Rewrites `document`'s joints; returns "PATH: f -> f' Hz" for each
/// spring changed.
std::vector<std::string> ResizeSprings23(
    const Scene& scene, const std::vector<std::pair<std::size_t, std::string>>& springs,
    Out& document)
{
    std::vector<std::string> changed;
    if (springs.empty())
    {
        return changed;
    }
    const BuiltScene built = BuildWorld(scene);
    for (const auto& [index, path] : springs)
    {
        const SceneJoint& joint = scene.joints[index];
        const double ratio = SpringMassRatio23(built.world, joint, built.joints[index]);
        // The same masses by both sizings (anchors on the centres of mass, say) give a ratio
        // within double round-off of 1 (a few 1e-16): left as the level says.
        if (ratio <= 0 || std::abs(ratio - 1) <= 1e-12)
        {
            continue;
        }
        const double scale = std::sqrt(ratio);
        Out& out = document["joints"][index];
        out["stiffness_hz"] = joint.stiffnessHz * scale;
        if (joint.dampingRatio > 0)
        {
            out["damping_ratio"] = joint.dampingRatio * scale;
        }
        char text[96];
        std::snprintf(text, sizeof text, " %.6g -> %.6g Hz", joint.stiffnessHz,
                      joint.stiffnessHz * scale);
        changed.push_back(path + text);
    }
    return changed;
}

/// The springs' choice, said in one warning line; with springsAs23, the springs resized and the
/// scene read again from the rewritten document.
void SaySprings(Converter& converter, const B2dJsonImportOptions& options, LoadedScene& loaded,
                const std::vector<std::pair<std::size_t, std::string>>& springs, Out& document,
                const std::string& sourcePath)
{
    std::vector<std::string> paths;
    for (const auto& [index, path] : springs)
    {
        paths.push_back(path);
    }
    if (!options.springsAs23)
    {
        converter.Warn("springs (distance frequency, wheel springFrequency, weld frequency) "
                       "sized as Box2D 2.4.1 does, from the bodies' masses (2.3, which R.U.B.E. "
                       "targets, sizes them from the joint's effective mass; without "
                       "--b2djson-springs 2.4.1 its stiffness is kept): " +
                       Importer::List(paths));
        return;
    }
    const std::vector<std::string> changed = ResizeSprings23(loaded.scene, springs, document);
    if (!changed.empty())
    {
        loaded.scene = scene_detail::ReadSceneDocument(Json(document), sourcePath);
    }
    converter.Warn("springs (distance frequency, wheel springFrequency, weld frequency) keep "
                   "Box2D 2.3's stiffness and damping, which R.U.B.E. targets (2.3 sizes them "
                   "from the joint's effective mass, 2.4.1 from the bodies' masses; "
                   "--b2djson-springs 2.4.1 takes the numbers as 2.4.1 reads them): " +
                   (changed.empty()
                        ? std::string("the same in both for ") + Importer::List(paths)
                        : "frequency and damping ratio rescaled: " + Importer::List(changed)));
}

} // namespace

namespace
{

/// What format detection needs of a document, read through nlohmann's SAX interface without
/// building it: whether the root is an object, and which keys it has. Nothing deeper than the
/// nesting cap is read (issue 36: building the whole document first took 2.4 GB for 32 million
/// nested brackets, before the capped loader could refuse them).
class TopLevelKeys : public nlohmann::json_sax<Json>
{
  public:
    bool rootIsObject = false;
    bool meffScene = false;  ///< has "meff_scene"
    bool b2dJsonKey = false; ///< has one of b2dJson's world fields
    bool tooDeep = false;    ///< stopped at the nesting cap

    bool null() override { return true; }
    bool boolean(bool) override { return true; }
    bool number_integer(number_integer_t) override { return true; }
    bool number_unsigned(number_unsigned_t) override { return true; }
    bool number_float(number_float_t, const string_t&) override { return true; }
    bool string(string_t&) override { return true; }
    bool binary(binary_t&) override { return true; }
    bool start_object(std::size_t) override { return Open(true); }
    bool start_array(std::size_t) override { return Open(false); }
    bool end_object() override { return Close(); }
    bool end_array() override { return Close(); }
    bool key(string_t& key) override
    {
        if (m_depth != 1)
        {
            return true;
        }
        meffScene = meffScene || key == "meff_scene";
        for (const char* name :
             {"body", "joint", "gravity", "allowSleep", "autoClearForces", "warmStarting",
              "continuousPhysics", "subStepping", "stepsPerSecond", "velocityIterations",
              "positionIterations", "image"})
        {
            b2dJsonKey = b2dJsonKey || key == name;
        }
        return true;
    }
    bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override
    {
        return false;
    }

  private:
    bool Open(bool object)
    {
        if (m_depth == 0)
        {
            rootIsObject = object;
        }
        if (++m_depth > scene_detail::kMaxJsonDepth)
        {
            tooDeep = true;
            return false;
        }
        return true;
    }
    bool Close()
    {
        --m_depth;
        return true;
    }

    std::size_t m_depth = 0;
};

} // namespace

bool LooksLikeB2dJson(std::string_view text)
{
    TopLevelKeys keys;
    const bool valid = Json::sax_parse(text, &keys);
    // Text that is not JSON goes to the meff loader, which says why. Text nested too deep goes
    // by the keys read before the cap: the loader of that format refuses the nesting in its
    // own words.
    return (valid || keys.tooDeep) && keys.rootIsObject && !keys.meffScene && keys.b2dJsonKey;
}

LoadedScene ImportB2dJson(std::string_view text, const std::string& sourcePath,
                          const SceneLimits& limits, const B2dJsonImportOptions& options)
{
    Converter converter(sourcePath);
    const std::optional<Json> level = scene_detail::ParseDocument(text, converter.Diag());
    // The counts before the conversion, which takes several times the level's memory.
    if (!level ||
        !scene_detail::CheckCounts(*level, "body", "fixture", "joint", limits, converter.Diag()))
    {
        converter.Diag().Throw();
    }
    if (!level->is_object())
    {
        converter.Error("", "a b2dJson level must be a JSON object", &*level);
        converter.Diag().Throw();
    }
    if (level->contains("meff_scene"))
    {
        converter.Error("meff_scene", "this is a meff scene, not a b2dJson level (read it as "
                                      "--format meff, or let the content decide)");
        converter.Diag().Throw();
    }
    Importer importer(converter, options);
    Out document = importer.Convert(*level);
    if (converter.Diag().HasErrors())
    {
        converter.Diag().Throw();
    }
    LoadedScene loaded;
    try
    {
        loaded.scene = scene_detail::ReadSceneDocument(Json(document), sourcePath);
        const BuiltScene built = BuildWorld(loaded.scene);
        scene_detail::CheckPairs(built, limits, sourcePath);
        CheckHandMass(converter, built, loaded.scene, importer.HandMass());
        if (importer.As23() && !importer.Springs23().empty())
        {
            SaySprings(converter, options, loaded, importer.Springs23(), document, sourcePath);
        }
    }
    catch (const SceneError& error)
    {
        throw SceneError(InLevelTerms(converter, error));
    }
    loaded.warnings = std::move(converter.Warnings());
    loaded.meffText = FormatJson(document);
    return loaded;
}

LoadedScene LoadSceneFile(const std::string& path, SceneFormat format, const SceneLimits& limits,
                          const B2dJsonImportOptions& options)
{
    const std::string text = scene_detail::ReadTextFile(path, limits.fileBytes);
    if (format == SceneFormat::B2dJson || (format == SceneFormat::Auto && LooksLikeB2dJson(text)))
    {
        return ImportB2dJson(text, path, limits, options);
    }
    LoadedScene loaded;
    loaded.scene = ParseScene(text, path, limits);
    return loaded;
}

} // namespace meff
