// CommandLine: rayvec's subcommands and their options, declared by each src/app/cmd_*.cpp.
// A thin wrapper so that CLI11 is included by exactly one file (command_line.cpp).
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace rayvec {

class Command {
 public:
  // flags: "-o,--output" or "--threads"; help is shown by --help.
  Command& option(const std::string& flags, std::string& out, const std::string& help);
  Command& option(const std::string& flags, int& out, const std::string& help);
  Command& option(const std::string& flags, double& out, const std::string& help);
  Command& flag(const std::string& flags, bool& out, const std::string& help);
  Command& required(const std::string& flags, std::string& out, const std::string& help);
  Command& positional(const std::string& name, std::string& out, const std::string& help,
                      bool required = true);
  // Text shown after the options in --help (examples, formats).
  Command& footer(const std::string& text);
  // What runs when the command is chosen; returns the exit status. The command line's input check
  // (CommandLine::check_before_input) runs first, unless the command declared reads_no_input().
  Command& run(std::function<int()> action);
  // The command reads no input file (`info`): it runs whatever the input check would say.
  Command& reads_no_input();
  // A nested command, e.g. `bench paper`.
  Command& subcommand(const std::string& name, const std::string& description);

 private:
  friend class CommandLine;
  Command(void* app, const std::function<void()>* input_check) : app_(app), input_check_(input_check) {}
  void* app_;                                 // CLI::App*
  const std::function<void()>* input_check_;  // CommandLine's, shared by every command
  bool reads_input_ = true;
  std::vector<std::unique_ptr<Command>> children_;
};

class CommandLine {
 public:
  CommandLine(const std::string& name, const std::string& description);
  ~CommandLine();
  Command& command(const std::string& name, const std::string& description);
  Command& root() { return *root_; }
  // Runs `check` before the action of every command that reads input; it throws InputError to stop
  // the command (exit 2). Help never reaches it.
  void check_before_input(std::function<void()> check) { input_check_ = std::move(check); }
  // Parses argv and runs the chosen command. Usage errors and InputError give exit status 2,
  // RuntimeError and other failures 1; messages go to stderr.
  int main(int argc, char** argv);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::function<void()> input_check_;
  std::unique_ptr<Command> root_;
};

}  // namespace rayvec
