// Scoring the twin against a published success map, as pure statistics (no MuJoCo).
//
// The paper ran 3 trials per cell and reports a cell's class: 3 of 3, 2 of 3 or at most 1 of 3.
// Scores (docs/fidelity.md):
//   class match          the twin's class from its first 3 trials equals the published class;
//   expected agreement   P(Binomial(3, p) lands in the published class), p the twin's success
//                        rate over N seeds, averaged over the cells;
//   opposite cells       published 3/3 where p <= 1/3, or published <= 1/3 where p >= 0.9.
#ifndef SSC_STUDIES_SCORES_MAP_SCORES_H_
#define SSC_STUDIES_SCORES_MAP_SCORES_H_

#include <array>
#include <limits>
#include <string>
#include <vector>

namespace ssc {

enum class MapClass { kThreeOfThree, kTwoOfThree, kAtMostOne };

// "3", "2", "<=1".
const char* MapClassName(MapClass c);
// Parses "3", "2" or "<=1"; false otherwise.
bool ParseMapClass(const std::string& text, MapClass* c);
// The class of k successes in 3 trials (k in [0, 3]).
MapClass ClassOfSuccesses(int successes_of_3);
// P(Binomial(3, p) in class c), exact.
double ClassProbability(MapClass c, double p_success);

struct MapCell {
  double step_mm = 0, beta = 0, pref_pa = 0;
  MapClass published = MapClass::kThreeOfThree;
};

// Outcomes of one cell's trials in repeat order (repeat 0, 1, ...).
// One trial of a map cell, in memory (for fits: no disk).
struct MapTrial {
  std::string outcome;
  double dr_mm = 0, sigma_r_mm = 0, s_c = 0;
};

struct CellTrials {
  std::vector<std::string> outcomes;  // "success", "failure_I", ... (OutcomeName)
};

struct CellScore {
  MapCell cell;
  int successes_of_3 = 0;  // among repeats 0..2
  MapClass twin_class = MapClass::kAtMostOne;
  bool class_match = false;
  int successes = 0, trials = 0;  // over all N repeats
  double p_success = 0;           // successes / trials
  std::array<double, 2> p_interval{};
  double expected_agreement = 0;  // P(3 twin trials land in the published class)
  bool opposite = false;
  int failure_off_edge = 0, failure_grasp = 0, timeout = 0, unstable = 0, lost_edge = 0;
  // The most common failure (its OutcomeName: "failure_I", "failure_II", "timeout",
  // "unstable", "lost_edge"; "" if none).
  std::string main_failure;
  // The smooth surface's success rate here (studies/map_ceiling.h), NaN when none was fitted.
  double surface_p = std::numeric_limits<double>::quiet_NaN();
};

struct MapScore {
  std::vector<CellScore> cells;
  int cells_scored = 0;
  double class_match = 0;                      // fraction of cells
  double expected_agreement = 0;               // mean over cells
  std::array<double, 2> agreement_interval{};  // 95 %, from the seeds (AgreementInterval)
  int opposite = 0;
  // The fit's map term: mean over cells of -log(max(P(class), floor)), floor 0.01.
  double log_loss = 0;
};

// Scores every cell; a cell needs at least 3 trials (false + *error naming it otherwise).
bool ScoreMap(const std::vector<MapCell>& cells, const std::vector<CellTrials>& trials,
              MapScore* score, std::string* error);

// The 95 % interval of the expected agreement that comes from the twin's finite seeds: each
// cell's rate drawn from its posterior Beta(k + 1/2, n - k + 1/2) (Jeffreys), the agreement
// recomputed, `draws` times; the 2.5 and 97.5 percentiles. Deterministic for a given seed.
std::array<double, 2> AgreementInterval(const std::vector<CellScore>& cells, int draws = 4000,
                                        unsigned long long seed = 1);

// "" when the plug-in expected agreement lies within its interval; else a note saying why it
// does not (the plug-in takes a cell at N/N or 0/N as a certainty, the seeds' posterior does
// not; at 3 seeds per cell on the published map it lands at or above the top), so a printed
// estimate outside its own interval is explained where it is printed.
std::string AgreementIntervalNote(const MapScore& score);

}  // namespace ssc

#endif  // SSC_STUDIES_SCORES_MAP_SCORES_H_
