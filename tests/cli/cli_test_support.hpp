// tests/cli/cli_test_support.hpp -- shared by the CLI tests: a command's exit
// status and captured output (run through the verbs' functions, through a
// verb's main() with the standard streams captured, or as the sepax program
// in a child process), and temporary input files (one directory per test
// process, removed at exit).
#pragma once

#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include "commands/query_command.hpp"

namespace sepax::cli::test {

struct CommandRun {
  int status;
  std::string out, err;
};

struct TempDir {
  std::filesystem::path path;
  explicit TempDir(const std::string& prefix) {
    path = std::filesystem::temp_directory_path() / (prefix + "_" + std::to_string(::getpid()));
    std::filesystem::create_directories(path);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  std::string write(const std::string& name, const std::string& text) const {
    const auto p = path / name;
    std::ofstream(p, std::ios::binary) << text;
    return p.string();
  }
};

/// This process's temporary directory.
inline const TempDir& temp_dir() {
  static const TempDir dir("sepax_cli_test");
  return dir;
}

/// The whole content of the file at path (binary-safe; "" when unreadable).
inline std::string file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// A file `name` with `text` in this process's temporary directory; its path.
inline std::string temp_file(const std::string& name, const std::string& text) {
  return temp_dir().write(name, text);
}

/// `sepax query ARGS` with stdin_text on standard input.
inline CommandRun query(const std::vector<std::string>& args, const std::string& stdin_text = "") {
  std::istringstream in(stdin_text);
  std::ostringstream out, err;
  const int s = run_query(args, in, out, err);
  return {s, out.str(), err.str()};
}

/// `sepax info ARGS`.
inline CommandRun info(const std::vector<std::string>& args) {
  std::ostringstream out, err;
  const int s = run_info(args, out, err);
  return {s, out.str(), err.str()};
}

/// argv for a main(): the strings' buffers (args must outlive the result).
inline std::vector<char*> argv_of(std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  return argv;
}

/// f() -- a main() that uses std::cin, std::cout and std::cerr -- with
/// stdin_text on std::cin and what it prints captured.
inline CommandRun with_captured_streams(const std::function<int()>& f, const std::string& stdin_text = "") {
  std::istringstream in(stdin_text);
  std::ostringstream out, err;
  auto* old_in = std::cin.rdbuf(in.rdbuf());
  auto* old_out = std::cout.rdbuf(out.rdbuf());
  auto* old_err = std::cerr.rdbuf(err.rdbuf());
  int s = -1;
  try {
    s = f();
  } catch (...) {
    std::cin.rdbuf(old_in);
    std::cout.rdbuf(old_out);
    std::cerr.rdbuf(old_err);
    throw;
  }
  std::cin.rdbuf(old_in);
  std::cout.rdbuf(old_out);
  std::cerr.rdbuf(old_err);
  return {s, out.str(), err.str()};
}

/// A verb's main() (argv[0] is the verb) run with the standard streams captured.
inline CommandRun verb_main(int (*main_fn)(int, char**), std::vector<std::string> args,
                            const std::string& stdin_text = "") {
  return with_captured_streams(
      [&] {
        auto argv = argv_of(args);
        return main_fn(static_cast<int>(args.size()), argv.data());
      },
      stdin_text);
}

#ifdef SEPAX_CLI_PROGRAM
/// The sepax program run in a child process.
struct ProgramRun {
  int status = -1;  // exit status (-1 when killed by a signal)
  int signal = 0;   // the signal that ended it, 0 when it exited
  bool timed_out = false;
  std::string out, err;
  long max_rss_kb = 0;     // its peak resident memory
  double cpu_seconds = 0;  // its user + system time
  double seconds = 0;      // wall time
};

/// Runs `sepax ARGS` (SEPAX_CLI_PROGRAM) with standard input from the file
/// stdin_path ("" for /dev/null) and standard output to stdout_path ("" for a
/// captured file; a given one is not read back); kills it after
/// timeout_seconds.
inline ProgramRun run_program(std::vector<std::string> args, const std::string& stdin_path = "",
                              double timeout_seconds = 60, const std::string& stdout_path = "") {
  static int serial = 0;
  const std::string tag = std::to_string(++serial);
  const std::string out_path = stdout_path.empty() ? (temp_dir().path / ("out" + tag)).string() : stdout_path;
  const std::string err_path = (temp_dir().path / ("err" + tag)).string();
  args.insert(args.begin(), SEPAX_CLI_PROGRAM);
  auto argv = argv_of(args);
  const auto t0 = std::chrono::steady_clock::now();
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int in = ::open(stdin_path.empty() ? "/dev/null" : stdin_path.c_str(), O_RDONLY);
    const int out = ::open(out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = ::open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (in < 0 || out < 0 || err < 0) ::_exit(127);
    ::dup2(in, 0);
    ::dup2(out, 1);
    ::dup2(err, 2);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  ProgramRun r;
  if (pid < 0) return r;
  int wstatus = 0;
  rusage usage{};
  while (true) {
    const pid_t done = ::wait4(pid, &wstatus, WNOHANG, &usage);
    if (done == pid) break;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (done < 0) return r;
    if (elapsed > timeout_seconds && !r.timed_out) {
      r.timed_out = true;
      ::kill(pid, SIGKILL);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (WIFEXITED(wstatus)) r.status = WEXITSTATUS(wstatus);
  if (WIFSIGNALED(wstatus)) r.signal = WTERMSIG(wstatus);
  r.max_rss_kb = usage.ru_maxrss;
  r.cpu_seconds = static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
                  static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec) * 1e-6;
  if (stdout_path.empty()) r.out = file_text(out_path);
  r.err = file_text(err_path);
  return r;
}
#endif

}  // namespace sepax::cli::test
