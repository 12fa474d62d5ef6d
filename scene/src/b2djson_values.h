// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// b2dJson's conventions for values: a float is a JSON number or a string of the 8 hex digits of
// its IEEE bits ("3FC00000" is 1.5f); a vector is {"x": ..., "y": ...}, or the number 0 for the
// zero vector; a list of points is {"x": [...], "y": [...]}. And the JSON layout the importer
// and exporter write: objects one field per line, arrays of numbers on one line.
#pragma once

#include "meff/scene.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace meff::b2djson_detail
{

using Json = nlohmann::json;
/// What the importer and exporter write: fields in the order they are put.
using OrderedJson = nlohmann::ordered_json;

/// "3FC00000" for 1.5f: the bits, most significant first, upper case (as b2dJson writes them).
std::string FloatToHex(float value);
/// The float whose bits `text` spells in 8 hex digits (either case); nullopt for anything else.
std::optional<float> HexToFloat(std::string_view text);

/// A b2dJson number: a JSON number, or a hex string; nullopt when it is neither.
std::optional<double> ReadNumber(const Json& value);
/// A b2dJson vector: {"x", "y"} (each a number, missing ones 0) or the number 0.
std::optional<SceneVec2> ReadVector(const Json& value);

/// `value` as b2dJson writes it: 0 and 1 as integers; with `hex`, a value that is exactly a
/// float as its hex string; else the shortest decimal that reads back as the same double.
OrderedJson WriteNumber(double value, bool hex);
/// The zero vector as 0, anything else as {"x", "y"}.
OrderedJson WriteVector(SceneVec2 value, bool hex);

/// Objects one field per line, indented by two; arrays of numbers, strings or [x, y] pairs on
/// one line; ends with a newline.
std::string FormatJson(const OrderedJson& value);

} // namespace meff::b2djson_detail
