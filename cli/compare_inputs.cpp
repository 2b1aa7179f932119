#include "cli/compare_inputs.hpp"

#include <cstdio>

#include "storage/actuator_profile.hpp"
#include "storage/print_diagnostics.hpp"

namespace vimg::cli {

std::optional<study::CompareActuator> load_compare_actuator(const std::string& argument) {
  study::CompareActuator actuator;
  if (argument.empty()) return actuator;
  const ProfileLoadResult loaded = load_actuator_profile(argument);
  for (const std::string& e : loaded.errors) std::fprintf(stderr, "%s\n", e.c_str());
  if (!loaded.profile) return std::nullopt;
  actuator.name = loaded.profile->name.empty() ? argument : loaded.profile->name;
  actuator.file = argument;
  actuator.response = loaded.profile->response;
  return actuator;
}

std::optional<PerceptionModel> load_model_argument(const std::string& file) {
  PerceptionModelLoadResult loaded = load_perception_model(file);
  print_diagnostics(loaded.diagnostics);
  return std::move(loaded.model);
}

}  // namespace vimg::cli
