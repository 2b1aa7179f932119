#pragma once
// Volume data seen through the vibrotactile shaders' field interfaces (primitives/cues):
//   - VolumeValueField: the data value itself (ScalarField), e.g. for the transition cue;
//   - MappedValueField: a transfer function of the data value (ScalarField), e.g. an amplitude;
//   - MappedSpatialFrequency: omega from the data, either directly (rad/m) or as 2 pi / period.
#include <memory>

#include "primitives/cues/scalar_field.hpp"
#include "primitives/cues/spatial_frequency_field.hpp"
#include "primitives/volume/transfer_function.hpp"
#include "primitives/volume/volume_field.hpp"

namespace vimg {

class VolumeValueField final : public ScalarField {
 public:
  explicit VolumeValueField(std::shared_ptr<const ScalarVolume> volume) : volume_(std::move(volume)) {}
  double value(const Vec3& position_m) const override { return volume_->value(position_m); }

 private:
  std::shared_ptr<const ScalarVolume> volume_;
};

class MappedValueField final : public ScalarField {
 public:
  MappedValueField(std::shared_ptr<const ScalarVolume> volume, TransferFunction transfer)
      : volume_(std::move(volume)), transfer_(std::move(transfer)) {}
  double value(const Vec3& position_m) const override { return transfer_(volume_->value(position_m)); }

 private:
  std::shared_ptr<const ScalarVolume> volume_;
  TransferFunction transfer_;
};

class MappedSpatialFrequency final : public SpatialFrequencyField {
 public:
  enum class Output { omega_rad_per_m, period_m };
  MappedSpatialFrequency(std::shared_ptr<const ScalarVolume> volume, TransferFunction transfer, Output output)
      : volume_(std::move(volume)), transfer_(std::move(transfer)), output_(output) {}
  double omega_rad_per_m(const Vec3& position_m) const override;

 private:
  std::shared_ptr<const ScalarVolume> volume_;
  TransferFunction transfer_;
  Output output_;
};

}  // namespace vimg
