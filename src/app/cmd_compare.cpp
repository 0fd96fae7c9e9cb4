// `rayvec compare A B`: how far two images are apart, for golden-image tests (the criteria of
// OpenImageIO's idiff: see docs/scenes.md#golden-image-tests). Exit 0 within the limits, 1 outside
// a fail limit, 3 outside only a warn limit, 2 on bad input (missing file, size mismatch).
#include <cmath>
#include <cstdio>

#include "app/command_line.h"
#include "app/commands.h"
#include "image/compare.h"
#include "image/image_io.h"
#include "io/input_error.h"

namespace rayvec {
namespace {

struct Options {
  std::string a, b, diff, diff_mode = "abs";
  double max_rmse = -1, max_pixel = -1, threshold = -1, fail_percent = -1;
  double warn_rmse = -1, warn_pixel = -1, warn_threshold = -1, warn_percent = -1, diff_scale = 0;
};

void check_limit(double value, const char* name) {
  if (value != -1 && !(value >= 0))
    throw InputError(std::string(name) + ": must be >= 0 (or -1 for no limit)");
}

// A percentage over 100 can never be exceeded: most likely a fraction written as a percentage.
void check_percent(double value, const char* name) {
  check_limit(value, name);
  if (value > 100) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    throw InputError(std::string(name) + ": " + text +
                     " is more than 100 percent of the pixels, a limit no image can exceed (a percentage: "
                     "0.5 for half a percent)");
  }
}

DiffMode parse_mode(const std::string& mode) {
  if (mode == "abs") return DiffMode::abs;
  if (mode == "scaled") return DiffMode::scaled;
  if (mode == "falsecolor") return DiffMode::falsecolor;
  throw InputError("--diff-mode: unknown '" + mode + "' (choose abs, scaled or falsecolor)");
}

std::string describe(const std::string& path, const Image& image, bool encoded) {
  return path + " (" + std::to_string(image.width) + "x" + std::to_string(image.height) + ", " +
         (encoded ? "integer, sRGB-encoded" : "float, linear") + ")";
}

// Prints one failed criterion; returns false so that callers can `ok = report(...) && ok`.
bool report(const char* level, const char* what, double value, const char* option, double limit) {
  std::printf("%s: %s %.6g > %s %.6g\n", level, what, value, option, limit);
  return false;
}

int run_compare(const Options& o) {
  for (auto [v, name] : {std::pair{o.max_rmse, "--max-rmse"},
                         {o.max_pixel, "--max-pixel"},
                         {o.warn_rmse, "--warn-rmse"},
                         {o.warn_pixel, "--warn-pixel"},
                         {o.threshold, "--threshold"},
                         {o.warn_threshold, "--warn-threshold"}})
    check_limit(v, name);
  check_percent(o.fail_percent, "--fail-percent");
  check_percent(o.warn_percent, "--warn-percent");
  const DiffMode mode = parse_mode(o.diff_mode);
  if (!o.diff.empty() && !is_writable_image_path(o.diff))
    throw InputError("--diff: " + o.diff + ": write the difference image as .png or .exr");
  if (!o.diff.empty()) require_image_writer(o.diff);
  const double threshold = o.threshold >= 0 ? o.threshold : (o.max_pixel >= 0 ? o.max_pixel : 1.0 / 255.0);
  const double warn_threshold = o.warn_threshold >= 0 ? o.warn_threshold : threshold;

  bool a_encoded = false, b_encoded = false;
  Image a = read_image(o.a, &a_encoded), b = read_image(o.b, &b_encoded);
  if (a.width != b.width || a.height != b.height)
    throw InputError(o.a + " is " + std::to_string(a.width) + "x" + std::to_string(a.height) + " but " + o.b +
                     " is " + std::to_string(b.width) + "x" + std::to_string(b.height) +
                     ": only images of the same size can be compared");
  std::printf("A: %s\nB: %s\n", describe(o.a, a, a_encoded).c_str(), describe(o.b, b, b_encoded).c_str());
  if (a_encoded == b_encoded) {
    std::printf("space: as stored (%s)\n", a_encoded ? "both sRGB-encoded in [0,1]" : "both linear");
  } else {
    Image& linear = a_encoded ? b : a;
    linear = to_srgb_encoded(linear);
    std::printf("space: sRGB-encoded in [0,1]; %s converted from linear as a PNG stores it (clamped)\n",
                (a_encoded ? o.b : o.a).c_str());
  }

  const ImageDifference d = compare_images(a, b, threshold);
  std::printf("size: %ld pixels\n", d.pixels);
  std::printf("rmse: %.6g\n", d.rmse);
  if (std::isinf(d.psnr))
    std::printf("psnr: inf dB\n");
  else
    std::printf("psnr: %.2f dB\n", d.psnr);
  std::printf("max pixel error: %.6g\n", d.max_error);
  std::printf("pixels over %.6g: %ld (%.3f%%)\n", threshold, d.over_threshold, d.percent_over(threshold));
  if (o.warn_percent >= 0 && warn_threshold != threshold)
    std::printf("pixels over %.6g: %ld (%.3f%%)\n", warn_threshold, d.count_over(warn_threshold),
                d.percent_over(warn_threshold));

  if (!o.diff.empty()) {
    write_image(o.diff, difference_image(a, b, mode, o.diff_scale, threshold));
    std::printf("difference image: %s (%s)\n", o.diff.c_str(), o.diff_mode.c_str());
  }

  bool pass = true, quiet = true;
  if (o.max_rmse >= 0 && !(d.rmse <= o.max_rmse))
    pass = report("FAIL", "rmse", d.rmse, "--max-rmse", o.max_rmse);
  if (o.max_pixel >= 0 && !(d.max_error <= o.max_pixel))
    pass = report("FAIL", "max pixel error", d.max_error, "--max-pixel", o.max_pixel);
  if (o.fail_percent >= 0 && !(d.percent_over(threshold) <= o.fail_percent))
    pass = report("FAIL", "percent of pixels over the threshold", d.percent_over(threshold), "--fail-percent",
                  o.fail_percent);
  if (o.warn_rmse >= 0 && !(d.rmse <= o.warn_rmse))
    quiet = report("WARN", "rmse", d.rmse, "--warn-rmse", o.warn_rmse);
  if (o.warn_pixel >= 0 && !(d.max_error <= o.warn_pixel))
    quiet = report("WARN", "max pixel error", d.max_error, "--warn-pixel", o.warn_pixel);
  if (o.warn_percent >= 0 && !(d.percent_over(warn_threshold) <= o.warn_percent))
    quiet = report("WARN", "percent of pixels over the warn threshold", d.percent_over(warn_threshold),
                   "--warn-percent", o.warn_percent);
  if (!pass) return 1;
  std::printf(quiet ? "ok\n" : "warn\n");
  return quiet ? 0 : 3;
}

}  // namespace

void register_compare_command(CommandLine& cli) {
  static Options o;
  cli.command("compare", "Compare two images: RMSE, PSNR, max pixel error, pixels over threshold")
      .positional("A", o.a, "first image (e.g. the reference)")
      .positional("B", o.b, "second image (e.g. a new render)")
      .option("--max-rmse", o.max_rmse, "fail (exit 1) when RMSE exceeds this (-1 = no limit)")
      .option("--max-pixel", o.max_pixel,
              "fail (exit 1) when any pixel's largest channel difference exceeds this (-1 = no limit)")
      .option("--threshold", o.threshold,
              "difference counted as 'over threshold' (-1 = --max-pixel if given, else 1/255)")
      .option("--fail-percent", o.fail_percent,
              "fail (exit 1) when more than this percentage of pixels are over --threshold (-1 = no limit)")
      .option("--warn-rmse", o.warn_rmse, "warn (exit 3) when RMSE exceeds this (-1 = no limit)")
      .option("--warn-pixel", o.warn_pixel, "warn (exit 3) when any pixel's difference exceeds this")
      .option("--warn-threshold", o.warn_threshold, "difference counted by --warn-percent (-1 = --threshold)")
      .option("--warn-percent", o.warn_percent,
              "warn (exit 3) when more than this percentage of pixels are over --warn-threshold")
      .option("--diff", o.diff, "write a difference image of the colour channels (.png or .exr)")
      .option("--diff-mode", o.diff_mode,
              "abs (|A-B|), scaled (|A-B| x --diff-scale) or falsecolor (black = equal, blue = tiny, "
              "yellow = at --threshold, red = twice it or more)")
      .option("--diff-scale", o.diff_scale,
              "factor for --diff-mode scaled (0 = largest difference becomes 1)")
      .footer(
          "Colour channels (the first three; grey as grey) are compared in one space: as stored when both\n"
          "files are of one kind (PNG and other integer files sRGB-encoded in [0,1], EXR linear); an EXR\n"
          "against a PNG is compared after encoding the EXR to sRGB as `render -o x.png` would. The\n"
          "output's 'space:' line says which.\n"
          "Exit status: 0 within every limit, 1 outside a fail limit (--max-rmse, --max-pixel,\n"
          "--fail-percent), 3 outside only a warn limit (--warn-*), 2 bad input (missing or unreadable\n"
          "file, sizes that differ: the message names both files and sizes).\n"
          "Examples:\n"
          "  rayvec render scenes/whitted.json --width 96 --height 72 --spp 1 -o new.png\n"
          "  rayvec compare tests/data/images/whitted.png new.png --max-rmse 0.01 --max-pixel 0.25\n"
          "  # idiff-style: fail when over 0.5 % of pixels differ by more than 0.02, and show where\n"
          "  rayvec compare ref.png new.png --threshold 0.02 --fail-percent 0.5 --diff d.png --diff-mode "
          "falsecolor")
      .run([] { return run_compare(o); });
}

}  // namespace rayvec
