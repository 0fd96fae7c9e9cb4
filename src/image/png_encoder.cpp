// The only file that includes zlib. A PNG's image data is one zlib stream; deflate streams ended by
// a sync flush are byte-aligned and join into one, so each band of rows is deflated on its own
// thread (as pigz does, without carrying the dictionary over) and only the checksum is combined.
#include "image/png_encoder.h"

#include <zlib.h>

#include <algorithm>
#include <climits>
#include <cstring>
#include <string>

#include "io/input_error.h"

namespace rayvec {
namespace {

constexpr std::size_t kBandBytes = 256 * 1024;  // row bytes a band holds at least
constexpr std::size_t kMaxChunk = 1 << 20;      // an IDAT chunk's data at most
constexpr int kLevel = 1;                       // benchmarks.md#decision-png-speed

// One band's piece of the deflate stream, the Adler-32 sum of its row bytes and their count.
struct Band {
  std::vector<std::uint8_t> data;
  uLong adler = 1;  // adler32() of no bytes
  std::size_t raw = 0;
  bool failed = false;
};

// deflateEnd on every way out of a band, exceptions included.
struct Deflater {
  z_stream z{};
  bool open = false;
  Deflater() { open = deflateInit2(&z, kLevel, Z_DEFLATED, -15, 8, Z_DEFAULT_STRATEGY) == Z_OK; }
  ~Deflater() {
    if (open) deflateEnd(&z);
  }
};

// Runs deflate(flush) on what z holds until it is done with it, growing `data` past its `used`
// bytes as needed: all input taken (Z_NO_FLUSH), the flush complete (Z_SYNC_FLUSH), the stream
// ended (Z_FINISH).
bool run_deflate(z_stream& z, int flush, std::vector<std::uint8_t>& data, std::size_t& used) {
  for (;;) {
    if (used == data.size()) data.resize(std::max<std::size_t>(4096, data.size() * 2));
    const std::size_t room = std::min<std::size_t>(data.size() - used, UINT_MAX);
    z.next_out = data.data() + used;
    z.avail_out = uInt(room);
    const int status = deflate(&z, flush);
    used += room - z.avail_out;
    if (status == Z_STREAM_ERROR) return false;
    const bool done = flush == Z_NO_FLUSH ? z.avail_in == 0
                      : flush == Z_FINISH ? status == Z_STREAM_END
                                          : z.avail_out != 0;
    if (done) return true;
  }
}

// Rows [y0, y1) as raw deflate (no zlib header), each row its filter byte (0, none) and pixels;
// ended by a sync flush, or by the final block for the last band.
void deflate_band(int width, int y0, int y1, bool last, const PngRowSource& rows, Band& band) {
  const std::size_t stride = 1 + 3 * std::size_t(width);
  std::vector<std::uint8_t> row(stride, 0);
  Deflater d;
  if (!d.open) {
    band.failed = true;
    return;
  }
  band.data.resize(std::max<std::size_t>(4096, stride * std::size_t(y1 - y0) / 8));
  std::size_t used = 0;
  for (int y = y0; y < y1; ++y) {
    rows(y, row.data() + 1);
    band.adler = adler32(band.adler, row.data(), uInt(stride));
    d.z.next_in = row.data();
    d.z.avail_in = uInt(stride);
    if (!run_deflate(d.z, Z_NO_FLUSH, band.data, used)) {
      band.failed = true;
      return;
    }
  }
  if (!run_deflate(d.z, last ? Z_FINISH : Z_SYNC_FLUSH, band.data, used)) band.failed = true;
  band.data.resize(used);
  band.raw = stride * std::size_t(y1 - y0);
}

void put32(std::vector<std::uint8_t>& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(std::uint8_t(v >> shift));
}

// A chunk: length, type, data, CRC-32 of type and data.
void put_chunk(std::vector<std::uint8_t>& out, const char* type, const std::uint8_t* data, std::size_t n) {
  put32(out, std::uint32_t(n));
  const std::size_t at = out.size();
  out.insert(out.end(), type, type + 4);
  if (n > 0) out.insert(out.end(), data, data + n);
  put32(out, std::uint32_t(crc32(0, out.data() + at, uInt(n + 4))));
}

void put_chunk(std::vector<std::uint8_t>& out, const char* type, const std::vector<std::uint8_t>& data) {
  put_chunk(out, type, data.data(), data.size());
}

std::vector<std::uint8_t> be32(std::initializer_list<std::uint32_t> values) {
  std::vector<std::uint8_t> bytes;
  for (const std::uint32_t v : values) put32(bytes, v);
  return bytes;
}

// A tEXt keyword: 1 to 79 Latin-1 printable characters, no leading, trailing or double spaces.
bool png_keyword(const std::string& key) {
  if (key.empty() || key.size() > 79 || key.front() == ' ' || key.back() == ' ') return false;
  for (std::size_t i = 0; i < key.size(); ++i) {
    const auto c = static_cast<unsigned char>(key[i]);
    if (!((c >= 32 && c <= 126) || c >= 161)) return false;
    if (c == ' ' && key[i - 1] == ' ') return false;
  }
  return true;
}

}  // namespace

int png_band_rows(int width) {
  const std::size_t stride = 1 + 3 * std::size_t(std::max(width, 0));
  return int(std::min<std::size_t>((kBandBytes + stride - 1) / stride, INT_MAX));
}

std::vector<std::uint8_t> encode_png_rgb8(int width, int height, const PngRowSource& rows,
                                          const ImageMetadata& metadata) {
  if (width <= 0 || height <= 0) throw RuntimeError("cannot encode PNG: empty image");
  for (const auto& [key, text] : metadata)
    if (!png_keyword(key))
      throw RuntimeError(
          "cannot encode PNG: metadata key '" + key +
          "' is not a PNG keyword (1 to 79 printable Latin-1 characters, single spaces inside)");
  const int band_rows = png_band_rows(width);
  const int bands = (height - 1) / band_rows + 1;
  std::vector<Band> parts(static_cast<std::size_t>(bands));
#pragma omp parallel for schedule(dynamic, 1) if (bands > 1)
  for (int b = 0; b < bands; ++b) {
    Band& band = parts[std::size_t(b)];
    try {  // nothing may leave an OpenMP region by exception
      deflate_band(width, b * band_rows, std::min(height, (b + 1) * band_rows), b == bands - 1, rows, band);
    } catch (...) {
      band.failed = true;
    }
  }
  std::size_t deflated = 0;
  for (const Band& band : parts) {
    if (band.failed) throw RuntimeError("cannot encode PNG: out of memory");
    deflated += band.data.size();
  }

  // the zlib stream: header (deflate, 32 KiB window, fastest level), the bands, Adler-32 of all rows
  std::vector<std::uint8_t> stream{0x78, 0x01};
  stream.reserve(deflated + 6);
  uLong adler = adler32(0, nullptr, 0);
  for (Band& band : parts) {
    stream.insert(stream.end(), band.data.begin(), band.data.end());
    adler = adler32_combine(adler, band.adler, z_off_t(band.raw));
    std::vector<std::uint8_t>().swap(band.data);
  }
  put32(stream, std::uint32_t(adler));

  std::vector<std::uint8_t> out{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  out.reserve(stream.size() + 4096);
  std::vector<std::uint8_t> ihdr = be32({std::uint32_t(width), std::uint32_t(height)});
  ihdr.insert(ihdr.end(), {8, 2, 0, 0, 0});  // 8 bits, RGB, deflate, no filter method, no interlace
  put_chunk(out, "IHDR", ihdr);
  // sRGB (perceptual intent) with the gAMA and cHRM values the sRGB chunk implies, for readers
  // without sRGB support (PNG 1.2, 11.3.3.5)
  put_chunk(out, "gAMA", be32({45455}));
  const std::uint8_t perceptual = 0;
  put_chunk(out, "sRGB", &perceptual, 1);
  put_chunk(out, "cHRM", be32({31270, 32900, 64000, 33000, 30000, 60000, 15000, 6000}));
  for (const auto& [key, text] : metadata) {
    std::vector<std::uint8_t> data(key.begin(), key.end());
    data.push_back(0);
    data.insert(data.end(), text.begin(), std::find(text.begin(), text.end(), '\0'));
    put_chunk(out, "tEXt", data);
  }
  for (std::size_t at = 0; at < stream.size(); at += kMaxChunk)
    put_chunk(out, "IDAT", stream.data() + at, std::min(kMaxChunk, stream.size() - at));
  put_chunk(out, "IEND", nullptr, 0);
  return out;
}

}  // namespace rayvec
