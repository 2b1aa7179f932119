#include "player/haptic/haptic_port.hpp"

namespace vimg {

const char* describe(PortFault fault) noexcept {
  switch (fault) {
    case PortFault::none: return "no fault";
    case PortFault::io_error: return "a transfer failed (device unplugged, no permission or a bus error)";
    case PortFault::device_fault: return "the device reported a fault";
    case PortFault::no_data: return "the device sent no probe position";
  }
  return "unknown fault";
}

}  // namespace vimg
