#pragma once
// The address a phone or tablet on the same network reaches this machine at (vimg serve --lan):
// the first IPv4 address of an interface that is up and is not the loopback (getifaddrs).
#include <optional>
#include <string>

namespace vimg::web {

std::optional<std::string> first_lan_ipv4_address();

// "http://HOST:PORT/" (an IPv6 host in brackets).
std::string site_url(const std::string& host, int port);

}  // namespace vimg::web
