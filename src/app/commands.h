// Every subcommand's registration function, one per cmd_*.cpp.
#pragma once

namespace rayvec {

class CommandLine;

void register_info_command(CommandLine& cli);

}  // namespace rayvec
