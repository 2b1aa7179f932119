#pragma once
// A small strict JSON reader (RFC 8259) for what `vimg study report --predicted` reads: the report
// of `vimg compare`. The project writes JSON (storage/export/json_writer.hpp) but read none before,
// and the report needs a few keys of one document, so this reader is bounded rather than general:
//   - at most kMaxJsonDepth nested arrays/objects and kMaxJsonValues values in all (the caller bounds
//     the text: read_regular_file with kMaxPredictedJsonBytes);
//   - exactly one value, surrounded by JSON whitespace only; no byte-order mark, comments, trailing
//     commas, single quotes, NaN/Infinity, leading zeros or '+'; numbers must fit a double;
//   - strings: valid UTF-8, no control characters, the escapes of RFC 8259 (\uXXXX with surrogate
//     pairs; a lone surrogate is refused); duplicate keys in an object are refused.
// The first problem stops the reader: `FILE:LINE: error: ...` with input quoted through
// escape_input().
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "storage/diagnostic.hpp"
#include "storage/limits.hpp"

namespace vimg {

inline constexpr std::size_t kMaxJsonDepth = 64;
inline constexpr std::size_t kMaxJsonValues = 200'000 / kLimitScale;  // scaled down in the fuzz build

struct JsonValue {
  enum class Kind { null, boolean, number, string, array, object };
  Kind kind = Kind::null;
  int line = 0;  // where the value starts, 1-based
  bool boolean = false;
  double number = 0.0;
  std::string text;               // a string's value (UTF-8)
  std::vector<JsonValue> items;   // an array's elements, or an object's member values
  std::vector<std::string> keys;  // an object's member names, parallel to items

  // The member named `key` of an object, or nullptr.
  const JsonValue* find(std::string_view key) const;
};

// Kind names for messages: "null", "true or false", "a number", "a string", "an array", "an object".
std::string_view json_kind_name(JsonValue::Kind kind);

struct JsonParseResult {
  std::optional<JsonValue> value;  // set when there is no error
  std::vector<Diagnostic> diagnostics;
};

JsonParseResult parse_json(std::string_view text, const std::string& file_name);

}  // namespace vimg
