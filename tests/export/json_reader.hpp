#pragma once
// A minimal JSON reader for the export tests (RFC 8259 values; \uXXXX escapes of the BMP), so that
// the tests check the files as a JSON consumer reads them, not as the writer meant them.
#include <cstdlib>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace vimg::test {

struct Json {
  using Object = std::map<std::string, Json>;
  using Array = std::vector<Json>;
  std::variant<std::nullptr_t, bool, double, std::string, std::shared_ptr<Array>, std::shared_ptr<Object>> value;

  bool is_object() const { return std::holds_alternative<std::shared_ptr<Object>>(value); }
  bool is_array() const { return std::holds_alternative<std::shared_ptr<Array>>(value); }
  bool is_number() const { return std::holds_alternative<double>(value); }
  bool is_string() const { return std::holds_alternative<std::string>(value); }
  const Object& object() const { return *std::get<std::shared_ptr<Object>>(value); }
  const Array& array() const { return *std::get<std::shared_ptr<Array>>(value); }
  double number() const { return std::get<double>(value); }
  const std::string& string() const { return std::get<std::string>(value); }
  bool has(const std::string& key) const { return is_object() && object().count(key) > 0; }
  const Json& operator[](const std::string& key) const { return object().at(key); }
};

class JsonReader {
 public:
  // Throws std::runtime_error naming the offset on anything that is not one JSON value.
  static Json parse(std::string_view text) {
    JsonReader r(text);
    Json v = r.value();
    r.space();
    if (r.pos_ != text.size()) r.fail("text after the value");
    return v;
  }

 private:
  explicit JsonReader(std::string_view text) : t_(text) {}
  [[noreturn]] void fail(const std::string& what) { throw std::runtime_error(what + " at " + std::to_string(pos_)); }
  void space() {
    while (pos_ < t_.size() && (t_[pos_] == ' ' || t_[pos_] == '\n' || t_[pos_] == '\r' || t_[pos_] == '\t')) ++pos_;
  }
  bool eat(char c) {
    space();
    if (pos_ < t_.size() && t_[pos_] == c) return ++pos_, true;
    return false;
  }
  void expect(char c) {
    if (!eat(c)) fail(std::string("'") + c + "' expected");
  }
  Json value() {
    space();
    if (pos_ >= t_.size()) fail("value expected");
    const char c = t_[pos_];
    if (c == '{') return object();
    if (c == '[') return array();
    if (c == '"') return Json{string()};
    if (t_.substr(pos_, 4) == "true") return pos_ += 4, Json{true};
    if (t_.substr(pos_, 5) == "false") return pos_ += 5, Json{false};
    if (t_.substr(pos_, 4) == "null") return pos_ += 4, Json{nullptr};
    return Json{number()};
  }
  Json object() {
    expect('{');
    auto o = std::make_shared<Json::Object>();
    if (!eat('}')) {
      do {
        space();
        const std::string k = string();
        expect(':');
        if (!o->emplace(k, value()).second) fail("duplicate key " + k);
      } while (eat(','));
      expect('}');
    }
    return Json{o};
  }
  Json array() {
    expect('[');
    auto a = std::make_shared<Json::Array>();
    if (!eat(']')) {
      do a->push_back(value());
      while (eat(','));
      expect(']');
    }
    return Json{a};
  }
  std::string string() {
    if (pos_ >= t_.size() || t_[pos_] != '"') fail("string expected");
    ++pos_;
    std::string out;
    while (true) {
      if (pos_ >= t_.size()) fail("unterminated string");
      const char c = t_[pos_++];
      if (c == '"') return out;
      if (static_cast<unsigned char>(c) < 0x20) fail("control character in string");
      if (c != '\\') {
        out += c;
        continue;
      }
      if (pos_ >= t_.size()) fail("bad escape");
      const char e = t_[pos_++];
      switch (e) {
        case '"': case '\\': case '/': out += e; break;
        case 'b': out += '\b'; break;
        case 'f': out += '\f'; break;
        case 'n': out += '\n'; break;
        case 'r': out += '\r'; break;
        case 't': out += '\t'; break;
        case 'u': {
          if (pos_ + 4 > t_.size()) fail("bad \\u escape");
          const unsigned code = static_cast<unsigned>(std::strtoul(std::string(t_.substr(pos_, 4)).c_str(), nullptr, 16));
          pos_ += 4;
          if (code < 0x80) {
            out += static_cast<char>(code);
          } else if (code < 0x800) {
            out += static_cast<char>(0xC0 | (code >> 6));
            out += static_cast<char>(0x80 | (code & 0x3F));
          } else {
            out += static_cast<char>(0xE0 | (code >> 12));
            out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
            out += static_cast<char>(0x80 | (code & 0x3F));
          }
          break;
        }
        default: fail("bad escape");
      }
    }
  }
  double number() {
    const std::size_t begin = pos_;
    if (pos_ < t_.size() && t_[pos_] == '-') ++pos_;
    const auto digits = [&] {
      const std::size_t s = pos_;
      while (pos_ < t_.size() && t_[pos_] >= '0' && t_[pos_] <= '9') ++pos_;
      return pos_ - s;
    };
    const std::size_t int_begin = pos_;
    if (digits() == 0) fail("number expected");
    if (t_[int_begin] == '0' && pos_ - int_begin > 1) fail("leading zero");
    if (pos_ < t_.size() && t_[pos_] == '.') {
      ++pos_;
      if (digits() == 0) fail("digits expected after '.'");
    }
    if (pos_ < t_.size() && (t_[pos_] == 'e' || t_[pos_] == 'E')) {
      ++pos_;
      if (pos_ < t_.size() && (t_[pos_] == '+' || t_[pos_] == '-')) ++pos_;
      if (digits() == 0) fail("exponent digits expected");
    }
    return std::strtod(std::string(t_.substr(begin, pos_ - begin)).c_str(), nullptr);
  }

  std::string_view t_;
  std::size_t pos_ = 0;
};

}  // namespace vimg::test
