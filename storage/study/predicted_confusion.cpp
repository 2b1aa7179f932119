#include "storage/study/predicted_confusion.hpp"

#include <cmath>

#include "storage/json_checker.hpp"
#include "storage/json_reader.hpp"
#include "storage/load_file.hpp"
#include "storage/study/perception_model_file.hpp"
#include "storage/study/study_file.hpp"

namespace vimg {

namespace {

class Extractor : public JsonChecker {
 public:
  explicit Extractor(const std::string& file_name) : JsonChecker(file_name) {}

  bool images(const JsonValue& root, PredictedConfusion& out) {
    const JsonValue* images = root.find("images");
    if (!images) return fail(root.line, "no \"images\" key (the image paths of `vimg compare`)");
    if (!expect(*images, JsonValue::Kind::array, "\"images\"")) return false;
    if (images->items.empty()) return fail(images->line, "\"images\" is empty");
    if (images->items.size() > kMaxPredictedImages)
      return fail(images->line, "\"images\" names " + std::to_string(images->items.size()) + " images (limit " +
                                    std::to_string(kMaxPredictedImages) + ")");
    for (const JsonValue& image : images->items) {
      if (!expect(image, JsonValue::Kind::string, "an image path")) return false;
      const std::string stem = image.text.empty() ? std::string() : study_image_name(image.text);
      if (stem.empty()) return fail(image.line, "an image path with no file name: \"" + escape_input(image.text) + "\"");
      out.stems.push_back(stem);
    }
    return true;
  }

  bool matrix(const JsonValue& root, PredictedConfusion& out) {
    const JsonValue* m = root.find("predicted_confusion");
    if (!m) return fail(root.line, "no \"predicted_confusion\" key (the predicted confusion matrix of `vimg compare`)");
    if (!expect(*m, JsonValue::Kind::array, "\"predicted_confusion\"")) return false;
    const std::size_t n = out.stems.size();
    if (m->items.size() != n)
      return fail(m->line, "\"predicted_confusion\" has " + std::to_string(m->items.size()) + " rows for " + std::to_string(n) + " images");
    for (std::size_t i = 0; i < n; ++i) {
      const JsonValue& row = m->items[i];
      const std::string name = "row " + std::to_string(i + 1) + " of \"predicted_confusion\"";
      if (!expect(row, JsonValue::Kind::array, name)) return false;
      if (row.items.size() != n)
        return fail(row.line, name + " has " + std::to_string(row.items.size()) + " cells for " + std::to_string(n) + " images");
      std::vector<double> cells;
      double sum = 0.0;
      for (const JsonValue& cell : row.items) {
        if (!expect(cell, JsonValue::Kind::number, "a cell of " + name)) return false;
        if (!(cell.number >= 0.0 && cell.number <= 1.0))
          return fail(cell.line, "a cell of " + name + " is not a probability in [0, 1]");
        cells.push_back(cell.number);
        sum += cell.number;
      }
      if (std::abs(sum - 1.0) > kPredictedRowSumTolerance) return fail(row.line, name + " does not sum to 1");
      out.matrix.push_back(std::move(cells));
    }
    return true;
  }

  // The constants of `model`, when it names all of them (an older report names none: no error).
  bool constants(const JsonValue& root, PredictedConfusion& out) {
    const JsonValue* model = root.find("model");
    if (!model || model->kind != JsonValue::Kind::object) return true;
    if (const JsonValue* file = model->find("model_file"); file && file->kind != JsonValue::Kind::null) {
      if (!expect(*file, JsonValue::Kind::string, "\"model_file\" of \"model\"")) return false;
      out.model_file = file->text;
    }
    if (!model->find("temperature_jnd") || !model->find("lapse_rate") || !model->find("cue_weight")) return true;
    DiscriminationConstants k;
    if (!read_discrimination_constants(*this, *model, k)) return false;
    out.constants = k;
    return true;
  }
};

}  // namespace

PredictedLoadResult parse_predicted_confusion(std::string_view json, const std::string& file_name) {
  PredictedLoadResult result;
  JsonParseResult parsed = parse_json(json, file_name);
  if (!parsed.value) {
    result.diagnostics = std::move(parsed.diagnostics);
    return result;
  }
  Extractor extract(file_name);
  PredictedConfusion p;
  p.source = file_name;
  const JsonValue& root = *parsed.value;
  const bool ok = extract.expect(root, JsonValue::Kind::object, "the report of `vimg compare`") && extract.images(root, p) &&
                  extract.matrix(root, p) && extract.constants(root, p);
  result.diagnostics = extract.take();
  if (ok) result.predicted = std::move(p);
  return result;
}

PredictedLoadResult load_predicted_confusion(const std::filesystem::path& file) {
  return load_file<PredictedLoadResult>(file, kMaxPredictedJsonBytes, parse_predicted_confusion);
}

}  // namespace vimg
