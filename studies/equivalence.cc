#include "studies/equivalence.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <sstream>

#include "studies/map_ceiling.h"
#include "studies/statistics/intervals.h"

namespace ssc {
namespace {

double LogChoose(int n, int k) {
  return std::lgamma(n + 1.0) - std::lgamma(k + 1.0) - std::lgamma(n - k + 1.0);
}

// The hypergeometric law of arm a's successes given the margins: support [lo, hi], and the
// probability of each x in it.
struct Hypergeometric {
  int lo = 0, hi = 0;
  std::vector<double> p;  // p[x - lo]
};

Hypergeometric TableLaw(int n_a, int n_b, int successes) {
  Hypergeometric h;
  const int failures = n_a + n_b - successes;
  h.lo = std::max(0, n_a - failures);
  h.hi = std::min(successes, n_a);
  const double total = LogChoose(n_a + n_b, n_a);
  for (int x = h.lo; x <= h.hi; ++x) {
    h.p.push_back(std::exp(LogChoose(successes, x) + LogChoose(failures, n_a - x) - total));
  }
  return h;
}

// Fisher's two-sided p-value of table x under the law h.
double FisherP(const Hypergeometric& h, int x) {
  const double observed = h.p[static_cast<std::size_t>(x - h.lo)] * (1 + 1e-7);
  double sum = 0;
  for (double q : h.p)
    if (q <= observed) sum += q;
  return std::min(1.0, sum);
}

// P(Binomial(n, q) >= k).
double BinomialAtLeast(int n, double q, int k) {
  return ProbabilityAtLeast(std::vector<double>(static_cast<std::size_t>(n), q), k);
}

}  // namespace

double FisherExactP(int k_a, int n_a, int k_b, int n_b) {
  if (n_a <= 0 || n_b <= 0) return 1;
  const Hypergeometric h = TableLaw(n_a, n_b, k_a + k_b);
  return FisherP(h, k_a);
}

double FisherFalseAlarmChance(int n_a, int n_b, int successes, double alpha) {
  if (n_a <= 0 || n_b <= 0) return 0;
  const Hypergeometric h = TableLaw(n_a, n_b, successes);
  double chance = 0;
  for (int x = h.lo; x <= h.hi; ++x) {
    if (FisherP(h, x) <= alpha) chance += h.p[static_cast<std::size_t>(x - h.lo)];
  }
  return chance;
}

namespace {

// "" when the arms can be compared: one count per cell in each arm, trials in every cell,
// successes within them, alpha in (0, 1).
std::string CheckArms(const std::vector<MapCell>& cells, const std::vector<ArmCounts>& a,
                      const std::vector<ArmCounts>& b, const EquivalenceOptions& options) {
  if (a.size() != cells.size() || b.size() != cells.size()) {
    return "equivalence: the arms' cell lists differ from the map's in length";
  }
  std::ostringstream os;
  if (!(options.alpha > 0 && options.alpha < 1)) {
    os << "equivalence: alpha = " << options.alpha << " is out of range (0, 1)";
    return os.str();
  }
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (a[i].trials <= 0 || b[i].trials <= 0 || a[i].successes < 0 || b[i].successes < 0 ||
        a[i].successes > a[i].trials || b[i].successes > b[i].trials) {
      os << "equivalence: cell step " << cells[i].step_mm << " mm, beta " << cells[i].beta
         << ", P_ref " << cells[i].pref_pa << " Pa: successes must be in [0, trials] and each "
         << "arm needs trials (got " << a[i].successes << "/" << a[i].trials << " and "
         << b[i].successes << "/" << b[i].trials << ")";
      return os.str();
    }
  }
  return "";
}

// One cell: both rates, their agreement with the published class, Fisher's test and its exact
// false-alarm chance at alpha.
CellDifference CompareCell(const MapCell& cell, const ArmCounts& a, const ArmCounts& b,
                           double alpha) {
  CellDifference c;
  c.cell = cell;
  c.a = a;
  c.b = b;
  c.rate_a = static_cast<double>(a.successes) / a.trials;
  c.rate_b = static_cast<double>(b.successes) / b.trials;
  c.agreement_a = ClassProbability(cell.published, c.rate_a);
  c.agreement_b = ClassProbability(cell.published, c.rate_b);
  c.p_value = FisherExactP(a.successes, a.trials, b.successes, b.trials);
  c.differs = c.p_value <= alpha;
  c.false_alarm_chance =
      FisherFalseAlarmChance(a.trials, b.trials, a.successes + b.successes, alpha);
  return c;
}

// Every cell (result->cells), how many differ against chance, the common shift (Cochran-Mantel-
// Haenszel) and each arm's summed agreement (the score before its mean).
void CompareCells(const std::vector<MapCell>& cells, const std::vector<ArmCounts>& a,
                  const std::vector<ArmCounts>& b, double alpha, Equivalence* result) {
  std::vector<double> false_alarm;
  double shift_sum = 0, shift_variance = 0;  // CMH: sum of (k_b - E k_b) and of its variances
  SuccessShift& sh = result->shift;
  DifferingCells& d = result->differing;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const CellDifference c = CompareCell(cells[i], a[i], b[i], alpha);
    false_alarm.push_back(c.false_alarm_chance);
    const double na = a[i].trials, nb = b[i].trials, m = a[i].successes + b[i].successes;
    const double total = na + nb;
    shift_sum += b[i].successes - nb * m / total;
    if (total > 1) shift_variance += na * nb * m * (total - m) / (total * total * (total - 1));
    sh.successes_a += a[i].successes;
    sh.successes_b += b[i].successes;
    sh.trials_a += a[i].trials;
    sh.trials_b += b[i].trials;
    d.differing += c.differs ? 1 : 0;
    d.expected_by_chance += c.false_alarm_chance;
    result->score.a += c.agreement_a;
    result->score.b += c.agreement_b;
    result->cells.push_back(c);
  }
  d.cells = static_cast<int>(cells.size());
  d.alpha = alpha;
  d.nominal_by_chance = alpha * d.cells;
  d.p_at_least = ProbabilityAtLeast(false_alarm, d.differing);
  if (shift_variance > 0) {
    const double corrected = std::max(0.0, std::fabs(shift_sum) - 0.5);
    sh.p_value = std::erfc(corrected / std::sqrt(2 * shift_variance));
  }
}

// The score difference: each arm's mean agreement, and b - a with its 95 % interval and
// posterior tail from each cell's rate drawn from its Jeffreys posterior.
void ScoreArms(const EquivalenceOptions& options, Equivalence* result) {
  ScoreDifference& s = result->score;
  const double n = static_cast<double>(std::max<std::size_t>(1, result->cells.size()));
  s.a /= n;
  s.b /= n;
  s.difference = s.b - s.a;
  if (result->cells.empty() || options.draws < 2) return;
  std::mt19937_64 rng(options.seed);
  std::vector<double> diff(static_cast<std::size_t>(options.draws), 0.0);
  auto draw_rate = [&rng](const ArmCounts& c) {
    std::gamma_distribution<double> yes(c.successes + 0.5, 1.0);
    std::gamma_distribution<double> no(c.trials - c.successes + 0.5, 1.0);
    const double x = yes(rng), y = no(rng);
    return x / (x + y);
  };
  for (const CellDifference& c : result->cells) {
    for (double& v : diff) {
      const double pa = draw_rate(c.a), pb = draw_rate(c.b);
      v += (ClassProbability(c.cell.published, pb) - ClassProbability(c.cell.published, pa)) / n;
    }
  }
  std::sort(diff.begin(), diff.end());
  const auto at = [&](double q) {
    return diff[static_cast<std::size_t>(std::lround(q * (options.draws - 1)))];
  };
  s.interval = {at(0.025), at(0.975)};
  const double draws = static_cast<double>(options.draws);
  const double below =
      static_cast<double>(std::upper_bound(diff.begin(), diff.end(), 0.0) - diff.begin());
  const double above =
      static_cast<double>(diff.end() - std::lower_bound(diff.begin(), diff.end(), 0.0));
  s.p_value = std::min(1.0, 2 * std::min(below, above) / draws);
}

// One Fig. 6 target in both arms: the difference and, with a spread in each, Welch's test.
TargetDifference CompareTarget(const TargetMeasure& ta, const TargetMeasure& tb, double alpha) {
  TargetDifference t;
  t.name = ta.name;
  t.published = ta.published;
  t.tolerance = ta.tolerance;
  t.a = ta;
  t.b = tb;
  if (ta.n > 0 && tb.n > 0) t.difference = tb.mean - ta.mean;
  const double va = ta.standard_error * ta.standard_error;
  const double vb = tb.standard_error * tb.standard_error;
  if (ta.n >= 2 && tb.n >= 2 && std::isfinite(va) && std::isfinite(vb) && va + vb > 0) {
    t.tested = true;
    t.standard_error = std::sqrt(va + vb);
    t.dof = (va + vb) * (va + vb) / (va * va / (ta.n - 1) + vb * vb / (tb.n - 1));
    t.p_value = StudentTwoSidedP(t.difference / t.standard_error, t.dof);
    t.differs = t.p_value <= alpha;
  }
  return t;
}

// The Fig. 6 targets, matched by name, and how many differ against chance.
void CompareTargets(const std::vector<TargetMeasure>& targets_a,
                    const std::vector<TargetMeasure>& targets_b, double alpha,
                    Equivalence* result) {
  std::map<std::string, const TargetMeasure*> by_name;
  for (const TargetMeasure& t : targets_b) by_name[t.name] = &t;
  for (const TargetMeasure& ta : targets_a) {
    const auto it = by_name.find(ta.name);
    if (it == by_name.end()) continue;
    const TargetDifference t = CompareTarget(ta, *it->second, alpha);
    result->targets_tested += t.tested ? 1 : 0;
    result->targets_differing += t.differs ? 1 : 0;
    result->targets.push_back(t);
  }
  result->targets_p_at_least =
      BinomialAtLeast(result->targets_tested, alpha, result->targets_differing);
}

// The verdict: each view's p-value against alpha / views (Bonferroni).
void JudgeViews(double alpha, Equivalence* result) {
  result->views = result->targets_tested > 0 ? 4 : 3;
  const double level = alpha / result->views;
  result->cells_beyond_chance = result->differing.p_at_least <= level;
  result->shift_differs = result->shift.p_value <= level;
  result->score_differs = result->score.p_value <= level;
  result->targets_beyond_chance = result->targets_tested > 0 && result->targets_p_at_least <= level;
  result->same = !result->cells_beyond_chance && !result->shift_differs && !result->score_differs &&
                 !result->targets_beyond_chance;
}

}  // namespace

bool CompareArms(const std::vector<MapCell>& cells, const std::vector<ArmCounts>& a,
                 const std::vector<ArmCounts>& b, const std::vector<TargetMeasure>& targets_a,
                 const std::vector<TargetMeasure>& targets_b, const EquivalenceOptions& options,
                 Equivalence* result, std::string* error) {
  if (std::string why = CheckArms(cells, a, b, options); !why.empty()) {
    *error = why;
    return false;
  }
  *result = Equivalence();
  CompareCells(cells, a, b, options.alpha, result);
  ScoreArms(options, result);
  CompareTargets(targets_a, targets_b, options.alpha, result);
  JudgeViews(options.alpha, result);
  return true;
}

}  // namespace ssc
