#pragma once
// Helpers for the storage tests: files, temporary directories and seeded random images.
#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <thread>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "primitives/image.hpp"

namespace vimg::test {

inline std::string read_text_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void write_text_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

// A fresh directory under the system temp dir, removed with everything in it at scope exit.
// While it lives, a thread keeps opening `fifo` for writing (for up to two seconds), so that a
// reader wrongly blocking in open() is released and the test fails instead of hanging.
class FifoReleaser {
 public:
  explicit FifoReleaser(std::filesystem::path fifo)
      : fifo_(std::move(fifo)), writer_([this] {
          for (int i = 0; i < 200 && !done_; ++i) {
            const int fd = ::open(fifo_.c_str(), O_WRONLY | O_NONBLOCK);
            if (fd >= 0) {
              ::close(fd);
              return;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
          }
        }) {}
  ~FifoReleaser() {
    done_ = true;
    writer_.join();
  }
  FifoReleaser(const FifoReleaser&) = delete;
  FifoReleaser& operator=(const FifoReleaser&) = delete;

 private:
  std::filesystem::path fifo_;
  std::atomic<bool> done_{false};
  std::thread writer_;
};

class TempDir {
 public:
  explicit TempDir(const std::string& tag) {
    static int counter = 0;
    path_ = std::filesystem::temp_directory_path() /
            ("vimg_storage_" + tag + "_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

// Random valid images: every kind, nested groups, meta, unknown elements and attributes, values
// with full double precision. Every element gets a unique id.
class RandomImages {
 public:
  explicit RandomImages(unsigned seed) : rng_(seed) {}

  Image make(int max_elements = 12) {
    Image image;
    image.version_minor = pick(0, 3);
    image.width_mm = uniform(1.0, 300.0);
    image.height_mm = uniform(1.0, 300.0);
    if (chance(0.7)) image.meta = make_meta();
    if (chance(0.6)) {
      InteractionParams p;
      p.mass_kg = uniform(1e-4, 0.5);
      p.full_speed_mm_per_s = uniform(1.0, 1000.0);
      p.max_deformation_mm = uniform(0.01, 5.0);
      if (chance(0.3)) p.extra_attributes.emplace_back("x:note", text());
      if (chance(0.3)) p.unknown_children.push_back(UnknownElement{"<x:finger model=\"soft\"/>"});
      image.interaction = p;
    }
    if (chance(0.3)) image.extra_attributes.emplace_back("x:layer", text());
    const int n = pick(0, max_elements);
    for (int i = 0; i < n; ++i) image.children.push_back(element(image, 0));
    return image;
  }

 private:
  int pick(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }
  bool chance(double p) { return std::bernoulli_distribution(p)(rng_); }

  // Values of many magnitudes, occasionally round or tiny, to exercise the number format.
  double coordinate(double extent) {
    switch (pick(0, 3)) {
      case 0: return static_cast<double>(pick(-10, static_cast<int>(extent)));
      case 1: return uniform(-extent, 2.0 * extent) * 1e-7;
      default: return uniform(-0.2 * extent, 1.2 * extent);
    }
  }

  std::string text() {
    static const std::string alphabet = "abcXYZ 019&<>\"'\n\t.,;:-_=\xC3\xA9";
    std::string s;
    const int n = pick(0, 12);
    for (int i = 0; i < n; ++i) {
      const char c = alphabet[static_cast<std::size_t>(pick(0, static_cast<int>(alphabet.size()) - 3))];
      if (c == '\xC3') {
        s += "\xC3\xA9";
      } else {
        s += c;
      }
    }
    return s;
  }

  Meta make_meta() {
    Meta m;
    if (chance(0.8)) m.title = text();
    if (chance(0.5)) m.author = text();
    if (chance(0.5)) m.description = text();
    if (chance(0.4)) m.created = "2026-11-22T04:30:00Z";
    for (int i = pick(0, 3); i > 0; --i) m.tags.push_back(text());
    if (chance(0.5)) m.tool = ToolInfo{"gen" + std::to_string(pick(0, 9)), text(), {}};
    if (m.tool && chance(0.3)) m.tool->extra_attributes.emplace_back("x:build", text());
    if (chance(0.3)) m.extra_attributes.emplace_back("x:lang", text());
    if (chance(0.3)) m.unknown_children.push_back(UnknownElement{"<x:licence kind=\"cc\">CC &amp; more</x:licence>"});
    return m;
  }

  std::string next_id(const char* kind) { return std::string(kind) + "_" + std::to_string(++ids_); }

  Element element(const Image& image, int depth) {
    Element e;
    const int kind = pick(0, depth < 4 ? 4 : 3);
    const double w = image.width_mm;
    const double h = image.height_mm;
    if (kind == 0) {
      Dot d;
      d.x_mm = coordinate(w);
      d.y_mm = coordinate(h);
      d.radius_mm = uniform(0.05, 10.0);
      d.gain = chance(0.2) ? 1.0 : uniform(0.0, 1.0);
      e.body = d;
      e.id = next_id("dot");
    } else if (kind == 1) {
      Line l;
      l.x1_mm = coordinate(w);
      l.y1_mm = coordinate(h);
      l.x2_mm = coordinate(w);
      l.y2_mm = coordinate(h);
      l.width_mm = uniform(0.1, 5.0);
      l.frequency_hz = chance(0.2) ? 1000.0 : uniform(1.0, 1000.0);
      l.damping = uniform(0.001, 0.999);
      l.gain = uniform(0.0, 1.0);
      e.body = l;
      e.id = next_id("line");
    } else if (kind == 2 || kind == 3) {
      Surface s;
      s.shape = static_cast<SurfaceShape>(pick(0, 2));
      if (s.shape == SurfaceShape::rect) {
        s.x_mm = coordinate(w);
        s.y_mm = coordinate(h);
        s.width_mm = uniform(0.5, w);
        s.height_mm = uniform(0.5, h);
      } else if (s.shape == SurfaceShape::ellipse) {
        s.cx_mm = coordinate(w);
        s.cy_mm = coordinate(h);
        s.rx_mm = uniform(0.5, w / 2.0);
        s.ry_mm = uniform(0.5, h / 2.0);
      } else {
        for (int i = pick(3, 7); i > 0; --i) s.points.push_back({coordinate(w), coordinate(h)});
      }
      s.period_mm = uniform(0.1, 10.0);
      s.relief_mm = uniform(0.01, 2.0);
      s.pattern = static_cast<SurfacePattern>(pick(0, 2));
      s.gain = uniform(0.0, 1.0);
      e.body = s;
      e.id = next_id("surface");
    } else {
      Group g;
      if (chance(0.5)) g.name = text();
      for (int i = pick(0, 4); i > 0; --i) g.children.push_back(element(image, depth + 1));
      if (chance(0.2)) g.children.push_back(Element{"", UnknownElement{"<sparkle rate=\"3\"/>"}, {}, {}, 0});
      e.body = g;
      e.id = next_id("group");
    }
    if (chance(0.15)) e.extra_attributes.emplace_back("x:custom", text());
    if (!std::holds_alternative<Group>(e.body) && chance(0.1)) {
      e.unknown_children.push_back(UnknownElement{"<x:animation period=\"2\"><key t=\"0\"/></x:animation>"});
    }
    return e;
  }

  std::mt19937 rng_;
  int ids_ = 0;
};

}  // namespace vimg::test
