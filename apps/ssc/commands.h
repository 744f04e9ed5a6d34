// The ssc subcommands. Each takes the arguments after its name and returns the exit code.
#ifndef SSC_APPS_SSC_COMMANDS_H_
#define SSC_APPS_SSC_COMMANDS_H_

namespace ssc {

int RunProbe(int argc, char** argv);

}  // namespace ssc

#endif  // SSC_APPS_SSC_COMMANDS_H_
