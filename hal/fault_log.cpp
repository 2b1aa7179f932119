#include "hal/fault_log.hpp"

#include "hal/device_error.hpp"

namespace vimg {

std::string describe(const FaultEvent& event, const std::string& device_path) {
  switch (event.kind) {
    case FaultKind::transfer_failed:
      return device_error_message(device_path, "transfer failed after retries; playback continues",
                                  event.error_number);
    case FaultKind::device_gone:
      return device_error_message(device_path, "device gone; output paused, reconnecting", event.error_number);
    case FaultKind::reconnected:
      return device_path + ": device is back and initialized; output resumed";
    case FaultKind::over_current:
      return device_path + ": over-current detected (STATUS OC_DETECT); output stopped, actuator in standby";
    case FaultKind::over_temperature:
      return device_path + ": over-temperature detected (STATUS OVER_TEMP); output stopped, actuator in standby";
    case FaultKind::underrun:
      return device_path + ": sample FIFO underrun; output went to 0 V until refilled";
    case FaultKind::rest_requested:
      return device_path + ": stop requested by a signal; actuator put to rest";
  }
  return device_path + ": unknown fault";
}

}  // namespace vimg
