#include "editor/core/device_messages.hpp"

#include "storage/diagnostic.hpp"

namespace vimg::editor {

std::size_t show_device_messages(const std::vector<std::string>& messages, const std::string& doing, Notices& notices,
                                 std::FILE* log) {
  for (const std::string& message : messages) std::fprintf(log, "vimg-editor: %s\n", printable_message(message).c_str());
  if (!messages.empty()) notices.status = doing + ": " + printable_message(messages.back());
  return messages.size();
}

}  // namespace vimg::editor
