// Storage benchmarks (docs/benchmarks/storage.md, "Storage"): loading and validating a 100 000-primitive
// image against tinyxml2's bare parse of the same text, saving it, and PNG export at 10 px/mm; and
// the hostile inputs of docs/limits.md.
//
// Goals (Release build, the figures are read from these benchmarks, never checked in unit tests):
//   BM_SavePng10PxPerMm/threads:0          <= 0.6 s  the picture of 100 000 primitives as PNG (wall time)
//   BM_ConvertPolygon100kPoints/circle     <= 2 s    XML text to PNG file, one 100 000-point polygon
//   BM_ConvertPolygon100kPoints/zigzag     <= 2 s    the same, every edge spanning the canvas
//   BM_ValidateElementWith200kAttributes   <= 2 s    2.3 MB, refused (limit 64 attributes)
//   BM_ValidateDenseFileAtTheSizeLimit     <= 2 s    64 MiB of elements of 64 attributes each (refused:
//                                                    over the attributes per file)
//   BM_ValidateWorstAcceptedFile           <= 2 s    the most elements, or the most attributes, that
//                                                    the limits let through to tinyxml2
#include <benchmark/benchmark.h>
#include <tinyxml2.h>

#include <cmath>
#include <filesystem>
#include <random>
#include <string>

#include "storage/image_io.hpp"
#include "storage/limits.hpp"
#include "storage/picture.hpp"
#include "storage/xml_limits.hpp"

namespace {

constexpr int kPrimitives = 100000;

// A 300 x 300 mm canvas holding a third each of dots, lines and surfaces (all three shapes), in
// groups of ten, every element with an id and full-precision coordinates.
vimg::Image big_image() {
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> pos(0.0, 300.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  vimg::Image image;
  image.width_mm = 300;
  image.height_mm = 300;
  vimg::Element group;
  for (int i = 0; i < kPrimitives; ++i) {
    vimg::Element e;
    e.id = "p" + std::to_string(i);
    const double x = pos(rng);
    const double y = pos(rng);
    switch (i % 5) {
      case 0:
      case 1: e.body = vimg::Dot{x, y, 0.5 + unit(rng), unit(rng)}; break;
      case 2: {
        vimg::Line l;
        l.x1_mm = x;
        l.y1_mm = y;
        l.x2_mm = x + 5 * unit(rng);
        l.y2_mm = y + 5 * unit(rng);
        l.frequency_hz = 50 + 500 * unit(rng);
        l.gain = unit(rng);
        e.body = l;
        break;
      }
      default: {
        vimg::Surface s;
        s.shape = static_cast<vimg::SurfaceShape>(i % 3);
        s.x_mm = x;
        s.y_mm = y;
        s.width_mm = 1 + 3 * unit(rng);
        s.height_mm = 1 + 3 * unit(rng);
        s.cx_mm = x;
        s.cy_mm = y;
        s.rx_mm = 0.5 + 2 * unit(rng);
        s.ry_mm = 0.5 + 2 * unit(rng);
        if (s.shape == vimg::SurfaceShape::polygon) s.points = {{x, y}, {x + 3, y}, {x + 1.5, y + 2.5}};
        s.period_mm = 0.5 + 3 * unit(rng);
        s.gain = unit(rng);
        e.body = s;
      }
    }
    if (i % 10 == 0) {
      if (i > 0) image.children.push_back(group);
      group = vimg::Element{};
      group.id = "g" + std::to_string(i / 10);
      group.body = vimg::Group{};
    }
    std::get<vimg::Group>(group.body).children.push_back(std::move(e));
  }
  image.children.push_back(group);
  return image;
}

const vimg::Image& image() {
  static const vimg::Image value = big_image();
  return value;
}

const std::string& text() {
  static const std::string value = vimg::write_image_xml(image());
  return value;
}

void BM_Tinyxml2BareParse(benchmark::State& state) {
  for (auto _ : state) {
    tinyxml2::XMLDocument doc(true, tinyxml2::PRESERVE_WHITESPACE);
    doc.Parse(text().data(), text().size());
    benchmark::DoNotOptimize(doc.RootElement());
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * text().size()));
}
BENCHMARK(BM_Tinyxml2BareParse)->Unit(benchmark::kMillisecond);

// The linear pass before tinyxml2 (storage/xml_limits.hpp): structure limits and the
// well-formedness tinyxml2 lacks. Every load runs it, and every save on the text it writes.
void BM_CheckXmlStructure(benchmark::State& state) {
  for (auto _ : state) {
    if (vimg::check_xml_limits(text())) state.SkipWithError("the benchmark image was refused");
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * text().size()));
}
BENCHMARK(BM_CheckXmlStructure)->Unit(benchmark::kMillisecond);

void BM_LoadAndValidate(benchmark::State& state) {
  for (auto _ : state) {
    const vimg::LoadResult result = vimg::parse_image_xml(text(), "bench.vimg");
    if (!result.ok()) state.SkipWithError("the benchmark image did not load");
    benchmark::DoNotOptimize(result.image->children.size());
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * text().size()));
}
BENCHMARK(BM_LoadAndValidate)->Unit(benchmark::kMillisecond);

void BM_WriteXmlText(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(vimg::write_image_xml(image()).size());
}
BENCHMARK(BM_WriteXmlText)->Unit(benchmark::kMillisecond);

void BM_SaveXmlFile(benchmark::State& state) {
  const auto path = std::filesystem::temp_directory_path() / "vimg_storage_bench.vimg";
  for (auto _ : state) {
    if (vimg::save_image_file(image(), path)) state.SkipWithError("save failed");
  }
  std::filesystem::remove(path);
}
BENCHMARK(BM_SaveXmlFile)->Unit(benchmark::kMillisecond);

void BM_DrawPicture10PxPerMm(benchmark::State& state) {
  vimg::RgbRaster raster;
  for (auto _ : state) {
    if (vimg::draw_picture(image(), 10.0, raster)) state.SkipWithError("draw failed");
    benchmark::DoNotOptimize(raster.rgb.data());
  }
}
BENCHMARK(BM_DrawPicture10PxPerMm)->Unit(benchmark::kMillisecond);

// threads:0 is the default (one thread per core), threads:1 the same work on one thread. The save
// runs on several threads, so the time to read is the wall time ("Time"); "CPU" is the whole
// process's CPU time.
void BM_SavePng10PxPerMm(benchmark::State& state) {
  const auto path = std::filesystem::temp_directory_path() / "vimg_storage_bench.png";
  vimg::SaveOptions options;
  options.scale_px_per_mm = 10.0;
  options.threads = static_cast<int>(state.range(0));
  for (auto _ : state) {
    if (vimg::save_image_file(image(), path, options)) state.SkipWithError("save failed");
  }
  state.counters["MB"] = static_cast<double>(std::filesystem::file_size(path)) / 1e6;
  std::filesystem::remove(path);
}
BENCHMARK(BM_SavePng10PxPerMm)->ArgName("threads")->Arg(0)->Arg(1)->UseRealTime()->MeasureProcessCPUTime()
    ->Unit(benchmark::kMillisecond);

// One polygon of 100 000 points on a 300 x 300 mm canvas, as XML text: a circle (each row crosses
// two edges) or a zigzag whose every edge spans the canvas (each row crosses all of them).
std::string polygon_text(bool zigzag) {
  vimg::Image image;
  image.width_mm = 300;
  image.height_mm = 300;
  vimg::Surface s;
  s.shape = vimg::SurfaceShape::polygon;
  constexpr int kPoints = 100000;
  for (int i = 0; i < kPoints; ++i) {
    const double t = static_cast<double>(i) / kPoints;
    if (zigzag) {
      s.points.push_back({290.0 * t + 5.0, i % 2 == 0 ? 5.0 : 295.0});
    } else {
      s.points.push_back({150.0 + 140.0 * std::cos(2.0 * 3.141592653589793 * t), 150.0 + 140.0 * std::sin(2.0 * 3.141592653589793 * t)});
    }
  }
  vimg::Element e;
  e.id = "p";
  e.body = s;
  image.children.push_back(e);
  return vimg::write_image_xml(image);
}

void BM_ConvertPolygon100kPoints(benchmark::State& state) {
  const std::string xml = polygon_text(state.range(0) != 0);
  const auto path = std::filesystem::temp_directory_path() / "vimg_storage_bench_polygon.png";
  for (auto _ : state) {
    const vimg::LoadResult loaded = vimg::parse_image_xml(xml, "polygon.vimg");
    if (!loaded.ok()) {
      state.SkipWithError("the polygon image did not load");
      break;
    }
    if (vimg::save_image_file(*loaded.image, path, {10.0})) state.SkipWithError("save failed");
  }
  std::filesystem::remove(path);
}
BENCHMARK(BM_ConvertPolygon100kPoints)->ArgName("zigzag")->Arg(0)->Arg(1)->UseRealTime()->MeasureProcessCPUTime()
    ->Unit(benchmark::kMillisecond);

void BM_ValidateElementWith200kAttributes(benchmark::State& state) {
  std::string xml = "<vibroimage version=\"1.0\" width=\"10\" height=\"10\">\n<dot x=\"1\" y=\"1\"";
  for (int i = 0; i < 200000; ++i) xml += " a" + std::to_string(i) + "=\"1\"";
  xml += "/>\n</vibroimage>\n";
  for (auto _ : state) {
    const vimg::LoadResult result = vimg::parse_image_xml(xml, "attributes.vimg");
    if (result.ok()) state.SkipWithError("200 000 attributes were accepted");
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * xml.size()));
}
BENCHMARK(BM_ValidateElementWith200kAttributes)->Unit(benchmark::kMillisecond);

// The densest valid-looking file: 64 MiB of unknown elements with 64 attributes each.
void BM_ValidateDenseFileAtTheSizeLimit(benchmark::State& state) {
  std::string element = "<x";
  for (int i = 0; i < 64; ++i) element += " a" + std::to_string(i) + "=\"\"";
  element += "/>";
  std::string xml = "<vibroimage version=\"1.0\" width=\"10\" height=\"10\">";
  while (xml.size() + element.size() + 20 < vimg::kMaxImageFileBytes) xml += element;
  xml += "</vibroimage>";
  for (auto _ : state) {
    const vimg::LoadResult result = vimg::parse_image_xml(xml, "dense.vimg");
    benchmark::DoNotOptimize(result.diagnostics.size());
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * xml.size()));
}
BENCHMARK(BM_ValidateDenseFileAtTheSizeLimit)->Unit(benchmark::kMillisecond);

// The costliest files the structure limits let through to tinyxml2 (docs/limits.md): /0 the most
// elements (dots of 6 attributes, up to kMaxXmlElements), /1 the most attributes (unknown
// elements of 64 attributes, up to kMaxXmlAttributes).
void BM_ValidateWorstAcceptedFile(benchmark::State& state) {
  std::string xml = "<vibroimage version=\"1.0\" width=\"300\" height=\"300\">\n";
  if (state.range(0) == 0) {
    for (std::size_t i = 1; i < vimg::kMaxXmlElements; ++i) {
      xml += "<dot id=\"d" + std::to_string(i) + "\" x=\"" + std::to_string(i % 300) + "\" y=\"" +
             std::to_string((i / 300) % 300) + "\" radius=\"1\" gain=\"0.5\" a=\"\"/>\n";
    }
  } else {
    std::string element = "<x";
    for (std::size_t i = 0; i < vimg::kMaxAttributesPerElement; ++i) element += " a" + std::to_string(i) + "=\"" + std::to_string(i) + "\"";
    element += "/>\n";
    for (std::size_t n = 3; n + vimg::kMaxAttributesPerElement <= vimg::kMaxXmlAttributes; n += vimg::kMaxAttributesPerElement) xml += element;
  }
  xml += "</vibroimage>\n";
  for (auto _ : state) {
    const vimg::LoadResult result = vimg::parse_image_xml(xml, "worst.vimg");
    if (!result.ok()) state.SkipWithError("the worst accepted file was refused");
    benchmark::DoNotOptimize(result.diagnostics.size());
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * xml.size()));
}
BENCHMARK(BM_ValidateWorstAcceptedFile)->ArgName("attributes")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
