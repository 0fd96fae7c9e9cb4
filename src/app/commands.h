// Every subcommand's registration function, one per cmd_*.cpp.
#pragma once

namespace rayvec {

class CommandLine;
class Command;

void register_info_command(CommandLine& cli);
void register_hits_command(CommandLine& cli);
void register_visibility_command(CommandLine& cli);
void register_compare_command(CommandLine& cli);
void register_render_command(CommandLine& cli);
void register_trace_command(CommandLine& cli);
void register_accuracy_command(CommandLine& cli);
// Subcommands of `rayvec bench`:
void register_bench_paper_command(Command& bench);
void register_bench_rays_command(Command& bench);
void register_bench_obj_command(Command& bench);
void register_bench_visibility_command(Command& bench);

}  // namespace rayvec
