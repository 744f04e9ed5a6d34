#include "apps/ssc/cli.h"

#include <limits.h>
#include <mujoco/mujoco.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <system_error>
#include <vector>

#include "common/exit_codes.h"
#include "common/output_file.h"

#ifndef SSC_VERSION
#define SSC_VERSION "unknown"
#endif

namespace ssc::cli {
namespace fs = std::filesystem;

namespace {
int g_noted_exit_code = 0;
}  // namespace

void NoteInputError(const std::string& error) { NoteExitCode(InputErrorCode(error)); }
void NoteExitCode(int code) {
  if (g_noted_exit_code == 0) g_noted_exit_code = code;  // the first problem decides
}
int NotedExitCode() { return g_noted_exit_code; }

std::string VersionText() {
  return std::string("ssc ") + SSC_VERSION + " (MuJoCo " + mj_versionString() + ")";
}

namespace {

std::string Shown(const std::string& path) {
  constexpr size_t kMax = 80;  // a 4 kB path is cut in messages
  return "'" + (path.size() > kMax ? path.substr(0, kMax) + "..." : path) + "'";
}

}  // namespace

bool CheckOutputDir(const std::string& dir, std::string* error) {
  if (dir.empty()) {
    *error = "empty output directory";
    return false;
  }
  if (dir.size() >= PATH_MAX) {
    *error = Shown(dir) + " is longer than " + std::to_string(PATH_MAX - 1) + " bytes";
    return false;
  }
  const fs::path p(dir);
  for (const fs::path& part : p) {
    if (part.native().size() > NAME_MAX) {
      *error = Shown(dir) + ": the name " + Shown(part.native()) + " is longer than " +
               std::to_string(NAME_MAX) + " bytes";
      return false;
    }
  }
  // From the path itself up to its nearest existing ancestor, which must be a writable
  // directory; nothing is created here.
  std::error_code ec;
  fs::path cur = p;
  for (bool first = true;; first = false) {
    const fs::file_status st = fs::status(cur, ec);  // follows links
    if (fs::exists(st)) {
      if (!fs::is_directory(st)) {
        *error =
            first ? Shown(dir) + " exists and is not a directory"
                  : Shown(cur.string()) + " (on the path of " + Shown(dir) + ") is not a directory";
        return false;
      }
      break;
    }
    if (fs::is_symlink(fs::symlink_status(cur, ec))) {
      *error = Shown(cur.string()) + " is a symbolic link to nothing (a dangling link)";
      return false;
    }
    fs::path parent = cur.parent_path();
    if (parent.empty()) parent = ".";
    if (parent == cur) break;
    cur = parent;
  }
  if (access(cur.c_str(), W_OK | X_OK) != 0) {
    *error = cur == p
                 ? "directory " + Shown(dir) + " is not writable"
                 : "cannot create " + Shown(dir) + ": " + Shown(cur.string()) + " is not writable";
    return false;
  }
  return true;
}

bool CreateOutputDir(const std::string& dir, std::string* error) {
  if (!CheckOutputDir(dir, error)) return false;
  // Records the folders it creates, for RemoveStartedOutputs() (common/output_file.h).
  if (!CreateRecordedDirectories(dir, error)) return false;
  if (access(dir.c_str(), W_OK | X_OK) != 0) {
    *error = "directory " + Shown(dir) + " is not writable";
    return false;
  }
  return true;
}

namespace {

bool CheckFileName(const std::string& file, std::string* error) {
  std::error_code ec;
  const fs::path p(file);
  if (file.empty()) {
    *error = "empty file name";
    return false;
  }
  if (p.filename().empty() || p.filename() == "." || p.filename() == ".." ||
      fs::is_directory(p, ec)) {
    *error = Shown(file) + " is a directory, not a file name";
    return false;
  }
  if (fs::exists(p, ec) && !fs::is_regular_file(p, ec)) {
    *error = Shown(file) + " exists and is not a regular file";
    return false;
  }
  return true;
}

}  // namespace

bool CheckOutputFile(const std::string& file, std::string* error) {
  if (!CheckFileName(file, error)) return false;
  const fs::path parent = fs::path(file).parent_path();
  return CheckOutputDir(parent.empty() ? "." : parent.string(), error);
}

bool CreateOutputFileDir(const std::string& file, std::string* error) {
  if (!CheckFileName(file, error)) return false;
  const fs::path parent = fs::path(file).parent_path();
  return CreateOutputDir(parent.empty() ? "." : parent.string(), error);
}

Command::Command(std::string name, const std::string& summary)
    : name_(std::move(name)), app_(std::make_unique<CLI::App>(summary, "ssc " + name_)) {
  app_->set_version_flag("--version", VersionText());
  app_->option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::Throw);
  app_->get_formatter()->column_width(34);
}

Command::~Command() = default;

CLI::Option* Command::AddValue(const std::string& name, const std::string& help,
                               const std::string& type, const std::string& default_text) {
  texts_.emplace_back();
  CLI::Option* o = app_->add_option("--" + name, texts_.back(), help);
  o->type_name(type);
  if (!default_text.empty()) o->default_str(default_text);
  return o;
}

void Command::Number(const std::string& name, double* target, const std::string& help,
                     const std::string& unit, const NumberRange& range, bool show_default) {
  AddValue(name, help + (unit.empty() ? "" : ", " + unit) + "; " + range.ToString(),
           unit.empty() ? "NUMBER" : unit, show_default ? FormatNumber(*target) : "");
  std::string* text = &texts_.back();
  converters_.push_back([this, name, text, target, range, unit](std::string* error) {
    if (!Given(name)) return true;
    std::string e;
    if (!ParseNumber(*text, range, target, &e)) {
      // The range in the option's unit ("expected [0, 500] mm"), as the help shows it.
      *error = "--" + name + ": " + e + (unit.empty() ? "" : " " + unit);
      return false;
    }
    return true;
  });
}

void Command::Integer(const std::string& name, long* target, const std::string& help,
                      const NumberRange& range) {
  NumberRange whole = range;
  whole.whole = true;
  AddValue(name, help + "; " + whole.ToString(), "INT", std::to_string(*target));
  std::string* text = &texts_.back();
  converters_.push_back([this, name, text, target, whole](std::string* error) {
    if (!Given(name)) return true;
    double v = 0;
    std::string e;
    if (!ParseNumber(*text, whole, &v, &e)) {
      *error = "--" + name + ": " + e;
      return false;
    }
    *target = static_cast<long>(v);
    return true;
  });
}

void Command::Seed(const std::string& name, std::uint64_t* target, const std::string& help) {
  const NumberRange range = kSeedRange;
  AddValue(name, help + "; " + range.ToString(), "INT", std::to_string(*target));
  std::string* text = &texts_.back();
  converters_.push_back([this, name, text, target, range](std::string* error) {
    if (!Given(name)) return true;
    double v = 0;
    std::string e;
    if (!ParseNumber(*text, range, &v, &e)) {
      *error = "--" + name + ": " + e;
      return false;
    }
    *target = static_cast<std::uint64_t>(v);
    return true;
  });
}

void Command::NumberList(const std::string& name, std::vector<double>* target,
                         const std::string& help, const std::string& unit, const NumberRange& range,
                         bool allow_repeats) {
  std::string def;
  for (double v : *target) def += (def.empty() ? "" : ",") + FormatNumber(v);
  AddValue(name,
           help + " (comma-separated" + (unit.empty() ? "" : ", " + unit) + "); each " +
               range.ToString(),
           "LIST", def);
  std::string* text = &texts_.back();
  converters_.push_back([this, name, text, target, range, allow_repeats](std::string* error) {
    if (!Given(name)) return true;
    std::string e;
    if (!ParseNumberList(*text, range, !allow_repeats, target, &e)) {
      *error = "--" + name + ": " + e;
      return false;
    }
    return true;
  });
}

void Command::Text(const std::string& name, std::string* target, const std::string& help) {
  AddValue(name, help, "TEXT", *target);
  std::string* text = &texts_.back();
  converters_.push_back([this, name, text, target](std::string* error) {
    if (!Given(name)) return true;
    if (text->empty()) {
      *error = "--" + name + ": empty value";
      return false;
    }
    *target = *text;
    return true;
  });
}

void Command::Choice(const std::string& name, std::string* target, const std::string& help,
                     const std::vector<std::string>& choices) {
  std::string list;
  for (const std::string& c : choices) list += (list.empty() ? "" : "|") + c;
  AddValue(name, help, list, *target);
  std::string* text = &texts_.back();
  converters_.push_back([this, name, text, target, choices, list](std::string* error) {
    if (!Given(name)) return true;
    for (const std::string& c : choices) {
      if (*text == c) {
        *target = c;
        return true;
      }
    }
    *error = "--" + name + ": '" + *text + "' is not one of " + list;
    return false;
  });
}

void Command::Flag(const std::string& name, bool* target, const std::string& help) {
  app_->add_flag("--" + name, *target, help)->multi_option_policy(CLI::MultiOptionPolicy::Throw);
}

void Command::OutputDir(const std::string& name, std::string* target, const std::string& help) {
  AddOutput(name, target, help, false);
}

void Command::OutputFile(const std::string& name, std::string* target, const std::string& help) {
  AddOutput(name, target, help, true);
}

void Command::AddOutput(const std::string& name, std::string* target, const std::string& help,
                        bool is_file) {
  AddValue(name, help, is_file ? "FILE" : "DIR", *target);
  outputs_.push_back({name, target, is_file});
  std::string* text = &texts_.back();
  converters_.push_back([this, name, text, target](std::string*) {
    if (Given(name)) *target = *text;
    return true;
  });
}

void Command::Check(std::function<std::string()> check) { checks_.push_back(std::move(check)); }

void Command::Positional(const std::string& name, std::string* target, const std::string& help,
                         bool required) {
  CLI::Option* o = app_->add_option(name, *target, help);
  if (required) o->required();
}

bool Command::Given(const std::string& name) const {
  const CLI::Option* o = app_->get_option_no_throw("--" + name);
  return o != nullptr && o->count() > 0;
}

std::string Command::Help() const { return app_->help(); }

int Command::Fail(const std::string& message) const {
  std::fprintf(stderr, "ssc %s: %s\n", name_.c_str(), message.c_str());
  return 2;
}

bool Command::Parse(int argc, char** argv, int* exit_code) {
  std::vector<std::string> args;
  for (int i = argc - 1; i >= 0; --i) args.emplace_back(argv[i]);  // CLI11 wants them reversed
  try {
    app_->parse(args);
  } catch (const CLI::CallForHelp&) {
    std::fputs(app_->help().c_str(), stdout);
    *exit_code = 0;
    return false;
  } catch (const CLI::CallForVersion&) {
    std::printf("%s\n", VersionText().c_str());
    *exit_code = 0;
    return false;
  } catch (const CLI::ParseError& e) {
    *exit_code = Fail(std::string(e.what()) + " (see ssc " + name_ + " --help)");
    return false;
  }
  for (const auto& convert : converters_) {
    std::string error;
    if (!convert(&error)) {
      *exit_code = Fail(error);
      return false;
    }
  }
  for (const auto& check : checks_) {
    if (const std::string error = check(); !error.empty()) {
      *exit_code = Fail(error);
      return false;
    }
  }
  for (const Output& o : outputs_) {
    if (o.target->empty() && !Given(o.name)) continue;  // optional output not asked for
    std::string error;
    if (!(o.is_file ? CheckOutputFile(*o.target, &error) : CheckOutputDir(*o.target, &error))) {
      *exit_code = Fail("--" + o.name + ": " + error);
      return false;
    }
  }
  *exit_code = 0;
  return true;
}

int Command::CreateOutputs() {
  for (const Output& o : outputs_) {
    if (o.target->empty() && !Given(o.name)) continue;
    std::string error;
    if (!(o.is_file ? CreateOutputFileDir(*o.target, &error)
                    : CreateOutputDir(*o.target, &error))) {
      std::fprintf(stderr, "ssc %s: --%s: %s\n", name_.c_str(), o.name.c_str(), error.c_str());
      return 1;
    }
  }
  return 0;
}

}  // namespace ssc::cli
