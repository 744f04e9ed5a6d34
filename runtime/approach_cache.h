// The shared approach: trials of a study that land and start the same way simulate that once.
//
// Every disk trial first descends onto the object until the F/T reads the start-up force, then
// moves to the start point (runtime/trial.h: kApproach, kMoveToStart): about a quarter of the
// published grid's simulated time, identical for every P_ref, beta, step and seed, because
// nothing in those phases reads the pressure sensor or the control law. The first trial with a
// given approach (ApproachKeyOf) runs it and publishes its state at the start of following: its
// mjData and the controller's FollowStart. Later trials with the same approach start from a copy
// of that mjData, with the pressure sensor's noise re-derived for their own seed (the noise is
// counter-based: plugin/pneumatics/sensor_chain.h), and follow from there. Their rows are those
// of a run from scratch to the bit (tests/runtime/shared_approach_test.sh compares whole sweeps).
//
// A trial runs from scratch instead (counted as `unshared`) when its model has a plugin other
// than the one pressure sensor, or a MuJoCo callback other than mjcb_control is installed (either
// could feed the seed-dependent pressures back into the physics), or its controller reads the
// sensors before following (Controller::ObservesBeforeFollowing: its readings are its seed's).
#ifndef SSC_RUNTIME_APPROACH_CACHE_H_
#define SSC_RUNTIME_APPROACH_CACHE_H_

#include <mujoco/mujoco.h>

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "runtime/mujoco_model.h"
#include "runtime/trial.h"

namespace ssc {

// Every TrialConfig field the approach and the move read (bit patterns): the servo's smoothing,
// the approach force and speeds, the landing and start points, the approach's depth limit, the
// lip shear effect (advanced during the move) and the log period. Not in it: the law, the
// thresholds, the control period, the timeout, the seed, the loop timing and chamber effects and
// the goal, which only following reads. A new TrialConfig field that the approach reads must
// be added here.
using ApproachKey = std::array<std::uint64_t, 15>;
ApproachKey ApproachKeyOf(const TrialConfig& c);

// Why trials on `m` cannot share their approach ("" when they can).
std::string ApproachUnshareableReason(const mjModel* m);

// Whether `trial` may start from (or publish) a shared approach now, given that its model's
// reason above is empty: no MuJoCo callback besides mjcb_control that could read the pressures
// into the physics, and a controller that does not read the approach (it needs its own seed's
// readings).
bool TrialMayShareApproach(const ContourTrial& trial);

// The follow starts of one model, shared by the threads of a study; built once per approach.
class ApproachCache {
 public:
  explicit ApproachCache(const mjModel* m);
  ApproachCache(const ApproachCache&) = delete;
  ApproachCache& operator=(const ApproachCache&) = delete;

  const mjModel* model() const { return m_; }
  // How the trials started: approaches simulated (and published), trials resumed from a
  // published one, trials run from scratch because sharing is impossible (see above).
  struct Counts {
    int simulated = 0, resumed = 0, unshared = 0;
  };
  Counts counts() const;
  // "" or why this model's trials run from scratch.
  const std::string& unshareable_reason() const { return unshareable_; }

 private:
  friend TrialResult RunTrialShared(const mjModel* m, const TrialConfig& config,
                                    ApproachCache* cache, std::string* error);
  struct Entry {
    DataPtr data;
    FollowStart start;
  };
  const Entry* Find(const ApproachKey& key) const;
  // Publishes a copy of `d` unless the key has an entry already.
  void Offer(const ApproachKey& key, const mjData* d, const FollowStart& start);
  void Count(int Counts::*which);

  const mjModel* m_;
  std::string unshareable_;
  mutable std::mutex mutex_;
  std::map<ApproachKey, std::unique_ptr<Entry>> entries_;
  Counts counts_;
};

// RunTrial (no log) through the cache: from a published follow start when there is one for this
// approach, else from scratch (publishing its follow start). Without a cache, or a cache of
// another model: RunTrial.
TrialResult RunTrialShared(const mjModel* m, const TrialConfig& config, ApproachCache* cache,
                           std::string* error);

}  // namespace ssc

#endif  // SSC_RUNTIME_APPROACH_CACHE_H_
