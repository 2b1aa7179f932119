#pragma once
// A device driver whose render-thread side only posts fault codes, with the rest done by the
// device service thread (hal/device_service.hpp): formatting the messages and reconnecting.
// Implemented by Drv2605lDriver, Bos1901Driver and HidHapticController.
#include <string>

#include "hal/device_link.hpp"
#include "hal/fault_log.hpp"

namespace vimg {

class ServicedDevice {
 public:
  virtual ~ServicedDevice() = default;

  // The render thread is the producer, the service thread the consumer.
  virtual FaultLog& faults() = 0;
  // Down from the render thread's take_down() until reconnect() succeeds.
  virtual const DeviceLink& link() const = 0;
  // For messages; may change at reconnect(), so read it on the service thread.
  virtual const std::string& device_path() const = 0;
  // Service thread, only while link() is down: reopen + initialize the device, put it back in the
  // state the render thread expects, then put the link up. Throws (DeviceError or another
  // std::exception with a message) while the device is still gone; the link stays down.
  virtual void reconnect() = 0;
};

}  // namespace vimg
