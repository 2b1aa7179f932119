// `vimg serve` and the address it listens on (docs/web-serving.md, "Serving"): 127.0.0.1 only unless --lan
// (the kernel's own table of listening sockets, /proc/net/tcp, says which address the port is bound
// to); with --lan every interface, the LAN URL (the first IPv4 address of an interface that is up
// and not the loopback) and a QR code of that URL drawn in half blocks, which a camera reads as that
// URL: its modules, read back from the drawing, are libqrencode's own encoding of the printed URL,
// inside a light quiet zone. No traffic leaves the machine: the test connects to 127.0.0.1 only.
#include <gtest/gtest.h>
#include <ifaddrs.h>
#include <net/if.h>
#include <netinet/in.h>
#include <arpa/inet.h>
#include <qrencode.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "tests/net/raw_http.hpp"
#include "tests/web_server/serve_output.hpp"
#include "web/server/terminal_qr.hpp"

namespace vimg::test {
namespace {

namespace fs = std::filesystem;

// The local IPv4 addresses that listen on `port` (the kernel's table: state 0A is LISTEN), as text.
std::vector<std::string> listening_ipv4_addresses(int port) {
  std::vector<std::string> found;
  std::istringstream table(file_text("/proc/net/tcp"));
  std::string line;
  std::getline(table, line);  // the header
  while (std::getline(table, line)) {
    std::istringstream fields(line);
    std::string slot, local, remote, state;
    fields >> slot >> local >> remote >> state;
    const std::size_t colon = local.find(':');
    if (state != "0A" || colon == std::string::npos || std::stoi(local.substr(colon + 1), nullptr, 16) != port) continue;
    in_addr address{};
    address.s_addr = static_cast<in_addr_t>(std::stoul(local.substr(0, colon), nullptr, 16));  // as the kernel stores it
    char text[INET_ADDRSTRLEN] = {};
    found.push_back(inet_ntop(AF_INET, &address, text, sizeof text));
  }
  return found;
}

// The first IPv4 address of an interface that is up and not the loopback, as docs/web-serving.md defines it.
std::optional<std::string> first_lan_address() {
  ifaddrs* interfaces = nullptr;
  if (getifaddrs(&interfaces) != 0) return std::nullopt;
  std::optional<std::string> found;
  for (const ifaddrs* i = interfaces; i && !found; i = i->ifa_next) {
    if (!i->ifa_addr || i->ifa_addr->sa_family != AF_INET) continue;
    if ((i->ifa_flags & IFF_UP) == 0 || (i->ifa_flags & IFF_LOOPBACK) != 0) continue;
    char text[INET_ADDRSTRLEN] = {};
    inet_ntop(AF_INET, &reinterpret_cast<const sockaddr_in*>(i->ifa_addr)->sin_addr, text, sizeof text);
    found = text;
  }
  freeifaddrs(interfaces);
  return found;
}

// The drawing read back into light modules, row by row: each character is two rows (upper, lower):
// U+2588 both light, U+2580 the upper, U+2584 the lower, a space neither. Empty if another character
// or a ragged line is found.
std::vector<std::vector<bool>> light_modules(const std::string& drawing) {
  std::vector<std::vector<bool>> rows;
  std::istringstream lines(drawing);
  for (std::string line; std::getline(lines, line);) {
    std::vector<bool> upper, lower;
    for (std::size_t i = 0; i < line.size();) {
      if (line[i] == ' ') {
        upper.push_back(false), lower.push_back(false), ++i;
      } else if (line.compare(i, 3, "\u2588") == 0) {
        upper.push_back(true), lower.push_back(true), i += 3;
      } else if (line.compare(i, 3, "\u2580") == 0) {
        upper.push_back(true), lower.push_back(false), i += 3;
      } else if (line.compare(i, 3, "\u2584") == 0) {
        upper.push_back(false), lower.push_back(true), i += 3;
      } else {
        return {};
      }
    }
    if (!rows.empty() && upper.size() != rows.front().size()) return {};
    rows.push_back(upper);
    rows.push_back(lower);
  }
  return rows;
}

// Whether `light` (quiet zone included) is libqrencode's encoding of `text` in byte mode at one of
// the four error-correction levels: the code a reader decodes to `text`.
bool is_qr_code_of(const std::vector<std::vector<bool>>& light, const std::string& text) {
  for (const QRecLevel level : {QR_ECLEVEL_L, QR_ECLEVEL_M, QR_ECLEVEL_Q, QR_ECLEVEL_H}) {
    const std::unique_ptr<QRcode, void (*)(QRcode*)> code(QRcode_encodeString(text.c_str(), 0, level, QR_MODE_8, 1),
                                                         QRcode_free);
    if (!code) continue;
    const int width = code->width, quiet = web::kQrQuietModules, side = width + 2 * quiet;
    // The last line's lower half lies beyond an odd side: drawn dark, not part of the code.
    if (light.empty() || static_cast<int>(light.front().size()) != side ||
        static_cast<int>(light.size()) != side + (side % 2)) {
      continue;
    }
    bool same = true;
    for (int r = 0; r < side && same; ++r) {
      for (int c = 0; c < side && same; ++c) {
        const bool in_code = r >= quiet && c >= quiet && r < quiet + width && c < quiet + width;
        const bool dark = in_code && (code->data[(r - quiet) * width + (c - quiet)] & 1) != 0;
        same = light[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)] == !dark;
      }
    }
    if (same) return true;
  }
  return false;
}

class ServeAddress : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(VIMG_BINARY_DIR) / "web_server_tests" /
           (std::string("ServeAddress.") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    write_stand_in_assets(dir_ / "assets");
    fs::copy_file(fs::path(VIMG_SOURCE_DIR) / "assets/examples/smiley.vimg", dir_ / "smiley.vimg");
  }
  fs::path dir_;
};

TEST_F(ServeAddress, ListensOnTheLoopbackOnlyWithoutLan) {
  ServeOutput serve({(dir_ / "smiley.vimg").string()}, dir_);
  const int port = serve.wait_for_port();
  ASSERT_GT(port, 0) << serve.out() << serve.err();
  EXPECT_EQ(serve.out(), "vimg serve: http://127.0.0.1:" + std::to_string(port) + "/ (Ctrl-C stops)\n");
  EXPECT_EQ(listening_ipv4_addresses(port), std::vector<std::string>{"127.0.0.1"});
  EXPECT_EQ(exchange(port, "GET", "/").status, 200);
  EXPECT_EQ(serve.stop_with(SIGINT), 130);
}

TEST_F(ServeAddress, WithLanListensOnEveryInterfaceAndPrintsTheLanUrlAndItsQrCode) {
  ServeOutput serve({(dir_ / "smiley.vimg").string(), "--lan"}, dir_);
  const int port = serve.wait_for_port();
  ASSERT_GT(port, 0) << serve.out() << serve.err();
  EXPECT_EQ(listening_ipv4_addresses(port), std::vector<std::string>{"0.0.0.0"});
  EXPECT_EQ(exchange(port, "GET", "/").status, 200);  // through the loopback, which every interface includes
  const std::string out = serve.out();
  const std::optional<std::string> lan = first_lan_address();
  if (!lan) {
    EXPECT_EQ(out, "vimg serve: http://127.0.0.1:" + std::to_string(port) +
                       "/ on every interface; no LAN address found (Ctrl-C stops)\n");
  } else {
    const std::string url = "http://" + *lan + ":" + std::to_string(port) + "/";
    const std::string first_line = "vimg serve: " + url + " on the LAN (Ctrl-C stops)\n";
    ASSERT_EQ(out.substr(0, first_line.size()), first_line) << out;
    const std::vector<std::vector<bool>> light = light_modules(out.substr(first_line.size()));
    ASSERT_FALSE(light.empty()) << out;
    EXPECT_TRUE(is_qr_code_of(light, url)) << out;
    EXPECT_FALSE(is_qr_code_of(light, url + "x"));  // the check tells codes apart
  }
  EXPECT_EQ(serve.stop_with(SIGTERM), 143);
}

}  // namespace
}  // namespace vimg::test
