// Mirror walls (walls.type "mirror", fluids and dry soil): ghost particles made afresh at every step by
// mirroring the material across the walls (Libersky, Petschek, Carney, Hipp & Allahdadi 1993, J. Comput. Phys. 109,
// 67-75; Randles & Libersky 1996, Comput. Methods Appl. Mech. Engrg. 139, 375-408, Sec. 5). They are
// not stored as particles: a fluid particle i within the kernel support of a wall sees, besides its
// neighbours x_j, their images T(x_j) across the wall planes near it (fluid/fluid_mirror_images.cpp).
//   Container faces: the planes x_a = min_a or max_a of its closed sides; near two (three) faces on
//   different axes a particle also sees the double (triple) mirror, the corner's image (Randles &
//   Libersky 1996). Two parallel faces (a channel narrower than two supports) each give their single
//   image, and no composite: the images of the images would be translations, an infinite series.
//   Curved and inclined walls (walls.boundaries): the multiple boundary tangent method (Yildiz, Rook &
//   Suleman 2009, Int. J. Numer. Meth. Engng 77, 1416-1438): particle i mirrors across the tangent
//   plane of each smooth piece of the surface within its support, at the piece's point nearest to it
//   (geometry::Shape::tangent_planes), so each particle has its own tangents and image set. Near a
//   corner the images across each tangent are kept only on the solid side their own plane fills
//   (MirrorSet::keep); at a right-angled concave corner the double image fills the solid behind both.
// An image is the affine map x' = R x + t, R = I - 2 n n^T per plane (n: the unit normal into the
// fluid); the composite of planes on different axes is the product of their maps. Each map is its own
// inverse, so the images within the support of x_i are the particles within the support of T(x_i).
// The image of particle j carries (fluid/fluid_mirror_images.cpp): its mass, the velocity R v_j (free
// slip: tangential velocity kept, normal velocity reversed) or -v_j (no slip: zero velocity on the
// wall), and the pressure p_j + rho_j g . (x_j' - x_j) - the hydrostatic step, the Neumann condition
// dp/dn = rho g . n of the momentum equation at a fixed wall - with the density the equation of state
// gives for it. Walls are fixed: a scene with mirror walls has no blocks (moving boxes are particles).
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "core/particles.hpp"
#include "geometry/shape.hpp"
#include "io/scene.hpp"

namespace geosph {

// One image map x' = R x + t, and the slip of the wall that made it.
struct MirrorImage {
  std::array<double, 9> R{};  // row-major, symmetric and orthogonal (a product of reflections)
  std::array<double, 3> t{};
  bool free_slip = false;
  // boundary images: the tangent planes (MirrorSet::planes) mirrored across, -1 for none
  int plane = -1, plane2 = -1;
  // the unit direction from the fluid into the wall (a corner's: along its diagonal)
  std::array<double, 3> into{};

  std::array<double, 3> apply(const double x[3]) const {
    std::array<double, 3> y{};
    for (int a = 0; a < 3; ++a) y[a] = R[3 * a] * x[0] + R[3 * a + 1] * x[1] + R[3 * a + 2] * x[2] + t[a];
    return y;
  }
  // R v (the linear part: displacements, free-slip velocities)
  std::array<double, 3> rotate(const double v[3]) const {
    std::array<double, 3> y{};
    for (int a = 0; a < 3; ++a) y[a] = R[3 * a] * v[0] + R[3 * a + 1] * v[1] + R[3 * a + 2] * v[2];
    return y;
  }
};

// A tangent plane of a boundary near a particle: the solid lies behind it (s(y) = n . (y - c) < 0).
struct MirrorPlane {
  std::array<double, 3> c{}, n{};
  int wall = 0;  // walls.boundaries index: planes of one wall are filtered against each other
  double side(const double y[3]) const { return n[0] * (y[0] - c[0]) + n[1] * (y[1] - c[1]) + n[2] * (y[2] - c[2]); }
};

// The images of one particle, and the boundary tangent planes they come from.
struct MirrorSet {
  std::vector<MirrorImage> images;
  std::vector<MirrorPlane> planes;
  // convex[m * planes.size() + k]: around the corner of planes m and k the solid is convex (the
  // fluid wraps around it: the solid is behind both), else concave (the solid is behind either)
  std::vector<std::uint8_t> convex;
  // Whether an image point y of T belongs to the solid side that T's plane fills (multiple boundary
  // tangents: near a corner the images across each tangent would overlap or spill into the fluid).
  // Behind its plane m; and for each other plane k of the same wall: at a convex corner behind k too (in
  // the solid), at a concave corner deeper behind m than behind k (the solid behind both is shared by
  // depth, so no point is filled twice). A double image (plane2) must be behind both its planes.
  bool keep(const MirrorImage& T, const double y[3]) const {
    if (T.plane < 0) return true;
    const MirrorPlane& m = planes[T.plane];
    const double sm = m.side(y);
    if (!(sm < 0)) return false;
    if (T.plane2 >= 0) return planes[T.plane2].side(y) < 0;
    for (std::size_t k = 0; k < planes.size(); ++k) {
      if (static_cast<int>(k) == T.plane || planes[k].wall != m.wall) continue;
      const double sk = planes[k].side(y);
      if (convex[T.plane * planes.size() + k] ? sk > 0 : sm > sk) return false;
    }
    return true;
  }
};

class MirrorWalls {
 public:
  explicit MirrorWalls(const Scene& scene);
  // The images seen by a particle at x (appended to `out`, which is cleared first): those of every wall
  // whose surface lies within the kernel support of x, on either side of it (a particle that has
  // crossed a face still sees its image, which pushes it back).
  void images(const double x[3], MirrorSet& out) const;
  // A fluid or soil particle that has crossed a wall within the last support (its image force vanishes as it
  // reaches the surface: the normal offset of its images shrinks with its distance, where a wall particle
  // of the other treatments stays dx/2 behind the surface) is reflected back across it, its normal
  // velocity reversed, as a specular bounce. Returns the particles reflected.
  std::size_t reflect_crossings(Particles& P) const;

 private:
  struct Face {
    int axis;
    double position;
    double sign;  // +1: the fluid is at x_axis > position (a min face); -1: a max face
  };
  struct Container {
    std::array<double, 3> lo, hi;
    std::vector<Face> faces;  // closed, non-periodic
    bool free_slip;
  };
  struct Boundary {
    geometry::ShapePtr shape;
    bool free_slip;
  };
  int dim_;
  double reach_, normal_step_;
  std::vector<Container> containers_;
  std::vector<Boundary> boundaries_;
};

}  // namespace geosph
