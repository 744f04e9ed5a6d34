// The ssc command line: each subcommand declares typed options (unit, range and default shown in
// --help) on top of CLI11; every number goes through the strict reader (common/strict_number.h).
// Unknown options, stray positional arguments and repeated options are errors; so is an output
// location that could not be created, checked by Parse() without creating anything. Outputs are
// created by CreateOutputs(), which a command calls once all its inputs are read and checked,
// so a failing invocation leaves no new directory behind. Errors print one line
// "ssc COMMAND: --option: what is wrong; the valid range" and exit with 2.
#ifndef SSC_APPS_SSC_CLI_H_
#define SSC_APPS_SSC_CLI_H_

#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "common/strict_number.h"

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace ssc::cli {

// "ssc 0.1.0 (MuJoCo 3.x.y)".
std::string VersionText();

// An input the command could not use, noted where it is read: the command then returns
// kExitFailed (1) as for any error, and main() ends with the input's class instead (missing
// input 3 or bad data 4, common/exit_codes.h), so every command reports a class the same way.
void NoteInputError(const std::string& error);
void NoteExitCode(int code);
int NotedExitCode();  // 0 when none was noted

// Checks, without creating anything, that `dir` is a writable directory or could be made one:
// no part of the path is a file or a dangling link, no name is longer than NAME_MAX, and the
// nearest existing ancestor is a writable directory. False + *error naming the path otherwise.
bool CheckOutputDir(const std::string& dir, std::string* error);
// CheckOutputDir, then creates the directory (and missing parents).
bool CreateOutputDir(const std::string& dir, std::string* error);
// The same two for a file to be written: not a directory; its directory as above.
bool CheckOutputFile(const std::string& file, std::string* error);
bool CreateOutputFileDir(const std::string& file, std::string* error);

class Command {
 public:
  Command(std::string name, const std::string& summary);
  ~Command();
  Command(const Command&) = delete;
  Command& operator=(const Command&) = delete;

  // Each option's target holds its default on entry and the parsed value after Parse(). `name`
  // is the long name without dashes; `unit` is shown in the help ("" for dimensionless).
  // show_default=false for options whose absence means "not asked for" (see Given()).
  void Number(const std::string& name, double* target, const std::string& help,
              const std::string& unit, const NumberRange& range, bool show_default = true);
  void Integer(const std::string& name, long* target, const std::string& help,
               const NumberRange& range);
  void Seed(const std::string& name, std::uint64_t* target, const std::string& help);
  // Comma-separated numbers; repeats are errors unless allow_repeats.
  void NumberList(const std::string& name, std::vector<double>* target, const std::string& help,
                  const std::string& unit, const NumberRange& range, bool allow_repeats = false);
  void Text(const std::string& name, std::string* target, const std::string& help);
  void Choice(const std::string& name, std::string* target, const std::string& help,
              const std::vector<std::string>& choices);
  void Flag(const std::string& name, bool* target, const std::string& help);
  // Output locations: checked by Parse(), created by CreateOutputs(). An empty value means
  // "none" for optional outputs.
  void OutputDir(const std::string& name, std::string* target, const std::string& help);
  void OutputFile(const std::string& name, std::string* target, const std::string& help);
  // A check run after every value is read and before outputs are prepared: returns "" when
  // fine, else the message (e.g. a config's Validate()).
  void Check(std::function<std::string()> check);
  // A positional argument (at most one per command).
  void Positional(const std::string& name, std::string* target, const std::string& help,
                  bool required);

  // Parses argv (the arguments after the subcommand). Returns true to go on; otherwise the
  // command returns *exit_code: 0 after --help/--version, 2 on an error (already printed).
  bool Parse(int argc, char** argv, int* exit_code);
  // Creates the output directories (for an output file, its directory). Call it once every
  // input is read and checked, just before the work that writes. Returns 0, or 1 after
  // printing the error (the location passed Parse()'s check but could not be made).
  int CreateOutputs();
  // Whether the user gave the option (for options whose absence means "not asked for").
  bool Given(const std::string& name) const;
  // Prints "ssc NAME: message" to stderr and returns 2 (usage error) for `return cmd.Fail(...)`.
  int Fail(const std::string& message) const;
  std::string Help() const;
  const std::string& name() const { return name_; }

 private:
  CLI::Option* AddValue(const std::string& name, const std::string& help, const std::string& type,
                        const std::string& default_text);
  void AddOutput(const std::string& name, std::string* target, const std::string& help,
                 bool is_file);

  std::string name_;
  std::unique_ptr<CLI::App> app_;
  std::deque<std::string> texts_;  // raw text of value options (stable addresses)
  std::vector<std::function<bool(std::string*)>> converters_;  // run in order after parsing
  std::vector<std::function<std::string()>> checks_;           // then these
  struct Output {
    std::string name;     // option name
    std::string* target;  // its value after Parse()
    bool is_file;
  };
  std::vector<Output> outputs_;  // checked last by Parse(), created by CreateOutputs()
};

}  // namespace ssc::cli

#endif  // SSC_APPS_SSC_CLI_H_
