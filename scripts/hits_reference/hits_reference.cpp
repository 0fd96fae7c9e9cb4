// hits_reference: the rival of `rayvec hits --accel brute` in docs/benchmarks.md ("hits and
// visibility") — the plain program one would write for the job in one file: read an OBJ mesh and a
// rays CSV, trace each ray against every triangle with AVX-512 Möller–Trumbore (Möller & Trumbore
// 1997; 16 triangles per step, precomputed edges in structure-of-arrays, f = 1/det, one ray at a
// time, nearest t, lowest id on equal t), print `ray,tri,t,u,v` as `rayvec hits` does. No tiling,
// no threads. Not part of rayvec; built by hand:
//   g++ -O3 -std=c++20 -mavx512f -mavx512dq -mfma scripts/hits_reference/hits_reference.cpp -o hits_reference
//   ./hits_reference MESH.obj RAYS.csv > hits.csv
// OBJ: `v x y z` and `f a b c ...` (1-based or negative indices, `a/b/c` forms, polygons as fans);
// CSV: a header line, then ox,oy,oz,dx,dy,dz[,tmin,tmax].
#include <immintrin.h>

#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <limits>
#include <string>
#include <vector>

namespace {

std::string read_file(const char* path) {
  std::FILE* f = std::fopen(path, "rb");
  if (!f) {
    std::fprintf(stderr, "%s: cannot open\n", path);
    std::exit(2);
  }
  std::string text;
  char buf[1 << 16];
  for (std::size_t got; (got = std::fread(buf, 1, sizeof buf, f)) > 0;) text.append(buf, got);
  std::fclose(f);
  return text;
}

struct Soa {  // 16-aligned rows, padded with zero triangles (det = 0: never hit)
  std::vector<float> v0x, v0y, v0z, e1x, e1y, e1z, e2x, e2y, e2z;
  std::size_t count = 0;
};

Soa load_obj(const char* path) {
  const std::string text = read_file(path);
  std::vector<float> pos;
  Soa s;
  const char* p = text.data();
  const char* end = p + text.size();
  auto add = [&](long a, long b, long c) {
    const float* A = &pos[3 * a];
    const float* B = &pos[3 * b];
    const float* C = &pos[3 * c];
    s.v0x.push_back(A[0]), s.v0y.push_back(A[1]), s.v0z.push_back(A[2]);
    s.e1x.push_back(B[0] - A[0]), s.e1y.push_back(B[1] - A[1]), s.e1z.push_back(B[2] - A[2]);
    s.e2x.push_back(C[0] - A[0]), s.e2y.push_back(C[1] - A[1]), s.e2z.push_back(C[2] - A[2]);
  };
  while (p < end) {
    const char* eol = static_cast<const char*>(std::memchr(p, '\n', end - p));
    if (!eol) eol = end;
    if (p[0] == 'v' && p[1] == ' ') {
      const char* q = p + 2;
      for (int k = 0; k < 3; ++k) {
        while (*q == ' ') ++q;
        float x = 0;
        q = std::from_chars(q, eol, x).ptr;
        pos.push_back(x);
      }
    } else if (p[0] == 'f' && p[1] == ' ') {
      std::vector<long> idx;
      for (const char* q = p + 2; q < eol;) {
        while (q < eol && (*q == ' ' || *q == '\r')) ++q;
        if (q >= eol) break;
        long i = 0;
        q = std::from_chars(q, eol, i).ptr;
        while (q < eol && *q != ' ') ++q;  // skip /vt/vn
        idx.push_back(i < 0 ? long(pos.size() / 3) + i : i - 1);
      }
      for (std::size_t k = 2; k < idx.size(); ++k) add(idx[0], idx[k - 1], idx[k]);
    }
    p = eol + 1;
  }
  s.count = s.v0x.size();
  for (auto* row : {&s.v0x, &s.v0y, &s.v0z, &s.e1x, &s.e1y, &s.e1z, &s.e2x, &s.e2y, &s.e2z})
    row->resize((s.count + 15) / 16 * 16, 0.0f);
  return s;
}

struct Ray {
  float o[3], d[3], tmin, tmax;
};

std::vector<Ray> load_rays(const char* path) {
  const std::string text = read_file(path);
  std::vector<Ray> rays;
  const char* p = text.data();
  const char* end = p + text.size();
  bool header = true;
  while (p < end) {
    const char* eol = static_cast<const char*>(std::memchr(p, '\n', end - p));
    if (!eol) eol = end;
    if (header || p == eol || *p == '#') {
      header = false;
      p = eol + 1;
      continue;
    }
    float v[8] = {0, 0, 0, 0, 0, 0, 0, std::numeric_limits<float>::infinity()};
    const char* q = p;
    for (int k = 0; k < 8 && q < eol; ++k) {
      if (*q == '+') ++q;
      q = std::from_chars(q, eol, v[k]).ptr;
      if (q < eol && *q == ',') ++q;
    }
    rays.push_back(Ray{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}, v[6], v[7]});
    p = eol + 1;
  }
  return rays;
}

struct Hit {
  float t = std::numeric_limits<float>::infinity(), u = 0, v = 0;
  int tri = -1;
};

Hit trace(const Soa& s, const Ray& r) {
  const __m512 ox = _mm512_set1_ps(r.o[0]), oy = _mm512_set1_ps(r.o[1]), oz = _mm512_set1_ps(r.o[2]);
  const __m512 dx = _mm512_set1_ps(r.d[0]), dy = _mm512_set1_ps(r.d[1]), dz = _mm512_set1_ps(r.d[2]);
  const __m512 tmin = _mm512_set1_ps(r.tmin), zero = _mm512_setzero_ps(), one = _mm512_set1_ps(1.0f);
  __m512 best_t = _mm512_set1_ps(r.tmax), best_u = zero, best_v = zero;
  __m512i best_id = _mm512_set1_epi32(-1),
          id = _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
  const __m512i sixteen = _mm512_set1_epi32(16);
  bool any = false;
  for (std::size_t i = 0; i < s.count; i += 16, id = _mm512_add_epi32(id, sixteen)) {
    const __m512 e1x = _mm512_load_ps(&s.e1x[i]), e1y = _mm512_load_ps(&s.e1y[i]),
                 e1z = _mm512_load_ps(&s.e1z[i]);
    const __m512 e2x = _mm512_load_ps(&s.e2x[i]), e2y = _mm512_load_ps(&s.e2y[i]),
                 e2z = _mm512_load_ps(&s.e2z[i]);
    // p = d × e2, det = e1 · p
    const __m512 px = _mm512_fmsub_ps(dy, e2z, _mm512_mul_ps(dz, e2y));
    const __m512 py = _mm512_fmsub_ps(dz, e2x, _mm512_mul_ps(dx, e2z));
    const __m512 pz = _mm512_fmsub_ps(dx, e2y, _mm512_mul_ps(dy, e2x));
    const __m512 det = _mm512_fmadd_ps(e1x, px, _mm512_fmadd_ps(e1y, py, _mm512_mul_ps(e1z, pz)));
    const __m512 f = _mm512_div_ps(one, det);
    // s = o − v0, u = f (s · p)
    const __m512 sx = _mm512_sub_ps(ox, _mm512_load_ps(&s.v0x[i]));
    const __m512 sy = _mm512_sub_ps(oy, _mm512_load_ps(&s.v0y[i]));
    const __m512 sz = _mm512_sub_ps(oz, _mm512_load_ps(&s.v0z[i]));
    const __m512 u =
        _mm512_mul_ps(f, _mm512_fmadd_ps(sx, px, _mm512_fmadd_ps(sy, py, _mm512_mul_ps(sz, pz))));
    // q = s × e1, v = f (d · q), t = f (e2 · q)
    const __m512 qx = _mm512_fmsub_ps(sy, e1z, _mm512_mul_ps(sz, e1y));
    const __m512 qy = _mm512_fmsub_ps(sz, e1x, _mm512_mul_ps(sx, e1z));
    const __m512 qz = _mm512_fmsub_ps(sx, e1y, _mm512_mul_ps(sy, e1x));
    const __m512 v =
        _mm512_mul_ps(f, _mm512_fmadd_ps(dx, qx, _mm512_fmadd_ps(dy, qy, _mm512_mul_ps(dz, qz))));
    const __m512 t =
        _mm512_mul_ps(f, _mm512_fmadd_ps(e2x, qx, _mm512_fmadd_ps(e2y, qy, _mm512_mul_ps(e2z, qz))));
    __mmask16 m = _mm512_cmp_ps_mask(u, zero, _CMP_GE_OQ) & _mm512_cmp_ps_mask(v, zero, _CMP_GE_OQ) &
                  _mm512_cmp_ps_mask(_mm512_add_ps(u, v), one, _CMP_LE_OQ) &
                  _mm512_cmp_ps_mask(t, tmin, _CMP_GE_OQ) & _mm512_cmp_ps_mask(t, best_t, _CMP_LT_OQ);
    if (m) {  // per lane: the first (lowest id) triangle at the lane's nearest t
      any = true;
      best_t = _mm512_mask_mov_ps(best_t, m, t);
      best_u = _mm512_mask_mov_ps(best_u, m, u);
      best_v = _mm512_mask_mov_ps(best_v, m, v);
      best_id = _mm512_mask_mov_epi32(best_id, m, id);
    }
  }
  Hit hit;
  if (!any) return hit;
  alignas(64) float ts[16], us[16], vs[16];
  alignas(64) int ids[16];
  _mm512_store_ps(ts, best_t), _mm512_store_ps(us, best_u), _mm512_store_ps(vs, best_v);
  _mm512_store_si512(ids, best_id);
  for (int k = 0; k < 16; ++k)
    if (ids[k] >= 0 && (ts[k] < hit.t || (ts[k] == hit.t && ids[k] < hit.tri)))
      hit = Hit{ts[k], us[k], vs[k], ids[k]};
  return hit;
}

void put(std::string& out, float x) {
  char buf[32];
  out.append(buf, std::to_chars(buf, buf + sizeof buf, x).ptr);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: hits_reference MESH.obj RAYS.csv > hits.csv\n");
    return 2;
  }
  const Soa tris = load_obj(argv[1]);
  const std::vector<Ray> rays = load_rays(argv[2]);
  const auto start = std::chrono::steady_clock::now();
  const std::clock_t cpu_start = std::clock();
  std::vector<Hit> hits(rays.size());
  for (std::size_t i = 0; i < rays.size(); ++i) hits[i] = trace(tris, rays[i]);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double cpu_seconds = double(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  std::string out = "ray,tri,t,u,v\n";
  for (std::size_t i = 0; i < hits.size(); ++i) {
    out += std::to_string(i) + ',' + std::to_string(hits[i].tri) + ',';
    put(out, hits[i].t), out += ',', put(out, hits[i].u), out += ',', put(out, hits[i].v), out += '\n';
  }
  std::fwrite(out.data(), 1, out.size(), stdout);
  std::fprintf(stderr,
               "hits_reference: %zu rays, %zu triangles, trace %.3f s (%.3f s cpu), %.2f G tests/s (cpu)\n",
               rays.size(), tris.count, seconds, cpu_seconds,
               double(rays.size()) * double(tris.count) / cpu_seconds * 1e-9);
  return 0;
}
