#include "geometry/stl_mesh.hpp"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

namespace geosph::geometry {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
using Primitive = CGAL::AABB_face_graph_triangle_primitive<Mesh>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;

using Triangle = std::array<std::array<double, 3>, 3>;

// Binary STL: 80-byte header, uint32 count, then 50 bytes per triangle (normal, 3 vertices as float32,
// uint16 attribute); recognised by its exact size. Otherwise ASCII: "vertex x y z" lines in threes.
std::vector<Triangle> read_triangles(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw ShapeError(file.string() + ": cannot be read");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<Triangle> tris;
  if (bytes.size() >= 84) {
    std::uint32_t n = 0;
    std::memcpy(&n, bytes.data() + 80, 4);
    if (bytes.size() == 84 + 50ull * n) {
      tris.resize(n);
      for (std::uint32_t t = 0; t < n; ++t)
        for (int v = 0; v < 3; ++v)
          for (int a = 0; a < 3; ++a) {
            float f = 0;
            std::memcpy(&f, bytes.data() + 84 + 50ull * t + 12 + 12 * v + 4 * a, 4);
            if (!std::isfinite(f)) throw ShapeError(file.string() + ": triangle " + std::to_string(t) + " has a non-finite vertex");
            tris[t][v][a] = f;
          }
      return tris;
    }
  }
  std::istringstream s(bytes);
  std::string word;
  std::vector<std::array<double, 3>> verts;
  long line_vertices = 0;
  while (s >> word) {
    if (word != "vertex") continue;
    std::array<double, 3> p{};
    if (!(s >> p[0] >> p[1] >> p[2]) || !std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      throw ShapeError(file.string() + ": vertex " + std::to_string(line_vertices) + " is not three finite numbers");
    verts.push_back(p);
    ++line_vertices;
  }
  if (verts.size() % 3 != 0)
    throw ShapeError(file.string() + ": " + std::to_string(verts.size()) + " vertices is not a whole number of triangles");
  for (std::size_t k = 0; k < verts.size(); k += 3) tris.push_back({verts[k], verts[k + 1], verts[k + 2]});
  return tris;
}

class StlSurface final : public Shape {
 public:
  explicit StlSurface(const std::filesystem::path& file) : Shape(3) {
    const auto tris = read_triangles(file);
    if (tris.empty()) throw ShapeError(file.string() + ": holds no triangle (neither binary STL nor ASCII 'vertex' lines)");
    std::vector<K::Point_3> points;
    std::vector<std::array<std::size_t, 3>> polys;
    std::map<std::array<double, 3>, std::size_t> index;  // shared vertices by their exact coordinates
    for (const auto& t : tris) {
      std::array<std::size_t, 3> f{};
      for (int v = 0; v < 3; ++v) {
        auto [it, fresh] = index.try_emplace(t[v], points.size());
        if (fresh) points.emplace_back(t[v][0], t[v][1], t[v][2]);
        f[v] = it->second;
      }
      if (f[0] == f[1] || f[1] == f[2] || f[0] == f[2]) continue;  // a degenerate (zero-area) facet
      polys.push_back(f);
    }
    namespace PMP = CGAL::Polygon_mesh_processing;
    if (!PMP::orient_polygon_soup(points, polys))
      throw ShapeError(file.string() + ": the triangles do not form one consistently oriented 2-manifold surface (an edge or vertex shared by more than one sheet)");
    PMP::polygon_soup_to_polygon_mesh(points, polys, mesh_);
    if (!CGAL::is_closed(mesh_)) {
      long border = 0;
      for (auto h : mesh_.halfedges()) border += mesh_.is_border(h) ? 1 : 0;
      throw ShapeError(file.string() + ": the surface is not closed (" + std::to_string(border) +
                       " border edges): a solid needs a watertight STL");
    }
    if (!PMP::is_outward_oriented(mesh_)) PMP::reverse_face_orientations(mesh_);
    volume_ = std::abs(PMP::volume(mesh_));
    const auto bb = PMP::bbox(mesh_);
    lo_ = {bb.xmin(), bb.ymin(), bb.zmin()};
    hi_ = {bb.xmax(), bb.ymax(), bb.zmax()};
    tree_ = std::make_unique<Tree>(faces(mesh_).first, faces(mesh_).second, mesh_);
    tree_->accelerate_distance_queries();
    side_ = std::make_unique<CGAL::Side_of_triangle_mesh<Mesh, K>>(*tree_);
    triangles_ = mesh_.number_of_faces();
  }
  double distance(const Point& p) const override {
    const K::Point_3 q(p[0], p[1], p[2]);
    const double d = std::sqrt(CGAL::to_double(tree_->squared_distance(q)));
    return (*side_)(q) == CGAL::ON_BOUNDED_SIDE ? -d : d;
  }
  bool inside(const Point& p) const override {
    for (int a = 0; a < 3; ++a)
      if (p[a] < lo_[a] || p[a] > hi_[a]) return false;
    return (*side_)(K::Point_3(p[0], p[1], p[2])) == CGAL::ON_BOUNDED_SIDE;
  }
  Bounds bounds() const override { return {lo_, hi_}; }
  double exact_measure() const override { return volume_; }
  std::string describe() const override { return "STL surface (" + std::to_string(triangles_) + " triangles)"; }

 private:
  Mesh mesh_;
  std::unique_ptr<Tree> tree_;
  std::unique_ptr<CGAL::Side_of_triangle_mesh<Mesh, K>> side_;
  double volume_ = 0;
  Point lo_{}, hi_{};
  std::size_t triangles_ = 0;
};

}  // namespace

ShapePtr make_stl(const std::filesystem::path& file) { return std::make_shared<StlSurface>(file); }

}  // namespace geosph::geometry
