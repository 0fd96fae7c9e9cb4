// The float `mt` kernels for several rays at once — the table's closest_group and occluded_group,
// which closest_batch and occluded_batch (brute force) call — and the `mt` table itself. Rays that
// start at one origin (a camera's, a visibility study's) share each step's triangle loads and its
// origin part (mt_origin_values) in groups; others go two at a time (closest) or one by one (any
// hit). Every ray gets bit for bit the hit it gets alone. Included by triangle_kernels_<isa>.cpp
// inside namespace rayvec::<isa>, after mt_float_rays.inl; no std:: calls here, as there.

// Whether rays[0..n) all start at t = 0 (the kernels' lower depth test then needs no product).
RAYVEC_INLINE bool tmin_all_zero(const Ray* rays, int n) {
  for (int k = 0; k < n; ++k)
    if (rays[k].tmin != 0.0f) return false;
  return true;
}

// R rays from one origin (bit for bit), every one finite, each ray testing every step itself: with
// the sign bits ANDed over the group (mt_any_ray_passes), with the ordered compares ray by ray.
template <class V, MtPretest P, int R>
void closest_mt_float_one_origin_per_ray(const TriangleArrays& T, uint32_t begin, uint32_t end,
                                         const Ray* rays, Hit* hits) {
  if (tmin_all_zero(rays, R))
    closest_mt_float_rays<V, true, R, P, true>(T, begin, end, rays, hits);
  else
    closest_mt_float_rays<V, false, R, P, true>(T, begin, end, rays, hits);
}

// R rays from one origin (bit for bit), every one finite: four rays and more take the crossed group
// test where the magnitudes allow it (a pair's share of its cross products would cost more than it
// saves), else go four at a time (larger groups of per-ray tests spill: not worth their code for so
// rare an input).
template <class V, MtPretest P, int R>
void closest_mt_float_one_origin(const TriangleArrays& T, uint32_t begin, uint32_t end, const Ray* rays,
                                 Hit* hits) {
  if constexpr (R >= 4) {
    const float slack = mt_crossed_slack(T, R, [rays](int k) -> const Ray& { return rays[k]; });
    if (slack >= 0.0f) {
      if (tmin_all_zero(rays, R))
        closest_mt_float_rays<V, true, R, P, true, true>(T, begin, end, rays, hits, slack);
      else
        closest_mt_float_rays<V, false, R, P, true, true>(T, begin, end, rays, hits, slack);
      return;
    }
    for (int k = 0; k < R; k += 4)
      closest_mt_float_one_origin_per_ray<V, P, 4>(T, begin, end, rays + k, hits + k);
  } else {
    closest_mt_float_one_origin_per_ray<V, P, R>(T, begin, end, rays, hits);
  }
}

// Whether rays[0..n) are all finite and start at rays[0]'s origin, bit for bit.
RAYVEC_INLINE bool finite_one_origin(const Ray* rays, int n) {
  for (int k = 0; k < n; ++k)
    if (!finite_ray(rays[k]) || !same_bits(rays[k].org, rays[0].org)) return false;
  return true;
}

template <class V, MtPretest P = MtPretest::sign_bits>
void closest_pair_mt_float(const TriangleArrays& T, uint32_t begin, uint32_t end, const Ray* rays,
                           Hit* hits) {
  if (!finite_ray(rays[0]) || !finite_ray(rays[1])) {
    closest_mt_float<V, P>(T, begin, end, rays[0], hits[0]);
    closest_mt_float<V, P>(T, begin, end, rays[1], hits[1]);
  } else if (same_bits(rays[0].org, rays[1].org)) {
    closest_mt_float_one_origin<V, P, 2>(T, begin, end, rays, hits);
  } else if (rays[0].tmin == 0.0f && rays[1].tmin == 0.0f) {
    closest_mt_float_rays<V, true, 2, P>(T, begin, end, rays, hits);
  } else {
    closest_mt_float_rays<V, false, 2, P>(T, begin, end, rays, hits);
  }
}

// Rays from one origin go through the kernel in groups of kOneOriginGroup (closest_group_mt_float):
// the origin part and the crossed group test's cross products are then formed once for that many
// rays, and each triangle step is loaded once for them; the group test a step grows cheaper per ray
// with the group (benchmarks.md#decision-crossed-group-test).
inline constexpr int kOneOriginGroup = 16;

// rays[0..n): the largest group of kOneOriginGroup, 8 or 4 rays that start at one origin, else two
// at a time, an odd one alone.
template <class V, MtPretest P = MtPretest::sign_bits>
void closest_group_mt_float(const TriangleArrays& T, uint32_t begin, uint32_t end, const Ray* rays, Hit* hits,
                            std::size_t n) {
  constexpr int G = kOneOriginGroup;
  std::size_t k = 0;
  while (k + 2 <= n) {
    if (k + G <= n && finite_one_origin(rays + k, G)) {
      closest_mt_float_one_origin<V, P, G>(T, begin, end, rays + k, hits + k);
      k += G;
    } else if (G > 8 && k + 8 <= n && finite_one_origin(rays + k, 8)) {
      closest_mt_float_one_origin<V, P, 8>(T, begin, end, rays + k, hits + k);
      k += 8;
    } else if (G > 4 && k + 4 <= n && finite_one_origin(rays + k, 4)) {
      closest_mt_float_one_origin<V, P, 4>(T, begin, end, rays + k, hits + k);
      k += 4;
    } else {
      closest_pair_mt_float<V, P>(T, begin, end, rays + k, hits + k);
      k += 2;
    }
  }
  if (k < n) closest_mt_float<V, P>(T, begin, end, rays[k], hits[k]);
}

// The any-hit steps of a step for the open rays (bits of `done` clear); returns `done` with the rays
// that found a hit. Unrolled: left a loop, each ray's lanes are reloaded at every step.
template <class V, int R>
RAYVEC_INLINE unsigned mt_any_hit_open_steps(const TriangleArrays& T, const auto& at, uint32_t i,
                                             const MtAnyHitRay<V>* q, const MtOrigin<V>& o,
                                             typename V::Mask active, const HitFilter* const* filters,
                                             unsigned done) {
#pragma GCC unroll 16
  for (int k = 0; k < R; ++k)
    if (!(done >> k & 1u) &&
        mt_any_hit_step<V>(T, i, mt_numerator_values<V>(at, q[k].r, o), active, q[k], filters[k]))
      done |= 1u << k;
  return done;
}

// The same out of line, for the rare steps where the group's sign test passes (as mt_closest_steps).
template <class V, int R>
[[gnu::noinline, gnu::cold]] unsigned mt_any_hit_steps(const TriangleArrays& T, const auto& at, uint32_t i,
                                                       const MtAnyHitRay<V>* q, const MtOrigin<V>& o,
                                                       typename V::Mask active,
                                                       const HitFilter* const* filters, unsigned done) {
  return mt_any_hit_open_steps<V, R>(T, at, i, q, o, active, filters, done);
}

// R rays from one origin (finite, the origin bit for bit) against [begin, end) for any hit, each
// triangle step loaded and its origin part formed once for all of them (as closest_mt_float_rays
// does); *rays[k] with filters[k] (may be null). A ray drops out at its first hit, and the walk ends
// once every ray has. Returns the bits of the occluded rays.
// On the vector ISAs the rays' steps are first tested together — Crossed: by
// mt_any_ray_passes_crossed, widened by `slack` (mt_crossed_slack); else, with the sign-bit tables,
// by mt_any_ray_passes (as the closest-hit groups do; a ray that dropped out has its upper factor at
// −inf, which fails every lane) — and only where a lane may pass does each open ray run its ordered
// any-hit step: one mask instruction a step instead of five a ray. The same hits: the group tests
// read lo·|det| and hi·|det| unrounded (fused) where the ordered one rounds them, and a lane the two
// disagree on has t within an ulp of lo = tmin·(1 − 2^-20) or hi = limit·(1 + 2^-20), which the
// exact test (tmin <= t < limit) rejects either way. The scalar ISA keeps its per-ray branches:
// every ray's values formed before one test took it twice as long.
template <class V, int R, MtPretest P, bool Crossed>
unsigned occluded_mt_float_one_origin(const TriangleArrays& T, uint32_t begin, uint32_t end,
                                      const Ray* const* rays, const HitFilter* const* filters, float slack) {
  const V vslack = V::broadcast(slack);
  MtAnyHitRay<V> q[R];
  V neg_lo[R], open_hi[R];  // the group test's −lo and hi, hi at −inf once a ray is done
  for (int k = 0; k < R; ++k) {
    q[k] = mt_any_hit_ray<V>(*rays[k]);
    neg_lo[k] = V::broadcast(0.0f) - q[k].lo;
    open_hi[k] = q[k].hi;
  }
  unsigned done = 0;
  mt_steps<V>(
      T, begin, end, [&](const auto& at, uint32_t i, typename V::Mask active) __attribute__((always_inline)) {
        const MtOrigin<V> o = mt_origin_values<V>(at, q[0].r);
        if constexpr (Crossed || (P == MtPretest::sign_bits && V::W > 1)) {
          const auto hi = [&](int k) __attribute__((always_inline)) { return open_hi[k]; };
          bool passes;
          if constexpr (Crossed)
            passes = mt_any_ray_passes_crossed<V, false, R, P>(at, q, o, active, vslack, neg_lo, hi);
          else
            passes = mt_any_ray_passes<V, false, R>(at, q, o, active, neg_lo, hi);
          if (passes) {
            const unsigned now = mt_any_hit_steps<V, R>(T, at, i, q, o, active, filters, done);
            for (int k = 0; k < R; ++k)
              if ((now & ~done) >> k & 1u) open_hi[k] = V::broadcast(-__builtin_inff());
            done = now;
          }
        } else {
          done = mt_any_hit_open_steps<V, R>(T, at, i, q, o, active, filters, done);
        }
        return done == (1u << R) - 1u;
      });
  return done;
}

// R rays from one origin for any hit: on the vector ISAs the crossed group test where the
// magnitudes allow it, else four at a time (as closest_mt_float_one_origin).
template <class V, int R, MtPretest P>
unsigned occluded_mt_float_one_origin(const TriangleArrays& T, uint32_t begin, uint32_t end,
                                      const Ray* const* rays, const HitFilter* const* filters) {
  if constexpr (V::W > 1) {
    const float slack = mt_crossed_slack(T, R, [rays](int k) -> const Ray& { return *rays[k]; });
    if (slack >= 0.0f)
      return occluded_mt_float_one_origin<V, R, P, true>(T, begin, end, rays, filters, slack);
    if constexpr (R > 4) {
      unsigned occluded = 0;
      for (int k = 0; k < R; k += 4)
        occluded |= occluded_mt_float_one_origin<V, 4, P, false>(T, begin, end, rays + k, filters + k, 0.0f)
                    << k;
      return occluded;
    }
  }
  return occluded_mt_float_one_origin<V, R, P, false>(T, begin, end, rays, filters, 0.0f);
}

// Whether *rays[0..n) are all finite and start at rays[0]'s origin, bit for bit.
RAYVEC_INLINE bool finite_one_origin(const Ray* const* rays, int n) {
  for (int k = 0; k < n; ++k)
    if (!finite_ray(*rays[k]) || !same_bits(rays[k]->org, rays[0]->org)) return false;
  return true;
}

// Any-hit rays from one origin go through the kernel this many at a time: on the vector ISAs, whose
// groups have the crossed test, as many as the closest-hit groups; on the scalar one eight.
template <class V>
inline constexpr int kOccludedOneOriginGroup = V::W > 1 ? kMaxOccludedGroup : 8;

// *rays[0..n) (n <= kMaxOccludedGroup) for any hit, filters[k] (may be null) for rays[k]: the largest
// group of kOccludedOneOriginGroup<V>, 8 or 4 rays that start at one origin, else one by one.
// Returns the bits of the occluded rays.
template <class V, MtPretest P>
unsigned occluded_group_mt_float(const TriangleArrays& T, uint32_t begin, uint32_t end,
                                 const Ray* const* rays, const HitFilter* const* filters, int n) {
  constexpr int G = kOccludedOneOriginGroup<V>;
  unsigned occluded = 0;
  int k = 0;
  while (k < n) {
    if (k + G <= n && finite_one_origin(rays + k, G)) {
      occluded |= occluded_mt_float_one_origin<V, G, P>(T, begin, end, rays + k, filters + k) << k;
      k += G;
    } else if (G > 8 && k + 8 <= n && finite_one_origin(rays + k, 8)) {
      occluded |= occluded_mt_float_one_origin<V, 8, P>(T, begin, end, rays + k, filters + k) << k;
      k += 8;
    } else if (G > 4 && k + 4 <= n && finite_one_origin(rays + k, 4)) {
      occluded |= occluded_mt_float_one_origin<V, 4, P>(T, begin, end, rays + k, filters + k) << k;
      k += 4;
    } else {
      occluded |= unsigned(occluded_mt_float<V>(T, begin, end, *rays[k], filters[k])) << k;
      ++k;
    }
  }
  return occluded;
}

template <class V, Intersector I, MtPretest P = MtPretest::sign_bits>
constexpr TriangleKernels make_kernels(Isa isa) {
  if constexpr (I == Intersector::mt && sizeof(typename V::Scalar) == 4)
    return TriangleKernels{isa,
                           I,
                           V::W,
                           &closest_mt_float<V, P>,
                           &occluded_mt_float<V>,
                           &closest_group_mt_float<V, P>,
                           &occluded_group_mt_float<V, P>};
  else
    return TriangleKernels{isa, I, V::W, &closest_impl<V, I>, &occluded_impl<V, I>};
}
