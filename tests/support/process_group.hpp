// Test support: shell scripts run in a process group of their own, killed
// whole with SIGKILL (crash-safety tests), and the lines a script logged.
#pragma once

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cctype>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace hydrocoef::test {

/// The /proc entries of the live (not zombie) processes of a process group.
inline std::vector<std::filesystem::path> live_processes(pid_t group) {
  std::vector<std::filesystem::path> out;
  std::error_code ec;
  for (const auto& proc : std::filesystem::directory_iterator("/proc", ec)) {
    const std::string pid = proc.path().filename().string();
    if (pid.empty() || !std::isdigit(static_cast<unsigned char>(pid[0]))) continue;
    std::ifstream stat(proc.path() / "stat");
    std::string line;
    if (!std::getline(stat, line) || line.rfind(')') == std::string::npos) continue;
    // pid (comm) state ppid pgrp ...; comm may hold spaces, so count from ')'.
    std::istringstream fields(line.substr(line.rfind(')') + 1));
    std::string state;
    long ppid = 0, pgrp = 0;
    if (fields >> state >> ppid >> pgrp && pgrp == group && state != "Z" && state != "X") out.push_back(proc.path());
  }
  return out;
}

/// Starts `script` under /bin/sh in a process group of its own.
inline pid_t start_group(const std::string& script, const std::filesystem::path& cwd) {
  const pid_t pid = fork();
  if (pid == 0) {
    setpgid(0, 0);
    if (chdir(cwd.c_str()) != 0) _exit(127);
    execl("/bin/sh", "sh", "-c", script.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  setpgid(pid,
          pid);  // also from here, so that the kill cannot race the child's setpgid
  return pid;
}

/// SIGKILLs the whole group (the shell and the hydrocoef it runs) and waits
/// until none of it is left.
inline void kill_group(pid_t pid) {
  kill(-pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (!live_processes(pid).empty() && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
}

/// Polls `ready` every 200 us until it holds or no process of the group is
/// left (the script ended first); true when it held. Events, not the clock,
/// decide: the 10-minute backstop only ends a wait on a hung child.
template <typename Ready>
bool wait_for_event(pid_t group, Ready&& ready) {
  const auto backstop = std::chrono::steady_clock::now() + std::chrono::minutes(10);
  while (!ready()) {
    if (live_processes(group).empty() || std::chrono::steady_clock::now() > backstop) return ready();
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  return true;
}

inline std::set<std::string> lines_of(const std::filesystem::path& path) {
  std::set<std::string> out;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) out.insert(line);
  return out;
}

}  // namespace hydrocoef::test
