#include "hal/i2c_bus.hpp"

#include <array>

namespace vimg {

void write_register(I2cBus& bus, std::uint8_t address, std::uint8_t reg, std::uint8_t value) {
  const std::array<std::uint8_t, 2> bytes{reg, value};
  bus.write(address, bytes);
}

std::uint8_t read_register(I2cBus& bus, std::uint8_t address, std::uint8_t reg) {
  const std::array<std::uint8_t, 1> out{reg};
  std::array<std::uint8_t, 1> in{};
  bus.write_read(address, out, in);
  return in[0];
}

int try_write_register(I2cBus& bus, std::uint8_t address, std::uint8_t reg, std::uint8_t value) noexcept {
  const std::array<std::uint8_t, 2> bytes{reg, value};
  return bus.try_write(address, bytes);
}

int try_read_register(I2cBus& bus, std::uint8_t address, std::uint8_t reg, std::uint8_t& value) noexcept {
  const std::array<std::uint8_t, 1> out{reg};
  std::array<std::uint8_t, 1> in{};
  const int error = bus.try_write_read(address, out, in);
  if (error == 0) value = in[0];
  return error;
}

}  // namespace vimg
