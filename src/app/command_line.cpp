// The only file that includes CLI11.
#include "app/command_line.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <iostream>

#include "io/error_report.h"
#include "io/input_error.h"

namespace rayvec {
namespace {

CLI::App& app_of(void* p) { return *static_cast<CLI::App*>(p); }

}  // namespace

Command& Command::option(const std::string& flags, std::string& out, const std::string& help) {
  app_of(app_).add_option(flags, out, help)->capture_default_str();
  return *this;
}
Command& Command::option(const std::string& flags, int& out, const std::string& help) {
  app_of(app_).add_option(flags, out, help)->capture_default_str();
  return *this;
}
Command& Command::option(const std::string& flags, double& out, const std::string& help) {
  app_of(app_).add_option(flags, out, help)->capture_default_str();
  return *this;
}
Command& Command::flag(const std::string& flags, bool& out, const std::string& help) {
  app_of(app_).add_flag(flags, out, help);
  return *this;
}
Command& Command::required(const std::string& flags, std::string& out, const std::string& help) {
  app_of(app_).add_option(flags, out, help)->required();
  return *this;
}
Command& Command::positional(const std::string& name, std::string& out, const std::string& help,
                             bool required) {
  auto* opt = app_of(app_).add_option(name, out, help);
  if (required) opt->required();
  return *this;
}
Command& Command::footer(const std::string& text) {
  app_of(app_).footer(text);
  return *this;
}
Command& Command::run(std::function<int()> action) {
  auto* app = &app_of(app_);
  app->callback([this, action = std::move(action)]() {
    if (reads_input_ && *input_check_) (*input_check_)();
    throw CLI::RuntimeError(action());
  });
  return *this;
}
Command& Command::reads_no_input() {
  reads_input_ = false;
  return *this;
}
Command& Command::subcommand(const std::string& name, const std::string& description) {
  CLI::App* sub = app_of(app_).add_subcommand(name, description);
  app_of(app_).require_subcommand(1);
  children_.push_back(std::unique_ptr<Command>(new Command(sub, input_check_)));
  return *children_.back();
}

struct CommandLine::Impl {
  CLI::App app;
};

CommandLine::CommandLine(const std::string& name, const std::string& description)
    : impl_(new Impl{CLI::App(description, name)}) {
  impl_->app.set_version_flag("--version", std::string(name) + " " + RAYVEC_VERSION);
  impl_->app.require_subcommand(1);
  root_.reset(new Command(&impl_->app, &input_check_));
}

CommandLine::~CommandLine() = default;

Command& CommandLine::command(const std::string& name, const std::string& description) {
  return root_->subcommand(name, description);
}

int CommandLine::main(int argc, char** argv) {
  CLI::App& app = impl_->app;
  // CLI11 takes an unknown word for a stray argument and says only "A subcommand is required":
  // name the word and the commands instead.
  {
    CLI::App* level = &app;
    std::string path = app.get_name();
    for (int i = 1; i < argc && argv[i][0] != '-'; ++i) {
      const auto subs = level->get_subcommands([](CLI::App*) { return true; });
      if (subs.empty()) break;
      CLI::App* next = nullptr;
      std::string names;
      for (CLI::App* sub : subs) {
        if (sub->get_name() == argv[i]) next = sub;
        names += (names.empty() ? "" : ", ") + sub->get_name();
      }
      if (!next) {
        std::cerr << path << ": unknown command '" << argv[i] << "' (commands: " << names << "; run `" << path
                  << " --help`)\n";
        return 2;
      }
      level = next;
      path += " " + next->get_name();
    }
  }
  try {
    app.parse(argc, argv);
    return 0;
  } catch (const CLI::RuntimeError& done) {  // a command's action finished with this status
    return done.get_exit_code();
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    report_error(std::string("rayvec: ") + e.what() + "\n(run `rayvec --help` or `rayvec COMMAND --help`)");
    return 2;
  } catch (const ReportedFailure& f) {
    return f.status;
  } catch (const InputError& e) {
    report_error(e.what());
    return 2;
  } catch (const RuntimeError& e) {
    report_error(std::string("rayvec: ") + e.what());
    return 1;
  } catch (const std::bad_alloc&) {
    report_error("rayvec: out of memory");
    return 1;
  } catch (const std::exception& e) {
    report_error(std::string("rayvec: error: ") + e.what());
    return 1;
  }
}

}  // namespace rayvec
