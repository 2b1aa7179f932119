#pragma once
// A small JSON writer for the clip exports (docs/export.md): objects, arrays, strings escaped per
// RFC 8259 (quotes, backslashes and control characters escaped; bytes that are not UTF-8 become
// U+FFFD so that the output is always valid UTF-8), and numbers in the shortest form that reads
// back to the same double. Two-space indentation, one value per line.
#include <string>
#include <string_view>
#include <vector>

namespace vimg {

class JsonWriter {
 public:
  void begin_object();
  void end_object();
  void begin_array();
  void end_array();
  // The key of the next member of the current object.
  void key(std::string_view name);
  void string(std::string_view text);
  // A finite number (a non-finite one is written as 0: JSON has no NaN or infinity).
  void number(double value);
  void integer(long long value);
  // JSON's null (a value that is undefined, e.g. a statistic of too few data).
  void null();
  // true or false.
  void boolean(bool value);
  // A number written exactly as given (e.g. "1.0" where a format's samples write it so); the text
  // must be a JSON number.
  void number_text(std::string_view json_number);
  // The document; the writer is empty afterwards.
  std::string take();

 private:
  void before_value();
  void close(char bracket);
  std::string out_;
  std::vector<bool> has_members_;  // per open container: anything written in it yet
  bool after_key_ = false;
};

// The JSON string literal for `text`, quotes included.
std::string json_quote(std::string_view text);

}  // namespace vimg
