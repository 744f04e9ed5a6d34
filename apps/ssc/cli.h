// A small command-line option parser for ssc subcommands: --name value pairs, each option
// documented with its unit and default, --help prints them.
#ifndef SSC_APPS_SSC_CLI_H_
#define SSC_APPS_SSC_CLI_H_

#include <map>
#include <string>
#include <vector>

namespace ssc::cli {

struct Option {
  std::string name;      // without the leading dashes
  std::string def;       // default value as text ("" = none)
  std::string help;      // one line, with the unit
  bool is_flag = false;  // takes no value
};

class Parser {
 public:
  Parser(std::string command, std::string summary, std::vector<Option> options);

  // Parses argv (after the subcommand). Returns false on error (message in error()), or when
  // --help was given (help_requested() is then true and Help() was printed).
  bool Parse(int argc, char** argv);
  bool help_requested() const { return help_; }
  const std::string& error() const { return error_; }
  std::string Help() const;

  std::string Get(const std::string& name) const;
  bool Flag(const std::string& name) const;
  // Numeric getters: on a malformed value they set error() and return false.
  bool GetDouble(const std::string& name, double* out);
  bool GetInt(const std::string& name, long* out);
  bool GetDoubleList(const std::string& name, std::vector<double>* out);
  const std::vector<std::string>& positional() const { return positional_; }

 private:
  std::string command_, summary_;
  std::vector<Option> options_;
  std::map<std::string, std::string> values_;
  std::vector<std::string> positional_;
  bool help_ = false;
  std::string error_;
};

}  // namespace ssc::cli

#endif  // SSC_APPS_SSC_CLI_H_
