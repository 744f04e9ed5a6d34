#include "studies/map_ceiling.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <nlopt.hpp>

namespace ssc {
namespace {

// A class probability as a sum of coef * p^i (1-p)^j.
struct Term {
  double coef;
  int i, j;
};
// Built from the class of each k of 3 (ClassOfSuccesses, the classes' one home): the binomial
// terms C(3, k) p^k (1-p)^(3-k) of the k that fall in class c.
std::vector<Term> ClassTerms(MapClass c) {
  constexpr double kChoose[4] = {1, 3, 3, 1};
  std::vector<Term> terms;
  for (int k = 0; k <= 3; ++k) {
    if (ClassOfSuccesses(k) == c) terms.push_back({kChoose[k], k, 3 - k});
  }
  return terms;
}

double LogBeta(double a, double b) { return std::lgamma(a) + std::lgamma(b) - std::lgamma(a + b); }

// E[sum of terms] under Beta(a, b): E[p^i (1-p)^j] = B(a+i, b+j) / B(a, b).
double Expectation(const std::vector<Term>& terms, const BetaPrior& prior) {
  const double base = LogBeta(prior.a, prior.b);
  double sum = 0;
  for (const Term& t : terms)
    sum += t.coef * std::exp(LogBeta(prior.a + t.i, prior.b + t.j) - base);
  return sum;
}

std::vector<Term> Product(const std::vector<Term>& x, const std::vector<Term>& y) {
  std::vector<Term> out;
  for (const Term& s : x) {
    for (const Term& t : y) out.push_back({s.coef * t.coef, s.i + t.i, s.j + t.j});
  }
  return out;
}

// sum_c P_p(c) P_q(c): the expected agreement of rate q with a fresh draw at rate p.
double AgreementWithDraw(double p, double q) {
  double sum = 0;
  for (MapClass c : {MapClass::kThreeOfThree, MapClass::kTwoOfThree, MapClass::kAtMostOne}) {
    sum += ClassProbability(c, p) * ClassProbability(c, q);
  }
  return sum;
}

}  // namespace

double PriorClassProbability(MapClass c, const BetaPrior& prior) {
  return Expectation(ClassTerms(c), prior);
}

double RerunAgreement(MapClass c, const BetaPrior& prior) {
  const std::vector<Term> terms = ClassTerms(c);
  return Expectation(Product(terms, terms), prior) / Expectation(terms, prior);
}

double OracleRate(double p) {
  p = std::clamp(p, 0.0, 1.0);
  // f(q) = C + (A - C) q^3 + 3 (B - C) q^2 (1 - q); f'(q) = 3q [(A - 3B + 2C) q + 2 (B - C)].
  const double a = ClassProbability(MapClass::kThreeOfThree, p);
  const double b = ClassProbability(MapClass::kTwoOfThree, p);
  const double c = ClassProbability(MapClass::kAtMostOne, p);
  double best_q = 0, best = AgreementWithDraw(p, 0);
  const auto consider = [&](double q) {
    const double f = AgreementWithDraw(p, q);
    if (f > best) best = f, best_q = q;
  };
  consider(1);
  const double denom = a - 3 * b + 2 * c;
  if (denom != 0) {
    const double q = -2 * (b - c) / denom;
    if (q > 0 && q < 1) consider(q);
  }
  return best_q;
}

double OracleAgreement(MapClass c, const BetaPrior& prior) {
  // p = sin^2(theta): the prior's density in theta is 2 sin^(2a-1) cos^(2b-1), finite for
  // a, b >= 0.5. Weights in logs so that Beta(1000, 1000) does not underflow.
  constexpr int kNodes = 4000;
  const double h = 0.5 * M_PI / kNodes;
  std::vector<double> log_w(kNodes), p(kNodes);
  double max_log = -INFINITY;
  for (int k = 0; k < kNodes; ++k) {
    const double theta = (k + 0.5) * h, s = std::sin(theta), co = std::cos(theta);
    p[k] = s * s;
    log_w[k] = (2 * prior.a - 1) * std::log(s) + (2 * prior.b - 1) * std::log(co);
    max_log = std::max(max_log, log_w[k]);
  }
  double num = 0, den = 0;
  for (int k = 0; k < kNodes; ++k) {
    const double w = std::exp(log_w[k] - max_log) * ClassProbability(c, p[k]);
    den += w;
    num += w * ClassProbability(c, OracleRate(p[k]));
  }
  return den > 0 ? num / den : 0;
}

bool FitClassPrior(const std::array<int, 3>& counts, BetaPrior* prior, std::string* error) {
  if (counts[0] < 0 || counts[1] < 0 || counts[2] < 0 || counts[0] + counts[1] + counts[2] == 0) {
    *error = "the map's class counts must be non-negative and not all zero";
    return false;
  }
  struct Data {
    std::array<int, 3> n;
  } data{counts};
  const auto nll = [](const std::vector<double>& x, std::vector<double>&, void* d) {
    const auto& n = static_cast<Data*>(d)->n;
    const BetaPrior pr{std::exp(x[0]), std::exp(x[1])};
    const MapClass classes[3] = {MapClass::kThreeOfThree, MapClass::kTwoOfThree,
                                 MapClass::kAtMostOne};
    double sum = 0;
    for (int c = 0; c < 3; ++c) {
      if (n[c] > 0) sum -= n[c] * std::log(std::max(PriorClassProbability(classes[c], pr), 1e-300));
    }
    return sum;
  };
  nlopt::opt opt(nlopt::LN_SBPLX, 2);
  opt.set_lower_bounds({std::log(kMinBetaPrior), std::log(kMinBetaPrior)});
  opt.set_upper_bounds({std::log(kMaxBetaPrior), std::log(kMaxBetaPrior)});
  opt.set_min_objective(nll, &data);
  opt.set_xtol_abs(1e-9);
  opt.set_maxeval(4000);
  std::vector<double> x = {0, 0};
  double value = 0;
  try {
    opt.optimize(x, value);
  } catch (const std::exception& e) {
    *error = std::string("fitting the class prior: ") + e.what();
    return false;
  }
  *prior = {std::exp(x[0]), std::exp(x[1])};
  return true;
}

double ProbabilityAtLeast(const std::vector<double>& probabilities, int k) {
  if (k <= 0) return 1;
  std::vector<double> dist(probabilities.size() + 1, 0.0);  // dist[m] = P(m events so far)
  dist[0] = 1;
  for (std::size_t i = 0; i < probabilities.size(); ++i) {
    const double q = std::clamp(probabilities[i], 0.0, 1.0);
    for (std::size_t m = i + 1; m > 0; --m) dist[m] = dist[m] * (1 - q) + dist[m - 1] * q;
    dist[0] *= 1 - q;
  }
  double sum = 0;
  for (std::size_t m = static_cast<std::size_t>(k); m < dist.size(); ++m) sum += dist[m];
  return sum;
}

namespace {

// The fewest matching cells that reach the goal.
int GoalCells(double goal, std::size_t cells) {
  return static_cast<int>(std::ceil(goal * static_cast<double>(cells) - 1e-9));
}

// The surface's features at each cell, beta and log10(P_ref) standardised over the map.
std::vector<std::array<double, 6>> SurfaceFeatures(const std::vector<MapCell>& cells) {
  const double n = static_cast<double>(cells.size());
  double mb = 0, ml = 0, sb = 0, sl = 0;
  for (const MapCell& c : cells) mb += c.beta / n, ml += std::log10(c.pref_pa) / n;
  for (const MapCell& c : cells) {
    sb += (c.beta - mb) * (c.beta - mb) / n;
    sl += (std::log10(c.pref_pa) - ml) * (std::log10(c.pref_pa) - ml) / n;
  }
  sb = std::sqrt(sb), sl = std::sqrt(sl);
  std::vector<std::array<double, 6>> x;
  for (const MapCell& c : cells) {
    const double b = sb > 0 ? (c.beta - mb) / sb : 0;
    const double l = sl > 0 ? (std::log10(c.pref_pa) - ml) / sl : 0;
    x.push_back({1, b, l, b * b, l * l, b * l});
  }
  return x;
}

double Logistic(const std::array<double, 6>& w, const std::array<double, 6>& x) {
  double z = 0;
  for (int k = 0; k < 6; ++k) z += w[k] * x[k];
  return 1 / (1 + std::exp(-z));
}

struct SurfaceData {
  const std::vector<std::array<double, 6>>* x;
  const std::vector<MapCell>* cells;
  int left_out;  // -1: none
};

double SurfaceNll(const std::vector<double>& w, std::vector<double>&, void* d) {
  const auto* data = static_cast<SurfaceData*>(d);
  std::array<double, 6> weights{};
  std::copy(w.begin(), w.end(), weights.begin());
  double sum = 0;
  for (std::size_t i = 0; i < data->cells->size(); ++i) {
    if (static_cast<int>(i) == data->left_out) continue;
    const double p = Logistic(weights, (*data->x)[i]);
    sum -= std::log(std::max(ClassProbability((*data->cells)[i].published, p), 1e-12));
  }
  return sum;
}

// Sbplx from `start`, then once more from where it stopped (a restart resizes the simplex).
std::array<double, 6> FitSurface(SurfaceData* data, const std::array<double, 6>& start,
                                 double* nll) {
  std::vector<double> w(start.begin(), start.end());
  for (int pass = 0; pass < 2; ++pass) {
    nlopt::opt opt(nlopt::LN_SBPLX, 6);
    opt.set_lower_bounds(std::vector<double>(6, -30.0));
    opt.set_upper_bounds(std::vector<double>(6, 30.0));
    opt.set_min_objective(SurfaceNll, data);
    opt.set_xtol_abs(1e-7);
    opt.set_maxeval(20000);
    try {
      opt.optimize(w, *nll);
    } catch (const std::exception&) {
      // A roundoff stop keeps the best point, which w holds.
      std::vector<double> unused;
      *nll = SurfaceNll(w, unused, data);
    }
  }
  std::array<double, 6> out{};
  std::copy(w.begin(), w.end(), out.begin());
  return out;
}

}  // namespace

std::vector<double> SurfaceRates(const std::vector<MapCell>& cells,
                                 const std::array<double, 6>& weights) {
  std::vector<double> p;
  for (const auto& x : SurfaceFeatures(cells)) p.push_back(Logistic(weights, x));
  return p;
}

SurfaceCeiling FitSurfaceCeiling(const std::vector<MapCell>& cells, double class_match_goal) {
  SurfaceCeiling s;
  std::vector<double> betas, prefs;
  for (const MapCell& c : cells) betas.push_back(c.beta), prefs.push_back(c.pref_pa);
  std::sort(betas.begin(), betas.end());
  std::sort(prefs.begin(), prefs.end());
  if (cells.size() < 8 || betas.front() == betas.back() || prefs.front() == prefs.back()) {
    return s;
  }
  const auto x = SurfaceFeatures(cells);
  SurfaceData data{&x, &cells, -1};
  s.weights = FitSurface(&data, {}, &s.negative_log_likelihood);
  s.fitted = true;
  const double n = static_cast<double>(cells.size());
  std::vector<double> rerun, oracle;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const double p = Logistic(s.weights, x[i]);
    rerun.push_back(ClassProbability(cells[i].published, p));
    oracle.push_back(ClassProbability(cells[i].published, OracleRate(p)));
    s.rerun_agreement += rerun.back() / n;
    s.oracle_agreement += oracle.back() / n;
    SurfaceData others{&x, &cells, static_cast<int>(i)};
    double nll = 0;
    const auto w = FitSurface(&others, s.weights, &nll);
    s.loo_agreement += ClassProbability(cells[i].published, Logistic(w, x[i])) / n;
  }
  s.rerun_reaches_goal = ProbabilityAtLeast(rerun, GoalCells(class_match_goal, cells.size()));
  s.oracle_reaches_goal = ProbabilityAtLeast(oracle, GoalCells(class_match_goal, cells.size()));
  return s;
}

std::vector<double> SurfaceRatesOfMap(const std::vector<MapCell>& cells,
                                      const MapCeilings& ceilings) {
  std::vector<double> rates(cells.size(), std::numeric_limits<double>::quiet_NaN());
  for (const SurfaceCeiling& s : ceilings.surfaces) {
    if (!s.fitted) continue;
    std::vector<MapCell> of_step;
    std::vector<std::size_t> index;
    for (std::size_t i = 0; i < cells.size(); ++i) {
      if (cells[i].step_mm == s.step_mm) of_step.push_back(cells[i]), index.push_back(i);
    }
    const std::vector<double> p = SurfaceRates(of_step, s.weights);
    for (std::size_t k = 0; k < p.size(); ++k) rates[index[k]] = p[k];
  }
  return rates;
}

bool ComputeMapCeilings(const std::vector<MapCell>& cells, double class_match_goal,
                        MapCeilings* ceilings, std::string* error) {
  if (cells.empty()) {
    *error = "the map has no cells";
    return false;
  }
  std::array<int, 3> counts{0, 0, 0};
  for (const MapCell& cell : cells) ++counts[static_cast<int>(cell.published)];
  BetaPrior fitted;
  if (!FitClassPrior(counts, &fitted, error)) return false;
  ceilings->priors.clear();
  ceilings->surfaces.clear();
  std::vector<double> steps;
  for (const MapCell& cell : cells) {
    if (std::find(steps.begin(), steps.end(), cell.step_mm) == steps.end()) {
      steps.push_back(cell.step_mm);
    }
  }
  for (double step : steps) {
    std::vector<MapCell> of_step;
    for (const MapCell& cell : cells) {
      if (cell.step_mm == step) of_step.push_back(cell);
    }
    ceilings->surfaces.push_back(FitSurfaceCeiling(of_step, class_match_goal));
    ceilings->surfaces.back().step_mm = step;
  }
  const std::pair<const char*, BetaPrior> priors[] = {
      {"fitted to the map's classes", fitted}, {"uniform", {1, 1}}, {"Jeffreys", {0.5, 0.5}}};
  const int goal_cells = GoalCells(class_match_goal, cells.size());
  for (const auto& [name, prior] : priors) {
    MapCeiling ceiling;
    ceiling.prior_name = name;
    ceiling.prior = prior;
    // One integral per class, not per cell.
    std::array<double, 3> rerun_of{}, oracle_of{};
    for (MapClass c : {MapClass::kThreeOfThree, MapClass::kTwoOfThree, MapClass::kAtMostOne}) {
      rerun_of[static_cast<int>(c)] = RerunAgreement(c, prior);
      oracle_of[static_cast<int>(c)] = OracleAgreement(c, prior);
    }
    std::vector<double> rerun, oracle;
    for (const MapCell& cell : cells) {
      rerun.push_back(rerun_of[static_cast<int>(cell.published)]);
      oracle.push_back(oracle_of[static_cast<int>(cell.published)]);
      ceiling.rerun_agreement += rerun.back() / static_cast<double>(cells.size());
      ceiling.oracle_agreement += oracle.back() / static_cast<double>(cells.size());
    }
    ceiling.rerun_reaches_goal = ProbabilityAtLeast(rerun, goal_cells);
    ceiling.oracle_reaches_goal = ProbabilityAtLeast(oracle, goal_cells);
    ceilings->priors.push_back(ceiling);
  }
  return true;
}

}  // namespace ssc
