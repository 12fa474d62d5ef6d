// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
#include "b2djson_values.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>

namespace meff::b2djson_detail
{

std::string FloatToHex(float value)
{
    char text[16];
    std::snprintf(text, sizeof text, "%08X", unsigned(std::bit_cast<std::uint32_t>(value)));
    return text;
}

std::optional<float> HexToFloat(std::string_view text)
{
    if (text.size() != 8)
    {
        return std::nullopt;
    }
    std::uint32_t bits = 0;
    for (const char c : text)
    {
        int digit = 0;
        if (c >= '0' && c <= '9')
        {
            digit = c - '0';
        }
        else if (c >= 'A' && c <= 'F')
        {
            digit = c - 'A' + 10;
        }
        else if (c >= 'a' && c <= 'f')
        {
            digit = c - 'a' + 10;
        }
        else
        {
            return std::nullopt;
        }
        bits = bits << 4 | std::uint32_t(digit);
    }
    return std::bit_cast<float>(bits);
}

std::optional<double> ReadNumber(const Json& value)
{
    if (value.is_number())
    {
        return value.get<double>();
    }
    if (value.is_string())
    {
        if (const std::optional<float> number = HexToFloat(value.get<std::string>()))
        {
            return double(*number);
        }
    }
    return std::nullopt;
}

std::optional<SceneVec2> ReadVector(const Json& value)
{
    if (value.is_number() && value.get<double>() == 0)
    {
        return SceneVec2{};
    }
    if (!value.is_object())
    {
        return std::nullopt;
    }
    SceneVec2 vector;
    for (const auto& [key, target] : {std::pair{"x", &vector.x}, std::pair{"y", &vector.y}})
    {
        const auto found = value.find(key);
        if (found == value.end())
        {
            continue; // b2dJson: a missing component is 0
        }
        const std::optional<double> number = ReadNumber(*found);
        if (!number)
        {
            return std::nullopt;
        }
        *target = *number;
    }
    return vector;
}

OrderedJson WriteNumber(double value, bool hex)
{
    if (value == 0)
    {
        return 0; // also -0: b2dJson writes every zero as 0
    }
    if (value == 1)
    {
        return 1;
    }
    if (hex && std::isfinite(value) && double(float(value)) == value)
    {
        return FloatToHex(float(value));
    }
    return value;
}

OrderedJson WriteVector(SceneVec2 value, bool hex)
{
    if (value.x == 0 && value.y == 0)
    {
        return 0;
    }
    return OrderedJson{{"x", WriteNumber(value.x, hex)}, {"y", WriteNumber(value.y, hex)}};
}

namespace
{

bool IsScalar(const OrderedJson& value)
{
    return value.is_primitive();
}

/// Arrays of scalars, or of arrays of scalars ([[x, y], ...]), fit on one line.
bool IsInline(const OrderedJson& value)
{
    if (!value.is_array())
    {
        return IsScalar(value);
    }
    for (const OrderedJson& element : value)
    {
        if (!IsScalar(element) &&
            !(element.is_array() && std::all_of(element.begin(), element.end(), IsScalar)))
        {
            return false;
        }
    }
    return true;
}

void Format(const OrderedJson& value, int indent, std::string& out)
{
    const std::string pad(std::size_t(indent), ' ');
    if (IsInline(value))
    {
        out += value.dump(-1, ' ', false, OrderedJson::error_handler_t::replace);
        return;
    }
    const bool object = value.is_object();
    out += object ? "{\n" : "[\n";
    std::size_t i = 0;
    for (auto it = value.begin(); it != value.end(); ++it, ++i)
    {
        out += pad + "  ";
        if (object)
        {
            out += OrderedJson(it.key()).dump() + ": ";
        }
        Format(*it, indent + 2, out);
        out += i + 1 < value.size() ? ",\n" : "\n";
    }
    out += pad + (object ? "}" : "]");
}

} // namespace

std::string FormatJson(const OrderedJson& value)
{
    std::string out;
    Format(value, 0, out);
    // One space after each comma of the one-line arrays, as people write them.
    std::string spaced;
    spaced.reserve(out.size() + out.size() / 8);
    bool inString = false;
    for (std::size_t i = 0; i < out.size(); ++i)
    {
        const char c = out[i];
        spaced += c;
        if (inString && c == '\\' && i + 1 < out.size())
        {
            spaced += out[++i]; // an escaped character, perhaps a quote
        }
        else if (c == '"')
        {
            inString = !inString;
        }
        else if (!inString && c == ',' && i + 1 < out.size() && out[i + 1] != '\n')
        {
            spaced += ' ';
        }
    }
    return spaced + "\n";
}

} // namespace meff::b2djson_detail
