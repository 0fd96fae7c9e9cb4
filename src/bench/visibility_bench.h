// `rayvec bench visibility`: the table of the CUDA visibility study (Gallina 2023: sequential CPU,
// GPU without and with shared memory) on its workload shape — the vertices of a closed bumpy sphere
// against its triangles, seen from outside — at its size and larger. Rows: the scalar kernel on one
// thread (the study's sequential row), rayvec's brute force per ISA on 1..N threads, the BVH, and on
// a GPU the global kernel, the shared tiles by tile size and the SoA tiles, with the transfers timed
// apart from the kernel. Every row's answers are checked against the BVH's (the same contract).
#pragma once
#include <cstdio>
#include <vector>

#include "geometry/triangle_mesh.h"
#include "kernels/intersector.h"

namespace rayvec {

struct VisibilityBenchOptions {
  std::vector<int> rings{100, 200};  // sphere rings: 100 is the study's size (19,802 vertices)
  std::vector<int> tiles{64, 128, 256, 512, 1024};
  int max_threads = 0;      // 0: all cores
  double cpu_budget = 4e9;  // skip a brute-force CPU row above this many tests per thread
  Intersector intersector = Intersector::mt;
  bool gpu = true;
};

// A closed UV sphere of radius ~1 with bumps (so that some vertices hide others): `rings` rings of
// 2·rings segments, (rings − 1)·2·rings + 2 vertices, 4·rings·(rings − 1) triangles.
TriangleMesh bumpy_sphere(int rings);

// Prints the table to `out`; returns the number of rows whose check failed.
int run_visibility_bench(const VisibilityBenchOptions& options, std::FILE* out);

}  // namespace rayvec
