#include "io/output_sink.h"

#include <cerrno>
#include <cstring>

#include "io/input_error.h"

namespace rayvec {

OutputSink::OutputSink(const std::string& path) : path_(path.empty() ? "-" : path) {
  if (path_ != "-") file_ = std::make_unique<AtomicFile>(path_);
}

void OutputSink::write(const char* data, std::size_t n) {
  if (n && std::fwrite(data, 1, n, stream()) != n)
    throw RuntimeError("cannot write " + std::string(is_stdout() ? "standard output" : path_) + ": " +
                       std::strerror(errno));
}

void OutputSink::commit() {
  if (file_) {
    file_->commit();
    return;
  }
  if (std::fflush(stdout) != 0 || std::ferror(stdout))
    throw RuntimeError(std::string("cannot write standard output: ") + std::strerror(errno));
}

}  // namespace rayvec
