// Convex Voronoi cells by successive half-space clipping (issue #18).

#include <algorithm>
#include <cmath>
#include <tribodyn/mca/voronoi_cell.h>

namespace tribodyn
{
  namespace mca
  {
    namespace
    {
      Vec3
      minus(const Vec3 &a, const Vec3 &b)
      {
        return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}};
      }

      /// Vector area of a planar polygon (normal times area).
      Vec3
      vector_area(const std::vector<Vec3> &p)
      {
        Vec3 sum = {{0, 0, 0}};
        for (std::size_t k = 1; k + 1 < p.size(); ++k)
          {
            const Vec3 c = cross(minus(p[k], p[0]), minus(p[k + 1], p[0]));
            for (unsigned int i = 0; i < 3; ++i)
              sum[i] += 0.5 * c[i];
          }
        return sum;
      }
    } // namespace


    VoronoiCell::VoronoiCell(const double size)
        : scale(size)
    {
      // The cube [-c, c]^3 (c = size/√2, the distance of the rhombic
      // dodecahedron's 4-valent vertices), cut by the 12 face planes: the
      // cube's faces shrink to those vertices and are dropped.
      const double c = size / std::sqrt(2.);
      for (unsigned int axis = 0; axis < 3; ++axis)
        for (const double side : {-1., 1.})
          {
            const unsigned int a = (axis + 1) % 3, b = (axis + 2) % 3;
            Face               f;
            f.tag = -1;
            for (const auto &corner : {std::array<double, 2>{{-1, -1}},
                                       std::array<double, 2>{{1, -1}},
                                       std::array<double, 2>{{1, 1}},
                                       std::array<double, 2>{{-1, 1}}})
              {
                Vec3 v;
                v[axis] = side * c;
                v[a]    = corner[0] * c;
                v[b]    = corner[1] * c;
                f.vertices.push_back(v);
              }
            faces.push_back(f);
          }
      const double s = 1. / std::sqrt(2.);
      for (unsigned int a = 0; a < 3; ++a)
        for (unsigned int b = a + 1; b < 3; ++b)
          for (const double sa : {-1., 1.})
            for (const double sb : {-1., 1.})
              {
                Vec3 n = {{0, 0, 0}};
                n[a]   = sa * s;
                n[b]   = sb * s;
                clip(n, size / 2, -1);
              }
    }


    void
    VoronoiCell::clip(const Vec3 &n, const double distance, const int tag)
    {
      const double eps = 1e-12 * scale;
      if (radius() <= distance - eps)
        return;
      bool              removes = false;
      std::vector<Vec3> cut;
      std::vector<Face> kept;
      for (const Face &face : faces)
        {
          const std::size_t   m = face.vertices.size();
          std::vector<double> s(m);
          bool                on_plane = true;
          for (std::size_t k = 0; k < m; ++k)
            {
              s[k]     = dot(n, face.vertices[k]) - distance;
              removes  = removes || s[k] > eps;
              on_plane = on_plane && std::abs(s[k]) <= eps;
            }
          // A face already on the plane (the bounding cell's face where the
          // neighbour is at the lattice distance) now belongs to the
          // neighbour: the plane supports the cell, nothing is cut.
          if (on_plane)
            {
              kept.push_back(Face{face.vertices, tag});
              continue;
            }
          // Sutherland-Hodgman against one plane; the points on the plane
          // (kept vertices and edge intersections) outline the new face.
          Face clipped;
          clipped.tag = face.tag;
          for (std::size_t k = 0; k < m; ++k)
            {
              const Vec3 &a = face.vertices[k], &b = face.vertices[(k + 1) % m];
              const double sa = s[k], sb = s[(k + 1) % m];
              if (sa <= eps)
                clipped.vertices.push_back(a);
              if (std::abs(sa) <= eps)
                cut.push_back(a);
              if ((sa < -eps && sb > eps) || (sa > eps && sb < -eps))
                {
                  const double t = sa / (sa - sb);
                  Vec3         p;
                  for (unsigned int i = 0; i < 3; ++i)
                    p[i] = a[i] + t * (b[i] - a[i]);
                  clipped.vertices.push_back(p);
                  cut.push_back(p);
                }
            }
          if (clipped.vertices.size() >= 3)
            kept.push_back(std::move(clipped));
        }
      if (!removes)
        {
          faces = std::move(kept); // retagged faces on the plane
          return;
        }

      // The new face: the distinct points on the plane, ordered by angle
      // around their centroid.
      std::vector<Vec3> points;
      for (const Vec3 &p : cut)
        {
          bool seen = false;
          for (const Vec3 &q : points)
            seen = seen || std::sqrt(dot(minus(p, q), minus(p, q))) <= 10 * eps;
          if (!seen)
            points.push_back(p);
        }
      faces = std::move(kept);
      if (points.size() < 3)
        return;
      Vec3 centre = {{0, 0, 0}};
      for (const Vec3 &p : points)
        for (unsigned int i = 0; i < 3; ++i)
          centre[i] += p[i] / points.size();
      // u: any unit vector normal to n; w = n x u.
      const Vec3 helper
        = std::abs(n[0]) < 0.9 ? Vec3{{1, 0, 0}} : Vec3{{0, 1, 0}};
      Vec3         u  = cross(n, helper);
      const double lu = std::sqrt(dot(u, u));
      for (double &c : u)
        c /= lu;
      const Vec3 w = cross(n, u);
      std::sort(points.begin(),
                points.end(),
                [&](const Vec3 &p, const Vec3 &q) {
                  const Vec3 dp = minus(p, centre), dq = minus(q, centre);
                  return std::atan2(dot(dp, w), dot(dp, u))
                         < std::atan2(dot(dq, w), dot(dq, u));
                });
      faces.push_back(Face{std::move(points), tag});
    }


    void
    VoronoiCell::clip_by_neighbour(const Vec3 &r, const int tag)
    {
      const double length = std::sqrt(dot(r, r));
      clip({{r[0] / length, r[1] / length, r[2] / length}}, length / 2, tag);
    }


    double
    VoronoiCell::volume() const
    {
      // Pyramids from the origin (inside the cell) on each face.
      double v = 0;
      for (const Face &f : faces)
        v += std::abs(dot(vector_area(f.vertices), f.vertices[0])) / 3;
      return v;
    }


    std::vector<std::pair<int, double>>
    VoronoiCell::face_areas() const
    {
      std::vector<std::pair<int, double>> areas;
      for (const Face &f : faces)
        {
          const Vec3   a    = vector_area(f.vertices);
          const double area = std::sqrt(dot(a, a));
          if (area > 1e-12 * scale * scale)
            areas.emplace_back(f.tag, area);
        }
      std::sort(areas.begin(), areas.end());
      std::vector<std::pair<int, double>> merged;
      for (const auto &e : areas)
        if (!merged.empty() && merged.back().first == e.first)
          merged.back().second += e.second;
        else
          merged.push_back(e);
      return merged;
    }


    std::vector<VoronoiCell::FaceGeometry>
    VoronoiCell::face_geometry() const
    {
      // first moments: each face a fan of triangles from its first vertex
      std::vector<FaceGeometry> moments;
      for (const Face &f : faces)
        {
          FaceGeometry m{f.tag, 0, {{0, 0, 0}}};
          const auto  &p = f.vertices;
          for (std::size_t k = 1; k + 1 < p.size(); ++k)
            {
              const Vec3   c = cross(minus(p[k], p[0]), minus(p[k + 1], p[0]));
              const double a = 0.5 * std::sqrt(dot(c, c));
              m.area += a;
              for (unsigned int i = 0; i < 3; ++i)
                m.centroid[i] += a * (p[0][i] + p[k][i] + p[k + 1][i]) / 3;
            }
          if (m.area > 1e-12 * scale * scale)
            moments.push_back(m);
        }
      std::stable_sort(moments.begin(),
                       moments.end(),
                       [](const FaceGeometry &a, const FaceGeometry &b) {
                         return a.tag < b.tag;
                       });
      std::vector<FaceGeometry> merged;
      for (const FaceGeometry &m : moments)
        if (!merged.empty() && merged.back().tag == m.tag)
          {
            merged.back().area += m.area;
            for (unsigned int i = 0; i < 3; ++i)
              merged.back().centroid[i] += m.centroid[i];
          }
        else
          merged.push_back(m);
      for (FaceGeometry &m : merged)
        for (unsigned int i = 0; i < 3; ++i)
          m.centroid[i] /= m.area;
      return merged;
    }


    double
    VoronoiCell::radius() const
    {
      double r2 = 0;
      for (const Face &f : faces)
        for (const Vec3 &v : f.vertices)
          r2 = std::max(r2, dot(v, v));
      return std::sqrt(r2);
    }
  } // namespace mca
} // namespace tribodyn
