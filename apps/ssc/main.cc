// ssc: command-line front end of the Smart Suction Cup digital twin.
#include <signal.h>

#include <cstdio>
#include <cstring>
#include <exception>
#include <string>

#include "apps/ssc/cli.h"
#include "apps/ssc/commands.h"
#include "common/exit_codes.h"
#include "common/output_file.h"
#include "runtime/mujoco_model.h"
#include "studies/jobs/job_runner.h"

namespace {

struct Command {
  const char* name;
  int (*run)(int, char**);
  const char* summary;
};

const Command kCommands[] = {
    {"probe", ssc::RunProbe,
     "move the cup kinematically across a straight edge and around a disk edge; CSV + plot"},
    {"trial", ssc::RunTrialCommand, "one contour-following disk trial, headless; log + plot"},
    {"sweep", ssc::RunSweepCommand,
     "grid of trials over P_ref x beta x dL x repeats on all cores; resumable CSV + maps"},
    {"validate", ssc::RunValidateCommand,
     "the twin on every cell of a published success map, N seeds per cell; scores + figure"},
    {"equivalence", ssc::RunEquivalenceCommand,
     "two models (scenes, plugin keys, effects) on the same map cells and seeds, by statistics"},
    {"objects", ssc::RunObjectsCommand,
     "write the test objects' scenes and run the trial on each; table + plots"},
    {"view", ssc::RunViewCommand,
     "the twin in a window (or --screenshot FILE.png --time T off-screen)"},
    {"compare", ssc::RunCompareCommand,
     "the twin against a robot log: replay the logged path, compare pressures; report"},
    {"stability", ssc::RunStabilityCommand,
     "largest stable, unchanged time step per integrator (disk trial sweep)"},
    {"calibrate", ssc::RunCalibrateCommand,
     "fit the pneumatic model to the published disk results; residuals + parameter file"},
    {"charts", ssc::RunChartsCommand,
     "speed-accuracy charts: the cup (sweep over dL) and the simulator (pressure error vs cost)"},
    {"tune", ssc::RunTuneCommand,
     "search a controller's parameters for speed at a success rate (NLopt); Pareto chart"},
    {"sil", ssc::RunSilCommand,
     "run a lab script (ROS 1 + ur_rtde) against the twin, unchanged (python -m ssc_twin.sil)"},
    {"bench", ssc::RunBench, "step cost with/without the pressure sensor (runs ssc_bench)"},
};

// SIGINT and SIGTERM outside a study's run (the job runner handles them there, keeping finished
// rows): remove what this process started (temporary files, empty output folders), then end as
// the signal would. A plot child ends with us (PR_SET_PDEATHSIG, apps/ssc/plotting.cc).
extern "C" void OnCommandStopSignal(int sig) {
  ssc::RemoveStartedOutputs();
  signal(sig, SIG_DFL);
  raise(sig);
}

void InstallSignalHandlers() {
  // A write past `ulimit -f` then fails with EFBIG, reported with the file's name, instead of
  // killing the process with a half-written file.
  signal(SIGXFSZ, SIG_IGN);
  struct sigaction sa;
  std::memset(&sa, 0, sizeof(sa));
  sa.sa_handler = OnCommandStopSignal;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
}

void PrintUsage() {
  std::printf(
      "usage: ssc <command> [options]   (ssc <command> --help for its options)\n"
      "       ssc --version\n\n");
  std::printf("Smart Suction Cup digital twin (MuJoCo %s).\n\ncommands:\n", mj_versionString());
  for (const Command& c : kCommands) std::printf("  %-12s %s\n", c.name, c.summary);
}

}  // namespace

int main(int argc, char** argv) {
  InstallSignalHandlers();
  ssc::InstallMuJoCoMessageHandlers();
  const std::string version_error = ssc::CheckMuJoCoVersion();
  if (!version_error.empty()) {
    std::fprintf(stderr, "ssc: %s\n", version_error.c_str());
    return 2;
  }
  if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h") ||
      !std::strcmp(argv[1], "help")) {
    PrintUsage();
    return argc < 2 ? 2 : 0;
  }
  if (!std::strcmp(argv[1], "--version") || !std::strcmp(argv[1], "version")) {
    std::printf("%s\n", ssc::cli::VersionText().c_str());
    return 0;
  }
  for (const Command& c : kCommands) {
    if (std::strcmp(argv[1], c.name)) continue;
    // Under mpirun the studies share their trials between ranks (studies/jobs/job_runner.h).
    ssc::InitJobRunnerMpi(&argc, &argv);
    int rc = 1;
    // Last line of defence: an unexpected exception (I/O, allocation) ends the command with a
    // message and exit code 1, never an abort. Expected errors are handled where they occur.
    try {
      rc = c.run(argc - 2, argv + 2);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "ssc %s: error: %s\n", c.name, e.what());
    }
    if (rc == ssc::kExitFailed && ssc::cli::NotedExitCode() != 0) rc = ssc::cli::NotedExitCode();
    if (rc != 0) ssc::RemoveStartedOutputs();      // e.g. a folder made for a write that failed
    ssc::FinalizeJobRunnerMpi(/*abort=*/rc != 0);  // a failed rank must not leave others waiting
    return rc;
  }
  std::fprintf(stderr, "ssc: unknown command '%s'\n\n", argv[1]);
  PrintUsage();
  return 2;
}
