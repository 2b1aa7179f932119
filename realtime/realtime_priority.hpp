#pragma once
// Real-time scheduling for the calling thread: SCHED_FIFO at a priority 1..99, or normal
// scheduling. The request never fails loudly on the real-time thread: it returns what happened,
// and the control thread turns that into a message with describe() (which allocates).
//
// Threads: request_realtime_priority() acts on the calling thread; it neither allocates nor locks.
#include <string>

namespace vimg {

struct RealtimePriority {
  int requested = 0;     // 0: normal scheduling was asked for
  bool granted = false;  // SCHED_FIFO at `requested` is in force
  int error_number = 0;  // why it was refused (EPERM: no CAP_SYS_NICE and no rtprio limit)
};

// Asks for SCHED_FIFO at `priority` (clamped to 1..99) for the calling thread; 0 or less asks for
// nothing and leaves the thread as it is.
RealtimePriority request_realtime_priority(int priority) noexcept;

// One line for a status display or a log: "SCHED_FIFO 80", "normal priority", or
// "normal priority (SCHED_FIFO 80 refused: Operation not permitted; grant CAP_SYS_NICE or an
// rtprio limit, see docs/hardware.md)".
std::string describe(const RealtimePriority& priority);

}  // namespace vimg
