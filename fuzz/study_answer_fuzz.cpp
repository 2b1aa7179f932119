// Fuzzes what vimg serve --study reads from a page before anything is written: the form text of an
// answer (web/study_server/form_text.hpp) and the answer in it (answer_form.hpp). Any bytes give a
// refusal with a reason or fields without control characters that read back the same through
// form_escape, and an accepted answer has its trial in range and finite numbers; never a crash.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "web/study_server/answer_form.hpp"
#include "web/study_server/form_text.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const vimg::web::FormFields form = vimg::web::parse_form_text(text);
  if (!form.ok()) return 0;
  std::string again;
  for (const auto& [name, value] : form.fields) {
    for (const char c : value) {
      if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) std::abort();
    }
    again += (again.empty() ? "" : "&") + vimg::web::form_escape(name) + "=" + vimg::web::form_escape(value);
  }
  const vimg::web::FormFields reread = vimg::web::parse_form_text(again);
  if (!reread.ok() || reread.fields != form.fields) std::abort();
  constexpr std::size_t kTrials = 40;
  const vimg::web::AnswerParse answer = vimg::web::parse_answer(form, kTrials);
  if (answer.answer) {
    const auto& a = *answer.answer;
    if (a.trial < 1 || a.trial > kTrials) std::abort();
    if (!std::isfinite(a.rub_s) || !std::isfinite(a.response_s) || !std::isfinite(a.path_mm)) std::abort();
  } else if (answer.error.empty()) {
    std::abort();
  }
  return 0;
}
