// ObjSample: what a few windows of an OBJ text say about the whole of it, before it is parsed — how
// many elements of each kind it holds (to reserve arrays once instead of growing them; each growth
// copies and touches fresh memory) and where to cut it into pieces that take about equally long to
// parse on parallel threads (a byte of a face line costs about 1.7 times one of a vertex line: more
// output per byte of text; see benchmarks.md#decision-obj-fast-path).
#pragma once
#include <cstddef>
#include <string_view>
#include <vector>

namespace rayvec {

struct ObjCounts {
  std::size_t positions = 0, normals = 0, texcoords = 0, triangles = 0;
};

class ObjSample {
 public:
  // Reads up to 32 windows of 4 KiB spread evenly over `text` (the whole text when it is shorter).
  explicit ObjSample(std::string_view text);

  // About how many elements of each kind the text holds, rounded up (20 % and 16 more): a capacity.
  ObjCounts capacity() const;
  // About how many elements of each kind lie before byte `offset` (no margin: may be over or under).
  ObjCounts before(std::size_t offset) const;
  // Cuts the text at line ends into at most `pieces` non-empty runs of whole lines of about equal
  // estimated parse cost, in order, covering it exactly (one piece, possibly empty, for empty text).
  std::vector<std::string_view> split(int pieces) const;

 private:
  // The text is a run of segments, each described by the window read at its start.
  struct Segment {
    std::size_t begin = 0, end = 0;  // bytes of the text
    double covered = 0;              // bytes of the whole lines read in its window
    double positions = 0, normals = 0, texcoords = 0, triangles = 0, cost = 0;
  };
  double cost_before(std::size_t offset) const;

  std::string_view text_;
  std::vector<Segment> segments_;
};

}  // namespace rayvec
