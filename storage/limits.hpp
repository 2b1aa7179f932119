#pragma once
// Every limit of the file formats and their readers, in one place (docs/limits.md gives each value
// its reason). A reader checks a limit before it allocates for what the input declares, and refuses
// with `FILE:LINE: error: … (limit N)`.
#include <cstddef>

namespace vimg {

// Fuzzing builds (VIMG_FUZZING, the fuzz preset) divide the size and count limits by 64, so that
// libFuzzer's inputs (-max_len in .ci/run) reach every limit and the code that refuses it.
#ifdef VIMG_FUZZING
inline constexpr std::size_t kLimitScale = 64;
#else
inline constexpr std::size_t kLimitScale = 1;
#endif

// --- The image format (spec section 1) -------------------------------------------------------------
inline constexpr int kFormatMajor = 1;               // the format version this code reads and writes
inline constexpr int kFormatMinor = 0;
inline constexpr double kMaxCanvasMm = 10000.0;      // width and height in (0, kMaxCanvasMm]
inline constexpr double kMaxFrequencyHz = 1000.0;    // line frequency in (0, kMaxFrequencyHz]
inline constexpr int kMaxGroupDepth = 32;            // groups nest at most this deep (spec)

// --- File sizes (bytes read before any parsing) ------------------------------------------------------
inline constexpr std::size_t kMiB = std::size_t{1} << 20;
inline constexpr std::size_t kMaxImageFileBytes = 64 * kMiB / kLimitScale;  // image XML, a PNG file, the XML inside a PNG
inline constexpr std::size_t kMaxSceneFileBytes = 4 * kMiB / kLimitScale;  // a volume scene (.vscene.xml)
inline constexpr std::size_t kMaxCsvFileBytes = 64 * kMiB / kLimitScale;   // a gesture or probe-path CSV
inline constexpr std::size_t kMaxNrrdHeaderBytes = 1 * kMiB / kLimitScale;  // the text header of a NRRD volume
inline constexpr std::size_t kMaxNrrdFieldLineBytes = 800;  // one `field: value` line of a NRRD header (teem's messages overflow from 963)
inline constexpr std::size_t kMaxNrrdAsciiSampleBytes = 256;  // one sample of ASCII NRRD data (teem scans each into a 1 KiB buffer)
inline constexpr std::size_t kMaxVolumeFileBytes = 1024 * kMiB;  // a whole NRRD file (header and data)

// --- XML structure (images and volume scenes; checked before tinyxml2 builds its tree) --------------
// Elements and attributes per file keep the validation of any file under 2 s (docs/limits.md):
// 2.3x and 2.1x the 100 000-primitive benchmark image (110 002 elements, 750 006 attributes).
inline constexpr std::size_t kMaxXmlElements = 250'000 / kLimitScale;  // elements, comments and other markup per file
inline constexpr std::size_t kMaxXmlAttributes = 1'600'000 / kLimitScale;  // attributes per file
inline constexpr std::size_t kMaxAttributesPerElement = 64;
// Unknown attributes kept on one element: the writer adds every known attribute the element lacks
// (a surface rect has 10), and what it writes must read back under kMaxAttributesPerElement.
inline constexpr std::size_t kMaxKnownAttributesPerElement = 10;
inline constexpr std::size_t kMaxUnknownAttributesPerElement = kMaxAttributesPerElement - kMaxKnownAttributesPerElement;
inline constexpr int kMaxXmlNestingDepth = 64;             // elements inside elements, the root is depth 1
inline constexpr std::size_t kMaxPolygonPoints = 100'000 / kLimitScale;  // points of one polygon surface

// --- PNG -------------------------------------------------------------------------------------------
inline constexpr double kMaxPngPixels = 25'000'000.0;         // PNG export: width_px * height_px at most
inline constexpr double kMaxDecodedPngPixels = 100'000'000.0;  // PNG import: pixels decoded at most
inline constexpr int kMaxPngSide = 200'000;                   // PNG import: width and height at most

// --- Volumes (NRRD) --------------------------------------------------------------------------------
inline constexpr std::size_t kMaxVolumeSamples = (std::size_t{1} << 27) / kLimitScale;  // voxels x components (512 MiB as float)
inline constexpr std::size_t kMaxVolumeDataBytes = 512 * kMiB / kLimitScale;  // declared data: samples x type size (raw or inflated)
inline constexpr double kMaxDeviceRateHz = 4000.0;              // a scene's device rate, Hz

// --- Gestures (storage/gesture_csv.cpp enforces these) -----------------------------------------------
inline constexpr std::size_t kMaxGestureRows = 1'000'000 / kLimitScale;
inline constexpr double kMaxGestureDurationS = 600.0;   // last time minus first time
inline constexpr double kMaxGestureTimeS = 86'400.0;    // |time_s| at most
inline constexpr double kMaxGestureCoordinateMm = kMaxCanvasMm;  // |x_mm|, |y_mm| at most
inline constexpr std::size_t kMaxTouchTraceFileBytes = 64 * kMiB / kLimitScale;  // an evemu or getevent recording
inline constexpr int kMaxTouchTraceFinger = 63;  // slots and fingers of a recording: a gesture's fingers 0..63

// --- Probe paths (storage/volume/probe_path_io.cpp) ------------------------------------------------
inline constexpr std::size_t kMaxProbePathRows = 1'000'000 / kLimitScale;
inline constexpr double kMaxProbePathDurationS = 600.0;   // last time minus first time
inline constexpr double kMaxProbeTimeS = 86'400.0;        // |time_s| at most
inline constexpr double kMaxProbeCoordinateMm = 10'000.0;  // |x_mm|, |y_mm|, |z_mm| at most
// Rows a probe render may produce: duration x rate, checked before reserving (at most 2 400 001).
inline constexpr std::size_t kMaxProbeRenderRows =
    static_cast<std::size_t>(kMaxProbePathDurationS * kMaxDeviceRateHz) + 1;

// --- Rendered signals compared by `vimg compare` (storage/signal_file.cpp, docs/studies.md) ----------
inline constexpr std::size_t kMaxSignalFileBytes = 64 * kMiB / kLimitScale;  // a WAV or render CSV given as input
inline constexpr double kMaxSignalDurationS = 610.0;  // a render: the longest gesture and its longest ring-down
inline constexpr std::size_t kMaxCompareInputs = 32;  // inputs of one comparison (each analysed render is held in memory)

// --- Import (storage/import, docs/import.md) --------------------------------------------------------
inline constexpr int kMaxPictureLevels = 16;                // grey levels of a picture import
inline constexpr double kMaxImportCoordinateMm = 1e9;       // |coordinate| of an SVG shape after its transforms
inline constexpr double kMaxPictureContainmentTests = 4e8;  // outline edges visited placing a picture's holes
// Primitives and groups an import may give: the written image's other two elements are its XML
// declaration and its <vibroimage> root (an SVG title takes two more: <meta> and its <title>).
inline constexpr std::size_t kMaxImportPrimitives = kMaxXmlElements - 2;
// Points an import (SVG or picture) may make in all, counted as they are produced: a written image holds a
// point in about 16 bytes, so more would not fit the largest image file (4 194 304).
inline constexpr std::size_t kMaxImportPoints = kMaxImageFileBytes / 16;
// Outline vertices and bounding boxes an SVG import visits placing its paths' subpaths (the nonzero
// fill's point-in-ring tests, each hole's nearest bridge vertex): a path of many subpaths nested in
// long rings is refused in seconds instead of running for minutes.
inline constexpr std::size_t kMaxImportOutlineTests = 100'000'000 / kLimitScale;

// --- Studies (storage/study: study files and trial files; docs/limits.md "Studies") ----------------
inline constexpr std::size_t kMaxStudyFileBytes = 1 * kMiB / kLimitScale;  // a matching or location study file
inline constexpr std::size_t kMaxStudySets = 64;           // image sets of a matching study
inline constexpr std::size_t kMaxStudyImagesPerSet = 64;   // images of one set (the answer screen shows them all)
inline constexpr int kMaxStudyRepetitions = 100;           // presentations of each image per set
inline constexpr double kMaxStudyTrainingMinutes = 600.0;  // training time per set
inline constexpr std::size_t kMaxStudyTrials = 10'000;     // trials of one participant in one study
inline constexpr std::size_t kMaxStudyNameBytes = 255;     // a set's name, an image's stem (a file name's length)
inline constexpr std::size_t kMaxTrialFileBytes = 64 * kMiB / kLimitScale;  // a trial file (CSV)
inline constexpr std::size_t kMaxTrialRows = 1'000'000 / kLimitScale;      // rows of a trial file

// --- Messages ----------------------------------------------------------------------------------------
inline constexpr std::size_t kMaxQuotedInputBytes = 64;  // input quoted in a message, before "..."
inline constexpr std::size_t kMaxMessageBytes = 512;     // one diagnostic's message text
inline constexpr std::size_t kMaxDiagnosticsPerFile = 50;  // then one line with the count of the rest

}  // namespace vimg
