#include "apps/ssc/cli.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace ssc::cli {

Parser::Parser(std::string command, std::string summary, std::vector<Option> options)
    : command_(std::move(command)), summary_(std::move(summary)), options_(std::move(options)) {
  options_.push_back({"help", "", "print this help", true});
  for (const Option& o : options_) {
    if (!o.is_flag) values_[o.name] = o.def;
  }
}

std::string Parser::Help() const {
  std::ostringstream os;
  os << "usage: ssc " << command_ << " [options]\n\n" << summary_ << "\n\noptions:\n";
  for (const Option& o : options_) {
    std::string left = "  --" + o.name + (o.is_flag ? "" : " VALUE");
    os << left;
    for (size_t i = left.size(); i < 28; ++i) os << ' ';
    os << o.help;
    if (!o.is_flag && !o.def.empty()) os << " (default: " << o.def << ")";
    os << "\n";
  }
  return os.str();
}

bool Parser::Parse(int argc, char** argv) {
  for (int i = 0; i < argc; ++i) {
    std::string arg = argv[i];
    if (arg.rfind("--", 0) != 0) {
      positional_.push_back(arg);
      continue;
    }
    std::string name = arg.substr(2);
    std::string value;
    bool has_value = false;
    if (auto eq = name.find('='); eq != std::string::npos) {
      value = name.substr(eq + 1);
      name = name.substr(0, eq);
      has_value = true;
    }
    const Option* opt = nullptr;
    for (const Option& o : options_) {
      if (o.name == name) opt = &o;
    }
    if (opt == nullptr) {
      error_ = "ssc " + command_ + ": unknown option --" + name + " (see ssc " + command_ +
               " --help)";
      return false;
    }
    if (opt->is_flag) {
      if (name == "help") {
        help_ = true;
        std::fputs(Help().c_str(), stdout);
        return false;
      }
      values_[name] = "1";
      continue;
    }
    if (!has_value) {
      if (i + 1 >= argc) {
        error_ = "ssc " + command_ + ": option --" + name + " needs a value";
        return false;
      }
      value = argv[++i];
    }
    values_[name] = value;
  }
  return true;
}

std::string Parser::Get(const std::string& name) const {
  auto it = values_.find(name);
  return it == values_.end() ? "" : it->second;
}

bool Parser::Flag(const std::string& name) const { return Get(name) == "1"; }

bool Parser::GetDouble(const std::string& name, double* out) {
  const std::string v = Get(name);
  char* end = nullptr;
  const double x = std::strtod(v.c_str(), &end);
  if (v.empty() || *end != '\0' || !std::isfinite(x)) {
    error_ = "ssc " + command_ + ": --" + name + " expects a finite number, got '" + v + "'";
    return false;
  }
  *out = x;
  return true;
}

bool Parser::GetInt(const std::string& name, long* out) {
  const std::string v = Get(name);
  char* end = nullptr;
  const long x = std::strtol(v.c_str(), &end, 10);
  if (v.empty() || *end != '\0') {
    error_ = "ssc " + command_ + ": --" + name + " expects a whole number, got '" + v + "'";
    return false;
  }
  *out = x;
  return true;
}

bool Parser::GetDoubleList(const std::string& name, std::vector<double>* out) {
  out->clear();
  std::stringstream ss(Get(name));
  std::string item;
  while (std::getline(ss, item, ',')) {
    char* end = nullptr;
    const double x = std::strtod(item.c_str(), &end);
    if (item.empty() || *end != '\0' || !std::isfinite(x)) {
      error_ = "ssc " + command_ + ": --" + name +
               " expects comma-separated finite numbers, got '" + Get(name) + "'";
      return false;
    }
    out->push_back(x);
  }
  if (out->empty()) {
    error_ = "ssc " + command_ + ": --" + name + " is empty";
    return false;
  }
  return true;
}

}  // namespace ssc::cli
