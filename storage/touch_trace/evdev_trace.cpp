#include "storage/touch_trace/evdev_trace.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>

#include "storage/limits.hpp"
#include "storage/load_file.hpp"
#include "storage/text_bytes.hpp"
#include "storage/touch_trace/evdev_line.hpp"
#include "storage/touch_trace/touch_log.hpp"

namespace vimg {
namespace {

// Lines that are not text (text_bytes.hpp) after which a file is called binary.
constexpr int kBinaryLinesOfABinaryFile = 3;

// What one finger reported so far; values persist between frames (evdev semantics).
struct Contact {
  long long id = -1;  // tracking id, -1 when none
  double x = 0.0, y = 0.0;
  std::optional<double> pressure;
  bool has_position = false;
  bool changed = false;
  int open = -1;  // index in the trace's contacts while touching, else -1
};

class TraceBuilder {
 public:
  explicit TraceBuilder(DiagnosticList& list) : list_(list) {}

  void axis(const EvdevAxisRange& a, int line) {
    const TouchAxis axis{static_cast<double>(a.min), static_cast<double>(a.max), static_cast<double>(a.resolution), line};
    if (a.code == evdev::kAbsMtPositionX || (a.code == evdev::kAbsX && !mt_x_)) trace_.x = axis;
    if (a.code == evdev::kAbsMtPositionY || (a.code == evdev::kAbsY && !mt_y_)) trace_.y = axis;
    if (a.code == evdev::kAbsMtPressure || (a.code == evdev::kAbsPressure && !mt_pressure_)) trace_.pressure = axis;
    mt_x_ = mt_x_ || a.code == evdev::kAbsMtPositionX;
    mt_y_ = mt_y_ || a.code == evdev::kAbsMtPositionY;
    mt_pressure_ = mt_pressure_ || a.code == evdev::kAbsMtPressure;
  }

  // False when reading must stop (a limit was reached).
  bool event(const EvdevEvent& e, int line) {
    if (!device_chosen(e)) return true;
    if (!clock(e, line)) return false;
    if (e.type == evdev::kEvSyn && e.code == evdev::kSynDropped) {
      list_.warning(line, "SYN_DROPPED: the device lost events; the frame is skipped");
      dropped_ = true;
      return true;
    }
    if (e.type == evdev::kEvSyn && e.code == evdev::kSynMtReport) {
      if (saw_slot_ || b_frames_) return mixed(line);
      saw_a_ = true;
      if (a_current_.has_position) a_frame_.push_back(a_current_);
      a_current_ = Contact{};
      return true;
    }
    if (e.type == evdev::kEvSyn && e.code == evdev::kSynReport) {
      if (dropped_) {
        dropped_ = false;
        a_frame_.clear();
        return true;
      }
      return frame(line);
    }
    if (e.type == evdev::kEvKey && e.code == evdev::kBtnTouch) touch_key_ = e.value != 0;
    if (e.type == evdev::kEvAbs) abs(e, line);
    return !list_.has_errors();
  }

  std::optional<TouchTrace> finish() {
    for (auto& c : slots_) close(c, trace_.last_line, true);
    for (auto& c : a_open_) close(c, trace_.last_line, true);
    close(single_, trace_.last_line, true);
    trace_.protocol = saw_a_ ? TouchTrace::Protocol::a : any_mt_ ? TouchTrace::Protocol::b : TouchTrace::Protocol::single;
    if (trace_.contacts.empty() && !list_.has_errors()) list_.error(trace_.last_line, "the recording has no touches");
    if (list_.has_errors()) return std::nullopt;
    return std::move(trace_);
  }

 private:
  bool device_chosen(const EvdevEvent& e) {
    if (e.device.empty() || e.device == device_) return true;
    const bool touch = e.type == evdev::kEvAbs && (e.code == evdev::kAbsMtPositionX || e.code == evdev::kAbsMtSlot ||
                                                    e.code == evdev::kAbsMtTrackingId || e.code == evdev::kAbsX);
    if (!device_.empty() || !touch) return false;
    device_ = e.device;
    return true;
  }

  bool clock(const EvdevEvent& e, int line) {
    if (!first_) first_ = e;
    if (e.seconds < first_->seconds - 1) {
      list_.error(line, "time goes backwards (before the first event)");
      return false;
    }
    if (e.seconds - first_->seconds > static_cast<std::int64_t>(kMaxGestureDurationS) + 1) {
      list_.error(line, touch_trace_too_long_problem());
      return false;
    }
    // Whole microseconds first, so that times keep the recording's decimals.
    const std::int64_t us = (e.seconds - first_->seconds) * 1'000'000 + (e.microseconds - first_->microseconds);
    const double t = static_cast<double>(us) / 1e6;
    if (t < time_s_) {
      list_.error(line, "time goes backwards (" + std::to_string(t) + " s after " + std::to_string(time_s_) + " s)");
      return false;
    }
    if (t > kMaxGestureDurationS) {
      list_.error(line, touch_trace_too_long_problem());
      return false;
    }
    time_s_ = t;
    trace_.duration_s = t;
    trace_.last_line = line;
    return true;
  }

  bool mixed(int line) {
    list_.error(line, "the recording mixes multi-touch protocols A (SYN_MT_REPORT) and B (slots)");
    return false;
  }

  void abs(const EvdevEvent& e, int line) {
    const double v = static_cast<double>(e.value);
    if (e.code == evdev::kAbsMtSlot) {
      if (saw_a_) {
        mixed(line);
        return;
      }
      saw_slot_ = true;
      if (e.value < 0 || e.value > kMaxTouchTraceFinger) {
        list_.error(line, "slot " + std::to_string(e.value) + " is beyond the " + std::to_string(kMaxTouchTraceFinger + 1) +
                              " fingers a gesture can hold (limit " + std::to_string(kMaxTouchTraceFinger) + ")");
        return;
      }
      slot_ = static_cast<int>(e.value);
      return;
    }
    if (e.code == evdev::kAbsMtPositionX || e.code == evdev::kAbsMtPositionY || e.code == evdev::kAbsMtTrackingId ||
        e.code == evdev::kAbsMtPressure) {
      // Protocol A or B is known at the frame's end (SYN_MT_REPORT or not): both are kept until then.
      for (Contact* c : {&a_current_, &slots_[static_cast<std::size_t>(slot_)]}) {
        if (e.code == evdev::kAbsMtPositionX) c->x = v;
        if (e.code == evdev::kAbsMtPositionY) c->y = v;
        if (e.code == evdev::kAbsMtPositionX || e.code == evdev::kAbsMtPositionY) c->has_position = true;
        if (e.code == evdev::kAbsMtPressure) c->pressure = v;
        if (e.code == evdev::kAbsMtTrackingId) c->id = e.value;
        c->changed = true;
      }
      any_mt_ = true;
      return;
    }
    if (any_mt_) return;  // the single-touch axes mirror the first contact
    if (e.code == evdev::kAbsX) single_.x = v, single_.has_position = true, single_.changed = true;
    if (e.code == evdev::kAbsY) single_.y = v, single_.has_position = true, single_.changed = true;
    if (e.code == evdev::kAbsPressure) single_.pressure = v, single_.changed = true;
  }

  bool frame(int line) {
    // A device that starts reporting multi-touch contacts ends its single-touch one (finger 0).
    if ((saw_a_ || any_mt_) && single_.open >= 0) close(single_, line, false);
    if (saw_a_) return frame_a(line);
    a_current_ = Contact{};
    if (any_mt_) return frame_b(line);
    if (single_.changed || touch_key_ != (single_.open >= 0)) {
      single_.changed = false;
      if (touch_key_ && single_.open < 0 && single_.has_position) open(single_, 0, line);
      else if (!touch_key_ && single_.open >= 0) close(single_, line, false);
      else if (single_.open >= 0) add(single_, TouchSample::Phase::move, line);
    }
    return !list_.has_errors();
  }

  // Protocol B: each slot holds one contact; a new tracking id in a slot is a new contact.
  bool frame_b(int line) {
    for (std::size_t s = 0; s < slots_.size(); ++s) {
      Contact& c = slots_[s];
      if (!c.changed) continue;
      c.changed = false;
      b_frames_ = true;
      if (c.open >= 0 && c.id < 0) {
        close(c, line, false);
      } else if (c.open >= 0 && c.id != opened_id_[s]) {
        close(c, line, false);
        open(c, static_cast<int>(s), line);
        opened_id_[s] = c.id;
      } else if (c.open < 0 && c.id >= 0 && c.has_position) {
        open(c, static_cast<int>(s), line);
        opened_id_[s] = c.id;
      } else if (c.open >= 0) {
        add(c, TouchSample::Phase::move, line);
      }
    }
    return !list_.has_errors();
  }

  // Protocol A: the frame lists every contact; match them to the open ones.
  bool frame_a(int line) {
    if (a_current_.has_position) a_frame_.push_back(a_current_);
    a_current_ = Contact{};
    std::vector<bool> matched(a_open_.size(), false);
    std::vector<Contact> next;
    for (Contact& c : a_frame_) {
      std::size_t best = a_open_.size();
      double best_d = 0.0;
      for (std::size_t i = 0; i < a_open_.size(); ++i) {
        if (matched[i]) continue;
        if (c.id >= 0 || a_open_[i].id >= 0) {
          if (c.id == a_open_[i].id) { best = i; break; }
          continue;
        }
        const double d = std::hypot(c.x - a_open_[i].x, c.y - a_open_[i].y);
        if (best == a_open_.size() || d < best_d) best = i, best_d = d;
      }
      if (best < a_open_.size()) {
        matched[best] = true;
        Contact& o = a_open_[best];
        o.x = c.x, o.y = c.y, o.pressure = c.pressure ? c.pressure : o.pressure;
        add(o, TouchSample::Phase::move, line);
        next.push_back(o);
      } else {
        const int finger = free_finger(next, matched);
        if (finger < 0) {
          list_.error(line, "more than " + std::to_string(kMaxTouchTraceFinger + 1) + " fingers at once (limit " +
                                std::to_string(kMaxTouchTraceFinger + 1) + ")");
          return false;
        }
        open(c, finger, line);
        c.changed = false;
        next.push_back(c);
      }
    }
    for (std::size_t i = 0; i < a_open_.size(); ++i) {
      if (!matched[i]) close(a_open_[i], line, false);
    }
    a_open_ = std::move(next);
    a_frame_.clear();
    return !list_.has_errors();
  }

  int free_finger(const std::vector<Contact>& next, const std::vector<bool>& matched) const {
    for (int f = 0; f <= kMaxTouchTraceFinger; ++f) {
      bool used = false;
      for (const auto& c : next) used = used || trace_.contacts[static_cast<std::size_t>(c.open)].finger == f;
      for (std::size_t i = 0; i < a_open_.size(); ++i) {
        used = used || (matched[i] && trace_.contacts[static_cast<std::size_t>(a_open_[i].open)].finger == f);
      }
      if (!used) return f;
    }
    return -1;
  }

  void open(Contact& c, int finger, int line) {
    trace_.contacts.push_back(TouchContact{finger, {}});
    c.open = static_cast<int>(trace_.contacts.size() - 1);
    add(c, TouchSample::Phase::down, line);
  }

  void close(Contact& c, int line, bool at_end) {
    if (c.open < 0) return;
    TouchContact& contact = trace_.contacts[static_cast<std::size_t>(c.open)];
    if (at_end) {
      list_.warning(line, "finger " + std::to_string(contact.finger) + " is still down at the end of the recording; it lifts there");
    }
    add(c, TouchSample::Phase::up, line);
    c.open = -1;
  }

  void add(const Contact& c, TouchSample::Phase phase, int line) {
    if (++samples_ > kMaxGestureRows) {
      if (samples_ == kMaxGestureRows + 1) {
        list_.error(line, "more than " + std::to_string(kMaxGestureRows) + " touch samples (limit " +
                              std::to_string(kMaxGestureRows) + " gesture rows)");
      }
      return;
    }
    trace_.contacts[static_cast<std::size_t>(c.open)].samples.push_back(TouchSample{time_s_, c.x, c.y, c.pressure, phase, line});
  }

  DiagnosticList& list_;
  TouchTrace trace_;
  std::optional<EvdevEvent> first_;
  double time_s_ = 0.0;
  std::string device_;
  bool mt_x_ = false, mt_y_ = false, mt_pressure_ = false;
  bool saw_a_ = false, saw_slot_ = false, b_frames_ = false, any_mt_ = false;
  bool dropped_ = false, touch_key_ = false;
  int slot_ = 0;
  std::array<Contact, kMaxTouchTraceFinger + 1> slots_{};
  std::array<long long, kMaxTouchTraceFinger + 1> opened_id_{};
  Contact a_current_;
  std::vector<Contact> a_frame_, a_open_;
  Contact single_;
  std::size_t samples_ = 0;
};

}  // namespace

TouchTraceParseResult parse_touch_trace(std::string_view text, const std::string& file_name) {
  if (looks_like_touch_log(text)) return parse_touch_log(text, file_name);
  DiagnosticList list(file_name);
  TraceBuilder builder(list);
  EvdevLineReader reader;
  int line_number = 0;
  std::size_t pos = 0;
  bool reading = true;
  int binary_lines = 0;
  std::size_t first_binary = std::string_view::npos;  // offset in the file
  while (reading && pos < text.size()) {
    std::size_t eol = text.find('\n', pos);
    if (eol == std::string_view::npos) eol = text.size();
    const std::string_view line = text.substr(pos, eol - pos);
    const std::size_t line_start = pos;
    pos = eol + 1;
    ++line_number;
    // A line that no text file holds is not shown (it would be bytes of garbage); a few of them and
    // the file is not a text recording at all.
    if (const std::size_t binary = first_binary_byte(line); binary != std::string_view::npos) {
      if (first_binary == std::string_view::npos) first_binary = line_start + binary;
      if (++binary_lines == kBinaryLinesOfABinaryFile) break;
      list.error(line_number, "the line is not text (binary data at byte " + std::to_string(line_start + binary) + ")");
      continue;
    }
    const EvdevLine l = reader.read(line);
    if (l.kind == EvdevLine::Kind::bad && !list.keeps(line_number)) {
      list.count(Diagnostic::Severity::error);  // beyond the limit: counted on the summary line
      continue;
    }
    if (l.kind == EvdevLine::Kind::bad) list.error(line_number, l.problem);
    if (l.kind == EvdevLine::Kind::axis) builder.axis(l.axis, line_number);
    if (l.kind == EvdevLine::Kind::event) reading = builder.event(l.event, line_number);
  }
  TouchTraceParseResult result;
  if (binary_lines == kBinaryLinesOfABinaryFile) {
    result.diagnostics.push_back({Diagnostic::Severity::error, file_name, 0,
                                  "this is not a text touch recording (binary data at byte " + std::to_string(first_binary) + ")"});
    return result;
  }
  result.trace = builder.finish();
  result.diagnostics = list.take();
  return result;
}

std::string touch_axis_problem(const TouchAxis& axis, const std::string& name) {
  if (axis.known()) return "";
  if (axis.line == 0) return "has none (an evemu-record header or getevent -lp lines give them)";
  const auto whole = [](double v) { return std::to_string(static_cast<long long>(v)); };
  const std::string where = ", line " + std::to_string(axis.line) + ")";
  if (axis.min == axis.max) return "gives an empty " + name + " range (min " + whole(axis.min) + " = max " + whole(axis.max) + where;
  return "gives a reversed " + name + " range (min " + whole(axis.min) + " > max " + whole(axis.max) + where;
}

std::string touch_trace_too_long_problem() {
  const std::string limit = std::to_string(static_cast<int>(kMaxGestureDurationS));
  return "the recording is longer than " + limit + " s (limit " + limit + ")";
}

TouchTraceParseResult load_touch_trace(const std::filesystem::path& path) {
  return load_file<TouchTraceParseResult>(path, kMaxTouchTraceFileBytes, parse_touch_trace);
}

}  // namespace vimg
