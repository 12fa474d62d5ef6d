// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Reading JSON for the scene loader: parsing with precise error positions, and typed access to
// fields that reports every problem as "FILE: FIELD.PATH: MESSAGE, got VALUE".
#pragma once

#include "meff/scene.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace meff::scene_detail
{

using Json = nlohmann::json;

/// Collects error messages for one file.
class Diagnostics
{
  public:
    explicit Diagnostics(std::string file) : m_file(std::move(file)) {}

    /// "FILE: FIELD.PATH: MESSAGE" (or "FILE: MESSAGE" for an empty path).
    void Report(const std::string& fieldPath, const std::string& message);
    /// The same with ", got VALUE" appended, VALUE being the JSON text of `got`.
    void Report(const std::string& fieldPath, const std::string& message, const Json& got);

    /// "FILE: FIELD.PATH: warning: MESSAGE": something accepted that the user should know
    /// (kept apart from the errors; a scene with only warnings loads).
    void Warn(const std::string& fieldPath, const std::string& message);
    const std::vector<std::string>& Warnings() const { return m_warnings; }

    bool HasErrors() const { return !m_messages.empty(); }
    std::size_t Count() const { return m_messages.size(); }
    const std::vector<std::string>& Messages() const { return m_messages; }
    [[noreturn]] void Throw() const { throw SceneError(m_messages); }

  private:
    std::string m_file;
    std::vector<std::string> m_messages;
    std::vector<std::string> m_warnings;
};

/// A JSON value as shown after "got": compact, and shortened when long.
std::string Describe(const Json& value);
/// The scene file's name of a joint type ("revolute", ...).
const char* JointTypeName(JointType type);
/// A name as scene files allow it (bodies, joints, characters): 1 to 64 characters from
/// A-Z a-z 0-9 _ - . (names end up unquoted in CSV columns and in file names).
bool IsPlainName(const std::string& name);
/// A number as shown in messages: the shortest text that reads back as the same double.
std::string FormatNumber(double value);
/// The same for an engine scalar, in its own precision (0.0025f is "0.0025").
std::string FormatReal(Real value);

std::string JoinPath(const std::string& parent, std::string_view key);
std::string IndexPath(const std::string& parent, std::size_t index);

/// How deeply arrays and objects may nest in a scene file (the format itself needs about 7).
inline constexpr std::size_t kMaxJsonDepth = 64;

/// Parses JSON text. On a syntax error, a number too large for a double, a key that appears
/// twice in one object or nesting deeper than kMaxJsonDepth, reports it and returns nullopt.
/// nlohmann::json alone would throw a number overflow without saying where, and silently keep the
/// last of duplicate keys. The cap is checked as the text is read, before anything deeper is
/// built. JSON embedded in another document (a b2dJson level's meff.* custom properties) passes
/// `outerDepth`, the number of containers it will be nested in once it is part of the scene, so
/// that one cap holds for every JSON the tools read: the scene it becomes nests no deeper than
/// kMaxJsonDepth either.
std::optional<Json> ParseDocument(std::string_view text, Diagnostics& diagnostics,
                                  std::size_t outerDepth = 0);

/// Typed access to the fields of one JSON object. Every field read is remembered as known, so
/// that Finish() can report the unknown ones. Each reader returns nullopt, after reporting why,
/// when the field is missing (and has no default) or has the wrong type; range checks are the
/// caller's, through Fail().
class ObjectReader
{
  public:
    ObjectReader(Diagnostics& diagnostics, const Json& object, std::string path);

    const std::string& Path() const { return m_path; }
    std::string PathOf(std::string_view key) const { return JoinPath(m_path, key); }
    Diagnostics& Diag() { return m_diagnostics; }

    /// The field's value, or nullptr when absent. Marks the key as known.
    const Json* Find(std::string_view key);
    /// Whether the object has the field, without marking it as known: for fields that only
    /// saved worlds write (joints' "impulses"), which the unknown-field hint does not offer.
    bool Has(std::string_view key) const { return m_object.contains(key); }
    /// Reports "PATH.KEY: MESSAGE, got VALUE" (without ", got" when the field is absent).
    void Fail(std::string_view key, const std::string& message);

    std::optional<double> Number(std::string_view key, std::optional<double> fallback);
    std::optional<long long> Integer(std::string_view key, std::optional<long long> fallback,
                                     long long minimum, long long maximum);
    std::optional<bool> Boolean(std::string_view key, std::optional<bool> fallback);
    std::optional<std::string> String(std::string_view key, std::optional<std::string> fallback);
    std::optional<SceneVec2> Vector(std::string_view key, std::optional<SceneVec2> fallback);
    /// A list of [x, y] points; reports a wrong element type once, for the whole list.
    std::optional<std::vector<SceneVec2>> VectorList(std::string_view key);
    /// A required list of numbers, each finite and within the engine's scalar; reports each
    /// bad element at its index.
    std::optional<std::vector<double>> NumberList(std::string_view key);
    /// An array field: nullptr (and a report unless `required` is false) when absent or not an
    /// array.
    const Json* Array(std::string_view key, bool required);
    /// A nested object field: nullptr (and a report unless `required` is false) when absent or
    /// not an object.
    const Json* Object(std::string_view key, bool required);

    /// Reports every field that no reader asked for.
    void Finish();

  private:
    /// Reports a missing field unless it has a default.
    void Missing(std::string_view key, bool hasFallback);

    Diagnostics& m_diagnostics;
    const Json& m_object;
    std::string m_path;
    std::vector<std::string> m_known;
};

/// The whole file; throws SceneError ("FILE: cannot open: REASON", "FILE: is a directory, ...",
/// "FILE: larger than 64 MiB: ..." past `maxBytes`, read no further).
std::string ReadTextFile(const std::string& path, std::size_t maxBytes = kMaxSceneFileBytes);

/// The counts of a parsed document against `limits` (SceneLimits): the lists named
/// `bodiesKey` and `jointsKey` at the top, and the `shapesKey` lists in the bodies. Reports each
/// one over its limit and returns false. Called before anything is read from the document.
bool CheckCounts(const Json& document, const char* bodiesKey, const char* shapesKey,
                 const char* jointsKey, const SceneLimits& limits, Diagnostics& diagnostics);

/// The pairs of shapes a built scene starts with (SceneLimits::pairs); throws SceneError
/// "FILE: bodies: more than N pairs ..." when over the limit. Counting stops there.
void CheckPairs(const BuiltScene& built, const SceneLimits& limits, const std::string& sourcePath);

/// Reads and checks a parsed scene document (what ParseScene does after parsing); throws
/// SceneError. The b2dJson importer gives it the scene it converted a level to.
Scene ReadSceneDocument(const Json& document, const std::string& sourcePath);

// Range checks: each reports through reader.Fail and returns whether the value passed.
bool CheckPositive(ObjectReader& reader, std::string_view key, double value);
bool CheckNonNegative(ObjectReader& reader, std::string_view key, double value);
bool CheckInRange(ObjectReader& reader, std::string_view key, double value, double low,
                  double high);

} // namespace meff::scene_detail
