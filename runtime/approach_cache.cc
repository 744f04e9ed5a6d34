#include "runtime/approach_cache.h"

#include <chrono>
#include <cstring>

#include "plugin/chamber_pressure_config.h"

namespace ssc {
namespace {

// A new field in these structs must be judged for the key (ApproachKeyOf).
static_assert(sizeof(ServoParams) == 3 * sizeof(double), "ServoParams changed: see ApproachKeyOf");
static_assert(sizeof(LipShearParams) == 3 * sizeof(double),
              "LipShearParams changed: see ApproachKeyOf");

std::uint64_t Bits(double v) {
  std::uint64_t b = 0;
  std::memcpy(&b, &v, sizeof(b));
  return b;
}

}  // namespace

ApproachKey ApproachKeyOf(const TrialConfig& c) {
  const TrialTarget& t = c.target;
  return {Bits(c.servo.smoothing_s),
          Bits(c.servo.max_speed_m_s),
          Bits(c.servo.damping),
          Bits(c.approach_force_n),
          Bits(c.approach_speed_m_s),
          Bits(c.move_speed_m_s),
          Bits(t.approach[0]),
          Bits(t.approach[1]),
          Bits(t.start[0]),
          Bits(t.start[1]),
          Bits(t.surface_top_z_m),
          Bits(c.effects.lip.slip_mm),
          Bits(c.effects.lip.tilt_decades),
          Bits(c.effects.lip.peel_decades),
          Bits(c.log_period_s)};
}

std::string ApproachUnshareableReason(const mjModel* m) {
  int slot = -1;
  const mjpPlugin* sensor = mjp_getPlugin(kChamberPressurePluginName, &slot);
  if (sensor == nullptr) return "the pressure plugin is not registered";
  if (m->nplugin != 1 || m->plugin[0] != slot) {
    return "the model has plugins other than one " + std::string(kChamberPressurePluginName) +
           " (their state is not known to be the same for every seed)";
  }
  return "";
}

ApproachCache::ApproachCache(const mjModel* m)
    : m_(m), unshareable_(ApproachUnshareableReason(m)) {}

ApproachCache::Counts ApproachCache::counts() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return counts_;
}

void ApproachCache::Count(int Counts::*which) {
  std::lock_guard<std::mutex> lock(mutex_);
  ++(counts_.*which);
}

const ApproachCache::Entry* ApproachCache::Find(const ApproachKey& key) const {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto it = entries_.find(key);
  return it == entries_.end() ? nullptr : it->second.get();
}

void ApproachCache::Offer(const ApproachKey& key, const mjData* d, const FollowStart& start) {
  if (Find(key) != nullptr) return;
  std::string error;
  auto entry = std::make_unique<Entry>();
  entry->data = MakeData(m_, &error);
  if (!entry->data) return;  // the trial itself runs on; later trials simulate their approach
  mj_copyData(entry->data.get(), m_, d);
  entry->start = start;
  std::lock_guard<std::mutex> lock(mutex_);
  entries_.emplace(key, std::move(entry));  // a concurrent first publisher keeps its entry
}

bool TrialMayShareApproach(const ContourTrial& trial) {
  // Callbacks that could read the pressures into the physics (mjcb_control is the trials').
  const bool callbacks = mjcb_passive || mjcb_act_dyn || mjcb_act_gain || mjcb_act_bias ||
                         mjcb_sensor || mjcb_contactfilter;
  return !callbacks && !trial.ControllerObservesApproach();
}

TrialResult RunTrialShared(const mjModel* m, const TrialConfig& config, ApproachCache* cache,
                           std::string* error) {
  if (cache == nullptr || cache->model() != m) return RunTrial(m, config, false, error);
  DataPtr data;
  TrialResult failed;
  auto trial = CreateTrialWithData(m, config, false, &data, &failed, error);
  if (!trial) return failed;
  trial->SetResultOnly(true);  // the data dies here (the cache copies it before Run)
  if (!cache->unshareable_reason().empty() || !TrialMayShareApproach(*trial)) {
    cache->Count(&ApproachCache::Counts::unshared);
    return trial->Run();
  }
  const auto t0 = std::chrono::steady_clock::now();
  const ApproachKey key = ApproachKeyOf(config);
  if (const ApproachCache::Entry* e = cache->Find(key)) {
    trial->ResumeAtFollowStart(e->data.get(), e->start);
    cache->Count(&ApproachCache::Counts::resumed);
  } else {
    if (trial->RunToFollowStart()) cache->Offer(key, data.get(), trial->SaveFollowStart());
    cache->Count(&ApproachCache::Counts::simulated);
  }
  TrialResult r = trial->Run();
  r.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

}  // namespace ssc
