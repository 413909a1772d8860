#pragma once
// Runs the real `tunica` binary with arguments and keeps its exit code and output.
#include <sys/wait.h>

#include <cstdio>
#include <string>

namespace tunica::test {

struct Outcome {
  int exit_code = -1;
  std::string output;  ///< stdout + stderr
};

inline Outcome run_cli(const std::string& args) {
  Outcome o;
  const std::string cmd = std::string(TUNICA_BINARY) + " " + args + " 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  char buf[4096];
  while (std::size_t n = std::fread(buf, 1, sizeof buf, p)) o.output.append(buf, n);
  const int status = pclose(p);
  o.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return o;
}

}  // namespace tunica::test
