#include <cctype>
#include <cmath>
#include <limits>

#include "storage/limits.hpp"
#include "storage/read_file.hpp"
#include "storage/volume/inflate_count.hpp"
#include "storage/volume/nrrd_volume.hpp"
#include "storage/volume/teem_nrrd.hpp"

namespace vimg {
namespace {

std::string in_quotes(std::string_view input) { return "'" + escape_input(input) + "'"; }

// The field a teem message is about, when it names one ("trouble parsing sizes info |…|",
// "failed to parse "frob" as field identifier").
std::string field_in(const std::string& message) {
  if (const std::size_t p = message.find("parsing "); p != std::string::npos) {
    const std::size_t info = message.find(" info", p);
    if (info != std::string::npos) return message.substr(p + 8, info - p - 8);
  }
  if (const std::size_t p = message.find("failed to parse \""); p != std::string::npos) {
    const std::size_t end = message.find('"', p + 17);
    if (end != std::string::npos) return message.substr(p + 17, end - p - 17);
  }
  return {};
}

// The last (most specific) line of a teem message, joined to the one before when it adds to it.
std::string last_line(const std::string& message) {
  const std::size_t nl = message.rfind('\n');
  return nl == std::string::npos ? message : message.substr(nl + 1);
}

// Reports a teem header error at the line of the field it names (line 0 when it names none).
// Problems met while skipping to the data (`line skip`, `byte skip`) are reported at `data_line`.
void header_error(const NrrdHeaderScan& scan, const std::string& message, int data_line, DiagnosticList& list) {
  const std::string field = field_in(message);
  const bool about_data = message.find("skip") != std::string::npos || message.find("seek") != std::string::npos;
  const int line = !field.empty() ? scan.line_of(field) : about_data ? data_line : 0;
  if (!field.empty() && message.find("as field identifier") != std::string::npos) {
    list.error(line, "unknown field " + in_quotes(field));
    return;
  }
  const std::string prefix = field.empty() ? std::string() : "field " + in_quotes(field) + ": ";
  list.error(line, prefix + escape_input(last_line(message), kMaxMessageBytes));
}

// Product of the axis sizes, or nothing past `limit`.
std::optional<std::size_t> sample_count(const Nrrd& n, std::size_t limit) {
  std::size_t count = 1;
  for (unsigned i = 0; i < n.dim; ++i) {
    const std::size_t s = n.axis[i].size;
    if (s == 0 || count > limit / s) return std::nullopt;
    count *= s;
  }
  return count;
}

std::string teem_name(const airEnum* e, int value) {
  const char* s = airEnumStr(e, value);
  return s && std::string(s) != "(unknown_kind)" && std::string(s) != "???" ? s : "";
}

NrrdVolume describe(const Nrrd& n, const std::string& encoding) {
  NrrdVolume v;
  v.type = teem_name(nrrdType, n.type);
  v.encoding = encoding;
  v.space_dimension = n.spaceDim;
  for (unsigned i = 0; i < n.dim; ++i) {
    const NrrdAxisInfo& a = n.axis[i];
    NrrdAxis axis;
    axis.size = a.size;
    axis.spacing = a.spacing;
    if (n.spaceDim > 0 && std::isfinite(a.spaceDirection[0])) {
      axis.space_direction.assign(a.spaceDirection, a.spaceDirection + n.spaceDim);
    }
    axis.kind = a.kind == nrrdKindUnknown ? "" : teem_name(nrrdKind, a.kind);
    axis.units = a.units ? a.units : "";
    v.axes.push_back(std::move(axis));
  }
  for (unsigned i = 0; i < n.spaceDim; ++i) {
    v.space_origin.push_back(n.spaceOrigin[i]);
    v.space_units.push_back(n.spaceUnits[i] ? n.spaceUnits[i] : "");
  }
  return v;
}

// Checks the data's size against the header before teem allocates for it. `where` names the data.
bool data_fits(std::string_view data, const TeemReadResult& head, std::size_t samples, std::size_t bytes, int line,
               const std::string& where, DiagnosticList& list) {
  const bool skips = head.line_skip != 0 || head.byte_skip != 0;
  const std::string needs = " the " + std::to_string(bytes) + " bytes the header declares";
  if (head.encoding == "raw") {
    if ((!skips && data.size() != bytes) || data.size() < bytes) {
      list.error(line, where + "data holds " + std::to_string(data.size()) + " bytes, the header needs " + std::to_string(bytes));
      return false;
    }
  } else if (head.encoding == "ASCII" && samples > data.size() / 2 + 1) {  // a digit and a separator each
    list.error(line, where + "data holds fewer than the " + std::to_string(samples) + " samples the header needs");
    return false;
  } else if (head.encoding == "ASCII") {
    // teem scans each sample with fscanf("%s") into a fixed 1 KiB buffer: a longer one would
    // overflow it (found by the fuzzer), so every whitespace-separated run is held to the limit.
    std::size_t run = 0;
    for (const char c : data) {
      run = std::isspace(static_cast<unsigned char>(c)) ? 0 : run + 1;
      if (run > kMaxNrrdAsciiSampleBytes) {
        list.error(line, where + "an ASCII sample is longer than " + std::to_string(kMaxNrrdAsciiSampleBytes) + " bytes (limit " +
                             std::to_string(kMaxNrrdAsciiSampleBytes) + ")");
        return false;
      }
    }
  } else if (head.encoding == "hex" && data.size() < 2 * bytes) {
    list.error(line, where + "data holds fewer than the " + std::to_string(2 * bytes) + " hex digits the header needs");
    return false;
  } else if (head.compressed && !skips && (head.encoding == "gzip" || head.encoding == "bzip2")) {
    const Compression c = head.encoding == "gzip" ? Compression::gzip : Compression::bzip2;
    const InflateCount count = count_inflated(data, c, bytes);
    if (count.bytes > bytes) {
      list.error(line, where + head.encoding + " data inflates to more than" + needs);
      return false;
    }
    if (!count.problem.empty()) {
      list.error(line, where + count.problem + " (" + std::to_string(count.bytes) + " of" + needs + ")");
      return false;
    }
    if (count.bytes < bytes) {
      list.error(line, where + "data holds " + std::to_string(count.bytes) + " bytes, the header needs " + std::to_string(bytes));
      return false;
    }
  }
  return true;
}

}  // namespace

std::optional<NrrdVolume> read_nrrd_volume(std::string_view bytes, const NrrdReadOptions& options, DiagnosticList& list) {
  std::optional<NrrdHeaderScan> scan = scan_nrrd_header(bytes, list);
  if (!scan) return std::nullopt;
  // 1. The data: attached, or the one data file, read like every path named in a file (bounded
  //    by kMaxVolumeFileBytes; teem has allocated nothing yet).
  std::string_view data = bytes.substr(scan->data_offset);
  FileReadResult detached;
  int data_line = scan->data_line;
  std::string where;  // names a detached data file in messages
  if (scan->data_file) {
    data_line = scan->data_file->line;
    const std::string name = in_quotes(scan->data_file->value);
    if (!options.folder) {
      list.error(data_line, "field 'data file' = " + name + ": a detached header must be read from a file");
      return std::nullopt;
    }
    const NamedFileReadResult named =
        read_named_file(*options.folder, scan->data_file->value, kMaxVolumeFileBytes, options.named, options.what_folder);
    if (!named.read.bytes) {
      list.error(data_line, "field 'data file' = " + name + ": " + named.read.error);
      return std::nullopt;
    }
    detached = named.read;
    data = *detached.bytes;
    where = "data file " + name + ": ";
  }
  // 2. The header alone (teem skips lines and bytes in the data, but allocates nothing for it).
  TeemReadResult head = teem_read(scan->teem_header, data, true);
  if (!head.nrrd) {
    header_error(*scan, head.error, data_line, list);
    return std::nullopt;
  }
  const Nrrd& h = *head.nrrd;
  if (h.type == nrrdTypeBlock) {
    list.error(scan->line_of("type"), "type 'block' is not supported (samples must be numbers)");
    return std::nullopt;
  }
  // 3. Limits on what the header declares.
  const std::optional<std::size_t> samples = sample_count(h, kMaxVolumeSamples);
  const int sizes_line = scan->line_of("sizes");
  if (!samples) {
    list.error(sizes_line, "the volume has more than " + std::to_string(kMaxVolumeSamples) + " samples (limit " +
                               std::to_string(kMaxVolumeSamples) + ")");
    return std::nullopt;
  }
  const std::size_t data_bytes = *samples * nrrdTypeSize[h.type];
  if (data_bytes > kMaxVolumeDataBytes) {
    list.error(sizes_line, "the header declares " + std::to_string(data_bytes) + " bytes of data (limit " +
                               std::to_string(kMaxVolumeDataBytes) + ")");
    return std::nullopt;
  }
  if (!data_fits(data, head, *samples, data_bytes, data_line, where, list)) return std::nullopt;
  // 4. teem reads header and data together.
  const TeemReadResult full = teem_read(scan->teem_header, data, false);
  if (!full.nrrd || !full.nrrd->data) {
    list.error(data_line, where + escape_input(last_line(full.error), kMaxMessageBytes));
    return std::nullopt;
  }
  NrrdVolume volume = describe(*full.nrrd, full.encoding);
  volume.values.resize(*samples);
  float (*lookup)(const void*, size_t) = nrrdFLookup[full.nrrd->type];
  for (std::size_t i = 0; i < *samples; ++i) volume.values[i] = lookup(full.nrrd->data, i);
  volume.header = std::move(*scan);
  return volume;
}

NrrdVolumeResult read_nrrd_volume(std::string_view bytes, const std::string& file_name, const NrrdReadOptions& options) {
  DiagnosticList list(file_name);
  NrrdVolumeResult result;
  result.volume = read_nrrd_volume(bytes, options, list);
  if (list.has_errors()) result.volume.reset();
  result.diagnostics = list.take();
  return result;
}

NrrdFile read_nrrd_file(const std::filesystem::path& path, const NamedFileOptions& named) {
  NrrdFile file;
  FileReadResult read = read_regular_file(path, kMaxVolumeFileBytes);
  if (!read.bytes) {
    file.diagnostics.push_back({Diagnostic::Severity::error, path.string(), 0, printable_message(read.error)});
    return file;
  }
  file.bytes = std::move(read.bytes);
  file.options.folder = path.parent_path();
  file.options.named = named;
  return file;
}

NrrdVolumeResult load_nrrd_volume(const std::filesystem::path& path, const NamedFileOptions& named) {
  const NrrdFile file = read_nrrd_file(path, named);
  if (!file.bytes) return {std::nullopt, file.diagnostics};
  return read_nrrd_volume(*file.bytes, path.string(), file.options);
}

}  // namespace vimg
