// The pieces of load_obj_fast: split at line ends, parse the pieces in parallel (obj_chunk.cpp),
// check the indices that cross pieces, then replay the order-dependent lines (mtllib, usemtl, s) and
// join. OBJ indices are global and may be relative, so a piece is parsed without knowing how many
// vertices come before it: relative indices are fixed up afterwards (ObjChunk::relative).
#include "scene/obj_fast.h"

#include <algorithm>
#include <exception>
#include <set>
#include <thread>
#include <vector>

#include "platform/large_buffer.h"
#include "scene/material_names.h"
#include "scene/obj_chunk.h"
#include "scene/obj_sample.h"
#include "scene/polygon_triangulation.h"

namespace rayvec {
namespace {

template <typename T>
void reserve(std::vector<T>& v, std::size_t count) {
  v.reserve(count);
  advise_huge_pages(v.data(), v.capacity() * sizeof(T));
}

void reserve(ObjChunk& c, const ObjCounts& n) {
  reserve(c.positions, n.positions);
  reserve(c.normals, n.normals);
  reserve(c.texcoords, n.texcoords);
  reserve(c.triangles, n.triangles);
  // the corner index arrays only where the sample saw the attribute: a file without it leaves them
  // empty (ObjChunk), one with it unsampled grows them as it goes
  if (n.normals > 0) reserve(c.triangle_normals, n.triangles);
  if (n.texcoords > 0) reserve(c.triangle_texcoords, n.triangles);
}

// Room reserved for one array of the joined result, and where a later piece will probably land in it.
struct Destination {
  const char* data;
  std::size_t capacity, element;  // elements, bytes per element
};

template <typename T>
Destination destination(const std::vector<T>& v) {
  return {reinterpret_cast<const char*>(v.data()), v.capacity(), sizeof(T)};
}

// Faults in the pages where `count` elements starting near `expected` will be appended, so that the
// serial append after the parallel parse copies into ready memory (fresh pages cost more than the
// copy). The estimate is a sample's: a margin on both sides; pages outside it fault on the append.
void prepare(const Destination& d, std::size_t expected, std::size_t count) {
  if (count == 0) return;
  const std::size_t margin = expected / 20 + 1024;
  const std::size_t from = std::min(d.capacity, expected - std::min(expected, margin));
  const std::size_t to = std::min(d.capacity, expected + margin + count);
  if (from < to) prefault_pages(d.data + from * d.element, (to - from) * d.element);
}

// The first piece's arrays have room for the whole file: the others are appended to them in place,
// into pages their own threads fault in while the first piece is still parsing.
void parse_in_parallel(std::string_view text, const ObjSample& sample,
                       const std::vector<std::string_view>& pieces, std::vector<ObjChunk>& chunks) {
  reserve(chunks[0], sample.capacity());
  const std::array<Destination, 6> joined{
      destination(chunks[0].positions),        destination(chunks[0].normals),
      destination(chunks[0].texcoords),        destination(chunks[0].triangles),
      destination(chunks[0].triangle_normals), destination(chunks[0].triangle_texcoords)};
  std::vector<std::exception_ptr> failures(pieces.size());
  std::vector<std::thread> workers;
  for (std::size_t i = 1; i < pieces.size(); ++i)
    workers.emplace_back([&, i] {
      try {
        ObjChunk& c = chunks[i];
        reserve(c, ObjSample(pieces[i]).capacity());
        parse_obj_chunk(pieces[i], c);
        if (!c.ok) return;
        const ObjCounts at = sample.before(static_cast<std::size_t>(pieces[i].data() - text.data()));
        prepare(joined[0], at.positions, c.positions.size());
        prepare(joined[1], at.normals, c.normals.size());
        prepare(joined[2], at.texcoords, c.texcoords.size());
        for (int k = 3; k < 6; ++k) prepare(joined[k], at.triangles, c.triangles.size());
      } catch (...) {  // std::bad_alloc: rethrown on the caller's thread
        failures[i] = std::current_exception();
      }
    });
  try {
    parse_obj_chunk(pieces[0], chunks[0]);
  } catch (...) {
    failures[0] = std::current_exception();
  }
  for (std::thread& w : workers) w.join();
  for (const std::exception_ptr& f : failures)
    if (f) std::rethrow_exception(f);
}

// tinyobjloader's reading of the text after `mtllib ` (after mtllib_text, as the reference
// path hands it over): names split at spaces, `\` escapes the next character, and the last
// (possibly empty) name always counts.
std::vector<std::string> mtllib_names(const std::string& text) {
  std::vector<std::string> names;
  std::string name;
  bool escaped = false;
  for (const char ch : text) {
    if (!escaped && ch == '\\') {
      escaped = true;
      continue;
    }
    if (!escaped && ch == ' ') {
      if (!name.empty()) names.push_back(name);
      name.clear();
      continue;
    }
    escaped = false;
    name += ch;
  }
  names.push_back(name);
  return names;
}

// Where each piece starts in the joined arrays.
struct Offsets {
  std::array<int64_t, 3> items{0, 0, 0};  // v, vt, vn
  std::size_t triangles = 0, lines = 0;
};

// Replays mtllib and usemtl in file order as tinyobjloader does; returns the material of every
// triangle.
std::vector<int32_t> replay_materials(const std::vector<ObjChunk>& chunks, const std::vector<Offsets>& at,
                                      std::size_t triangles, const MtlLibraries& mtl, std::string& warn,
                                      std::string& err) {
  std::vector<int32_t> material(triangles, -1);
  std::map<std::string, int> by_name;
  std::set<std::string> loaded;
  int current = -1;
  std::size_t from = 0;  // first triangle not yet given a material
  for (std::size_t i = 0; i < chunks.size(); ++i) {
    for (const ObjEvent& e : chunks[i].events) {
      const std::size_t triangle = at[i].triangles + e.triangle;
      if (e.kind == ObjEvent::usemtl) {
        const std::string key = material_key(e.text);
        const auto it = by_name.find(key);
        if (it == by_name.end()) warn += unknown_material_text(key, at[i].lines + e.line) + "\n";
        std::fill(material.begin() + static_cast<std::ptrdiff_t>(from),
                  material.begin() + static_cast<std::ptrdiff_t>(triangle), current);
        from = triangle;
        current = it == by_name.end() ? -1 : it->second;
      } else {
        // the first name that loads, or one loaded before, counts (tinyobjloader's second warning
        // for a line of names that all fail, which load_obj drops, is not written)
        for (const std::string& name : mtllib_names(mtllib_text(e.text, mtl.exists))) {
          if (loaded.count(name) > 0) continue;
          std::string mtl_warn, mtl_err;
          const bool ok = mtl.load(name, by_name, mtl_warn, mtl_err);
          warn += mtl_warn;
          err += mtl_err;
          if (ok) {
            loaded.insert(name);
            break;
          }
        }
      }
    }
  }
  std::fill(material.begin() + static_cast<std::ptrdiff_t>(from), material.end(), current);
  return material;
}

// The smoothing group of every triangle, the last `s` line before it counting (tinyobjloader's
// state runs across pieces, `g` and `o`); empty when every triangle's is 0 (ObjModel).
std::vector<uint32_t> replay_smoothing(const std::vector<ObjChunk>& chunks, const std::vector<Offsets>& at,
                                       std::size_t triangles) {
  std::vector<uint32_t> group;
  uint32_t current = 0;
  std::size_t from = 0;  // first triangle not yet given a group
  for (std::size_t i = 0; i < chunks.size(); ++i)
    for (const ObjChunk::Smoothing& s : chunks[i].smoothing) {
      const std::size_t triangle = at[i].triangles + s.triangle;
      if (current != 0 && triangle > from) {
        group.resize(triangles, 0);
        std::fill(group.begin() + std::ptrdiff_t(from), group.begin() + std::ptrdiff_t(triangle), current);
      }
      from = triangle;
      current = s.group;
    }
  if (current != 0 && triangles > from) {
    group.resize(triangles, 0);
    std::fill(group.begin() + std::ptrdiff_t(from), group.end(), current);
  }
  return group;
}

// The quads' second split where quad_splits_at_0_2 says so (the chunks store every quad as
// (0,1,2), (0,2,3)).
void split_quads(const std::vector<uint32_t>& quads, ObjModel& m) {
  const auto& p = m.mesh.positions;
  for (const uint32_t q : quads) {
    auto& a = m.mesh.triangles[q];
    auto& b = m.mesh.triangles[q + 1];
    if (quad_splits_at_0_2({p[a[0]], p[a[1]], p[a[2]], p[b[2]]})) continue;
    // the other split: (0,1,3), (1,2,3)
    const auto resplit = [](auto& t0, auto& t1) {
      const auto c0 = t0[0], c1 = t0[1], c2 = t0[2], c3 = t1[2];
      t0 = {c0, c1, c3};
      t1 = {c1, c2, c3};
    };
    resplit(a, b);
    if (!m.triangle_texcoords.empty()) resplit(m.triangle_texcoords[q], m.triangle_texcoords[q + 1]);
    if (!m.triangle_normals.empty()) resplit(m.triangle_normals[q], m.triangle_normals[q + 1]);
  }
}

// The corners of the polygon stored as the fan of n − 2 triangles from `first`: (c0,c1,c2),
// (c0,c2,c3), ...
template <typename T>
void fan_corners(const std::vector<std::array<T, 3>>& tris, uint32_t first, uint32_t n, std::vector<T>& out) {
  out.assign({tris[first][0], tris[first][1]});
  for (uint32_t j = 0; j + 2 < n; ++j) out.push_back(tris[first + j][2]);
}

// Rewrites the fan from `first` as the triangles `cut` (triples of corner positions).
template <typename T>
void recut(std::vector<std::array<T, 3>>& tris, uint32_t first, const std::vector<T>& corners,
           const std::vector<std::array<uint32_t, 3>>& cut) {
  for (std::size_t j = 0; j < cut.size(); ++j)
    tris[first + j] = {corners[cut[j][0]], corners[cut[j][1]], corners[cut[j][2]]};
}

// The polygons' fans cut as triangulate_polygon cuts them, as the reference path does.
void triangulate_polygons(const std::vector<ObjChunk::Polygon>& polygons, ObjModel& m) {
  std::vector<uint32_t> corners;
  std::vector<int32_t> attribute;
  std::vector<Vec3f> positions;
  std::vector<std::array<uint32_t, 3>> cut;
  for (const ObjChunk::Polygon& p : polygons) {
    fan_corners(m.mesh.triangles, p.first, p.corners, corners);
    positions.clear();
    for (uint32_t c : corners) positions.push_back(m.mesh.positions[c]);
    cut.clear();
    triangulate_polygon(positions, cut);
    recut(m.mesh.triangles, p.first, corners, cut);
    for (auto* attributes : {&m.triangle_normals, &m.triangle_texcoords}) {
      if (attributes->empty()) continue;
      fan_corners(*attributes, p.first, p.corners, attribute);
      recut(*attributes, p.first, attribute, cut);
    }
  }
}

// Gives every chunk's corner index array of one kind its -1 entries when some chunk has that kind
// and this one has not (ObjChunk keeps such an array empty), so the joined array is either empty
// or one entry per triangle.
void fill_corner_indices(std::vector<ObjChunk>& chunks,
                         std::vector<std::array<int32_t, 3>> ObjChunk::*indices) {
  const bool any =
      std::any_of(chunks.begin(), chunks.end(), [&](const ObjChunk& c) { return !(c.*indices).empty(); });
  if (!any) return;
  for (ObjChunk& c : chunks)
    if ((c.*indices).empty()) (c.*indices).assign(c.triangles.size(), kNoCornerIndices);
}

template <typename T>
void append(std::vector<T>& to, std::vector<T>& from) {
  if (to.empty() && to.capacity() < from.capacity())
    to = std::move(from);
  else
    to.insert(to.end(), from.begin(), from.end());
}

}  // namespace

bool load_obj_fast(std::string_view text, int threads, const MtlLibraries& mtl, ObjModel& model,
                   std::string& warn, std::string& err) {
  const ObjSample sample(text);
  return load_obj_pieces(text, sample, sample.split(std::max(threads, 1)), mtl, model, warn, err);
}

bool load_obj_pieces(std::string_view text, const ObjSample& sample,
                     const std::vector<std::string_view>& pieces, const MtlLibraries& mtl, ObjModel& model,
                     std::string& warn, std::string& err) {
  std::vector<ObjChunk> chunks(pieces.size());
  parse_in_parallel(text, sample, pieces, chunks);

  // Indices that leave their piece: valid only if the earlier pieces define what they refer to.
  // Forward references (valid OBJ, but tinyobjloader may drop a quad using one) take the
  // reference path too.
  std::vector<Offsets> at(chunks.size() + 1);
  for (std::size_t i = 0; i < chunks.size(); ++i) {
    const ObjChunk& c = chunks[i];
    if (!c.ok) return false;
    const std::array<std::size_t, 3> counts{c.positions.size(), c.texcoords.size(), c.normals.size()};
    for (int kind = 0; kind < 3; ++kind) {
      if (c.highest_ahead[kind] > at[i].items[kind] || at[i].items[kind] + c.lowest_relative[kind] < 0)
        return false;
      at[i + 1].items[kind] = at[i].items[kind] + static_cast<int64_t>(counts[kind]);
    }
    at[i + 1].triangles = at[i].triangles + c.triangles.size();
    at[i + 1].lines = at[i].lines + c.lines;
  }
  if (at.back().items[0] >= INT32_MAX || at.back().triangles >= UINT32_MAX / 3) return false;

  // From here on the text is ours: no more fallbacks, so the MTL files load exactly once.
  ObjModel out;
  out.triangle_material = replay_materials(chunks, at, at.back().triangles, mtl, warn, err);
  out.triangle_smoothing = replay_smoothing(chunks, at, at.back().triangles);
  if (std::any_of(chunks.begin(), chunks.end(), [](const ObjChunk& c) { return !c.colors.empty(); }))
    for (ObjChunk& c : chunks)
      if (c.colors.empty()) c.colors.assign(c.positions.size(), Vec3f{1, 1, 1});
  fill_corner_indices(chunks, &ObjChunk::triangle_normals);
  fill_corner_indices(chunks, &ObjChunk::triangle_texcoords);
  std::vector<uint32_t> quads;
  std::vector<ObjChunk::Polygon> polygons;
  for (std::size_t i = 0; i < chunks.size(); ++i) {
    ObjChunk& c = chunks[i];
    for (uint32_t slot : c.relative[0])
      c.triangles[slot / 3][slot % 3] += static_cast<uint32_t>(at[i].items[0]);
    for (uint32_t slot : c.relative[1])
      c.triangle_texcoords[slot / 3][slot % 3] += static_cast<int32_t>(at[i].items[1]);
    for (uint32_t slot : c.relative[2])
      c.triangle_normals[slot / 3][slot % 3] += static_cast<int32_t>(at[i].items[2]);
    for (uint32_t q : c.quads) quads.push_back(q + static_cast<uint32_t>(at[i].triangles));
    for (ObjChunk::Polygon p : c.polygons)
      polygons.push_back({p.first + static_cast<uint32_t>(at[i].triangles), p.corners});
    append(out.mesh.positions, c.positions);
    append(out.colors, c.colors);
    append(out.normals, c.normals);
    append(out.texcoords, c.texcoords);
    append(out.mesh.triangles, c.triangles);
    append(out.triangle_normals, c.triangle_normals);
    append(out.triangle_texcoords, c.triangle_texcoords);
  }
  split_quads(quads, out);
  triangulate_polygons(polygons, out);
  out.materials = std::move(model.materials);
  out.warnings = std::move(model.warnings);
  model = std::move(out);
  return true;
}

}  // namespace rayvec
