// The report's statistics against SciPy, the standard package (issue 20: "the t-test agrees with a
// standard statistics package within 1e-6"): many random data sets generated here, the same data
// given to `python3 -c` with scipy.stats, every value compared. Wilson has no SciPy function
// (statsmodels is not installed), so the script finds its bounds by inverting the score test with
// scipy.optimize.brentq and z from scipy.stats.norm: a different computation from the closed form.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "study/statistics.hpp"

namespace vimg::study {
namespace {

namespace fs = std::filesystem;

// The script reads one case per line and prints one line of numbers per case (repr: 17 digits).
//   W n k level         -> Wilson lower upper
//   T level x1 x2 ...   -> mean sd lower upper (t.interval of the mean)
//   X a1,a2,...;b1,...  -> t df p d (ttest_ind equal_var=False; Welch-Satterthwaite df; Cohen's d, pooled SD)
//   R x1,...;y1,...     -> r (pearsonr)
constexpr const char* kScript = R"PY(
import math, sys
import numpy as np
from scipy import optimize, stats
def nums(t): return np.array([float(v) for v in t.split(",")])
for line in open(sys.argv[1]):
    f = line.split()
    if f[0] == "W":
        n, k, level = int(f[1]), int(f[2]), float(f[3])
        z = stats.norm.ppf((1 + level) / 2)
        ph = k / n
        score = lambda p: (ph - p) ** 2 - z * z * p * (1 - p) / n
        lo = 0.0 if k == 0 else optimize.brentq(score, 0.0, ph - 1e-12, xtol=1e-15, rtol=1e-15, maxiter=500)
        hi = 1.0 if k == n else optimize.brentq(score, ph + 1e-12, 1.0, xtol=1e-15, rtol=1e-15, maxiter=500)
        print(repr(lo), repr(hi))
    elif f[0] == "T":
        level = float(f[1]); x = np.array([float(v) for v in f[2:]])
        m = float(np.mean(x)); sd = float(np.std(x, ddof=1))
        lo, hi = stats.t.interval(level, len(x) - 1, loc=m, scale=stats.sem(x))
        print(repr(m), repr(sd), repr(float(lo)), repr(float(hi)))
    elif f[0] == "X":
        a, b = (nums(t) for t in f[1].split(";"))
        r = stats.ttest_ind(a, b, equal_var=False)
        qa, qb = np.var(a, ddof=1) / len(a), np.var(b, ddof=1) / len(b)
        df = (qa + qb) ** 2 / (qa ** 2 / (len(a) - 1) + qb ** 2 / (len(b) - 1))
        sp = math.sqrt(((len(a) - 1) * np.var(a, ddof=1) + (len(b) - 1) * np.var(b, ddof=1)) / (len(a) + len(b) - 2))
        d = (np.mean(a) - np.mean(b)) / sp
        print(repr(float(r.statistic)), repr(float(df)), repr(float(r.pvalue)), repr(float(d)))
    elif f[0] == "R":
        x, y = (nums(t) for t in f[1].split(";"))
        print(repr(float(stats.pearsonr(x, y)[0])))
)PY";

// Debian's interpreter first: python3-scipy installs there (scripts/setup.sh), while a `python3`
// earlier on PATH (pyenv, a virtualenv) may lack it.
std::string python_with_scipy() {
  for (const char* candidate : {"/usr/bin/python3", "python3"}) {
    const std::string probe = std::string(candidate) + " -c 'import scipy.stats, scipy.optimize, numpy' >/dev/null 2>&1";
    if (std::system(probe.c_str()) == 0) return candidate;
  }
  return "";
}

std::vector<std::vector<double>> run_scipy(const std::string& cases) {
  const std::string python = python_with_scipy();
  if (python.empty()) {
    ADD_FAILURE() << "no python3 with SciPy and NumPy (scripts/setup.sh installs python3-scipy)";
    return {};
  }
  const fs::path file = fs::temp_directory_path() / ("vimg_scipy_cases_" + std::to_string(::getpid()) + ".txt");
  std::ofstream(file) << cases;
  std::string command = python + " -c '" + kScript + "' '" + file.string() + "'";
  std::vector<std::vector<double>> rows;
  FILE* pipe = ::popen(command.c_str(), "r");
  std::string out;
  char buffer[4096];
  std::size_t n = 0;
  while (pipe && (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) out.append(buffer, n);
  const int status = pipe ? ::pclose(pipe) : -1;
  fs::remove(file);
  EXPECT_EQ(status, 0) << out;
  std::istringstream lines(out);
  std::string line;
  while (std::getline(lines, line)) {
    std::istringstream fields(line);
    std::vector<double> row;
    std::string field;
    // strtod, not stod: SciPy prints p-values down to the subnormal range (4.9e-324), which stod
    // refuses as out of range.
    while (fields >> field) row.push_back(std::strtod(field.c_str(), nullptr));
    rows.push_back(row);
  }
  return rows;
}

// Within 1e-6, relative for values beyond 1 in magnitude.
void expect_near(double ours, double scipy, const std::string& what) {
  EXPECT_LE(std::abs(ours - scipy), 1e-6 * std::max(1.0, std::abs(scipy))) << what << ": ours " << ours << ", SciPy " << scipy;
}

// Within 1e-6 of the value itself, however small: a p-value of 1e-40 is held to 1e-46, where an
// absolute 1e-6 would accept any p below 1e-6. Below the smallest normal double, where SciPy and
// Boost may round to 0 or to different subnormals, both need only be there.
void expect_relative(double ours, double scipy, const std::string& what) {
  constexpr double kNormal = std::numeric_limits<double>::min();
  if (std::abs(scipy) < kNormal && std::abs(ours) < kNormal) return;
  EXPECT_LE(std::abs(ours - scipy), 1e-6 * std::abs(scipy)) << what << ": ours " << ours << ", SciPy " << scipy;
}

std::string joined(const std::vector<double>& values, char separator) {
  std::ostringstream s;
  s.precision(17);
  for (std::size_t i = 0; i < values.size(); ++i) s << (i ? std::string(1, separator) : "") << values[i];
  return s.str();
}

// Data as studies give it: accuracies near 1, errors in mm, integers with ties, far from zero.
std::vector<double> random_values(std::mt19937_64& rng, std::size_t n) {
  const int shape = static_cast<int>(rng() % 4);
  std::normal_distribution<double> normal(std::uniform_real_distribution<double>(-50, 50)(rng),
                                          std::uniform_real_distribution<double>(0.01, 20)(rng));
  std::vector<double> v;
  for (std::size_t i = 0; i < n; ++i) {
    if (shape == 0) v.push_back(std::round(normal(rng)));                                    // integers, ties
    else if (shape == 1) v.push_back(1.0 - std::abs(normal(rng)) * 1e-3);                   // accuracies near 1
    else if (shape == 2) v.push_back(1e4 + normal(rng));                                     // far from zero
    else v.push_back(std::abs(normal(rng)));                                                 // errors in mm
  }
  if (v.size() >= 2 && v[0] == v[1]) v[1] += 0.5;  // never all equal
  return v;
}

TEST(StatisticsAgainstScipy, ManyRandomCasesAgreeWithin1e6) {
  std::mt19937_64 rng(20261125);
  std::ostringstream cases;
  struct Wilson { std::size_t n, k; double level; };
  struct TCase { double level; std::vector<double> x; };
  struct Pair { std::vector<double> a, b; };
  std::vector<Wilson> wilson;
  std::vector<TCase> t_cases;
  std::vector<Pair> welch, pearson;
  const double levels[] = {0.8, 0.9, 0.95, 0.99, 0.999};
  for (int i = 0; i < 150; ++i) {
    const std::size_t n = 1 + rng() % 600;
    const std::size_t k = i % 10 == 0 ? 0 : i % 10 == 1 ? n : rng() % (n + 1);
    wilson.push_back({n, k, i % 2 ? 0.95 : levels[rng() % 5]});
    cases << "W " << n << " " << k << " " << wilson.back().level << "\n";
  }
  for (int i = 0; i < 150; ++i) {
    t_cases.push_back({levels[rng() % 5], random_values(rng, 2 + rng() % 80)});
    cases << "T " << t_cases.back().level << " " << joined(t_cases.back().x, ' ') << "\n";
  }
  for (int i = 0; i < 200; ++i) {
    welch.push_back({random_values(rng, 2 + rng() % 60), random_values(rng, 2 + rng() % 60)});
    cases << "X " << joined(welch.back().a, ',') << ";" << joined(welch.back().b, ',') << "\n";
  }
  for (int i = 0; i < 60; ++i) {
    std::vector<double> x = random_values(rng, 3 + rng() % 40), y = x;
    for (double& v : y) v = 0.5 * v + std::normal_distribution<double>(0, 5)(rng);
    pearson.push_back({x, y});
    cases << "R " << joined(x, ',') << ";" << joined(y, ',') << "\n";
  }
  const std::vector<std::vector<double>> ref = run_scipy(cases.str());
  ASSERT_EQ(ref.size(), wilson.size() + t_cases.size() + welch.size() + pearson.size());
  std::size_t row = 0;
  for (const Wilson& w : wilson) {
    const auto ours = wilson_interval(w.k, w.n, w.level);
    ASSERT_TRUE(ours);
    const std::string what = "Wilson " + std::to_string(w.k) + "/" + std::to_string(w.n);
    expect_near(ours->lower, ref[row][0], what + " lower");
    expect_near(ours->upper, ref[row][1], what + " upper");
    ++row;
  }
  for (const TCase& c : t_cases) {
    const Summary s = summarize(c.x);
    const auto ours = t_interval_of_mean(c.x, c.level);
    ASSERT_TRUE(ours && s.sd);
    expect_near(s.mean, ref[row][0], "mean");
    expect_near(*s.sd, ref[row][1], "SD");
    expect_near(ours->lower, ref[row][2], "t interval lower");
    expect_near(ours->upper, ref[row][3], "t interval upper");
    ++row;
  }
  int tiny_p = 0;  // cases an absolute 1e-6 could not check
  for (const Pair& p : welch) {
    const auto ours = welch_t_test(p.a, p.b);
    const auto d = cohens_d(p.a, p.b);
    ASSERT_TRUE(ours && d);
    expect_near(ours->t, ref[row][0], "Welch t");
    expect_near(ours->df, ref[row][1], "Welch df");
    expect_relative(ours->p, ref[row][2], "Welch p");
    tiny_p += ref[row][2] < 1e-6;
    expect_near(*d, ref[row][3], "Cohen's d");
    ++row;
  }
  std::printf("Welch p below 1e-6 (held to 1e-6 of itself): %d of %zu\n", tiny_p, welch.size());
  for (const Pair& p : pearson) {
    const auto r = pearson_correlation(p.a, p.b);
    ASSERT_TRUE(r);
    expect_near(*r, ref[row][0], "Pearson r");
    ++row;
  }
}

TEST(Statistics, UndefinedCasesSayNone) {
  const std::vector<double> one{1.0}, same{2.0, 2.0, 2.0}, other{3.0, 3.0};
  EXPECT_FALSE(wilson_interval(0, 0));
  EXPECT_FALSE(wilson_interval(3, 2));
  EXPECT_FALSE(t_interval_of_mean(one, 0.99));
  EXPECT_FALSE(summarize(one).sd);
  EXPECT_FALSE(welch_t_test(one, same));
  EXPECT_FALSE(welch_t_test(same, other));  // no variance anywhere: t is 0/0
  EXPECT_FALSE(cohens_d(same, other));
  EXPECT_FALSE(pearson_correlation(same, std::vector<double>{1.0, 2.0, 3.0}));
  EXPECT_FALSE(pearson_correlation(other, same));  // sizes differ
  // One group without variance is fine: df is then the other group's n - 1.
  const std::vector<double> spread{1.0, 2.0, 4.0};
  const auto w = welch_t_test(same, spread);
  ASSERT_TRUE(w);
  EXPECT_NEAR(w->df, 2.0, 1e-12);
}

// Published Wilson score intervals (95 %): Newcombe 1998, "Two-sided confidence intervals for the
// single proportion: comparison of seven methods", Statistics in Medicine 17, 857-872, Table II,
// method 3 (score interval without continuity correction), its four worked examples, printed to 4
// decimals; and the same examples to full precision with two other levels from SciPy 1.10.1's
// `scipy.stats.binomtest(k, n).proportion_ci(level, method="wilson")`.
TEST(Statistics, WilsonMatchesPublishedIntervals) {
  struct Published { std::size_t k, n; double lower, upper; };
  for (const Published& c : {Published{81, 263, 0.2553, 0.3662}, Published{15, 148, 0.0624, 0.1605},
                             Published{0, 20, 0.0, 0.1611}, Published{1, 29, 0.0061, 0.1718}}) {
    const auto w = wilson_interval(c.k, c.n, 0.95);
    ASSERT_TRUE(w);
    EXPECT_NEAR(w->lower, c.lower, 0.5e-4) << c.k << "/" << c.n;
    EXPECT_NEAR(w->upper, c.upper, 0.5e-4) << c.k << "/" << c.n;
  }
  struct Scipy { std::size_t k, n; double level, lower, upper; };
  for (const Scipy& c : {Scipy{81, 263, 0.95, 0.2552885198782742, 0.36620957698280004},
                         Scipy{15, 148, 0.95, 0.06238639953073629, 0.16048724172330803},
                         Scipy{0, 20, 0.95, 0.0, 0.16112515805281935},
                         Scipy{1, 29, 0.95, 0.006113214292762667, 0.17175521879320282},
                         Scipy{29, 29, 0.95, 0.8830302015002592, 1.0},
                         Scipy{0, 1, 0.95, 0.0, 0.7934506856227626},
                         Scipy{81, 263, 0.99, 0.24013690268760768, 0.3852825023182298},
                         Scipy{15, 148, 0.9, 0.06744326224687144, 0.14957293174640027}}) {
    const auto w = wilson_interval(c.k, c.n, c.level);
    ASSERT_TRUE(w);
    EXPECT_NEAR(w->lower, c.lower, 1e-12) << c.k << "/" << c.n << " at " << c.level;
    EXPECT_NEAR(w->upper, c.upper, 1e-12) << c.k << "/" << c.n << " at " << c.level;
  }
}

}  // namespace
}  // namespace vimg::study
