#include "apps/ssc/plotting.h"

#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <thread>

#include "runtime/mujoco_model.h"

extern char** environ;

namespace ssc {
namespace {

// A plot is never waited for without end: past kPlotTimeoutS it is killed and named.
constexpr double kPlotTimeoutS = 300;

bool WaitBounded(pid_t pid, const std::string& script, int* status) {
  const auto start = std::chrono::steady_clock::now();
  while (true) {
    const pid_t done = waitpid(pid, status, WNOHANG);
    if (done == pid) return true;
    if (done < 0 && errno != EINTR) {
      std::fprintf(stderr, "plot failed: waiting for %s: %s\n", script.c_str(),
                   std::strerror(errno));
      return false;
    }
    const double waited_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (waited_s > kPlotTimeoutS) {
      kill(pid, SIGKILL);
      while (waitpid(pid, status, 0) < 0 && errno == EINTR) {
      }
      std::fprintf(stderr,
                   "plot failed: %s did not finish in %.0f s and was stopped (the results "
                   "are written; a memory limit such as ulimit -v can stall Python)\n",
                   script.c_str(), kPlotTimeoutS);
      return false;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

}  // namespace

bool RunPlotScript(const std::string& script, const std::vector<std::string>& args) {
  const std::string root = SourceDir();
  const std::string python = root + "/.venv/bin/python";
  if (!std::filesystem::exists(python)) {
    std::fprintf(stderr, "plot skipped: %s not found (run tools/setup.sh)\n", python.c_str());
    return false;
  }
  // The script runs directly (no shell): paths holding quotes, spaces or ';' stay one argument.
  const std::string script_path = root + "/tools/" + script;
  std::vector<char*> argv;
  argv.push_back(const_cast<char*>(python.c_str()));
  argv.push_back(const_cast<char*>(script_path.c_str()));
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  // One BLAS thread: a plot needs no more, and OpenBLAS waits for ever on threads it cannot
  // start (an address-space limit, ulimit -v).
  std::vector<std::string> env_text = {"MPLBACKEND=Agg", "OPENBLAS_NUM_THREADS=1",
                                       "OMP_NUM_THREADS=1"};
  for (char** e = environ; *e != nullptr; ++e) {
    const bool ours = std::strncmp(*e, "MPLBACKEND=", 11) == 0 ||
                      std::strncmp(*e, "OPENBLAS_NUM_THREADS=", 21) == 0 ||
                      std::strncmp(*e, "OMP_NUM_THREADS=", 16) == 0;
    if (!ours) env_text.emplace_back(*e);
  }
  std::vector<char*> envp;
  for (std::string& e : env_text) envp.push_back(e.data());
  envp.push_back(nullptr);
  std::fflush(stdout);
  std::fflush(stderr);
  // fork + exec (not posix_spawn) so the child can ask to end with its parent: a plot never
  // writes after ssc was stopped. Only async-signal-safe calls between fork and exec.
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) {
    std::fprintf(stderr, "plot failed: cannot start %s: %s\n", python.c_str(),
                 std::strerror(errno));
    return false;
  }
  if (pid == 0) {
    prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (getppid() != parent) _exit(1);  // the parent ended before prctl
    execve(python.c_str(), argv.data(), envp.data());
    _exit(127);
  }
  int status = 0;
  if (!WaitBounded(pid, script, &status)) return false;
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::fprintf(stderr, "plot failed: %s %s %d\n", script.c_str(),
                 WIFEXITED(status) ? "exited with" : "killed by signal",
                 WIFEXITED(status) ? WEXITSTATUS(status) : WTERMSIG(status));
    return false;
  }
  return true;
}

}  // namespace ssc
