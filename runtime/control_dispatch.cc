#include "runtime/control_dispatch.h"

#include <mutex>
#include <shared_mutex>
#include <unordered_map>

namespace ssc {
namespace {

std::shared_mutex& Mutex() {
  static std::shared_mutex mutex;
  return mutex;
}

std::unordered_map<const mjData*, ControlCallback*>& Registry() {
  static std::unordered_map<const mjData*, ControlCallback*> registry;
  return registry;
}

void Dispatch(const mjModel* m, mjData* d) {
  ControlCallback* callback = nullptr;
  {
    std::shared_lock<std::shared_mutex> lock(Mutex());
    auto it = Registry().find(d);
    if (it != Registry().end()) callback = it->second;
  }
  if (callback) callback->Control(m, d);
}

}  // namespace

bool RegisterControl(const mjData* d, ControlCallback* callback) {
  std::unique_lock<std::shared_mutex> lock(Mutex());
  if (mjcb_control != nullptr && mjcb_control != Dispatch) return false;
  mjcb_control = Dispatch;
  Registry()[d] = callback;
  return true;
}

void UnregisterControl(const mjData* d) {
  std::unique_lock<std::shared_mutex> lock(Mutex());
  Registry().erase(d);
}

}  // namespace ssc
