#include "storage/touch_trace/evdev_line.hpp"

#include <charconv>
#include <map>
#include <vector>

#include "storage/diagnostic.hpp"
#include "storage/text_trim.hpp"

namespace vimg {
namespace {

std::vector<std::string_view> words(std::string_view s) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t' || s[i] == '\r')) ++i;
    std::size_t j = i;
    while (j < s.size() && s[j] != ' ' && s[j] != '\t' && s[j] != '\r') ++j;
    if (j > i) out.push_back(s.substr(i, j - i));
    i = j;
  }
  return out;
}

template <class T>
std::optional<T> number(std::string_view s, int base) {
  T v{};
  if (s.empty()) return std::nullopt;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v, base);
  if (r.ec != std::errc{} || r.ptr != s.data() + s.size()) return std::nullopt;
  return v;
}

// "12345.678901" -> whole seconds and microseconds (six digits at most after the point).
bool timestamp(std::string_view s, EvdevEvent& e) {
  const std::size_t dot = s.find('.');
  const auto whole = number<std::int64_t>(s.substr(0, dot), 10);
  if (!whole || *whole < 0) return false;
  e.seconds = *whole;
  e.microseconds = 0;
  if (dot == std::string_view::npos) return true;
  const std::string_view frac = s.substr(dot + 1);
  if (frac.empty() || frac.size() > 9) return false;
  const auto digits = number<std::int64_t>(frac, 10);
  if (!digits || frac.front() == '-' || frac.front() == '+') return false;
  std::int64_t us = *digits;
  for (std::size_t n = frac.size(); n < 6; ++n) us *= 10;
  for (std::size_t n = frac.size(); n > 6; --n) us /= 10;
  e.microseconds = us;
  return true;
}

// getevent -l names of what the trace reader uses; other names are ignored.
const std::map<std::string_view, int>& type_names() {
  static const std::map<std::string_view, int> m = {{"EV_SYN", evdev::kEvSyn}, {"EV_KEY", evdev::kEvKey}, {"EV_ABS", evdev::kEvAbs}};
  return m;
}
const std::map<std::string_view, int>& code_names() {
  static const std::map<std::string_view, int> m = {
      {"SYN_REPORT", evdev::kSynReport},       {"SYN_MT_REPORT", evdev::kSynMtReport}, {"SYN_DROPPED", evdev::kSynDropped},
      {"BTN_TOUCH", evdev::kBtnTouch},         {"ABS_X", evdev::kAbsX},                {"ABS_Y", evdev::kAbsY},
      {"ABS_PRESSURE", evdev::kAbsPressure},   {"ABS_MT_SLOT", evdev::kAbsMtSlot},     {"ABS_MT_POSITION_X", evdev::kAbsMtPositionX},
      {"ABS_MT_POSITION_Y", evdev::kAbsMtPositionY}, {"ABS_MT_TRACKING_ID", evdev::kAbsMtTrackingId},
      {"ABS_MT_PRESSURE", evdev::kAbsMtPressure}};
  return m;
}

// A type or code: a getevent -l name, or four hex digits; -1 for a name this reader ignores.
std::optional<int> type_or_code(std::string_view s, const std::map<std::string_view, int>& names) {
  if (const auto it = names.find(s); it != names.end()) return it->second;
  if (const auto hex = number<int>(s, 16); hex && *hex >= 0 && *hex <= 0xffff) return *hex;
  const bool is_name = !s.empty() && s.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_") == std::string_view::npos;
  if (is_name) return -1;
  return std::nullopt;
}

EvdevLine bad(std::string problem) {
  EvdevLine l;
  l.kind = EvdevLine::Kind::bad;
  l.problem = std::move(problem);
  return l;
}

std::string quoted(std::string_view s) { return "'" + escape_input(s) + "'"; }

}  // namespace

EvdevLine EvdevLineReader::read(std::string_view raw) {
  const std::string_view line = trim_blanks(raw);
  if (line.empty()) return {};
  if (line.starts_with("E:")) return read_evemu_event(line.substr(2));
  if (line.starts_with("[")) return read_getevent(line);
  if (line.front() == '#') return read_comment(line.substr(1));
  if (line.starts_with("A:")) {
    const auto w = words(line.substr(2));
    if (w.size() < 3) return bad("an axis line 'A: code min max …' needs a code, a minimum and a maximum");
    const auto code = number<int>(w[0], 16);
    const auto min = number<std::int64_t>(w[1], 10);
    const auto max = number<std::int64_t>(w[2], 10);
    if (!code || !min || !max) return bad("bad axis line " + quoted(line));
    EvdevLine l;
    l.kind = EvdevLine::Kind::axis;
    l.axis = {*code, *min, *max, w.size() >= 6 ? number<std::int64_t>(w[5], 10).value_or(0) : 0};
    return l;
  }
  // evemu's device lines (N: name, I: ids, P: properties, B: bits, L: LEDs, S: switches).
  for (const char* prefix : {"N:", "I:", "P:", "B:", "L:", "S:"}) {
    if (line.starts_with(prefix)) return {};
  }
  // getevent's device list and `getevent -lp` descriptions.
  if (line.starts_with("add device") || line.starts_with("name:") || line.starts_with("could not get") ||
      line.starts_with("events:") || line.starts_with("input props:") || line.starts_with("KEY (") ||
      line.starts_with("INPUT_PROP_") || line.starts_with("<none>") || line.starts_with("bus:") ||
      line.starts_with("location:") || line.starts_with("id:") || line.starts_with("version:")) {
    return {};
  }
  if (const std::size_t colon = line.find(": value "); colon != std::string_view::npos) {
    std::string_view name = line;
    if (name.starts_with("ABS (0003):")) name.remove_prefix(11);
    name = trim_blanks(name.substr(0, name.find(':')));
    const auto code = type_or_code(name, code_names());
    const auto min_at = line.find("min "), max_at = line.find("max ");
    if (!code || *code < 0 || min_at == std::string_view::npos || max_at == std::string_view::npos) return {};
    const auto field = [&](std::size_t at) { return trim_blanks(line.substr(at + 4, line.find(',', at) - at - 4)); };
    const auto min = number<std::int64_t>(field(min_at), 10), max = number<std::int64_t>(field(max_at), 10);
    const std::size_t res_at = line.find("resolution ");
    if (!min || !max) return bad("bad axis description " + quoted(line));
    EvdevLine l;
    l.kind = EvdevLine::Kind::axis;
    l.axis = {*code, *min, *max, res_at == std::string_view::npos ? 0 : number<std::int64_t>(trim_blanks(line.substr(res_at + 11)), 10).value_or(0)};
    return l;
  }
  return bad("expected an evemu event 'E: seconds type code value' or a getevent line '[seconds] device: type code value', got " +
             quoted(line));
}

EvdevLine EvdevLineReader::read_evemu_event(std::string_view rest) const {
  const std::size_t hash = rest.find('#');
  const auto w = words(rest.substr(0, hash));
  if (w.size() != 4) return bad("an evemu event needs 4 fields 'E: seconds type code value', got " + std::to_string(w.size()));
  EvdevLine l;
  l.kind = EvdevLine::Kind::event;
  const auto type = number<int>(w[1], 16);
  const auto code = number<int>(w[2], 16);
  const auto value = number<std::int64_t>(w[3], 10);
  if (!timestamp(w[0], l.event)) return bad("bad time " + quoted(w[0]) + " (seconds.microseconds)");
  if (!type || !code || *type < 0 || *type > 0xffff || *code < 0 || *code > 0xffff) return bad("bad type or code " + quoted(w[1]) + " " + quoted(w[2]));
  if (!value) return bad("bad value " + quoted(w[3]) + " (a decimal integer)");
  l.event.type = *type;
  l.event.code = *code;
  l.event.value = *value;
  return l;
}

EvdevLine EvdevLineReader::read_getevent(std::string_view line) const {
  const std::size_t close = line.find(']');
  if (close == std::string_view::npos) return bad("a getevent line starts with '[seconds]'");
  EvdevLine l;
  l.kind = EvdevLine::Kind::event;
  if (!timestamp(trim_blanks(line.substr(1, close - 1)), l.event)) return bad("bad time " + quoted(line.substr(0, close + 1)));
  std::string_view rest = trim_blanks(line.substr(close + 1));
  auto w = words(rest);
  if (!w.empty() && w[0].back() == ':') {
    l.event.device = std::string(w[0].substr(0, w[0].size() - 1));
    w.erase(w.begin());
  }
  if (w.size() != 3) return bad("a getevent line needs 'type code value' after the time, got " + quoted(rest));
  const auto type = type_or_code(w[0], type_names());
  const auto code = type_or_code(w[1], code_names());
  if (!type || !code) return bad("bad type or code " + quoted(w[0]) + " " + quoted(w[1]));
  l.event.type = *type;
  l.event.code = *code;
  if (w[2] == "DOWN") l.event.value = 1;
  else if (w[2] == "UP") l.event.value = 0;
  else if (const auto v = number<std::uint32_t>(w[2], 16); v && w[2].size() <= 8) {
    l.event.value = static_cast<std::int32_t>(*v);  // getevent prints the 32-bit value in hex: ffffffff is -1
  } else {
    return bad("bad value " + quoted(w[2]) + " (hex, DOWN or UP)");
  }
  return l;
}

// evemu's header comments: `Event code 53 (ABS_MT_POSITION_X)` opens an axis, `Min`, `Max` and
// `Resolution` lines complete it; the axis is reported at its `Resolution` (or `Max`) line.
EvdevLine EvdevLineReader::read_comment(std::string_view comment) {
  const auto w = words(comment);
  if (w.size() >= 3 && w[0] == "Event" && w[1] == "code") {
    described_.reset();
    if (const auto code = number<int>(w[2], 10); code && *code >= 0 && *code <= 0xffff) described_ = EvdevAxisRange{*code, 0, 0, 0};
    return {};
  }
  if (w.size() == 2 && described_ && (w[0] == "Min" || w[0] == "Max" || w[0] == "Resolution")) {
    const auto v = number<std::int64_t>(w[1], 10);
    if (!v) return {};
    if (w[0] == "Min") described_->min = *v;
    if (w[0] == "Max") described_->max = *v;
    if (w[0] == "Resolution") described_->resolution = *v;
    if (w[0] != "Min") {
      EvdevLine l;
      l.kind = EvdevLine::Kind::axis;
      l.axis = *described_;
      return l;
    }
  }
  if (w.size() >= 2 && w[0] == "Event" && w[1] == "type") described_.reset();
  return {};
}

}  // namespace vimg
