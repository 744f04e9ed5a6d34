#include "studies/scores/map_scores.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>

#include "studies/statistics/intervals.h"
#include "trial/trial_outcome.h"

namespace ssc {

const char* MapClassName(MapClass c) {
  switch (c) {
    case MapClass::kThreeOfThree:
      return "3";
    case MapClass::kTwoOfThree:
      return "2";
    case MapClass::kAtMostOne:
      return "<=1";
  }
  return "?";
}

bool ParseMapClass(const std::string& text, MapClass* c) {
  if (text == "3") {
    *c = MapClass::kThreeOfThree;
  } else if (text == "2") {
    *c = MapClass::kTwoOfThree;
  } else if (text == "<=1") {
    *c = MapClass::kAtMostOne;
  } else {
    return false;
  }
  return true;
}

MapClass ClassOfSuccesses(int successes_of_3) {
  if (successes_of_3 >= 3) return MapClass::kThreeOfThree;
  if (successes_of_3 == 2) return MapClass::kTwoOfThree;
  return MapClass::kAtMostOne;
}

double ClassProbability(MapClass c, double p) {
  p = std::clamp(p, 0.0, 1.0);
  const double three = p * p * p, two = 3 * p * p * (1 - p);
  switch (c) {
    case MapClass::kThreeOfThree:
      return three;
    case MapClass::kTwoOfThree:
      return two;
    case MapClass::kAtMostOne:
      return std::max(0.0, 1.0 - three - two);
  }
  return 0;
}

bool ScoreMap(const std::vector<MapCell>& cells, const std::vector<CellTrials>& trials,
              MapScore* score, std::string* error) {
  if (cells.size() != trials.size()) {
    *error = "map scoring: cells and trial lists differ in length";
    return false;
  }
  *score = MapScore();
  double match = 0, agreement = 0, loss = 0;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const std::vector<std::string>& out = trials[i].outcomes;
    if (out.size() < 3) {
      std::ostringstream os;
      os << "map cell step " << cells[i].step_mm << " mm, beta " << cells[i].beta << ", P_ref "
         << cells[i].pref_pa << " Pa has " << out.size() << " trials; at least 3 are needed";
      *error = os.str();
      return false;
    }
    CellScore c;
    c.cell = cells[i];
    for (std::size_t r = 0; r < out.size(); ++r) {
      const bool ok = out[r] == OutcomeName(Outcome::kSuccess);
      if (r < 3 && ok) ++c.successes_of_3;
      c.successes += ok ? 1 : 0;
      if (out[r] == OutcomeName(Outcome::kFailureOffEdge)) ++c.failure_off_edge;
      if (out[r] == OutcomeName(Outcome::kFailureGrasp)) ++c.failure_grasp;
      if (out[r] == OutcomeName(Outcome::kTimeout)) ++c.timeout;
      if (out[r] == OutcomeName(Outcome::kUnstable)) ++c.unstable;
      if (out[r] == OutcomeName(Outcome::kLostEdge)) ++c.lost_edge;
    }
    c.trials = static_cast<int>(out.size());
    c.twin_class = ClassOfSuccesses(c.successes_of_3);
    c.class_match = c.twin_class == c.cell.published;
    c.p_success = static_cast<double>(c.successes) / c.trials;
    c.p_interval = WilsonInterval(c.successes, c.trials);
    c.expected_agreement = ClassProbability(c.cell.published, c.p_success);
    c.opposite =
        (c.cell.published == MapClass::kThreeOfThree && c.p_success <= 1.0 / 3.0 + 1e-12) ||
        (c.cell.published == MapClass::kAtMostOne && c.p_success >= 0.9 - 1e-12);
    const std::array<std::pair<int, const char*>, 5> modes = {
        {{c.failure_off_edge, OutcomeName(Outcome::kFailureOffEdge)},
         {c.failure_grasp, OutcomeName(Outcome::kFailureGrasp)},
         {c.timeout, OutcomeName(Outcome::kTimeout)},
         {c.unstable, OutcomeName(Outcome::kUnstable)},
         {c.lost_edge, OutcomeName(Outcome::kLostEdge)}}};
    int most = 0;
    for (const auto& [count, name] : modes) {
      if (count > most) {
        most = count;
        c.main_failure = name;
      }
    }
    match += c.class_match ? 1 : 0;
    agreement += c.expected_agreement;
    loss += -std::log(std::max(c.expected_agreement, 0.01));
    score->opposite += c.opposite ? 1 : 0;
    score->cells.push_back(c);
  }
  const double n = static_cast<double>(std::max<std::size_t>(1, cells.size()));
  score->cells_scored = static_cast<int>(cells.size());
  score->class_match = match / n;
  score->expected_agreement = agreement / n;
  score->log_loss = loss / n;
  score->agreement_interval = AgreementInterval(score->cells);
  return true;
}

std::array<double, 2> AgreementInterval(const std::vector<CellScore>& cells, int draws,
                                        unsigned long long seed) {
  if (cells.empty() || draws < 2) return {0, 0};
  std::mt19937_64 rng(seed);
  std::vector<double> agreement(static_cast<std::size_t>(draws), 0.0);
  const double n = static_cast<double>(cells.size());
  for (const CellScore& c : cells) {
    std::gamma_distribution<double> yes(c.successes + 0.5, 1.0);
    std::gamma_distribution<double> no(c.trials - c.successes + 0.5, 1.0);
    for (double& a : agreement) {
      const double x = yes(rng), y = no(rng);
      a += ClassProbability(c.cell.published, x / (x + y)) / n;
    }
  }
  std::sort(agreement.begin(), agreement.end());
  const auto at = [&](double q) {
    return agreement[static_cast<std::size_t>(std::lround(q * (draws - 1)))];
  };
  return {at(0.025), at(0.975)};
}

std::string AgreementIntervalNote(const MapScore& score) {
  const double a = score.expected_agreement;
  const std::array<double, 2>& i = score.agreement_interval;
  if (!(a > i[1]) && !(a < i[0])) return "";
  return std::string("the estimate lies ") + (a > i[1] ? "above" : "below") +
         " its interval: it takes a cell at N/N or 0/N successes as certain, the interval's "
         "posterior does not; more seeds per cell close the gap";
}

}  // namespace ssc
