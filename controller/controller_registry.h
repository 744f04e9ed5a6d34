// The controllers a trial can run, by name, each with a key table for its parameters (unit,
// default, range, what it is): the one home of those facts for parsing, --help and docs. The
// published law is "published"; the others are listed in ControllerTypes()
// (controller_registry.cc).
//
// Every controller also gets the trial's ContourLawParams (P_ref, beta, dL, P_n, P_g, the follow
// side and dead band: the grid point of a sweep, the map cell of a validation), so the study
// options that vary the law vary any controller built on it.
#ifndef SSC_CONTROLLER_CONTROLLER_REGISTRY_H_
#define SSC_CONTROLLER_CONTROLLER_REGISTRY_H_

#include <functional>
#include <initializer_list>
#include <memory>
#include <string>
#include <vector>

#include "common/strict_number.h"
#include "controller/contour_law.h"
#include "controller/controller.h"

namespace ssc {

// What a controller is built with, besides its own parameters.
struct ControllerContext {
  ContourLawParams law;
  double control_period_s = 0.15;  // the host's nominal loop period, s
};

struct ControllerParamKey {
  std::string key, unit;
  double default_value = 0, min = 0, max = 0;
  std::string what;
  bool whole = false;  // whole numbers only: counts, and on/off switches (0 or 1)
};

// The values a key takes: [min, max], whole numbers only where the key is a count or a switch.
NumberRange KeyRange(const ControllerParamKey& k);

using ControllerValues = std::vector<double>;  // one per key, in key order
using ControllerFactory =
    std::function<std::unique_ptr<Controller>(const ControllerContext&, const ControllerValues&)>;

// A rule between two keys of a controller: the value of keys[lower] may not exceed that of
// keys[upper]. Rules are data, not code, so a search box can be checked against them exactly
// (studies/controller_tune.h) as well as a single set of values.
struct ControllerKeyOrder {
  size_t lower = 0, upper = 0;  // indices in the keys
};

struct ControllerType {
  std::string name, what;
  std::vector<ControllerParamKey> keys;
  ControllerFactory make;
  // The rules between keys (each value's own range is checked by the keys).
  std::vector<ControllerKeyOrder> orders;
};

// The rule as text: "step_min_mm <= step_max_mm".
std::string KeyOrderText(const ControllerType& type, const ControllerKeyOrder& order);
// "" when `values` (one per key of `type`) keep every rule between keys, else the first rule
// broken: "step_min_mm = 9 exceeds step_max_mm = 7.5 (mm; set both: step_min_mm <= step_max_mm)".
std::string CheckKeyOrders(const ControllerType& type, const ControllerValues& values);

// A parameter of controller parameters struct P: its key table row, with the default read from
// P{} (the struct's initialisers are the one home of the defaults).
template <typename P>
struct ParamField {
  const char* key;
  const char* unit;
  double min, max;
  const char* what;
  double P::*field;
  bool whole = false;  // a count or an on/off switch: whole numbers only
};

// A rule between two fields of P: the first may not exceed the second.
template <typename P>
struct ParamOrder {
  double P::*lower;
  double P::*upper;
};

// The ControllerType of a controller class C constructed as C(context, P); `orders` are the
// rules between its fields (each field of a rule must be one of `fields`).
template <typename C, typename P>
ControllerType MakeControllerType(const char* name, const char* what,
                                  std::initializer_list<ParamField<P>> fields,
                                  std::initializer_list<ParamOrder<P>> orders = {}) {
  ControllerType t;
  t.name = name;
  t.what = what;
  std::vector<double P::*> members;
  const P defaults{};
  for (const ParamField<P>& f : fields) {
    t.keys.push_back({f.key, f.unit, defaults.*(f.field), f.min, f.max, f.what, f.whole});
    members.push_back(f.field);
  }
  const auto params_of = [members](const ControllerValues& values) {
    P p{};
    for (size_t i = 0; i < members.size() && i < values.size(); ++i) p.*(members[i]) = values[i];
    return p;
  };
  t.make = [params_of](const ControllerContext& context, const ControllerValues& values) {
    return std::unique_ptr<Controller>(new C(context, params_of(values)));
  };
  const auto index_of = [&members](double P::*field) {
    size_t i = 0;
    while (i < members.size() && members[i] != field) ++i;
    return i;
  };
  for (const ParamOrder<P>& o : orders) t.orders.push_back({index_of(o.lower), index_of(o.upper)});
  return t;
}

// The registered controllers, "published" first.
const std::vector<ControllerType>& ControllerTypes();
const ControllerType* FindControllerType(const std::string& name);

// The controller a trial runs.
struct ControllerChoice {
  std::string name = "published";
  ControllerValues values;  // one per key of the type; empty = every default
  // A factory from outside the registry (a Python callable); `name` is then its label only.
  std::shared_ptr<const std::function<std::unique_ptr<Controller>(const ControllerContext&)>>
      custom;

  // The published law, as the trial runs it without a choice.
  bool IsPublished() const { return !custom && name == "published"; }
  // "" when the name is registered (or custom is set) and every value is within its key's range.
  std::string Validate() const;
  // "name" with no parameters, else "name:key=value,..." with every key (manifests, summaries).
  std::string Text() const;
  // Null when Validate() fails.
  std::unique_ptr<Controller> Make(const ControllerContext& context) const;
};

// key=value,... over `type`'s defaults onto *values (one per key, in key order).
bool ParseControllerValues(const ControllerType& type, const std::string& params,
                           ControllerValues* values, std::string* error);
// --controller NAME --controller-param key=value,...: the values over the type's defaults. Keys
// must be the type's, each at most once, values strict numbers within the key's range; the
// error names the key, the value and the range (or the registered names).
bool ParseControllerChoice(const std::string& name, const std::string& params,
                           ControllerChoice* choice, std::string* error);

// The registered names, ", "-separated.
std::string ControllerNames();
// One line per controller and per key (name, unit, default, range, what) for --help and docs.
std::string ControllerKeyTable();

}  // namespace ssc

#endif  // SSC_CONTROLLER_CONTROLLER_REGISTRY_H_
