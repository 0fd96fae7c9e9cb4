// The only file that includes OpenEXRCore. Its errors go to a callback that keeps the last message
// (the default one prints to stderr), and the message is thrown once the library has returned.
#include "image/exr_header.h"

#include <OpenEXR/openexr.h>

#include <cstdio>

#include "io/input_error.h"

namespace rayvec {
namespace {

struct ErrorText {
  char text[256] = "";
};

extern "C" void keep_exr_error(exr_const_context_t ctxt, exr_result_t code, const char* msg) {
  void* user = nullptr;
  if (ctxt && exr_get_user_data(ctxt, &user) == EXR_ERR_SUCCESS && user)
    std::snprintf(static_cast<ErrorText*>(user)->text, sizeof ErrorText::text, "%s",
                  msg ? msg : exr_get_default_error_message(code));
}

}  // namespace

bool has_exr_magic(const unsigned char* bytes, std::size_t size) {
  return size >= 4 && bytes[0] == 0x76 && bytes[1] == 0x2f && bytes[2] == 0x31 && bytes[3] == 0x01;
}

ExrHeader read_exr_header(const std::string& path) {
  ErrorText error;
  exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
  init.error_handler_fn = keep_exr_error;
  init.user_data = &error;
  exr_context_t ctxt = nullptr;
  exr_result_t rc = exr_start_read(&ctxt, path.c_str(), &init);
  auto fail = [&](exr_result_t code) {
    const std::string why = error.text[0] ? error.text : exr_get_default_error_message(code);
    exr_finish(&ctxt);
    return InputError(path, 0, "cannot read EXR: " + why);
  };
  if (rc != EXR_ERR_SUCCESS) throw fail(rc);
  ExrHeader h;
  exr_storage_t storage{};
  exr_attr_box2i_t box{};
  const exr_attr_chlist_t* channels = nullptr;
  if ((rc = exr_get_count(ctxt, &h.parts)) != EXR_ERR_SUCCESS ||
      (rc = exr_get_storage(ctxt, 0, &storage)) != EXR_ERR_SUCCESS ||
      (rc = exr_get_data_window(ctxt, 0, &box)) != EXR_ERR_SUCCESS ||
      (rc = exr_get_channels(ctxt, 0, &channels)) != EXR_ERR_SUCCESS)
    throw fail(rc);
  h.deep = storage == EXR_STORAGE_DEEP_SCANLINE || storage == EXR_STORAGE_DEEP_TILED;
  h.min_x = box.min.x;
  h.min_y = box.min.y;
  const long long w = (long long)box.max.x - box.min.x + 1, ht = (long long)box.max.y - box.min.y + 1;
  h.width = w > 0 && w <= 0x7fffffff ? int(w) : 0;
  h.height = ht > 0 && ht <= 0x7fffffff ? int(ht) : 0;
  for (int c = 0; channels && c < channels->num_channels; ++c) {
    const exr_attr_chlist_entry_t& e = channels->entries[c];
    h.channels.emplace_back(e.name.str, std::size_t(e.name.length));
    h.subsampled = h.subsampled || e.x_sampling != 1 || e.y_sampling != 1;
  }
  exr_finish(&ctxt);
  return h;
}

}  // namespace rayvec
