// The only file that includes the OpenEXR C++ library. Writes go to an in-memory stream (the caller
// commits the bytes through AtomicFile); reads check the header first (exr_header.cpp).
#include "image/exr_file.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <algorithm>
#include <cstring>
#include <exception>
#include <numeric>

#include "image/exr_header.h"
#include "image/image_budget.h"
#include "io/input_error.h"

namespace rayvec {
namespace {

constexpr int kStripRows = 64;  // scanlines decoded per readPixels call

class MemoryStream : public Imf::OStream {
 public:
  MemoryStream() : Imf::OStream("memory") {}
  void write(const char c[], int n) override {
    if (pos_ + std::size_t(n) > bytes_.size()) bytes_.resize(pos_ + std::size_t(n));
    std::memcpy(bytes_.data() + pos_, c, std::size_t(n));
    pos_ += std::size_t(n);
  }
  uint64_t tellp() override { return pos_; }
  void seekp(uint64_t pos) override { pos_ = std::size_t(pos); }
  std::vector<std::uint8_t>& bytes() { return bytes_; }

 private:
  std::vector<std::uint8_t> bytes_;
  std::size_t pos_ = 0;
};

// OpenImageIO's order: within a layer R G B A Z first; the unlayered channels before any layer.
int rank_in_layer(const std::string& base) {
  static const char* const kFirst[] = {"R", "G", "B", "A", "Z"};
  for (int i = 0; i < 5; ++i)
    if (base == kFirst[i]) return i;
  return 5;
}

std::vector<std::string> oiio_order(std::vector<std::string> names) {
  auto split = [](const std::string& n) {
    const auto dot = n.rfind('.');
    return dot == std::string::npos
               ? std::pair<std::string, std::string>{"", n}
               : std::pair<std::string, std::string>{n.substr(0, dot), n.substr(dot + 1)};
  };
  std::stable_sort(names.begin(), names.end(), [&](const std::string& a, const std::string& b) {
    const auto [la, ba] = split(a);
    const auto [lb, bb] = split(b);
    if (la != lb) return la < lb;  // "" (no layer) sorts first
    return rank_in_layer(ba) < rank_in_layer(bb);
  });
  return names;
}

}  // namespace

Image read_exr(const std::string& path) {
  const ExrHeader h = read_exr_header(path);
  if (h.deep) throw InputError(path, 0, "cannot read EXR: deep images are not supported");
  if (h.subsampled) throw InputError(path, 0, "cannot read EXR: subsampled channels are not supported");
  check_declared_image_size(path, h.width, h.height, int(h.channels.size()));

  Image image;
  image.width = h.width;
  image.height = h.height;
  image.channels = oiio_order(h.channels);
  const std::size_t nch = image.channels.size();
  const std::size_t row_floats = std::size_t(h.width) * nch;
  try {
    Imf::InputFile file(path.c_str());
    for (int y0 = 0; y0 < h.height; y0 += kStripRows) {
      const int y1 = std::min(h.height, y0 + kStripRows);  // rows [y0, y1) of the data window
      image.pixels.resize(std::size_t(y1) * row_floats);
      // The slice addresses pixel (x, y) of the data window at base + x*xs + y*ys; point it at row 0.
      char* row0 = reinterpret_cast<char*>(image.pixels.data()) -
                   (std::ptrdiff_t(h.min_y) * std::ptrdiff_t(row_floats) +
                    std::ptrdiff_t(h.min_x) * std::ptrdiff_t(nch)) *
                       std::ptrdiff_t(sizeof(float));
      Imf::FrameBuffer fb;
      for (std::size_t c = 0; c < nch; ++c)
        fb.insert(image.channels[c], Imf::Slice(Imf::FLOAT, row0 + c * sizeof(float), nch * sizeof(float),
                                                row_floats * sizeof(float)));
      file.setFrameBuffer(fb);
      file.readPixels(h.min_y + y0, h.min_y + y1 - 1);
    }
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(path, 0, std::string("cannot read EXR: ") + e.what());
  }
  return image;
}

std::vector<std::uint8_t> encode_exr(const Image& image, const ImageMetadata& metadata) {
  Imf::Header header(image.width, image.height);
  header.compression() = Imf::ZIP_COMPRESSION;
  const std::size_t nch = image.channels.size();
  for (const std::string& name : image.channels) header.channels().insert(name, Imf::Channel(Imf::FLOAT));
  header.insert("oiio:ColorSpace", Imf::StringAttribute("Linear"));
  for (const auto& [key, value] : metadata) header.insert(key, Imf::StringAttribute(value));

  MemoryStream stream;
  try {
    Imf::OutputFile file(stream, header);
    Imf::FrameBuffer fb;
    char* base = reinterpret_cast<char*>(const_cast<float*>(image.pixels.data()));
    for (std::size_t c = 0; c < nch; ++c)
      fb.insert(image.channels[c], Imf::Slice(Imf::FLOAT, base + c * sizeof(float), nch * sizeof(float),
                                              std::size_t(image.width) * nch * sizeof(float)));
    file.setFrameBuffer(fb);
    file.writePixels(image.height);
  } catch (const std::exception& e) {
    throw RuntimeError(std::string("cannot encode EXR: ") + e.what());
  }
  return std::move(stream.bytes());
}

}  // namespace rayvec
