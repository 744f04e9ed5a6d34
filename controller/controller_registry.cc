#include "controller/controller_registry.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "common/strict_number.h"
#include "controller/crimp_hop.h"
#include "controller/edge_track.h"
#include "controller/example_controller.h"
#include "controller/fast_following.h"
#include "controller/force_height.h"
#include "controller/published_controller.h"

namespace ssc {

const std::vector<ControllerType>& ControllerTypes() {
  // A new controller: its ControllerType here (the published law stays first: the default).
  static const std::vector<ControllerType> kTypes = {
      PublishedControllerType(),   FastFollowingControllerType(), EdgeTrackControllerType(),
      ForceHeightControllerType(), CrimpHopControllerType(),      ExampleControllerType()};
  return kTypes;
}

const ControllerType* FindControllerType(const std::string& name) {
  for (const ControllerType& t : ControllerTypes())
    if (t.name == name) return &t;
  return nullptr;
}

std::string ControllerNames() {
  std::string names;
  for (const ControllerType& t : ControllerTypes()) names += (names.empty() ? "" : ", ") + t.name;
  return names;
}

NumberRange KeyRange(const ControllerParamKey& k) {
  return k.whole ? NumberRange::Whole(k.min, k.max) : NumberRange::Closed(k.min, k.max);
}

std::string ControllerChoice::Validate() const {
  if (custom) return "";
  const ControllerType* type = FindControllerType(name);
  if (type == nullptr)
    return "unknown controller '" + name + "' (controllers: " + ControllerNames() + ")";
  if (values.empty()) return "";
  if (values.size() != type->keys.size()) {
    std::ostringstream os;
    os << "controller '" << name << "' takes " << type->keys.size() << " parameters, got "
       << values.size();
    return os.str();
  }
  for (size_t i = 0; i < values.size(); ++i) {
    const ControllerParamKey& k = type->keys[i];
    if (!KeyRange(k).Contains(values[i])) {
      std::ostringstream os;
      os << "controller " << name << ": " << k.key << " = " << values[i] << " is out of range "
         << KeyRange(k).ToString() << (k.unit == "1" ? "" : " " + k.unit);
      return os.str();
    }
  }
  if (std::string why = CheckKeyOrders(*type, values); !why.empty())
    return "controller " + name + ": " + why;
  return "";
}

std::string KeyOrderText(const ControllerType& type, const ControllerKeyOrder& order) {
  return type.keys[order.lower].key + " <= " + type.keys[order.upper].key;
}

std::string CheckKeyOrders(const ControllerType& type, const ControllerValues& values) {
  for (const ControllerKeyOrder& o : type.orders) {
    if (o.lower >= values.size() || o.upper >= values.size()) continue;
    if (values[o.lower] <= values[o.upper]) continue;
    const ControllerParamKey& lower = type.keys[o.lower];
    std::ostringstream os;
    os << lower.key << " = " << values[o.lower] << " exceeds " << type.keys[o.upper].key << " = "
       << values[o.upper] << " (" << (lower.unit.empty() ? "" : lower.unit + "; ")
       << "set both: " << KeyOrderText(type, o) << ")";
    return os.str();
  }
  return "";
}

std::string ControllerChoice::Text() const {
  const ControllerType* type = custom ? nullptr : FindControllerType(name);
  if (type == nullptr || type->keys.empty()) return name;
  std::string text = name + ":";
  for (size_t i = 0; i < type->keys.size(); ++i) {
    const double v = i < values.size() ? values[i] : type->keys[i].default_value;
    text += (i ? "," : "") + type->keys[i].key + "=" + FormatNumber(v);
  }
  return text;
}

std::unique_ptr<Controller> ControllerChoice::Make(const ControllerContext& context) const {
  if (custom) return (*custom)(context);
  if (!Validate().empty()) return nullptr;
  const ControllerType* type = FindControllerType(name);
  if (!values.empty()) return type->make(context, values);
  ControllerValues defaults;
  for (const ControllerParamKey& k : type->keys) defaults.push_back(k.default_value);
  return type->make(context, defaults);
}

bool ParseControllerValues(const ControllerType& type, const std::string& params,
                           ControllerValues* values, std::string* error) {
  const std::string& name = type.name;
  values->clear();
  for (const ControllerParamKey& k : type.keys) values->push_back(k.default_value);
  if (params.empty()) return true;
  if (type.keys.empty()) {
    *error = "controller '" + name + "' takes no parameters (got '" + params + "')";
    return false;
  }
  std::vector<bool> seen(type.keys.size(), false);
  std::size_t pos = 0;
  while (pos <= params.size()) {
    const std::size_t end = std::min(params.find(',', pos), params.size());
    const std::string item = params.substr(pos, end - pos);
    const std::size_t eq = item.find('=');
    if (item.empty() || eq == std::string::npos) {
      *error = "controller " + name + ": expected key=value, got '" + item + "'";
      return false;
    }
    const std::string key = item.substr(0, eq), value = item.substr(eq + 1);
    std::size_t i = 0;
    while (i < type.keys.size() && type.keys[i].key != key) ++i;
    if (i == type.keys.size()) {
      std::string keys;
      for (const ControllerParamKey& k : type.keys) keys += (keys.empty() ? "" : ", ") + k.key;
      *error = "controller " + name + ": unknown key '" + key + "' (keys: " + keys + ")";
      return false;
    }
    // A key given twice is a typo, not an override: which one was meant is unknowable.
    if (seen[i]) {
      *error = "controller " + name + ": " + key + " is given twice";
      return false;
    }
    seen[i] = true;
    const ControllerParamKey& k = type.keys[i];
    std::string why;
    if (!ParseNumber(value, KeyRange(k), &(*values)[i], &why)) {
      *error = "controller " + name + ": " + key + " = '" + value + "': " + why +
               (k.unit.empty() ? "" : " (" + k.unit + ")");
      return false;
    }
    pos = end + 1;
  }
  if (std::string why = CheckKeyOrders(type, *values); !why.empty()) {
    *error = "controller " + name + ": " + why;
    return false;
  }
  return true;
}

bool ParseControllerChoice(const std::string& name, const std::string& params,
                           ControllerChoice* choice, std::string* error) {
  const ControllerType* type = FindControllerType(name);
  if (type == nullptr) {
    *error = "unknown controller '" + name + "' (controllers: " + ControllerNames() + ")";
    return false;
  }
  ControllerValues values;
  if (!ParseControllerValues(*type, params, &values, error)) return false;
  choice->name = name;
  choice->values = std::move(values);
  choice->custom.reset();
  return true;
}

std::string ControllerKeyTable() {
  std::ostringstream os;
  for (const ControllerType& t : ControllerTypes()) {
    os << t.name << ": " << t.what << "\n";
    for (const ControllerParamKey& k : t.keys) {
      os << "  " << k.key << " = " << FormatNumber(k.default_value)
         << (k.unit.empty() || k.unit == "1" ? "" : " " + k.unit) << " in [" << FormatNumber(k.min)
         << ", " << FormatNumber(k.max) << "]" << (k.whole ? ", whole" : "") << ": " << k.what
         << "\n";
    }
  }
  return os.str();
}

}  // namespace ssc
