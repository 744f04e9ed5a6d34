// The exit codes of every command (ssc and its subcommands, ssc sil, the Python entry points
// that exit): one code per class of outcome, the one home of the table that docs/reliability.md
// shows and the tests check command by command.
#ifndef SSC_COMMON_EXIT_CODES_H_
#define SSC_COMMON_EXIT_CODES_H_

#include <cctype>
#include <string>

namespace ssc {

enum ExitCode : int {
  kExitOk = 0,                // done (a trial: it succeeded)
  kExitFailed = 1,            // failed while running: I/O, a script that raised, an internal error
  kExitUsage = 2,             // the command line: unknown option or name, a value out of its range
  kExitMissingInput = 3,      // a file or scene named that is not there or cannot be read
  kExitBadData = 4,           // an input that is there but is not what it must be
  kExitTrialFailed = 5,       // it ran, and the trial did not succeed (its outcome names why)
  kExitMissingInterface = 6,  // ssc sil: the script needs an interface the twin does not have
  kExitInterrupted = 130,     // SIGINT or SIGTERM: the finished work is kept
};

struct ExitCodeRow {
  ExitCode code;
  const char* name;
  const char* meaning;
};

inline constexpr ExitCodeRow kExitCodeTable[] = {
    {kExitOk, "ok", "done; a trial succeeded"},
    {kExitFailed, "failed", "failed while running: I/O, a script that raised, an internal error"},
    {kExitUsage, "usage",
     "the command line: an unknown command, option or name, a value out of its range"},
    {kExitMissingInput, "missing_input",
     "a file or scene named that is not there, or cannot be read"},
    {kExitBadData, "bad_data",
     "an input that is there but is not what it must be: a scene that does not compile, a "
     "malformed log, map or table, a script that is not Python"},
    {kExitTrialFailed, "trial_failed",
     "it ran, and the trial did not succeed: off the edge, grasp, never touched, timed out, ..."},
    {kExitMissingInterface, "missing_interface",
     "ssc sil: the script needs an interface the twin does not have (named)"},
    {kExitInterrupted, "interrupted", "SIGINT or SIGTERM: the finished work is kept"},
};

// The class of an input that could not be read, from the reader's message: "no such file" (any
// case) is a missing input, anything else a bad one.
inline ExitCode InputErrorCode(const std::string& error) {
  std::string lower(error);
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return lower.find("no such file") != std::string::npos ? kExitMissingInput : kExitBadData;
}

}  // namespace ssc

#endif  // SSC_COMMON_EXIT_CODES_H_
