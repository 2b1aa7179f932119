#include "web/server/descriptor_budget.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <climits>

namespace vimg::web {

int raise_descriptor_limit() {
  rlimit limit{};
  if (getrlimit(RLIMIT_NOFILE, &limit) != 0) return kMaxConnections + kMaxRefusingConnections + kKeptDescriptors;
  if (limit.rlim_cur < limit.rlim_max) {
    limit.rlim_cur = limit.rlim_max;
    setrlimit(RLIMIT_NOFILE, &limit);
    getrlimit(RLIMIT_NOFILE, &limit);
  }
  if (limit.rlim_cur == RLIM_INFINITY || limit.rlim_cur > static_cast<rlim_t>(INT_MAX)) return INT_MAX;
  return static_cast<int>(limit.rlim_cur);
}

namespace {

// The sockets the budget allows besides the held files and the kept descriptors.
long long sockets_allowed(int descriptor_limit, int files_held) {
  return static_cast<long long>(descriptor_limit) - kKeptDescriptors - std::max(0, files_held);
}

}  // namespace

int connection_cap(int max_connections, int descriptor_limit) {
  const long long allowed = sockets_allowed(descriptor_limit, 0) - kMaxRefusingConnections;
  return static_cast<int>(std::clamp<long long>(allowed, 0, max_connections));
}

Admission admit_connection(const DescriptorUse& use, int max_connections, int descriptor_limit) {
  const long long sockets = sockets_allowed(descriptor_limit, use.files_held);
  const long long open = static_cast<long long>(use.connections) + use.refusing;
  if (use.connections < max_connections && open + kMaxRefusingConnections < sockets) return Admission::serve;
  if (use.refusing < kMaxRefusingConnections && open < sockets) return Admission::refuse_busy;
  return Admission::close;
}

}  // namespace vimg::web
