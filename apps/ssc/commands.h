// The ssc subcommands. Each takes the arguments after its name and returns the exit code.
#ifndef SSC_APPS_SSC_COMMANDS_H_
#define SSC_APPS_SSC_COMMANDS_H_

namespace ssc {

int RunProbe(int argc, char** argv);
int RunBench(int argc, char** argv);  // execs build/bin/ssc_bench
int RunTrialCommand(int argc, char** argv);
int RunSweepCommand(int argc, char** argv);
int RunValidateCommand(int argc, char** argv);
int RunEquivalenceCommand(int argc, char** argv);
int RunObjectsCommand(int argc, char** argv);
int RunViewCommand(int argc, char** argv);
int RunCompareCommand(int argc, char** argv);
int RunStabilityCommand(int argc, char** argv);
int RunCalibrateCommand(int argc, char** argv);
int RunChartsCommand(int argc, char** argv);
int RunTuneCommand(int argc, char** argv);
int RunSilCommand(int argc, char** argv);  // execs PYTHON -m ssc_twin.sil

}  // namespace ssc

#endif  // SSC_APPS_SSC_COMMANDS_H_
