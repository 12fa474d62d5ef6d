// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
#include "json_document.h"

#include "meff/math.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>

namespace meff::scene_detail
{

namespace
{

constexpr std::size_t kMaxDescribedLength = 80;

/// The largest magnitude the engine's scalar can hold, as text for messages.
std::string MaxRealText()
{
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.9g", double(kMaxReal));
    return buffer;
}

/// A finite double that also stays finite when converted to the engine's scalar.
bool FitsReal(double value)
{
    return std::isfinite(value) && std::abs(value) <= double(kMaxReal);
}

/// Strings people write when they mean a non-finite number; JSON itself has no such numbers.
bool LooksNonFinite(const Json& value)
{
    if (!value.is_string())
    {
        return false;
    }
    std::string text = value.get<std::string>();
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    if (!text.empty() && (text[0] == '+' || text[0] == '-'))
    {
        text.erase(0, 1);
    }
    return text == "nan" || text == "inf" || text == "infinity";
}

/// Builds the document through nlohmann's SAX interface, so that it knows the field path of
/// every value: needed to say where a number overflowed and which key was duplicated. The path
/// is kept as one key per open container and spelled out only for a message, so memory stays
/// linear in the depth; and nesting deeper than kMaxJsonDepth is refused outright (a scene
/// needs about 7 levels).
class DocumentBuilder : public nlohmann::json_sax<Json>
{
  public:
    DocumentBuilder(Diagnostics& diagnostics, std::size_t outerDepth)
        : m_diagnostics(diagnostics), m_outerDepth(outerDepth)
    {
    }

    Json TakeRoot() { return std::move(m_root); }

    bool null() override { return Add(Json(nullptr)); }
    bool boolean(bool value) override { return Add(Json(value)); }
    bool number_integer(number_integer_t value) override { return Add(Json(value)); }
    bool number_unsigned(number_unsigned_t value) override { return Add(Json(value)); }
    bool number_float(number_float_t value, const string_t&) override { return Add(Json(value)); }
    bool string(string_t& value) override { return Add(Json(std::move(value))); }
    bool binary(binary_t& value) override { return Add(Json::binary(std::move(value))); }

    bool start_object(std::size_t) override { return Open(Json::object()); }
    bool key(string_t& key) override
    {
        Container& object = m_open.back();
        object.key = key;
        if (object.value->contains(key))
        {
            m_diagnostics.Report(CurrentValuePath(),
                                 "duplicate key: each field may appear only once");
        }
        return true;
    }
    bool end_object() override
    {
        m_open.pop_back();
        return true;
    }
    bool start_array(std::size_t) override { return Open(Json::array()); }
    bool end_array() override
    {
        m_open.pop_back();
        return true;
    }

    bool parse_error(std::size_t, const std::string& lastToken,
                     const nlohmann::detail::exception& error) override
    {
        constexpr int kNumberOverflow = 406;
        if (error.id == kNumberOverflow)
        {
            m_diagnostics.Report(CurrentValuePath(), "must be a finite number, got " + lastToken);
            return false;
        }
        // nlohmann's text reads "[json.exception.parse_error.101] parse error at line 2,
        // column 7: syntax error while parsing value - ..."; keep from "line" on.
        std::string message = error.what();
        const std::string marker = "parse error at ";
        if (const auto at = message.find(marker); at != std::string::npos)
        {
            message.erase(0, at + marker.size());
        }
        m_diagnostics.Report("", message);
        return false;
    }

  private:
    struct Container
    {
        Json* value;
        std::string key; ///< objects: the key of the value being read
    };

    /// The field path of the value about to be added: through each open container's open
    /// child (an array's last element, an object's current key) to the innermost container's
    /// next value (an array's next index is its size).
    std::string CurrentValuePath() const
    {
        std::string path;
        for (std::size_t i = 0; i < m_open.size(); ++i)
        {
            const Container& container = m_open[i];
            if (container.value->is_array())
            {
                const std::size_t size = container.value->size();
                path = IndexPath(path, i + 1 < m_open.size() ? size - 1 : size);
            }
            else
            {
                path = JoinPath(path, container.key);
            }
        }
        return path;
    }

    bool Open(Json&& container)
    {
        if (m_outerDepth + m_open.size() >= kMaxJsonDepth)
        {
            const std::string limit = "nested deeper than " + std::to_string(kMaxJsonDepth) +
                                      " levels (a scene needs about 7)";
            m_diagnostics.Report(CurrentValuePath(),
                                 m_outerDepth == 0
                                     ? limit + ": not a scene file"
                                     : limit + " once in the scene, inside its " +
                                           std::to_string(m_outerDepth) + " outer levels");
            return false;
        }
        Json* value = AddContainer(std::move(container));
        m_open.push_back({value, {}});
        return true;
    }

    Json* AddContainer(Json&& value)
    {
        if (m_open.empty())
        {
            m_root = std::move(value);
            return &m_root;
        }
        Container& parent = m_open.back();
        if (parent.value->is_array())
        {
            parent.value->push_back(std::move(value));
            return &parent.value->back();
        }
        Json& slot = (*parent.value)[parent.key];
        slot = std::move(value);
        return &slot;
    }

    bool Add(Json&& value)
    {
        AddContainer(std::move(value));
        return true;
    }

    Diagnostics& m_diagnostics;
    std::size_t m_outerDepth; ///< containers around the document once it is in the scene
    Json m_root;
    // Pointers stay valid: a container's own slot never moves while it is open, because only
    // the innermost open container grows.
    std::vector<Container> m_open;
};

} // namespace

void Diagnostics::Report(const std::string& fieldPath, const std::string& message)
{
    if (fieldPath.empty())
    {
        m_messages.push_back(m_file + ": " + message);
    }
    else
    {
        m_messages.push_back(m_file + ": " + fieldPath + ": " + message);
    }
}

void Diagnostics::Warn(const std::string& fieldPath, const std::string& message)
{
    m_warnings.push_back(m_file + ": " + (fieldPath.empty() ? "" : fieldPath + ": ") +
                         "warning: " + message);
}

void Diagnostics::Report(const std::string& fieldPath, const std::string& message, const Json& got)
{
    Report(fieldPath, message + ", got " + Describe(got));
}

std::string Describe(const Json& value)
{
    std::string text = value.dump(-1, ' ', false, Json::error_handler_t::replace);
    // dump() separates nothing; a space after each comma reads like the files people write.
    std::string spaced;
    spaced.reserve(text.size());
    bool inString = false;
    bool escaped = false;
    for (const char c : text)
    {
        spaced += c;
        if (inString)
        {
            inString = escaped || c != '"';
            escaped = !escaped && c == '\\';
        }
        else if (c == '"')
        {
            inString = true;
        }
        else if (c == ',' || c == ':')
        {
            spaced += ' ';
        }
    }
    if (spaced.size() > kMaxDescribedLength)
    {
        spaced.resize(kMaxDescribedLength - 3);
        spaced += "...";
    }
    return spaced;
}

std::string FormatNumber(double value)
{
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

std::string FormatReal(Real value)
{
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

std::string JoinPath(const std::string& parent, std::string_view key)
{
    if (parent.empty())
    {
        return std::string(key);
    }
    return parent + "." + std::string(key);
}

std::string IndexPath(const std::string& parent, std::size_t index)
{
    return parent + "[" + std::to_string(index) + "]";
}

std::optional<Json> ParseDocument(std::string_view text, Diagnostics& diagnostics,
                                  std::size_t outerDepth)
{
    const std::size_t errorsBefore = diagnostics.Count();
    DocumentBuilder builder(diagnostics, outerDepth);
    const bool parsed = Json::sax_parse(text, &builder);
    if (!parsed || diagnostics.Count() != errorsBefore)
    {
        return std::nullopt;
    }
    return builder.TakeRoot();
}

ObjectReader::ObjectReader(Diagnostics& diagnostics, const Json& object, std::string path)
    : m_diagnostics(diagnostics), m_object(object), m_path(std::move(path))
{
}

const Json* ObjectReader::Find(std::string_view key)
{
    if (std::find(m_known.begin(), m_known.end(), key) == m_known.end())
    {
        m_known.emplace_back(key);
    }
    const auto found = m_object.find(key);
    return found == m_object.end() ? nullptr : &*found;
}

void ObjectReader::Fail(std::string_view key, const std::string& message)
{
    if (const Json* value = Find(key))
    {
        m_diagnostics.Report(PathOf(key), message, *value);
    }
    else
    {
        m_diagnostics.Report(PathOf(key), message);
    }
}

void ObjectReader::Missing(std::string_view key, bool hasFallback)
{
    if (!hasFallback)
    {
        m_diagnostics.Report(PathOf(key), "required field is missing");
    }
}

std::optional<double> ObjectReader::Number(std::string_view key, std::optional<double> fallback)
{
    const Json* value = Find(key);
    if (value == nullptr)
    {
        Missing(key, fallback.has_value());
        return fallback;
    }
    if (LooksNonFinite(*value))
    {
        Fail(key, "must be a finite number");
        return std::nullopt;
    }
    if (!value->is_number())
    {
        Fail(key, "must be a number");
        return std::nullopt;
    }
    const double number = value->get<double>();
    if (!FitsReal(number))
    {
        Fail(key, "must be a finite number (at most " + MaxRealText() + " in magnitude)");
        return std::nullopt;
    }
    return number;
}

std::optional<long long> ObjectReader::Integer(std::string_view key,
                                               std::optional<long long> fallback, long long minimum,
                                               long long maximum)
{
    const Json* value = Find(key);
    if (value == nullptr)
    {
        Missing(key, fallback.has_value());
        return fallback;
    }
    std::optional<long long> integer;
    if (value->is_number_unsigned())
    {
        const auto number = value->get<std::uint64_t>();
        if (number <= std::uint64_t(std::numeric_limits<long long>::max()))
        {
            integer = static_cast<long long>(number);
        }
    }
    else if (value->is_number_integer())
    {
        integer = value->get<long long>();
    }
    else if (value->is_number_float())
    {
        // 240.0 means 240; only whole numbers in a sane range are taken.
        const double number = value->get<double>();
        if (std::trunc(number) == number && std::abs(number) < 1e15)
        {
            integer = static_cast<long long>(number);
        }
    }
    if (!integer || *integer < minimum || *integer > maximum)
    {
        Fail(key, "must be an integer in [" + std::to_string(minimum) + ", " +
                      std::to_string(maximum) + "]");
        return std::nullopt;
    }
    return integer;
}

std::optional<bool> ObjectReader::Boolean(std::string_view key, std::optional<bool> fallback)
{
    const Json* value = Find(key);
    if (value == nullptr)
    {
        Missing(key, fallback.has_value());
        return fallback;
    }
    if (!value->is_boolean())
    {
        Fail(key, "must be true or false");
        return std::nullopt;
    }
    return value->get<bool>();
}

std::optional<std::string> ObjectReader::String(std::string_view key,
                                                std::optional<std::string> fallback)
{
    const Json* value = Find(key);
    if (value == nullptr)
    {
        Missing(key, fallback.has_value());
        return fallback;
    }
    if (!value->is_string())
    {
        Fail(key, "must be a string");
        return std::nullopt;
    }
    return value->get<std::string>();
}

namespace
{

std::optional<SceneVec2> ToVector(const Json& value)
{
    if (!value.is_array() || value.size() != 2 || !value[0].is_number() || !value[1].is_number())
    {
        return std::nullopt;
    }
    const double x = value[0].get<double>();
    const double y = value[1].get<double>();
    if (!FitsReal(x) || !FitsReal(y))
    {
        return std::nullopt;
    }
    return SceneVec2{x, y};
}

const char* const kVectorMessage = "must be [x, y] with two finite numbers";

} // namespace

std::optional<SceneVec2> ObjectReader::Vector(std::string_view key,
                                              std::optional<SceneVec2> fallback)
{
    const Json* value = Find(key);
    if (value == nullptr)
    {
        Missing(key, fallback.has_value());
        return fallback;
    }
    const std::optional<SceneVec2> vector = ToVector(*value);
    if (!vector)
    {
        Fail(key, kVectorMessage);
    }
    return vector;
}

std::optional<std::vector<SceneVec2>> ObjectReader::VectorList(std::string_view key)
{
    const Json* list = Array(key, true);
    if (list == nullptr)
    {
        return std::nullopt;
    }
    std::vector<SceneVec2> points;
    bool allValid = true;
    for (std::size_t i = 0; i < list->size(); ++i)
    {
        if (const std::optional<SceneVec2> point = ToVector((*list)[i]))
        {
            points.push_back(*point);
        }
        else
        {
            m_diagnostics.Report(IndexPath(PathOf(key), i), kVectorMessage, (*list)[i]);
            allValid = false;
        }
    }
    if (!allValid)
    {
        return std::nullopt;
    }
    return points;
}

std::optional<std::vector<double>> ObjectReader::NumberList(std::string_view key)
{
    const Json* list = Array(key, true);
    if (list == nullptr)
    {
        return std::nullopt;
    }
    std::vector<double> numbers;
    bool allValid = true;
    for (std::size_t i = 0; i < list->size(); ++i)
    {
        const Json& value = (*list)[i];
        if (value.is_number() && !LooksNonFinite(value) && FitsReal(value.get<double>()))
        {
            numbers.push_back(value.get<double>());
        }
        else
        {
            m_diagnostics.Report(
                IndexPath(PathOf(key), i),
                "must be a finite number (at most " + MaxRealText() + " in magnitude)", value);
            allValid = false;
        }
    }
    if (!allValid)
    {
        return std::nullopt;
    }
    return numbers;
}

const Json* ObjectReader::Array(std::string_view key, bool required)
{
    const Json* value = Find(key);
    if (value == nullptr)
    {
        Missing(key, !required);
        return nullptr;
    }
    if (!value->is_array())
    {
        Fail(key, "must be an array");
        return nullptr;
    }
    return value;
}

const Json* ObjectReader::Object(std::string_view key, bool required)
{
    const Json* value = Find(key);
    if (value == nullptr)
    {
        Missing(key, !required);
        return nullptr;
    }
    if (!value->is_object())
    {
        Fail(key, "must be an object");
        return nullptr;
    }
    return value;
}

void ObjectReader::Finish()
{
    std::string known;
    for (const std::string& key : m_known)
    {
        known += known.empty() ? key : ", " + key;
    }
    for (const auto& [key, value] : m_object.items())
    {
        if (std::find(m_known.begin(), m_known.end(), key) == m_known.end())
        {
            m_diagnostics.Report(PathOf(key), "unknown field (known fields here: " + known + ")");
        }
    }
}

bool CheckPositive(ObjectReader& reader, std::string_view key, double value)
{
    // The engine computes in its scalar (float by default): a positive double below its
    // smallest denormal becomes 0 there, which the engine refuses (MakeBox throws on a zero
    // half extent), so the loader must refuse it too, at its field.
    if (value > 0 && Real(value) > 0)
    {
        return true;
    }
    reader.Fail(key, value > 0 ? "must be > 0 in the engine's scalar (this rounds to 0)"
                               : "must be > 0");
    return false;
}

bool CheckNonNegative(ObjectReader& reader, std::string_view key, double value)
{
    if (value >= 0)
    {
        return true;
    }
    reader.Fail(key, "must be >= 0");
    return false;
}

bool CheckInRange(ObjectReader& reader, std::string_view key, double value, double low, double high)
{
    if (value >= low && value <= high)
    {
        return true;
    }
    reader.Fail(key, "must be in [" + FormatNumber(low) + ", " + FormatNumber(high) + "]");
    return false;
}

const char* JointTypeName(JointType type)
{
    static const char* const kNames[] = {"revolute", "distance", "prismatic", "wheel",  "weld",
                                         "motor",    "mouse",    "friction",  "pulley", "gear"};
    return kNames[int(type)];
}

bool IsPlainName(const std::string& name)
{
    constexpr std::size_t kMaxNameLength = 64;
    if (name.empty() || name.size() > kMaxNameLength)
    {
        return false;
    }
    for (const char c : name)
    {
        const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                           (c >= '0' && c <= '9') || c == '_' || c == '-' || c == '.';
        if (!plain)
        {
            return false;
        }
    }
    return true;
}

} // namespace meff::scene_detail
