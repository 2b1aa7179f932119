// A pointer that moves at a steady rate, for the editor's live-path test: XTest motion events sent
// at absolute deadlines on CLOCK_MONOTONIC (clock_nanosleep, TIMER_ABSTIME), so that, unlike one
// xdotool process per move, no event comes late or in a burst because of the sender.
//
// usage: steady_pointer X0 Y0 X1 Y1 PERIOD_MS DURATION_MS LOG.csv
//   Moves to (X0, Y0) (screen pixels), presses button 1, then every PERIOD_MS moves to the point
//   of the straight line to (X1, Y1) reached at that moment (constant speed, DURATION_MS in all),
//   and releases the button at (X1, Y1) one period after the last move. Every event is flushed to
//   the X server with XSync before the next deadline. LOG.csv gets one row per event,
//   `deadline_s,sent_s,x_px,y_px,event` (CLOCK_MONOTONIC seconds); stdout a summary of how late
//   the sends were. Exit 0, usage errors 2, no display or no XTest 1.
#include <X11/Xlib.h>
#include <X11/extensions/XTest.h>
#include <sched.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <vector>

namespace {

std::int64_t now_ns() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec;
}

void sleep_until_ns(std::int64_t deadline_ns) {
  timespec ts{};
  ts.tv_sec = static_cast<time_t>(deadline_ns / 1'000'000'000);
  ts.tv_nsec = static_cast<long>(deadline_ns % 1'000'000'000);
  while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr) == EINTR) {
  }
}

bool parse_number(const char* text, double& out) {
  char* end = nullptr;
  errno = 0;
  out = std::strtod(text, &end);
  return errno == 0 && end != text && *end == '\0' && std::isfinite(out);
}

struct Sent {
  std::int64_t deadline_ns;
  std::int64_t sent_ns;
  int x_px;
  int y_px;
  const char* event;
};

}  // namespace

int main(int argc, char** argv) {
  if (argc == 2 && std::string(argv[1]) == "--help") {
    std::puts("usage: steady_pointer X0 Y0 X1 Y1 PERIOD_MS DURATION_MS LOG.csv");
    return 0;
  }
  double v[6];
  bool ok = argc == 8;
  for (int i = 0; ok && i < 6; ++i) ok = parse_number(argv[i + 1], v[i]);
  if (!ok || v[4] < 1.0 || v[4] > 100.0 || v[5] < v[4] || v[5] > 10'000.0) {
    std::fprintf(stderr, "usage: steady_pointer X0 Y0 X1 Y1 PERIOD_MS(1-100) DURATION_MS(PERIOD-10000) LOG.csv\n");
    return 2;
  }
  Display* display = XOpenDisplay(nullptr);
  if (!display) {
    std::fprintf(stderr, "steady_pointer: cannot open the display\n");
    return 1;
  }
  int event_base = 0, error_base = 0, major = 0, minor = 0;
  if (!XTestQueryExtension(display, &event_base, &error_base, &major, &minor)) {
    std::fprintf(stderr, "steady_pointer: the X server has no XTest\n");
    return 1;
  }
  // Like the editor's render thread: SCHED_FIFO where allowed, so that a busy machine delays the
  // sends less; normal scheduling otherwise (the log shows how late each send was).
  sched_param priority{};
  priority.sched_priority = 50;
  const bool fifo = sched_setscheduler(0, SCHED_FIFO, &priority) == 0;
  const double x0 = v[0], y0 = v[1], x1 = v[2], y1 = v[3];
  const std::int64_t period_ns = std::llround(v[4] * 1e6);
  const int moves = static_cast<int>(std::llround(v[5] / v[4]));
  std::vector<Sent> sent;
  sent.reserve(static_cast<std::size_t>(moves) + 3);
  const auto send = [&](std::int64_t deadline_ns, int x, int y, const char* event) {
    sleep_until_ns(deadline_ns);
    if (event[0] == 'm') {
      XTestFakeMotionEvent(display, -1, x, y, CurrentTime);
    } else {
      XTestFakeButtonEvent(display, 1, event[0] == 'd' ? True : False, CurrentTime);
    }
    XSync(display, False);
    sent.push_back(Sent{deadline_ns, now_ns(), x, y, event});
  };
  const std::int64_t start_ns = now_ns() + period_ns;
  const int ix0 = static_cast<int>(std::lround(x0)), iy0 = static_cast<int>(std::lround(y0));
  send(start_ns, ix0, iy0, "move");
  send(start_ns + period_ns, ix0, iy0, "down");
  for (int k = 1; k <= moves; ++k) {
    const double u = static_cast<double>(k) / moves;
    send(start_ns + (k + 1) * period_ns, static_cast<int>(std::lround(x0 + (x1 - x0) * u)),
         static_cast<int>(std::lround(y0 + (y1 - y0) * u)), "move");
  }
  send(start_ns + (moves + 2) * period_ns, static_cast<int>(std::lround(x1)), static_cast<int>(std::lround(y1)), "up");
  XCloseDisplay(display);

  std::FILE* log = std::fopen(argv[7], "w");
  if (!log) {
    std::fprintf(stderr, "steady_pointer: cannot write %s\n", argv[7]);
    return 1;
  }
  std::fprintf(log, "deadline_s,sent_s,x_px,y_px,event\n");
  std::vector<double> late_ms;
  for (const Sent& s : sent) {
    std::fprintf(log, "%.6f,%.6f,%d,%d,%s\n", static_cast<double>(s.deadline_ns) * 1e-9, static_cast<double>(s.sent_ns) * 1e-9, s.x_px, s.y_px, s.event);
    late_ms.push_back(static_cast<double>(s.sent_ns - s.deadline_ns) * 1e-6);
  }
  std::fclose(log);
  std::sort(late_ms.begin(), late_ms.end());
  std::printf("steady_pointer (%s): %zu events every %.1f ms; sent after their deadline by p50 %.2f ms, p99 %.2f ms, max %.2f ms\n",
              fifo ? "SCHED_FIFO 50" : "normal priority", late_ms.size(), v[4], late_ms[late_ms.size() / 2], late_ms[late_ms.size() * 99 / 100], late_ms.back());
  return 0;
}
