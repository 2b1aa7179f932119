#pragma once
// The ids of imported elements: an SVG `id` made a valid vibroimage id (letters, digits, '_', '.',
// '-', not starting with a digit, at most 64 characters) and unique in the image. SVG resolves an id
// shared by several elements to the first of them in document order (getElementById, `url(#id)`),
// so the first keeps it and each later one gets the next free `-2`, `-3`, ... suffix. A counter per
// id remembers the last suffix given: n elements sharing an id cost O(n), not O(n^2). Pure: no I/O.
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>

namespace vimg::svg {

class UniqueIds {
 public:
  // The valid, unique id for `raw` (empty when `raw` is null or empty), now taken.
  std::string take(const char* raw);
  // Gives back an id taken but not used (an element left out after all), so that a later element
  // with the same SVG id gets it.
  void release(const std::string& id);
  // Ids tried in all, taken or not: the work done (tests count it).
  std::size_t attempts() const { return attempts_; }

 private:
  std::unordered_set<std::string> taken_;
  std::unordered_map<std::string, int> next_suffix_;  // valid id -> the suffix to try next
  std::size_t attempts_ = 0;
};

}  // namespace vimg::svg
