// Cell-linked list against brute force on random particles, including particles on the domain
// edges, in 2D and 3D, with and without periodic axes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <vector>

#include "core/cell_list.hpp"

using namespace geosph;

namespace {

Particles random_particles(const Box& box, int n, unsigned seed) {
  Particles P;
  P.dim = box.dim;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  auto at = [&](int a, double f) { return box.lo[a] + f * box.length(a); };
  for (int i = 0; i < n; ++i) {
    double c[3] = {0, 0, 0};
    for (int a = 0; a < box.dim; ++a) c[a] = at(a, u(rng));
    // every 10th particle sits exactly on a lower face or just inside an upper face
    if (i % 10 == 0) c[i % box.dim] = box.lo[i % box.dim];
    if (i % 10 == 5) c[i % box.dim] = std::nextafter(box.hi[i % box.dim], box.lo[i % box.dim]);
    P.add(c[0], c[1], c[2], 1.0, 1.0, Kind::Fluid, 0);
  }
  return P;
}

double min_image(double d, const Box& box, int a) {
  if (!box.periodic[a]) return d;
  const double L = box.length(a);
  return d - L * std::round(d / L);
}

void compare_with_brute_force(const Box& box, double radius, int n, unsigned seed, bool permute) {
  Particles P = random_particles(box, n, seed);
  CellList cl;
  ASSERT_EQ(cl.build(P, box, radius), -1);
  if (permute) {
    P.permute(cl.sorted());
    cl.mark_permuted();
  }
  std::size_t pairs = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    std::set<std::size_t> expect, got;
    for (std::size_t j = 0; j < P.size(); ++j) {
      if (j == i) continue;
      const double dx = min_image(P.x[i] - P.x[j], box, 0), dy = min_image(P.y[i] - P.y[j], box, 1),
                   dz = min_image(P.z[i] - P.z[j], box, 2);
      if (dx * dx + dy * dy + dz * dz < radius * radius) expect.insert(j);
    }
    cl.for_each_neighbor(P, i, [&](std::size_t j, double dx, double dy, double dz, double r2) {
      EXPECT_TRUE(got.insert(j).second) << "neighbour " << j << " visited twice";
      EXPECT_NEAR(r2, dx * dx + dy * dy + dz * dz, 1e-15);
      EXPECT_NEAR(dx, min_image(P.x[i] - P.x[j], box, 0), 1e-12);
    });
    EXPECT_EQ(got, expect) << "particle " << i << " at (" << P.x[i] << ", " << P.y[i] << ", " << P.z[i] << ")";
    pairs += got.size();
  }
  EXPECT_GT(pairs, 0u);
}

}  // namespace

TEST(CellList, MatchesBruteForce2D) {
  Box box; box.dim = 2; box.lo = {-0.3, 0.1, 0}; box.hi = {0.7, 0.65, 0};
  compare_with_brute_force(box, 0.06, 1500, 1, false);
  compare_with_brute_force(box, 0.06, 1500, 2, true);
}

TEST(CellList, MatchesBruteForce3D) {
  Box box; box.dim = 3; box.lo = {0, 0, 0}; box.hi = {0.5, 0.4, 0.3};
  compare_with_brute_force(box, 0.07, 1200, 3, true);
}

TEST(CellList, MatchesBruteForcePeriodic) {
  Box box; box.dim = 2; box.lo = {0, 0, 0}; box.hi = {0.3, 0.5, 0}; box.periodic = {true, false, false};
  compare_with_brute_force(box, 0.08, 800, 4, false);
  Box box3; box3.dim = 3; box3.lo = {0, 0, 0}; box3.hi = {0.3, 0.3, 0.3}; box3.periodic = {true, true, true};
  compare_with_brute_force(box3, 0.09, 800, 5, true);
}

// for_each_near_point (a ghost wall's mirror point): every particle within radius of an arbitrary point,
// minimum image on periodic axes, the same as brute force, also after the particles are permuted.
TEST(CellList, PointQueryMatchesBruteForce) {
  Box box; box.dim = 2; box.lo = {0, 0, 0}; box.hi = {0.6, 0.5, 0}; box.periodic = {true, false, false};
  for (const bool permute : {false, true}) {
    Particles P = random_particles(box, 1200, 7);
    CellList cl;
    const double radius = 0.07;
    ASSERT_EQ(cl.build(P, box, radius), -1);
    if (permute) {
      P.permute(cl.sorted());
      cl.mark_permuted();
    }
    std::mt19937 rng(8);
    std::uniform_real_distribution<double> ux(0.0, 0.6), uy(0.0, 0.5);
    std::size_t found = 0;
    for (int q = 0; q < 200; ++q) {
      const double x = q == 0 ? 0.0 : ux(rng), y = q == 1 ? 0.5 : uy(rng);  // on the edges too
      std::set<std::size_t> expect, got;
      for (std::size_t j = 0; j < P.size(); ++j) {
        const double dx = min_image(x - P.x[j], box, 0), dy = y - P.y[j];
        if (dx * dx + dy * dy < radius * radius) expect.insert(j);
      }
      cl.for_each_near_point(P, x, y, 0.0, [&](std::size_t j, double dx, double dy, double dz, double r2) {
        EXPECT_TRUE(got.insert(j).second) << "particle " << j << " visited twice";
        EXPECT_NEAR(dx, min_image(x - P.x[j], box, 0), 1e-12);
        EXPECT_NEAR(dy, y - P.y[j], 1e-12);
        EXPECT_EQ(dz, 0.0);
        EXPECT_NEAR(r2, dx * dx + dy * dy, 1e-15);
      });
      EXPECT_EQ(got, expect) << "point (" << x << ", " << y << ")";
      found += got.size();
    }
    EXPECT_GT(found, 1000u);
  }
}

TEST(CellList, SortedIsAPermutationGroupedByCell) {
  Box box; box.dim = 2; box.lo = {0, 0, 0}; box.hi = {1, 1, 0};
  Particles P = random_particles(box, 500, 6);
  CellList cl;
  cl.build(P, box, 0.1);
  std::vector<std::uint32_t> s = cl.sorted();
  std::sort(s.begin(), s.end());
  for (std::uint32_t k = 0; k < s.size(); ++k) ASSERT_EQ(s[k], k);
  // consecutive particles in sorted order never go back to a lower cell
  const auto nc = cl.cells();
  EXPECT_GE(1.0 / nc[0], 0.1 / 2);  // cells are at least half the search radius wide
  auto cell = [&](std::uint32_t i) {
    return static_cast<int>(P.y[i] * nc[1]) * nc[0] + static_cast<int>(P.x[i] * nc[0]);
  };
  for (std::size_t k = 1; k < cl.sorted().size(); ++k) EXPECT_LE(cell(cl.sorted()[k - 1]), cell(cl.sorted()[k]));
}

TEST(CellList, ReportsParticleOutsideTheBox) {
  Box box; box.dim = 2; box.lo = {0, 0, 0}; box.hi = {1, 1, 0};
  Particles P = random_particles(box, 50, 7);
  P.x[17] = 1.0;  // the upper face is outside (half-open box)
  CellList cl;
  EXPECT_EQ(cl.build(P, box, 0.1), 17);
  EXPECT_EQ(cl.find_outside(P, box), 17);  // the check a step makes while its pair list is current
  P.x[17] = 0.5;
  P.y[3] = std::nan("");
  EXPECT_EQ(cl.build(P, box, 0.1), 3);
  EXPECT_EQ(cl.find_outside(P, box), 3);
  P.y[3] = 0.5;
  EXPECT_EQ(cl.find_outside(P, box), -1);
}

// A neighbour query inside another's pair function (e.g. a wall particle's sums within a fluid
// particle's loop) keeps both neighbour sets intact.
TEST(CellList, NestedQueriesKeepTheirNeighbours) {
  Box box;
  box.dim = 2;
  box.hi = {1, 1, 1};
  Particles P = random_particles(box, 400, 7);
  CellList cl;
  ASSERT_EQ(cl.build(P, box, 0.12), -1);
  for (std::size_t i = 0; i < P.size(); i += 37) {
    std::set<std::size_t> outer_alone;
    cl.for_each_neighbor(P, i, [&](std::size_t j, double, double, double, double) { outer_alone.insert(j); });
    std::set<std::size_t> outer;
    cl.for_each_neighbor(P, i, [&](std::size_t j, double, double, double, double) {
      outer.insert(j);
      std::set<std::size_t> inner, inner_alone;
      cl.for_each_neighbor(P, j, [&](std::size_t k, double, double, double, double) { inner.insert(k); });
      for (std::size_t k = 0; k < P.size(); ++k) {
        const double dx = P.x[j] - P.x[k], dy = P.y[j] - P.y[k];
        if (k != j && dx * dx + dy * dy < 0.12 * 0.12) inner_alone.insert(k);
      }
      EXPECT_EQ(inner, inner_alone);
    });
    EXPECT_EQ(outer, outer_alone);
  }
}

namespace {

struct Pair {
  std::size_t j;
  double dx, dy, dz, r2;
};

std::vector<Pair> neighbours(const CellList& cl, const Particles& P, std::size_t i) {
  std::vector<Pair> v;
  cl.for_each_neighbor(P, i, [&](std::size_t j, double dx, double dy, double dz, double r2) {
    v.push_back({j, dx, dy, dz, r2});
  });
  return v;
}

// The pair list's neighbours of every particle are the scan's, in ascending j, with the same bits.
void expect_list_matches_scan(const CellList& list, const Particles& P, const Box& box, double radius) {
  CellList scan;
  ASSERT_EQ(scan.build(P, box, radius), -1);
  ASSERT_FALSE(scan.pairs_cached());
  ASSERT_TRUE(list.pairs_cached());
  std::size_t pairs = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    std::vector<Pair> a = neighbours(scan, P, i), b = neighbours(list, P, i);
    std::sort(a.begin(), a.end(), [](const Pair& p, const Pair& q) { return p.j < q.j; });
    ASSERT_EQ(a.size(), b.size()) << "particle " << i;
    for (std::size_t k = 0; k < a.size(); ++k) {
      ASSERT_EQ(a[k].j, b[k].j) << "particle " << i;
      EXPECT_EQ(a[k].dx, b[k].dx);
      EXPECT_EQ(a[k].dy, b[k].dy);
      EXPECT_EQ(a[k].dz, b[k].dz);
      EXPECT_EQ(a[k].r2, b[k].r2);
    }
    pairs += b.size();
  }
  EXPECT_GT(pairs, P.size());
}

// Moves every particle by less than `most` (one that would leave the box stays).
void jiggle(Particles& P, const Box& box, double most, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double step = most / std::sqrt(3.0);
  for (std::size_t i = 0; i < P.size(); ++i) {
    const double x = P.x[i] + step * u(rng), y = P.y[i] + step * u(rng), z = box.dim == 3 ? P.z[i] + step * u(rng) : P.z[i];
    if (box.contains(x, y, z)) { P.x[i] = x; P.y[i] = y; P.z[i] = z; }
  }
}

void check_pair_list(const Box& box, double radius, int n, unsigned seed) {
  const double skin = 0.2 * radius;
  Particles P = random_particles(box, n, seed);
  CellList list;
  ASSERT_EQ(list.build(P, box, radius, skin), -1);
  EXPECT_FALSE(list.pairs_current(P));
  list.rebuild_pairs(P);
  expect_list_matches_scan(list, P, box, radius);
  // moves under half the skin keep the list, and it still has every pair
  for (int round = 0; round < 3; ++round) {
    jiggle(P, box, 0.16 * skin, seed + 10 + round);  // 3 rounds: up to 0.48 skin in all
    ASSERT_EQ(list.build(P, box, radius, skin), -1);
    EXPECT_TRUE(list.pairs_current(P)) << "round " << round;
    expect_list_matches_scan(list, P, box, radius);
  }
  // one particle beyond half the skin: rebuilt
  const std::size_t far = P.size() / 2;
  P.x[far] = box.lo[0] + std::fmod(P.x[far] - box.lo[0] + 0.51 * skin, box.length(0));
  ASSERT_EQ(list.build(P, box, radius, skin), -1);
  EXPECT_FALSE(list.pairs_current(P));
  list.rebuild_pairs(P);
  expect_list_matches_scan(list, P, box, radius);
  // a permutation renames the particles: rebuilt
  P.permute(list.sorted());
  list.mark_permuted();
  EXPECT_FALSE(list.pairs_cached());
  EXPECT_FALSE(list.pairs_current(P));
  list.rebuild_pairs(P);
  expect_list_matches_scan(list, P, box, radius);
  EXPECT_EQ(list.pair_list_builds(), 3);
}

}  // namespace

TEST(CellList, PairListGivesTheScansNeighboursUntilAParticleMovesHalfTheSkin) {
  Box box2; box2.dim = 2; box2.lo = {-0.3, 0.1, 0}; box2.hi = {0.7, 0.65, 0};
  check_pair_list(box2, 0.06, 1500, 21);
  Box box3; box3.dim = 3; box3.lo = {0, 0, 0}; box3.hi = {0.5, 0.4, 0.3};
  check_pair_list(box3, 0.07, 1200, 22);
}

TEST(CellList, PairListAcrossPeriodicBoundaries) {
  Box box2; box2.dim = 2; box2.lo = {0, 0, 0}; box2.hi = {0.3, 0.5, 0}; box2.periodic = {true, false, false};
  check_pair_list(box2, 0.08, 800, 23);
  Box box3; box3.dim = 3; box3.lo = {0, 0, 0}; box3.hi = {0.3, 0.3, 0.3}; box3.periodic = {true, true, true};
  check_pair_list(box3, 0.09, 800, 24);
}

namespace {

// A gather restricted to some kinds (ranges_of) returns exactly the full gather's neighbours of those
// kinds, in its order and with its bits: with the kinds interleaved (loose ranges) and in index blocks
// (a two-phase reorder, for which rebuild_pairs first puts each list in block order).
void check_kind_ranges(const Box& box, double radius, int n, unsigned seed, bool blocks) {
  Particles P = random_particles(box, n, seed);
  const Kind kinds[3] = {Kind::Soil, Kind::Fluid, Kind::DummyWall};
  for (std::size_t i = 0; i < P.size(); ++i) P.kind[i] = kinds[(i * 7 + i / 5) % 3];
  CellList cl;
  ASSERT_EQ(cl.build(P, box, radius, 0.2 * radius), -1);
  if (blocks) {
    std::vector<std::uint32_t> order;
    for (const Kind k : kinds)
      for (const std::uint32_t i : cl.sorted())
        if (P.kind[i] == k) order.push_back(i);
    P.permute(order);
    ASSERT_EQ(cl.build(P, box, radius, 0.2 * radius), -1);
  }
  cl.rebuild_pairs(P);
  ASSERT_TRUE(cl.pairs_cached());
  for (std::size_t i = 0; i + 1 < P.size(); ++i) {  // each list ascending
    const auto l = cl.listed(i);
    ASSERT_TRUE(std::is_sorted(l.begin(), l.end())) << "particle " << i;
  }
  const std::vector<std::vector<Kind>> sets = {{Kind::Fluid}, {Kind::Soil, Kind::DummyWall}, {Kind::DummyWall, Kind::Fluid},
                                               {Kind::Soil, Kind::Fluid, Kind::DummyWall}, {Kind::Structure}};
  Neighbors all, some;
  std::size_t kept_total = 0, full_total = 0;
  for (const auto& set : sets) {
    IndexRanges r;
    if (set.size() == 1) r = cl.ranges_of({set[0]});
    else if (set.size() == 2) r = cl.ranges_of({set[0], set[1]});
    else r = cl.ranges_of({set[0], set[1], set[2]});
    for (std::size_t i = 0; i < P.size(); ++i) {
      cl.gather_any_dim(P, i, all);
      cl.gather_any_dim(P, i, some, r);
      const auto in_set = [&](std::uint32_t j) { return std::find(set.begin(), set.end(), P.kind[j]) != set.end(); };
      // the restricted gather may return others of the other kinds (loose ranges), never fewer of these
      std::vector<std::size_t> a, b;
      for (std::size_t k = 0; k < all.n; ++k)
        if (in_set(all.j[k])) a.push_back(k);
      for (std::size_t k = 0; k < some.n; ++k)
        if (in_set(some.j[k])) b.push_back(k);
      ASSERT_EQ(a.size(), b.size()) << "particle " << i;
      for (std::size_t q = 0; q < a.size(); ++q) {
        EXPECT_EQ(some.j[b[q]], all.j[a[q]]);
        EXPECT_EQ(some.dx[b[q]], all.dx[a[q]]);
        EXPECT_EQ(some.dy[b[q]], all.dy[a[q]]);
        EXPECT_EQ(some.r2[b[q]], all.r2[a[q]]);
      }
      if (blocks) {
        EXPECT_EQ(b.size(), some.n) << "particle " << i;  // tight ranges: only these kinds
      }
      kept_total += some.n;
      full_total += all.n;
    }
  }
  if (blocks) {
    EXPECT_LT(kept_total, full_total);  // the blocks let the queries skip the other kinds
  }
}

}  // namespace

TEST(CellList, KindRestrictedGatherKeepsTheFullGathersNeighboursOfThoseKinds) {
  Box box2; box2.dim = 2; box2.lo = {0, 0, 0}; box2.hi = {0.6, 0.4, 0};
  check_kind_ranges(box2, 0.06, 1200, 31, false);
  check_kind_ranges(box2, 0.06, 1200, 31, true);
  Box box3; box3.dim = 3; box3.hi = {0.3, 0.3, 0.3}; box3.periodic = {true, false, true};
  check_kind_ranges(box3, 0.09, 900, 32, true);
}

TEST(CellList, NoSkinKeepsNoPairList) {
  Box box; box.dim = 2; box.hi = {1, 1, 1};
  Particles P = random_particles(box, 300, 25);
  CellList cl;
  ASSERT_EQ(cl.build(P, box, 0.1), -1);
  cl.rebuild_pairs(P);
  EXPECT_FALSE(cl.pairs_cached());
  EXPECT_FALSE(cl.pairs_current(P));
}

namespace {

// The point list (ghost walls' mirror points): each query point rides on a particle at a fixed offset;
// after moves under half the skin, the listed query gives the scan's neighbours of the kept kind in the
// scan's order with the same bits, and a stale list (after a rebuild of the pairs) falls back to the scan.
void check_point_list(const Box& box, double radius, int n, unsigned seed) {
  const double skin = 0.2 * radius;
  Particles P = random_particles(box, n, seed);
  for (std::size_t i = 0; i < P.size(); i += 3) P.kind[i] = Kind::DummyWall;  // the carriers, and not kept
  const double off[3] = {0.3 * radius, -0.2 * radius, box.dim == 3 ? 0.1 * radius : 0.0};
  const auto point_of = [&](std::size_t q, double xq[3]) {
    if (P.kind[q] != Kind::DummyWall) return false;
    const double p[3] = {P.x[q] + off[0], P.y[q] + off[1], P.z[q] + off[2]};
    for (int a = 0; a < 3; ++a) xq[a] = p[a];
    return true;  // a point outside the box is queried too (the cell scan clamps to the edge cells)
  };
  CellList cl;
  ASSERT_EQ(cl.build(P, box, radius, skin), -1);
  cl.rebuild_pairs(P);
  PointList pl;
  EXPECT_FALSE(cl.point_list_current(pl));
  cl.list_near_points(P, P.size(), point_of, [&](std::uint32_t j) { return P.kind[j] == Kind::Fluid; }, pl);
  EXPECT_TRUE(cl.point_list_current(pl));
  std::size_t found = 0;
  for (int round = 0; round < 3; ++round) {
    if (round > 0) {
      jiggle(P, box, 0.16 * skin, seed + 30 + round);  // as a step does: cells kept while the pairs are current
      ASSERT_EQ(cl.find_outside(P, box), -1);
      ASSERT_TRUE(cl.pairs_current(P));
    }
    for (std::size_t q = 0; q < P.size(); ++q) {
      double xq[3];
      if (!point_of(q, xq)) continue;
      std::vector<Pair> scan, listed;
      cl.for_each_near_point(P, xq[0], xq[1], xq[2], [&](std::uint32_t j, double dx, double dy, double dz, double r2) {
        if (P.kind[j] == Kind::Fluid) scan.push_back({j, dx, dy, dz, r2});
      });
      cl.for_each_near_point(P, pl, q, xq[0], xq[1], xq[2], [&](std::uint32_t j, double dx, double dy, double dz, double r2) {
        listed.push_back({j, dx, dy, dz, r2});
      });
      ASSERT_EQ(scan.size(), listed.size()) << "point " << q << ", round " << round;
      for (std::size_t k = 0; k < scan.size(); ++k) {
        ASSERT_EQ(scan[k].j, listed[k].j) << "point " << q;
        EXPECT_EQ(scan[k].dx, listed[k].dx);
        EXPECT_EQ(scan[k].dy, listed[k].dy);
        EXPECT_EQ(scan[k].dz, listed[k].dz);
        EXPECT_EQ(scan[k].r2, listed[k].r2);
      }
      found += listed.size();
    }
  }
  EXPECT_GT(found, P.size());
  cl.rebuild_pairs(P);  // a new build: the list is stale and the query scans
  EXPECT_FALSE(cl.point_list_current(pl));
  std::size_t all = 0;
  cl.for_each_near_point(P, pl, 0, P.x[0] + off[0], P.y[0] + off[1], P.z[0] + off[2],
                         [&](std::uint32_t, double, double, double, double) { ++all; });
  std::size_t expect = 0;
  cl.for_each_near_point(P, P.x[0] + off[0], P.y[0] + off[1], P.z[0] + off[2],
                         [&](std::uint32_t, double, double, double, double) { ++expect; });
  EXPECT_EQ(all, expect);
}

}  // namespace

TEST(CellList, PointListGivesTheScansNeighboursInItsOrder) {
  Box box2; box2.dim = 2; box2.lo = {-0.3, 0.1, 0}; box2.hi = {0.7, 0.65, 0};
  check_point_list(box2, 0.06, 1500, 31);
  Box box3; box3.dim = 3; box3.lo = {0, 0, 0}; box3.hi = {0.5, 0.4, 0.3};
  check_point_list(box3, 0.07, 1200, 32);
}

TEST(CellList, PointListAcrossPeriodicBoundaries) {
  Box box2; box2.dim = 2; box2.lo = {0, 0, 0}; box2.hi = {0.3, 0.5, 0}; box2.periodic = {true, false, false};
  check_point_list(box2, 0.08, 800, 33);
  Box box3; box3.dim = 3; box3.lo = {0, 0, 0}; box3.hi = {0.3, 0.3, 0.3}; box3.periodic = {true, true, true};
  check_point_list(box3, 0.09, 800, 34);
}

TEST(CellList, PointListNeedsThePairList) {
  Box box; box.dim = 2; box.hi = {1, 1, 1};
  Particles P = random_particles(box, 100, 35);
  CellList cl;
  ASSERT_EQ(cl.build(P, box, 0.1), -1);
  PointList pl;
  EXPECT_THROW(cl.list_near_points(P, P.size(), [](std::size_t, double*) { return false; },
                                   [](std::uint32_t) { return true; }, pl),
               std::logic_error);
}
