#include "study/report_model.hpp"

#include <utility>

namespace vimg::study {

GroupComparison compare_groups(std::string a, const std::vector<double>& values_a, std::string b,
                               const std::vector<double>& values_b) {
  GroupComparison c;
  c.a = std::move(a);
  c.b = std::move(b);
  c.summary_a = summarize(values_a);
  c.summary_b = summarize(values_b);
  c.welch = welch_t_test(values_a, values_b);
  c.cohens_d = cohens_d(values_a, values_b);
  return c;
}

}  // namespace vimg::study
