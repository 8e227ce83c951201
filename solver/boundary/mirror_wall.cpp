#include "boundary/mirror_wall.hpp"

#include <algorithm>
#include <cmath>

namespace geosph {

namespace {

MirrorImage identity(bool free_slip) {
  MirrorImage m;
  m.R = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  m.free_slip = free_slip;
  return m;
}

// The reflection across the plane through c with unit normal n: R = I - 2 n n^T, t = 2 (c . n) n.
MirrorImage reflection(const double c[3], const double n[3], bool free_slip) {
  MirrorImage m = identity(free_slip);
  const double cn = c[0] * n[0] + c[1] * n[1] + c[2] * n[2];
  for (int a = 0; a < 3; ++a) {
    for (int b = 0; b < 3; ++b) m.R[3 * a + b] -= 2 * n[a] * n[b];
    m.t[a] = 2 * cn * n[a];
    m.into[a] = -n[a];
  }
  return m;
}

}  // namespace

MirrorWalls::MirrorWalls(const Scene& s)
    : dim_(s.dim), reach_(s.support()), normal_step_(1e-3 * s.dx) {
  for (const auto& c : s.walls.containers) {
    Container k{c.lo, c.hi, {}, c.slip == "free_slip"};
    for (int a = 0; a < s.dim; ++a) {
      if (s.domain.periodic[a]) continue;
      for (const bool upper : {false, true}) {
        const char* side = container_side(s.dim, a, upper);
        if (std::find(c.open.begin(), c.open.end(), side) != c.open.end()) continue;
        k.faces.push_back({a, upper ? c.hi[a] : c.lo[a], upper ? -1.0 : 1.0});
      }
    }
    containers_.push_back(std::move(k));
  }
  for (const auto& b : s.walls.boundaries) {
    boundaries_.push_back({b.shape, b.slip == "free_slip"});
  }
}

void MirrorWalls::images(const double x[3], MirrorSet& set) const {
  std::vector<MirrorImage>& out = set.images;
  out.clear();
  set.planes.clear();
  for (const auto& c : containers_) {
    bool near = true;  // within the container's box grown by the support
    for (int a = 0; a < dim_; ++a) near = near && x[a] > c.lo[a] - reach_ && x[a] < c.hi[a] + reach_;
    if (!near) continue;
    const std::size_t first = out.size();
    for (const Face& f : c.faces) {
      if (std::abs(x[f.axis] - f.position) >= reach_) continue;
      // the face's reflection x_a -> 2 position - x_a, alone and composed with each image so far made
      // from faces on other axes (the composite maps commute: the axes differ)
      MirrorImage single = identity(c.free_slip);
      single.R[4 * f.axis] = -1;
      single.t[f.axis] = 2 * f.position;
      single.into[f.axis] = -f.sign;
      const std::size_t made = out.size();
      for (std::size_t k = first; k < made; ++k) {
        const MirrorImage& o = out[k];
        if (o.R[4 * f.axis] < 0) continue;  // already mirrored on this axis (the parallel face)
        MirrorImage comp = o;
        comp.R[4 * f.axis] = -1;
        comp.t[f.axis] = 2 * f.position;
        comp.into[f.axis] = -f.sign;  // components +-1, normalised below
        out.push_back(comp);
      }
      out.push_back(single);
    }
    for (std::size_t k = first; k < out.size(); ++k) {
      auto& v = out[k].into;
      const double len = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
      for (auto& c2 : v) c2 /= len;
    }
  }
  std::vector<geometry::TangentPlane> tangents;
  const std::size_t image0 = out.size();  // boundary plane k's single image is out[image0 + k]
  for (std::size_t w = 0; w < boundaries_.size(); ++w) {
    const Boundary& b = boundaries_[w];
    const geometry::Point p{x[0], x[1], dim_ == 3 ? x[2] : 0.0};
    tangents.clear();
    b.shape->tangent_planes(p, reach_, tangents);
    const std::size_t first = set.planes.size();
    for (const auto& t : tangents) {
      MirrorPlane m{t.point, t.normal, static_cast<int>(w)};
      if (dim_ == 2) { m.c[2] = 0; m.n[2] = 0; }
      bool repeated = false;  // the same plane from two pieces (a face shared by two parts)
      for (std::size_t k = first; k < set.planes.size(); ++k)
        repeated = repeated || (std::abs(set.planes[k].side(m.c.data())) < 1e-9 * reach_ &&
                                m.n[0] * set.planes[k].n[0] + m.n[1] * set.planes[k].n[1] + m.n[2] * set.planes[k].n[2] > 1 - 1e-9);
      if (!repeated) set.planes.push_back(m);
    }
    for (std::size_t k = first; k < set.planes.size(); ++k) {
      out.push_back(reflection(set.planes[k].c.data(), set.planes[k].n.data(), b.free_slip));
      out.back().plane = static_cast<int>(k);
    }
  }
  // the corner type of each pair of a wall's planes, and the double image of a right-angled concave pair
  const std::size_t np = set.planes.size();
  set.convex.assign(np * np, 0);
  for (std::size_t m = 0; m < np; ++m)
    for (std::size_t k = m + 1; k < np; ++k) {
      const MirrorPlane &A = set.planes[m], &B = set.planes[k];
      if (A.wall != B.wall) continue;
      const double cosab = A.n[0] * B.n[0] + A.n[1] * B.n[1] + A.n[2] * B.n[2];
      if (std::abs(cosab) > 1 - 1e-6) continue;  // parallel: no corner between them
      // a point just behind A and just in front of B near A's tangent point: solid there means a
      // concave corner (the solid behind either plane), fluid a convex one (the solid behind both)
      const double delta = 1e-3 * reach_, sb = B.side(A.c.data());
      // c_A + alpha n_A + beta n_B with side_A = -delta, side_B = +delta
      const double det = 1 - cosab * cosab;
      const double alpha = (-delta - cosab * (delta - sb)) / det, beta = (delta - sb + cosab * delta) / det;
      const geometry::Point z{A.c[0] + alpha * A.n[0] + beta * B.n[0], A.c[1] + alpha * A.n[1] + beta * B.n[1],
                              A.c[2] + alpha * A.n[2] + beta * B.n[2]};
      const bool convex = boundaries_[A.wall].shape->distance(z) > 0;
      set.convex[m * np + k] = set.convex[k * np + m] = convex ? 1 : 0;
      if (!convex && std::abs(cosab) < 1e-6) {  // a right angle: the double mirror, commuting reflections
        const MirrorImage ta = out[image0 + m];
        MirrorImage both = reflection(B.c.data(), B.n.data(), ta.free_slip);
        MirrorImage comp = both;
        for (int r = 0; r < 3; ++r)
          for (int c = 0; c < 3; ++c) {
            double v = 0;
            for (int q = 0; q < 3; ++q) v += ta.R[3 * r + q] * both.R[3 * q + c];
            comp.R[3 * r + c] = v;
          }
        // T_A(T_B(x)) = R_A (R_B x + t_B) + t_A
        for (int r = 0; r < 3; ++r) comp.t[r] = ta.t[r] + ta.R[3 * r] * both.t[0] + ta.R[3 * r + 1] * both.t[1] + ta.R[3 * r + 2] * both.t[2];
        comp.plane = static_cast<int>(m);
        comp.plane2 = static_cast<int>(k);
        for (int r = 0; r < 3; ++r) comp.into[r] = -(set.planes[m].n[r] + set.planes[k].n[r]) / std::sqrt(2.0);
        out.push_back(comp);
      }
    }
}

std::size_t MirrorWalls::reflect_crossings(Particles& P) const {
  const std::size_t n = P.size();
  std::size_t reflected = 0;
#pragma omp parallel for schedule(static) reduction(+ : reflected)
  for (std::size_t i = 0; i < n; ++i) {
    if (P.kind[i] != Kind::Fluid && P.kind[i] != Kind::Soil) continue;
    double* x[3] = {&P.x[i], &P.y[i], &P.z[i]};
    double* v[3] = {&P.vx[i], &P.vy[i], &P.vz[i]};
    bool crossed = false;
    for (const auto& c : containers_) {
      bool near = true;
      for (int a = 0; a < dim_; ++a) near = near && *x[a] > c.lo[a] - reach_ && *x[a] < c.hi[a] + reach_;
      if (!near) continue;
      for (const Face& f : c.faces) {
        const double s = f.sign * (*x[f.axis] - f.position);
        if (s >= 0 || s <= -reach_) continue;
        *x[f.axis] = 2 * f.position - *x[f.axis];
        *v[f.axis] = -*v[f.axis];
        crossed = true;
      }
    }
    for (const auto& b : boundaries_) {
      const geometry::Point p{*x[0], *x[1], dim_ == 3 ? *x[2] : 0.0};
      const double d = b.shape->distance(p);
      if (d >= 0 || d <= -reach_) continue;
      const geometry::Point nrm = geometry::outward_normal(*b.shape, p, normal_step_);
      const double vn = *v[0] * nrm[0] + *v[1] * nrm[1] + (dim_ == 3 ? *v[2] * nrm[2] : 0.0);
      for (int a = 0; a < dim_; ++a) {
        *x[a] -= 2 * d * nrm[a];
        if (vn < 0) *v[a] -= 2 * vn * nrm[a];
      }
      crossed = true;
    }
    reflected += crossed ? 1 : 0;
  }
  return reflected;
}

}  // namespace geosph
