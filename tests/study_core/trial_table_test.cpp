// Trial files (storage/study/trial_table.hpp, docs/format-studies.md "Trial files"): rows to cells and back
// exactly, and every problem of a file at its line.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>

#include "storage/limits.hpp"
#include "storage/study/trial_table.hpp"
#include "tests/storage/storage_test_support.hpp"

namespace vimg {
namespace {

std::string join(const std::vector<std::string>& cells) {
  std::string line;
  for (std::size_t i = 0; i < cells.size(); ++i) line += (i ? "," : "") + cells[i];
  return line + "\n";
}

template <class Row>
std::string messages(const TrialTableResult<Row>& r) {
  std::string all;
  for (const auto& d : r.diagnostics) all += d.to_string() + "\n";
  return all;
}

const std::string kMatchingHeader = "participant,set,trial,presented,chosen,correct,rub_s,response_s,path_mm,time_utc\n";
const std::string kLocationHeader =
    "participant,trial,metaphor,seed,target_x_mm,target_z_mm,mark_x_mm,mark_y_mm,mark_z_mm,error_mm,explore_s,time_utc\n";

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Doubles of every magnitude, including the awkward ones: subnormals, -0, the largest finite.
double random_double(std::mt19937_64& rng, bool nonnegative) {
  double v = 0;
  switch (rng() % 6) {
    case 0: {
      std::uint64_t bits = rng();
      std::memcpy(&v, &bits, sizeof v);
      if (!std::isfinite(v)) v = 1.0 / 3.0;
      break;
    }
    case 1: v = std::numeric_limits<double>::denorm_min() * static_cast<double>(rng() % 1000); break;
    case 2: v = -0.0; break;
    case 3: v = std::numeric_limits<double>::max(); break;
    default: v = std::uniform_real_distribution<double>(-500.0, 500.0)(rng); break;
  }
  return nonnegative ? std::fabs(v) : v;
}

std::string random_name(std::mt19937_64& rng) {
  static const std::string alphabet = "abcXYZ019 _-.;:'\xC3\xA9";
  std::string s(1 + rng() % 12, 'a');
  for (char& c : s) c = alphabet[rng() % (alphabet.size() - 1)];
  if (s.back() == '\xC3') s.back() = 'e';
  return s;
}

TEST(TrialTable, MatchingRowsReadBackExactly) {
  std::mt19937_64 rng(20);
  std::vector<MatchingTrial> rows;
  std::string text = kMatchingHeader;
  for (int i = 1; i <= 300; ++i) {
    MatchingTrial t;
    t.participant = (rng() % 2) ? "P01" : "p_2-x";
    t.set = random_name(rng);
    t.trial = i;
    t.presented = random_name(rng);
    t.chosen = rng() % 3 ? random_name(rng) : t.presented;
    t.correct = t.presented == t.chosen;
    t.rub_s = random_double(rng, true);
    t.response_s = random_double(rng, true);
    t.path_mm = random_double(rng, true);
    t.time_utc = "2026-11-25T16:38:" + std::to_string(10 + rng() % 50) + "Z";
    rows.push_back(t);
    text += join(to_cells(t));
  }
  const auto r = parse_matching_trials(text, "m.csv");
  ASSERT_TRUE(r.ok()) << messages(r);
  ASSERT_EQ(r.rows.size(), rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    SCOPED_TRACE(join(to_cells(rows[i])));
    const MatchingTrial& a = rows[i];
    const MatchingTrial& b = r.rows[i];
    EXPECT_EQ(a.participant, b.participant);
    EXPECT_EQ(a.set, b.set);
    EXPECT_EQ(a.trial, b.trial);
    EXPECT_EQ(a.presented, b.presented);
    EXPECT_EQ(a.chosen, b.chosen);
    EXPECT_EQ(a.correct, b.correct);
    EXPECT_TRUE(same_bits(a.rub_s, b.rub_s) && same_bits(a.response_s, b.response_s) && same_bits(a.path_mm, b.path_mm));
    EXPECT_EQ(a.time_utc, b.time_utc);
    EXPECT_EQ(to_cells(a), to_cells(b));
  }
}

TEST(TrialTable, LocationRowsReadBackExactly) {
  std::mt19937_64 rng(21);
  std::vector<LocationTrial> rows;
  std::string text = kLocationHeader;
  for (int i = 1; i <= 300; ++i) {
    LocationTrial t;
    t.participant = "P7";
    t.trial = i;
    t.metaphor = rng() % 2 ? LocationMetaphor::roughness : LocationMetaphor::transition_cue;
    t.seed = rng();
    t.target_x_mm = std::uniform_real_distribution<double>(-80, 80)(rng);
    t.target_z_mm = std::uniform_real_distribution<double>(-60, 60)(rng);
    t.mark_x_mm = rng() % 5 ? std::uniform_real_distribution<double>(-80, 80)(rng) : t.target_x_mm;
    t.mark_y_mm = random_double(rng, false);
    t.mark_z_mm = std::uniform_real_distribution<double>(-60, 60)(rng);
    t.error_mm = std::hypot(t.mark_x_mm - t.target_x_mm, t.mark_z_mm - t.target_z_mm);
    t.explore_s = random_double(rng, true);
    t.time_utc = "2030-01-31T23:59:60Z";
    rows.push_back(t);
    text += join(to_cells(t));
  }
  const auto r = parse_location_trials(text, "l.csv");
  ASSERT_TRUE(r.ok()) << messages(r);
  ASSERT_EQ(r.rows.size(), rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const LocationTrial& a = rows[i];
    const LocationTrial& b = r.rows[i];
    EXPECT_EQ(a.seed, b.seed);
    EXPECT_EQ(a.metaphor, b.metaphor);
    for (const auto member : {&LocationTrial::target_x_mm, &LocationTrial::target_z_mm, &LocationTrial::mark_x_mm,
                              &LocationTrial::mark_y_mm, &LocationTrial::mark_z_mm, &LocationTrial::error_mm,
                              &LocationTrial::explore_s}) {
      EXPECT_TRUE(same_bits(a.*member, b.*member)) << join(to_cells(a));
    }
    EXPECT_EQ(to_cells(a), to_cells(b));
  }
}

TEST(TrialTable, HeadersAreTheDocumentedOnes) {
  EXPECT_EQ(join(kMatchingTrialHeader), kMatchingHeader);
  EXPECT_EQ(join(kLocationTrialHeader), kLocationHeader);
}

// The one diagnostic of a matching file.
std::string matching_only(const std::string& text) {
  const auto r = parse_matching_trials(text, "m.csv");
  EXPECT_FALSE(r.ok());
  EXPECT_TRUE(r.rows.empty());
  return r.diagnostics.size() == 1 ? r.diagnostics[0].to_string() : "several:\n" + messages(r);
}

TEST(TrialTable, EachProblemAtItsLine) {
  const std::string h = kMatchingHeader;
  const std::string ok1 = "P1,s,1,dot,dot,1,2.5,1,30,2026-11-25T16:38:51Z\n";
  EXPECT_EQ(matching_only("participant,set\n"),
            "m.csv:1: error: expected the header 'participant,set,trial,presented,chosen,correct,rub_s,response_s,path_mm,time_utc'");
  EXPECT_EQ(matching_only(kLocationHeader),
            "m.csv:1: error: this is a location trial file, expected a matching trial file (header "
            "'participant,set,trial,presented,chosen,correct,rub_s,response_s,path_mm,time_utc')");
  EXPECT_EQ(matching_only(h + ok1 + "P1,s,2,dot,dot,1\n"),
            "m.csv:3: error: expected 10 cells (participant,set,trial,presented,chosen,correct,rub_s,response_s,path_mm,time_utc), found 6");
  EXPECT_EQ(matching_only(h + "P1,s,1,dot,dot,1,2,5,1,30,2026-11-25T16:38:51Z\n"),
            "m.csv:2: error: expected 10 cells (participant,set,trial,presented,chosen,correct,rub_s,response_s,path_mm,time_utc), found 11");
  EXPECT_EQ(matching_only(h + "P1,s,1,dot,dot,1,2.5s,1,30,2026-11-25T16:38:51Z\n"), "m.csv:2: error: rub_s '2.5s' is not a number");
  EXPECT_EQ(matching_only(h + "P1,s,1,dot,dot,1,nan,1,30,2026-11-25T16:38:51Z\n"), "m.csv:2: error: rub_s 'nan' is NaN, expected a finite number");
  EXPECT_EQ(matching_only(h + "P1,s,1,dot,dot,1,2,-1,30,2026-11-25T16:38:51Z\n"), "m.csv:2: error: response_s '-1' is negative");
  EXPECT_EQ(matching_only(h + "P1,s,0,dot,dot,1,2,1,30,2026-11-25T16:38:51Z\n"), "m.csv:2: error: trial '0' is not a trial number in 1..10000");
  EXPECT_EQ(matching_only(h + "P1,s,+1,dot,dot,1,2,1,30,2026-11-25T16:38:51Z\n"), "m.csv:2: error: trial '+1' is not a trial number in 1..10000");
  EXPECT_EQ(matching_only(h + "P 1,s,1,dot,dot,1,2,1,30,2026-11-25T16:38:51Z\n"),
            "m.csv:2: error: participant 'P 1' is not a participant ID (1 to 64 of A-Z a-z 0-9 _ -)");
  EXPECT_EQ(matching_only(h + "P1,s,1,dot,,0,2,1,30,2026-11-25T16:38:51Z\n"), "m.csv:2: error: chosen '' is empty");
  EXPECT_EQ(matching_only(h + "P1,s,1,dot,dot,yes,2,1,30,2026-11-25T16:38:51Z\n"), "m.csv:2: error: correct 'yes' is not 0 or 1");
  EXPECT_EQ(matching_only(h + "P1,s,1,dot,line,1,2,1,30,2026-11-25T16:38:51Z\n"),
            "m.csv:2: error: correct '1' but the image chosen is not the one presented");
  EXPECT_EQ(matching_only(h + "P1,s,1,dot,dot,0,2,1,30,2026-11-25T16:38:51Z\n"),
            "m.csv:2: error: correct '0' but the image chosen is the one presented");
  EXPECT_EQ(matching_only(h + "P1,s,1,dot,dot,1,2,1,30,2026-11-25 16:38:51\n"),
            "m.csv:2: error: time_utc '2026-11-25 16:38:51' is not a UTC time such as 2026-11-25T16:38:51Z");
  EXPECT_EQ(matching_only(h + "P1,s,1,dot,dot,1,2,1,30,2026-13-25T16:38:51Z\n"),
            "m.csv:2: error: time_utc '2026-13-25T16:38:51Z' is not a UTC time such as 2026-11-25T16:38:51Z");
  EXPECT_EQ(matching_only(h + ok1 + "\n"), "m.csv:3: error: empty line (every line after the header is one trial)");
  EXPECT_EQ(matching_only(h + ok1 + "P2,s,5,dot,dot,1,2,1,30,2026-11-25T16:38:51Z\n" + "P1,s,1,dot,dot,1,2,1,30,2026-11-25T16:38:51Z\n"),
            "m.csv:4: error: trial 1 of participant 'P1' follows trial 1 (line 2): trial numbers must increase");
  // Input quoted in a message is escaped: no control character reaches the terminal.
  EXPECT_EQ(matching_only(h + "P1,s,1,dot,dot,1,\x1b[2J,1,30,2026-11-25T16:38:51Z\n"), "m.csv:2: error: rub_s '\\x1B[2J' is not a number");
}

TEST(TrialTable, SeveralParticipantsAndGapsInOneFile) {
  const std::string text = kMatchingHeader + "P1,s,1,a,a,1,1,1,1,2026-11-25T16:38:51Z\n" + "P2,s,1,a,b,0,1,1,1,2026-11-25T16:38:51Z\r\n" +
                           "P1,s,3,a,a,1,1,1,1,2026-11-25T16:38:51Z\n";
  const auto r = parse_matching_trials(text, "m.csv");
  ASSERT_TRUE(r.ok()) << messages(r);
  EXPECT_EQ(r.rows.size(), 3u);
}

TEST(TrialTable, LocationProblems) {
  const auto one = [](const std::string& row) {
    const auto r = parse_location_trials(kLocationHeader + row, "l.csv");
    EXPECT_FALSE(r.ok());
    return r.diagnostics.size() == 1 ? r.diagnostics[0].to_string() : "several:\n" + messages(r);
  };
  EXPECT_EQ(one("P1,1,friction,3,0,0,3,0,4,5,10,2026-11-25T16:38:51Z\n"), "l.csv:2: error: metaphor 'friction' is not roughness or transitionCue");
  EXPECT_EQ(one("P1,1,roughness,-3,0,0,3,0,4,5,10,2026-11-25T16:38:51Z\n"),
            "l.csv:2: error: seed '-3' is not a whole number in 0..18446744073709551615");
  EXPECT_EQ(one("P1,1,roughness,18446744073709551616,0,0,3,0,4,5,10,2026-11-25T16:38:51Z\n"),
            "l.csv:2: error: seed '18446744073709551616' is not a whole number in 0..18446744073709551615");
  EXPECT_EQ(one("P1,1,roughness,3,0,0,3,0,4,6,10,2026-11-25T16:38:51Z\n"),
            "l.csv:2: error: error_mm '6' is not the mark's distance from the target in the x-z plane (5 mm)");
  const auto good = parse_location_trials(kLocationHeader + "P1,1,transitionCue,18446744073709551615,1,1,4,-70,5,5,10,2026-11-25T16:38:51Z\n", "l.csv");
  ASSERT_TRUE(good.ok()) << messages(good);
  EXPECT_EQ(good.rows[0].seed, 18446744073709551615u);
  EXPECT_EQ(good.rows[0].metaphor, LocationMetaphor::transition_cue);
}

TEST(TrialTable, TornLastLineIsLeftOutWithAWarning) {
  const std::string ok1 = "P1,s,1,dot,dot,1,2.5,1,30,2026-11-25T16:38:51Z\n";
  const std::string row2 = "P1,s,2,dot,line,0,2.5,1,30,2026-11-25T16:38:52Z";
  // Cut anywhere inside the second row: one row and a warning.
  for (std::size_t cut = 1; cut < row2.size(); ++cut) {
    const auto r = parse_matching_trials(kMatchingHeader + ok1 + row2.substr(0, cut), "m.csv");
    ASSERT_TRUE(r.ok()) << cut << "\n" << messages(r);
    EXPECT_EQ(r.rows.size(), 1u);
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_EQ(r.diagnostics[0].to_string(),
              "m.csv:3: warning: the last line is cut short (no line break): the trial under way when the file was cut, left out");
  }
  // Only the line break lost: the row is whole and counts.
  const auto whole = parse_matching_trials(kMatchingHeader + ok1 + row2, "m.csv");
  ASSERT_TRUE(whole.ok());
  EXPECT_EQ(whole.rows.size(), 2u);
  EXPECT_TRUE(whole.diagnostics.empty());
  // A header cut short, or nothing at all: no trials, a warning.
  const auto cut_header = parse_matching_trials(kMatchingHeader.substr(0, 20), "m.csv");
  EXPECT_TRUE(cut_header.ok());
  ASSERT_EQ(cut_header.diagnostics.size(), 1u);
  EXPECT_EQ(cut_header.diagnostics[0].to_string(),
            "m.csv:1: warning: the header line is cut short (the file was cut while it was begun): no trials");
  const auto empty = parse_matching_trials("", "m.csv");
  EXPECT_TRUE(empty.ok());
  ASSERT_EQ(empty.diagnostics.size(), 1u);
  EXPECT_EQ(empty.diagnostics[0].to_string(), "m.csv:1: warning: the file is empty: no header, no trials");
  // A torn line inside the file (followed by a line break) is damage, not a crash's trace.
  EXPECT_EQ(matching_only(kMatchingHeader + row2.substr(0, 10) + "\n" + ok1),
            "m.csv:2: error: expected 10 cells (participant,set,trial,presented,chosen,correct,rub_s,response_s,path_mm,time_utc), found 4");
}

TEST(TrialTable, Limits) {
  std::string text = kMatchingHeader;
  const std::string row = "P1,s,1,a,a,1,1,1,1,2026-11-25T16:38:51Z\n";
  text.reserve(text.size() + (kMaxTrialRows + 1) * row.size());
  for (std::size_t i = 0; i <= kMaxTrialRows; ++i) text += row;
  EXPECT_EQ(matching_only(text), "m.csv:1000002: error: more than 1000000 rows (limit 1000000)");
  test::TempDir dir("trial_limits");
  test::write_text_file(dir / "big.csv", std::string(kMaxTrialFileBytes + 1, 'x'));
  const auto big = read_matching_trials(dir / "big.csv");
  ASSERT_EQ(big.diagnostics.size(), 1u);
  EXPECT_EQ(big.diagnostics[0].to_string(), (dir / "big.csv").string() + ": error: is larger than 64 MiB (limit 67108864 bytes)");
}

TEST(TrialTable, FilesAndTheirKind) {
  test::TempDir dir("trial_kind");
  test::write_text_file(dir / "m.csv", kMatchingHeader + "P1,s,1,a,a,1,1,1,1,2026-11-25T16:38:51Z\n");
  test::write_text_file(dir / "l.csv", kLocationHeader);
  test::write_text_file(dir / "g.csv", "time_s,finger,x_mm,y_mm,pressure,phase\n");
  EXPECT_EQ(trial_file_kind(dir / "m.csv"), TrialFileKind::matching);
  EXPECT_EQ(trial_file_kind(dir / "l.csv"), TrialFileKind::location);
  EXPECT_EQ(trial_file_kind(dir / "g.csv"), TrialFileKind::unknown);
  EXPECT_EQ(trial_file_kind(dir / "missing.csv"), TrialFileKind::unknown);
  const auto m = read_matching_trials(dir / "m.csv");
  ASSERT_TRUE(m.ok()) << messages(m);
  EXPECT_EQ(m.rows.size(), 1u);
  const auto l = read_location_trials(dir / "l.csv");
  EXPECT_TRUE(l.ok() && l.rows.empty() && l.diagnostics.empty()) << messages(l);
  const auto wrong = read_location_trials(dir / "m.csv");
  EXPECT_FALSE(wrong.ok());
}

}  // namespace
}  // namespace vimg
