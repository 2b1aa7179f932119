#include "primitives/kinaesthetic/combined_feedback.hpp"

#include <utility>

namespace vimg {

CombinedFeedback::CombinedFeedback(std::vector<const ForceShader*> kinaesthetic,
                                   std::vector<const ForceShader*> vibrotactile)
    : kinaesthetic_(std::move(kinaesthetic)),
      vibrotactile_(std::move(vibrotactile)),
      kinaesthetic_states_(kinaesthetic_.size()),
      vibrotactile_states_(vibrotactile_.size()) {
  begin_contact();
}

void CombinedFeedback::begin_contact() {
  for (std::size_t i = 0; i < kinaesthetic_.size(); ++i) kinaesthetic_[i]->begin_contact(kinaesthetic_states_[i]);
  for (std::size_t i = 0; i < vibrotactile_.size(); ++i) vibrotactile_[i]->begin_contact(vibrotactile_states_[i]);
}

FeedbackParts CombinedFeedback::evaluate(const InteractionState& interaction) {
  FeedbackParts parts;
  for (std::size_t i = 0; i < kinaesthetic_.size(); ++i) {
    parts.kinaesthetic_N += kinaesthetic_[i]->force_N(interaction, kinaesthetic_states_[i]);
  }
  for (std::size_t i = 0; i < vibrotactile_.size(); ++i) {
    parts.vibrotactile_N += vibrotactile_[i]->force_N(interaction, vibrotactile_states_[i]);
  }
  return parts;
}

}  // namespace vimg
