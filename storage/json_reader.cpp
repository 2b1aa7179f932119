#include "storage/json_reader.hpp"

#include <charconv>
#include <cstdint>
#include <initializer_list>
#include <set>
#include <system_error>
#include <tuple>

namespace vimg {

namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

void append_utf8(std::string& out, std::uint32_t code) {
  if (code < 0x80) {
    out += static_cast<char>(code);
  } else if (code < 0x800) {
    out += static_cast<char>(0xC0 | (code >> 6));
    out += static_cast<char>(0x80 | (code & 0x3F));
  } else if (code < 0x10000) {
    out += static_cast<char>(0xE0 | (code >> 12));
    out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (code >> 18));
    out += static_cast<char>(0x80 | ((code >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code & 0x3F));
  }
}

// Length of the valid UTF-8 sequence (of two to four bytes) at text[i], or 0.
std::size_t utf8_length(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char b = byte(i);
  std::size_t n = 0;
  std::uint32_t min = 0;
  if (b >= 0xC2 && b <= 0xDF) n = 2, min = 0x80;
  else if (b >= 0xE0 && b <= 0xEF) n = 3, min = 0x800;
  else if (b >= 0xF0 && b <= 0xF4) n = 4, min = 0x10000;
  else return 0;
  if (i + n > text.size()) return 0;
  std::uint32_t code = b & (0xFFu >> (n + 1));
  for (std::size_t k = 1; k < n; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) return 0;
    code = (code << 6) | (byte(i + k) & 0x3Fu);
  }
  if (code < min || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) return 0;
  return n;
}

class Parser {
 public:
  Parser(std::string_view text, const std::string& file_name) : text_(text), list_(file_name) {}

  JsonParseResult run() {
    JsonParseResult result;
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") {
      fail("the file starts with a byte-order mark, which JSON does not allow");
    } else {
      space();
      JsonValue value;
      if (parse_value(value, 0)) {
        space();
        if (pos_ < text_.size()) {
          fail("text after the JSON value: " + found());
        } else {
          result.value = std::move(value);
        }
      }
    }
    result.diagnostics = list_.take();
    if (has_errors(result.diagnostics)) result.value.reset();
    return result;
  }

 private:
  bool fail(const std::string& message) {
    if (!failed_) list_.error(line_, message);
    failed_ = true;
    return false;
  }

  // What stands at the current position, for messages.
  std::string found() const {
    if (pos_ >= text_.size()) return "the end of the file";
    std::size_t end = pos_ + 1;
    while (end < text_.size() && end - pos_ < 16 && text_[end] != ',' && text_[end] != ' ' && text_[end] != '\n' &&
           text_[end] != '}' && text_[end] != ']')
      ++end;
    return "'" + escape_input(text_.substr(pos_, end - pos_)) + "'";
  }

  void space() {
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == '\n') ++line_;
      if (c != ' ' && c != '\t' && c != '\n' && c != '\r') return;
      ++pos_;
    }
  }

  bool parse_value(JsonValue& v, std::size_t depth) {
    if (++values_ > kMaxJsonValues) return fail("more than " + std::to_string(kMaxJsonValues) + " values (the limit)");
    v.line = line_;
    if (pos_ >= text_.size()) return fail("expected a value, found the end of the file");
    const char c = text_[pos_];
    if (c == '{' || c == '[') {
      if (depth >= kMaxJsonDepth) return fail("arrays and objects nested deeper than " + std::to_string(kMaxJsonDepth));
      return c == '{' ? parse_object(v, depth + 1) : parse_array(v, depth + 1);
    }
    if (c == '"') {
      v.kind = JsonValue::Kind::string;
      return parse_string(v.text);
    }
    if (c == '-' || is_digit(c)) return parse_number(v);
    for (const auto& [word, kind, truth] : {std::tuple{"true", JsonValue::Kind::boolean, true},
                                            std::tuple{"false", JsonValue::Kind::boolean, false},
                                            std::tuple{"null", JsonValue::Kind::null, false}}) {
      const std::string_view w(word);
      if (text_.substr(pos_, w.size()) == w) {
        pos_ += w.size();
        v.kind = kind;
        v.boolean = truth;
        return true;
      }
    }
    return fail("expected a value, found " + found());
  }

  bool parse_object(JsonValue& v, std::size_t depth) {
    v.kind = JsonValue::Kind::object;
    ++pos_;  // '{'
    space();
    if (pos_ < text_.size() && text_[pos_] == '}') return ++pos_, true;
    std::set<std::string, std::less<>> seen;  // a set, not a scan: many keys stay linearithmic
    while (true) {
      space();
      if (pos_ >= text_.size() || text_[pos_] != '"') return fail("expected a member name in quotes, found " + found());
      const int key_line = line_;
      std::string key;
      if (!parse_string(key)) return false;
      if (!seen.insert(key).second) {
        line_ = key_line;
        return fail("the key \"" + escape_input(key) + "\" appears twice in one object");
      }
      space();
      if (pos_ >= text_.size() || text_[pos_] != ':') return fail("expected ':' after a member name, found " + found());
      ++pos_;
      space();
      v.keys.push_back(std::move(key));
      v.items.emplace_back();
      if (!parse_value(v.items.back(), depth)) return false;
      space();
      if (pos_ < text_.size() && text_[pos_] == ',') {
        ++pos_;
        continue;
      }
      if (pos_ < text_.size() && text_[pos_] == '}') return ++pos_, true;
      return fail("expected ',' or '}' in an object, found " + found());
    }
  }

  bool parse_array(JsonValue& v, std::size_t depth) {
    v.kind = JsonValue::Kind::array;
    ++pos_;  // '['
    space();
    if (pos_ < text_.size() && text_[pos_] == ']') return ++pos_, true;
    while (true) {
      space();
      v.items.emplace_back();
      if (!parse_value(v.items.back(), depth)) return false;
      space();
      if (pos_ < text_.size() && text_[pos_] == ',') {
        ++pos_;
        continue;
      }
      if (pos_ < text_.size() && text_[pos_] == ']') return ++pos_, true;
      return fail("expected ',' or ']' in an array, found " + found());
    }
  }

  // Four hex digits at pos_ (after "\u"); -1 when they are not.
  int hex4() {
    if (pos_ + 4 > text_.size()) return -1;
    int code = 0;
    for (std::size_t k = 0; k < 4; ++k) {
      const int h = hex_value(text_[pos_ + k]);
      if (h < 0) return -1;
      code = code * 16 + h;
    }
    pos_ += 4;
    return code;
  }

  bool parse_escape(std::string& out) {
    if (pos_ >= text_.size()) return fail("a string is not closed before the end of the file");
    const char e = text_[pos_++];
    switch (e) {
      case '"': out += '"'; return true;
      case '\\': out += '\\'; return true;
      case '/': out += '/'; return true;
      case 'b': out += '\b'; return true;
      case 'f': out += '\f'; return true;
      case 'n': out += '\n'; return true;
      case 'r': out += '\r'; return true;
      case 't': out += '\t'; return true;
      case 'u': break;
      default: --pos_; return fail("unknown escape in a string: " + found());
    }
    const int code = hex4();
    if (code < 0) return fail("\\u must be followed by four hexadecimal digits");
    if (code >= 0xDC00 && code <= 0xDFFF) return fail("a \\u escape names a lone low surrogate");
    if (code < 0xD800 || code > 0xDBFF) return append_utf8(out, static_cast<std::uint32_t>(code)), true;
    if (text_.substr(pos_, 2) != "\\u") return fail("a \\u escape names a high surrogate without its low surrogate");
    pos_ += 2;
    const int low = hex4();
    if (low < 0xDC00 || low > 0xDFFF) return fail("a \\u escape names a high surrogate without its low surrogate");
    append_utf8(out, 0x10000u + ((static_cast<std::uint32_t>(code) - 0xD800u) << 10) + (static_cast<std::uint32_t>(low) - 0xDC00u));
    return true;
  }

  bool parse_string(std::string& out) {
    ++pos_;  // opening quote
    while (true) {
      if (pos_ >= text_.size()) return fail("a string is not closed before the end of the file");
      const auto c = static_cast<unsigned char>(text_[pos_]);
      if (c == '"') return ++pos_, true;
      if (c == '\\') {
        ++pos_;
        if (!parse_escape(out)) return false;
      } else if (c < 0x20) {
        return fail("a control character (" + hex_byte(c) + ") inside a string; JSON needs it escaped");
      } else if (c < 0x80) {
        out += static_cast<char>(c);
        ++pos_;
      } else if (const std::size_t n = utf8_length(text_, pos_); n > 0) {
        out.append(text_.substr(pos_, n));
        pos_ += n;
      } else {
        return fail("a string holds a byte that is not UTF-8 (" + hex_byte(c) + ")");
      }
    }
  }

  bool parse_number(JsonValue& v) {
    const std::size_t begin = pos_;
    auto digits = [&] {
      const std::size_t from = pos_;
      while (pos_ < text_.size() && is_digit(text_[pos_])) ++pos_;
      return pos_ - from;
    };
    if (text_[pos_] == '-') ++pos_;
    if (pos_ < text_.size() && text_[pos_] == '0') {
      ++pos_;
      if (pos_ < text_.size() && is_digit(text_[pos_])) return pos_ = begin, fail("a number with a leading zero: " + found());
    } else if (digits() == 0) {
      return pos_ = begin, fail("expected a value, found " + found());
    }
    bool negative_exponent = false;
    if (pos_ < text_.size() && text_[pos_] == '.') {
      ++pos_;
      if (digits() == 0) return pos_ = begin, fail("a number with no digit after '.': " + found());
    }
    if (pos_ < text_.size() && (text_[pos_] == 'e' || text_[pos_] == 'E')) {
      ++pos_;
      if (pos_ < text_.size() && (text_[pos_] == '+' || text_[pos_] == '-')) negative_exponent = text_[pos_++] == '-';
      if (digits() == 0) return pos_ = begin, fail("a number with no digit in its exponent: " + found());
    }
    const char* first = text_.data() + begin;
    const char* last = text_.data() + pos_;
    v.kind = JsonValue::Kind::number;
    const auto [ptr, ec] = std::from_chars(first, last, v.number, std::chars_format::general);
    if (ec == std::errc::result_out_of_range && negative_exponent) {
      v.number = 0.0;  // below the smallest double: it reads as zero
    } else if (ec != std::errc() || ptr != last) {
      pos_ = begin;
      return fail("a number that does not fit a double: " + found());
    }
    return true;
  }

  std::string_view text_;
  DiagnosticList list_;
  std::size_t pos_ = 0;
  int line_ = 1;
  std::size_t values_ = 0;
  bool failed_ = false;
};

}  // namespace

const JsonValue* JsonValue::find(std::string_view key) const {
  if (kind != Kind::object) return nullptr;
  for (std::size_t i = 0; i < keys.size(); ++i) {
    if (keys[i] == key) return &items[i];
  }
  return nullptr;
}

std::string_view json_kind_name(JsonValue::Kind kind) {
  switch (kind) {
    case JsonValue::Kind::null: return "null";
    case JsonValue::Kind::boolean: return "true or false";
    case JsonValue::Kind::number: return "a number";
    case JsonValue::Kind::string: return "a string";
    case JsonValue::Kind::array: return "an array";
    case JsonValue::Kind::object: return "an object";
  }
  return "a value";
}

JsonParseResult parse_json(std::string_view text, const std::string& file_name) {
  return Parser(text, file_name).run();
}

}  // namespace vimg
