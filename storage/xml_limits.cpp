#include "storage/xml_limits.hpp"

#include <algorithm>
#include <cstddef>
#include <string_view>
#include <vector>

#include "storage/diagnostic.hpp"
#include "storage/limits.hpp"
#include "storage/xml_characters.hpp"

namespace vimg {

namespace {

class Scanner {
 public:
  explicit Scanner(std::string_view xml) : xml_(xml) {}

  std::optional<XmlLimitError> run() {
    if (auto error = check_encoding()) return error;
    while (pos_ < xml_.size()) {
      const std::size_t lt = xml_.find('<', pos_);
      if (check_text(pos_, lt == std::string_view::npos ? xml_.size() : lt)) return error_;
      if (lt == std::string_view::npos) break;
      advance_to(lt);
      const std::string_view rest = xml_.substr(pos_);
      if (rest.starts_with("<!--")) {
        if (check_comment()) return error_;
        if (!markup(4, "-->")) return error_;  // never closed: the parser says so
      } else if (rest.starts_with("<![CDATA[")) {
        if (!markup(9, "]]>")) return error_;  // text, not counted by tinyxml2 as markup, but a node all the same
      } else if (rest.starts_with("<?")) {
        if (late_declaration(rest)) {
          return XmlLimitError{line_, "an XML declaration '<?xml ...?>' that is not at the very start of the file "
                                      "(nothing, not even a blank, may come before it)"};
        }
        if (!markup(2, "?>")) return error_;
      } else if (rest.starts_with("<!DOCTYPE")) {
        // tinyxml2 skips a DTD without expanding its entities, so "&name;" would reach the
        // values as text and be reported as a bad value: say what is really there.
        return XmlLimitError{line_, "a <!DOCTYPE> declaration (a DTD, entities) is not allowed in this format"};
      } else if (rest.starts_with("<!")) {
        if (!markup(2, ">")) return error_;
      } else if (rest.starts_with("</")) {
        if (close_tag()) return error_;
        if (!skip_past(2, ">")) return error_;
      } else if (!start_tag()) {
        return error_;
      }
      if (error_) return error_;
    }
    if (!open_.empty()) {
      const OpenElement& last = open_.back();
      return XmlLimitError{line_, "the file ends before <" + escape_input(last.name) + "> (opened at line " +
                                      std::to_string(last.line) + ") is closed"};
    }
    return error_;
  }

 private:
  // The text must be UTF-8 without NUL bytes: UTF-16 and UTF-32 (with or without a byte order
  // mark) and NULs would otherwise reach tinyxml2, which stops at the first NUL ("the file is
  // empty") or reports a bare syntax error.
  std::optional<XmlLimitError> check_encoding() const {
    const auto starts = [&](std::string_view bom) { return xml_.substr(0, bom.size()) == bom; };
    using namespace std::string_view_literals;
    if (starts("\x00\x00\xFE\xFF"sv) || starts("\xFF\xFE\x00\x00"sv)) {
      return XmlLimitError{1, "the text is UTF-32 (byte order mark); this format is UTF-8"};
    }
    if (starts("\xFE\xFF"sv) || starts("\xFF\xFE"sv)) {
      return XmlLimitError{1, "the text is UTF-16 (byte order mark); this format is UTF-8"};
    }
    const std::size_t nul = xml_.find('\0');
    if (nul != std::string_view::npos) {
      return XmlLimitError{line_at(nul), "a NUL byte at offset " + std::to_string(nul) +
                                     " (XML text never holds one; is this UTF-16 or a binary file?)"};
    }
    const std::size_t control = find_forbidden_control_byte(xml_);
    if (control != std::string_view::npos) {
      return XmlLimitError{line_at(control), "a control character (byte " + hex_byte(static_cast<unsigned char>(xml_[control])) + ") at offset " +
                                                 std::to_string(control) + ", which XML does not allow"};
    }
    const std::size_t end = xml_.starts_with("<?xml") ? xml_.find("?>") : std::string_view::npos;
    if (end != std::string_view::npos) {
      const std::string_view declaration = xml_.substr(0, end);
      const std::size_t at = declaration.find("encoding");
      if (at != std::string_view::npos) {
        std::size_t q = declaration.find_first_of("\"'", at);
        if (q != std::string_view::npos) {
          const std::size_t close = declaration.find(declaration[q], q + 1);
          std::string name(declaration.substr(q + 1, close == std::string_view::npos ? 0 : close - q - 1));
          for (char& c : name) c = static_cast<char>(c >= 'a' && c <= 'z' ? c - 'a' + 'A' : c);
          if (name != "UTF-8" && name != "UTF8") {
            return XmlLimitError{1, "the XML declaration names the encoding \"" + escape_input(name) +
                                        "\"; this format is UTF-8"};
          }
        }
      }
    }
    return std::nullopt;
  }

  // The 1-based line of offset `at` (counted from the start: for errors only).
  int line_at(std::size_t at) const {
    return 1 + static_cast<int>(std::count(xml_.begin(), xml_.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
  }

  // Character data in [from, to): no "]]>" (it ends only a CDATA section), and references as
  // check_references; true (with error_ set) when it breaks either.
  bool check_text(std::size_t from, std::size_t to) {
    const std::size_t cdata_end = xml_.substr(from, to - from).find("]]>");
    if (cdata_end != std::string_view::npos) {
      error_ = XmlLimitError{line_at(from + cdata_end), "']]>' in text outside a CDATA section; write ']]&gt;'"};
      return true;
    }
    return check_references(from, to);
  }

  // A comment at pos_ may not hold "--" nor end in "--->"; true (with error_ set) when it does.
  bool check_comment() {
    const std::size_t end = xml_.find("-->", pos_ + 4);
    if (end == std::string_view::npos) return false;  // never closed: the parser says so
    const std::size_t dashes = xml_.substr(pos_ + 4, end - pos_ - 4 + 1).find("--");
    if (dashes == std::string_view::npos) return false;
    error_ = XmlLimitError{line_at(pos_ + 4 + dashes), "'--' inside a comment (XML allows it only in the closing '-->')"};
    return true;
  }

  // `rest` starts with "<?": true when it is an XML declaration anywhere but at the start of the
  // file (after a UTF-8 byte order mark, if any).
  bool late_declaration(std::string_view rest) const {
    if (pos_ == 0 || (pos_ == 3 && xml_.starts_with("\xEF\xBB\xBF"))) return false;
    if (rest.size() < 6) return false;
    const auto lower = [](char c) { return static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c); };
    const bool xml = lower(rest[2]) == 'x' && lower(rest[3]) == 'm' && lower(rest[4]) == 'l';
    const char after = rest[5];
    return xml && (after == ' ' || after == '\t' || after == '\n' || after == '\r' || after == '?');
  }

  // Every '&' in [from, to) must start a well-formed reference to an allowed character; true
  // (with error_ set) when one does not.
  bool check_references(std::size_t from, std::size_t to) {
    const std::string_view segment = xml_.substr(from, to - from);  // searched alone: linear overall
    for (std::size_t at = segment.find('&'); at != std::string_view::npos; at = segment.find('&', at + 1)) {
      const std::size_t amp = from + at;
      if (auto problem = reference_error(xml_.substr(amp, to - amp))) {
        error_ = XmlLimitError{line_at(amp), std::move(*problem)};
        return true;
      }
    }
    return false;
  }

  // Moves to `to`, counting the newlines passed.
  void advance_to(std::size_t to) {
    line_ += static_cast<int>(std::count(xml_.begin() + static_cast<std::ptrdiff_t>(pos_),
                                         xml_.begin() + static_cast<std::ptrdiff_t>(to), '\n'));
    pos_ = to;
  }

  // Skips from pos_ + `open` to just past `close`; false when it never comes (malformed).
  bool skip_past(std::size_t open, std::string_view close) {
    const std::size_t end = xml_.find(close, pos_ + open);
    if (end == std::string_view::npos) return false;
    advance_to(end + close.size());
    return true;
  }

  bool count_node(int line) {
    if (++nodes_ > kMaxXmlElements) {
      error_ = XmlLimitError{line, "more than " + std::to_string(kMaxXmlElements) +
                                       " elements, comments and processing instructions (limit " +
                                       std::to_string(kMaxXmlElements) + ")"};
      return false;
    }
    return true;
  }

  bool markup(std::size_t open, std::string_view close) {
    if (!count_node(line_)) return true;
    return skip_past(open, close);
  }

  static bool name_char(char c) {
    const auto b = static_cast<unsigned char>(c);
    return b >= 0x80 || (b >= 'a' && b <= 'z') || (b >= 'A' && b <= 'Z') || (b >= '0' && b <= '9') || c == '_' ||
           c == ':' || c == '.' || c == '-';
  }

  // The name starting at `from` (empty when none does).
  std::string_view name_at(std::size_t from) const {
    std::size_t end = from;
    while (end < xml_.size() && name_char(xml_[end])) ++end;
    return xml_.substr(from, end - from);
  }

  // An end tag at pos_ must close the element open last; true (with error_ set) when it does not.
  bool close_tag() {
    const std::string_view name = name_at(pos_ + 2);
    if (name.empty()) return false;  // malformed: the parser says so
    if (open_.empty()) {
      error_ = XmlLimitError{line_, "</" + escape_input(name) + "> closes no element (all are closed already)"};
      return true;
    }
    if (open_.back().name != name) {
      error_ = XmlLimitError{line_, "</" + escape_input(name) + "> does not close <" + escape_input(open_.back().name) +
                                        "> (opened at line " + std::to_string(open_.back().line) + ")"};
      return true;
    }
    open_.pop_back();
    return false;
  }

  // A start tag at pos_: counts it, checks the depth and its attributes, moves past its '>'.
  bool start_tag() {
    const int line = line_;
    const std::string_view name = name_at(pos_ + 1);
    if (name.empty()) return false;  // "< x" or "<=": malformed, the parser says so
    std::size_t i = pos_ + 1 + name.size();
    if (!count_node(line)) return true;
    if (open_.size() + 1 > static_cast<std::size_t>(kMaxXmlNestingDepth)) {  // this element inside all that are open
      error_ = XmlLimitError{line, "elements nested more than " + std::to_string(kMaxXmlNestingDepth) + " deep (limit " +
                                       std::to_string(kMaxXmlNestingDepth) + ")"};
      return true;
    }
    std::size_t attributes = 0;
    for (; i < xml_.size(); ++i) {
      const char c = xml_[i];
      if (c == '"' || c == '\'') {
        const std::size_t close = xml_.find(c, i + 1);
        if (close == std::string_view::npos) return false;  // the value never ends: malformed
        const std::size_t lt = xml_.substr(i + 1, close - i - 1).find('<');
        if (lt != std::string_view::npos) {
          error_ = XmlLimitError{line_at(i + 1 + lt), "a '<' inside the value of an attribute of <" + escape_input(name) +
                                                          ">; write '&lt;' for the character itself"};
          return true;
        }
        if (check_references(i + 1, close)) return true;
        i = close;  // past the value
        const char next = close + 1 < xml_.size() ? xml_[close + 1] : ' ';
        if (next != ' ' && next != '\t' && next != '\n' && next != '\r' && next != '/' && next != '>') {
          const std::string_view next_name = name_at(close + 1);
          error_ = XmlLimitError{line_at(close), "no space between two attributes of <" + escape_input(name) +
                                                     "> (before '" + escape_input(next_name.empty() ? xml_.substr(close + 1, 1) : next_name) + "')"};
          return true;
        }
      } else if (c == '=') {
        if (++attributes_ > kMaxXmlAttributes) {
          error_ = XmlLimitError{line, "more than " + std::to_string(kMaxXmlAttributes) + " attributes in the file (limit " +
                                           std::to_string(kMaxXmlAttributes) + ")"};
          return true;
        }
        if (++attributes > kMaxAttributesPerElement) {
          error_ = XmlLimitError{line, "<" + escape_input(name) + "> has more than " +
                                           std::to_string(kMaxAttributesPerElement) + " attributes (limit " +
                                           std::to_string(kMaxAttributesPerElement) + ")"};
          return true;
        }
      } else if (c == '<') {
        return false;  // the tag is not closed before the next one: the parser says so, at its line
      } else if (c == '>') {
        if (xml_[i - 1] != '/') open_.push_back({name, line});  // not <empty/>; kMaxXmlNestingDepth at most: checked above
        advance_to(i + 1);
        return true;
      }
    }
    return false;  // the tag never ends: malformed, the parser says so
  }

  struct OpenElement {
    std::string_view name;
    int line;
  };

  std::string_view xml_;
  std::vector<OpenElement> open_;  // the elements open at pos_, outermost first
  std::size_t pos_ = 0;
  int line_ = 1;
  std::size_t nodes_ = 0;
  std::size_t attributes_ = 0;  // in the whole file
  std::optional<XmlLimitError> error_;
};

}  // namespace

std::optional<XmlLimitError> check_xml_limits(std::string_view xml) { return Scanner(xml).run(); }

}  // namespace vimg
