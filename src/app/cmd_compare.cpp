// `rayvec compare A B`: how far two images are apart, for golden-image tests.
// Exit 0 within the limits, 1 outside them, 2 on bad input (missing file, size mismatch).
#include <cmath>
#include <cstdio>

#include "app/command_line.h"
#include "app/commands.h"
#include "image/compare.h"
#include "image/image_io.h"
#include "io/input_error.h"

namespace rayvec {

void register_compare_command(CommandLine& cli) {
  struct Options {
    std::string a, b;
    double max_rmse = -1, max_pixel = -1, threshold = -1;
  };
  static Options o;
  cli.command("compare", "Compare two images: RMSE, PSNR, max pixel error, pixels over threshold")
      .positional("A", o.a, "first image (e.g. the reference)")
      .positional("B", o.b, "second image (e.g. a new render)")
      .option("--max-rmse", o.max_rmse, "fail (exit 1) when RMSE exceeds this (-1 = no limit)")
      .option("--max-pixel", o.max_pixel,
              "fail (exit 1) when any pixel's largest channel difference exceeds this (-1 = no limit)")
      .option("--threshold", o.threshold,
              "difference counted as 'over threshold' (-1 = --max-pixel if given, else 1/255)")
      .footer(
          "Compares the colour channels as stored: PNG values sRGB-encoded in [0,1], EXR linear.\n"
          "Example golden test:\n"
          "  rayvec render scenes/whitted.json --width 96 --height 72 -o new.png\n"
          "  rayvec compare tests/data/images/whitted.png new.png --max-rmse 0.01 --max-pixel 0.25")
      .run([] {
        if (o.max_rmse != -1 && !(o.max_rmse >= 0)) throw InputError("--max-rmse: must be >= 0");
        if (o.max_pixel != -1 && !(o.max_pixel >= 0)) throw InputError("--max-pixel: must be >= 0");
        const double threshold =
            o.threshold >= 0 ? o.threshold : (o.max_pixel >= 0 ? o.max_pixel : 1.0 / 255.0);
        const ImageDifference d = compare_images(read_image(o.a), read_image(o.b), threshold);
        std::printf("size: %ld pixels\n", d.pixels);
        std::printf("rmse: %.6g\n", d.rmse);
        if (std::isinf(d.psnr))
          std::printf("psnr: inf dB\n");
        else
          std::printf("psnr: %.2f dB\n", d.psnr);
        std::printf("max pixel error: %.6g\n", d.max_error);
        std::printf("pixels over %.6g: %ld (%.3f%%)\n", threshold, d.over_threshold,
                    d.pixels ? 100.0 * double(d.over_threshold) / double(d.pixels) : 0.0);
        bool pass = true;
        if (o.max_rmse >= 0 && !(d.rmse <= o.max_rmse)) {
          std::printf("FAIL: rmse %.6g > --max-rmse %.6g\n", d.rmse, o.max_rmse);
          pass = false;
        }
        if (o.max_pixel >= 0 && !(d.max_error <= o.max_pixel)) {
          std::printf("FAIL: max pixel error %.6g > --max-pixel %.6g\n", d.max_error, o.max_pixel);
          pass = false;
        }
        if (pass) std::printf("ok\n");
        return pass ? 0 : 1;
      });
}

}  // namespace rayvec
