// `rayvec bench obj FILE`: how fast load_obj reads an OBJ, per phase, through tinyobjloader (the
// reference) and through rayvec's fast reader on 1 and 2 threads, alternated in one process so
// that the ratios hold on a noisy machine.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "app/command_line.h"
#include "app/commands.h"
#include "io/input_error.h"
#include "scene/obj_loader.h"

namespace rayvec {
namespace {

struct Way {
  const char* name;
  ObjLoadOptions options;
  std::vector<ObjLoadTimes> runs;
};

double total(const ObjLoadTimes& t) { return t.read + t.check + t.parse + t.convert; }

// The run with the shortest total: the least disturbed by other work on the machine.
const ObjLoadTimes& best(const std::vector<ObjLoadTimes>& runs) {
  return *std::min_element(runs.begin(), runs.end(),
                           [](const ObjLoadTimes& a, const ObjLoadTimes& b) { return total(a) < total(b); });
}

}  // namespace

void register_bench_obj_command(Command& bench) {
  struct Options {
    std::string model;
    int repeats = 3;
  };
  static Options o;
  bench.subcommand("obj", "Time OBJ loading per phase: tinyobjloader against rayvec's fast reader")
      .positional("OBJ", o.model, "the OBJ file to load")
      .option("--repeats", o.repeats, "loads per way; the fastest of each is shown (default 3)")
      .footer(
          "Loads the file --repeats times in each of three ways, alternating: `reference` (rayvec's\n"
          "error pre-scan, then tinyobjloader), `fast-1` and `fast-2` (rayvec's reader on 1 and 2\n"
          "threads). Prints the seconds of each phase of the fastest load and the file's megabytes\n"
          "(10^6 bytes) per second of the whole load, and the reader that loaded it. `fast reader:\n"
          "no` means the file lies outside the fast reader's subset (e.g. `l` or `p` lines)\n"
          "and every way used tinyobjloader.\n"
          "Example (the 1M-triangle sphere of docs/benchmarks.md):\n"
          "  python3 scripts/make_bumpy_sphere.py sphere1m.obj\n"
          "  rayvec bench obj sphere1m.obj --repeats 5")
      .run([] {
        if (o.repeats < 1) throw InputError("--repeats: must be 1 or more");
        std::vector<Way> ways = {{"reference", {.reference = true}, {}},
                                 {"fast-1", {.threads = 1}, {}},
                                 {"fast-2", {.threads = 2}, {}}};
        std::size_t triangles = 0;
        bool fast = true;
        for (int r = 0; r < o.repeats; ++r)
          for (Way& w : ways) {
            ObjLoadTimes t;
            const ObjModel m = load_obj(o.model, w.options, &t);
            w.runs.push_back(t);
            triangles = m.mesh.size();
            if (!w.options.reference) fast = fast && t.fast;
          }
        const double mb = double(std::filesystem::file_size(o.model)) / 1e6;
        std::printf("file: %s (%.1f MB, %zu triangles)\nfast reader: %s\n", o.model.c_str(), mb, triangles,
                    fast ? "yes" : "no");
        std::printf("%-10s %8s %8s %8s %8s %8s %8s  %s\n", "way", "read_s", "check_s", "parse_s", "convert_s",
                    "total_s", "MB/s", "reader");
        for (const Way& w : ways) {
          const ObjLoadTimes& t = best(w.runs);
          std::printf("%-10s %8.4f %8.4f %8.4f %8.4f %8.4f %8.1f  %s\n", w.name, t.read, t.check, t.parse,
                      t.convert, total(t), mb / total(t), t.fast ? "fast" : "tinyobjloader");
        }
        return 0;
      });
}

}  // namespace rayvec
