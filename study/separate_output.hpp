#pragma once
// The report of `vimg separate` (docs/separate.md, "The report"), written to OUT/separate.json and
// OUT/separate.html beside the proposed images:
//   .json  `target`, `outcome` ("already_distinct", "reached" or "out_of_reach"), `vary` (the
//          parameters the search could move), `limits` (when out of reach: what limits it), per
//          image in `images`: `path` (the input), `label`, `output` (the file written; null when
//          nothing is), `kept`, `changes` ([{element, id, parameter, from, to, text}]),
//          `change_jnd` (its felt change from the original), `identified_before`,
//          `identified_after`; `before` and `after`: `predicted_confusion` (rows presented,
//          columns chosen), `information_transfer_bits` and `lowest_identified`; the search's
//          `total_change_jnd`, `variants_rendered` and `states_scored`; and `actuator`,
//          `exploration` and `model` as `vimg compare` writes them;
//   .html  a self-contained page: the outcome, the changes per image, the predicted confusion
//          before and after as heat maps, the share identified per image, the limits, how the
//          images were felt.
#include <optional>
#include <string>
#include <vector>

#include "study/separate.hpp"

namespace vimg::study {

// `outputs[i]`: the file written for image i ("" when none).
std::string separate_json(const SeparateResult& r, const std::vector<std::string>& outputs,
                          const std::string& model_file = {});
std::string separate_html(const SeparateResult& r, const std::vector<std::string>& outputs);

// "already_distinct", "reached", "out_of_reach".
std::string_view separate_outcome_name(const SeparateResult& r);

}  // namespace vimg::study
