#include <algorithm>
#include <cmath>
#include <random>
#include <tribodyn/core/errors.h>
#include <tribodyn/mca/inclusions.h>

namespace tribodyn
{
  namespace mca
  {
    using Point3  = dealii::Point<3>;
    using Vector3 = dealii::Tensor<1, 3>;

    namespace
    {
      constexpr double pi = 3.14159265358979323846;

      /// Uniform in [0, 1) from the top 53 bits: the same numbers on every
      /// platform (std::uniform_real_distribution is implementation
      /// defined).
      double
      uniform(std::mt19937_64 &engine)
      {
        return (engine() >> 11) * (1.0 / 9007199254740992.0);
      }

      /// Isotropic unit vector by rejection from the cube [-1, 1]^3 (only
      /// +, *, sqrt: correctly rounded everywhere, unlike cos and sin).
      Vector3
      random_direction(std::mt19937_64 &engine)
      {
        while (true)
          {
            Vector3 v;
            for (unsigned int d = 0; d < 3; ++d)
              v[d] = 2 * uniform(engine) - 1;
            const double r2 = v.norm_square();
            if (r2 <= 1 && r2 > 1e-6)
              return v / std::sqrt(r2);
          }
      }

      double
      point_segment_distance(const Point3 &p, const Point3 &a, const Point3 &b)
      {
        const Vector3 axis = b - a;
        const double  L2   = axis.norm_square();
        double        s    = L2 > 0 ? (p - a) * axis / L2 : 0.;
        s                  = std::min(1., std::max(0., s));
        return (p - (a + s * axis)).norm();
      }

      /// Half-extent of a shape about its centre along direction d.
      double
      half_extent(const Inclusion &s, const unsigned int d)
      {
        if (s.shape == Inclusion::Shape::sphere)
          return s.radius;
        const Vector3 axis = s.b - s.a;
        const double  L    = axis.norm();
        const double  u    = L > 0 ? axis[d] / L : 0.;
        return 0.5 * std::abs(axis[d])
               + s.radius * std::sqrt(std::max(0., 1 - u * u));
      }

      Point3
      centre(const Inclusion &s)
      {
        return Point3(0.5 * (s.a[0] + s.b[0]),
                      0.5 * (s.a[1] + s.b[1]),
                      0.5 * (s.a[2] + s.b[2]));
      }

      /// Do shapes @p s and @p t come closer than their clearance + gap?
      bool
      overlap(const Inclusion &s, const Inclusion &t, const double gap)
      {
        const double clearance = s.radius + t.radius + gap;
        // Quick reject by bounding spheres about the centres.
        const double reach_s = 0.5 * (s.b - s.a).norm();
        const double reach_t = 0.5 * (t.b - t.a).norm();
        if (centre(s).distance(centre(t)) >= reach_s + reach_t + clearance)
          return false;
        const bool cs = s.shape == Inclusion::Shape::cylinder;
        const bool ct = t.shape == Inclusion::Shape::cylinder;
        double     distance;
        if (cs && ct)
          distance = segment_segment_distance(s.a, s.b, t.a, t.b);
        else if (cs)
          distance = point_segment_distance(t.a, s.a, s.b);
        else if (ct)
          distance = point_segment_distance(s.a, t.a, t.b);
        else
          distance = s.a.distance(t.a);
        return distance < clearance;
      }

      Inclusion
      shifted(const Inclusion &s, const Vector3 &shift)
      {
        Inclusion t = s;
        t.a += shift;
        t.b += shift;
        return t;
      }

      /// Box-box intersection (closed).
      bool
      meets(const std::pair<Point3, Point3> &bb,
            const Point3                    &lower,
            const Point3                    &upper)
      {
        for (unsigned int d = 0; d < 3; ++d)
          if (bb.second[d] < lower[d] || bb.first[d] > upper[d])
            return false;
        return true;
      }
    } // namespace


    InclusionOrientation
    parse_inclusion_orientation(const std::string &text,
                                const std::string &parameter_name)
    {
      if (text == "isotropic")
        return InclusionOrientation::isotropic;
      if (text == "x")
        return InclusionOrientation::x;
      if (text == "y")
        return InclusionOrientation::y;
      if (text == "z")
        return InclusionOrientation::z;
      throw InputError(parameter_name + ": unknown orientation '" + text
                       + "' (allowed: isotropic, x, y, z).");
    }


    bool
    Inclusion::contains(const Point3 &p) const
    {
      if (shape == Shape::sphere)
        return p.distance_square(a) <= radius * radius;
      const Vector3 axis = b - a;
      const double  L2   = axis.norm_square();
      const double  s    = (p - a) * axis / L2;
      if (s < 0 || s > 1)
        return false;
      return ((p - a) - s * axis).norm_square() <= radius * radius;
    }


    double
    Inclusion::volume() const
    {
      if (shape == Shape::sphere)
        return 4. / 3. * pi * radius * radius * radius;
      return pi * radius * radius * (b - a).norm();
    }


    std::pair<Point3, Point3>
    Inclusion::bounding_box() const
    {
      const Point3 c = centre(*this);
      Point3       lo, hi;
      for (unsigned int d = 0; d < 3; ++d)
        {
          const double h = half_extent(*this, d);
          lo[d]          = c[d] - h;
          hi[d]          = c[d] + h;
        }
      return {lo, hi};
    }


    double
    segment_segment_distance(const Point3 &p0,
                             const Point3 &p1,
                             const Point3 &q0,
                             const Point3 &q1)
    {
      // Closest points of two segments (Ericson, Real-Time Collision
      // Detection, 5.1.9), with the degenerate (point) cases.
      const Vector3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
      const double  a = d1 * d1, e = d2 * d2, f = d2 * r;
      const double  eps = 1e-30 * std::max(1., std::max(a, e));
      const auto    clamp
        = [](const double x) { return std::min(1., std::max(0., x)); };
      double s = 0, t = 0;
      if (a <= eps && e <= eps)
        return r.norm();
      if (a <= eps)
        t = clamp(f / e);
      else
        {
          const double c = d1 * r;
          if (e <= eps)
            s = clamp(-c / a);
          else
            {
              const double b     = d1 * d2;
              const double denom = a * e - b * b; // >= 0
              // Parallel segments (denom ~ 0): any s works, take 0.
              s = denom > 1e-14 * a * e ? clamp((b * f - c * e) / denom) : 0.;
              t = (b * s + f) / e;
              if (t < 0)
                {
                  t = 0;
                  s = clamp(-c / a);
                }
              else if (t > 1)
                {
                  t = 1;
                  s = clamp((b - c) / a);
                }
            }
        }
      return ((p0 + s * d1) - (q0 + t * d2)).norm();
    }


    namespace
    {
      /// All lattice shifts k * period (k_d in [-k_max_d, k_max_d] in the
      /// periodic directions, 0 otherwise), the zero shift first.
      std::vector<Vector3>
      periodic_shifts(const std::array<double, 3>       &size,
                      const std::array<bool, 3>         &periodic,
                      const std::array<unsigned int, 3> &k_max)
      {
        std::vector<Vector3> shifts{Vector3()};
        int                  k[3];
        int                  m[3];
        for (unsigned int d = 0; d < 3; ++d)
          m[d] = periodic[d] ? static_cast<int>(k_max[d]) : 0;
        for (k[0] = -m[0]; k[0] <= m[0]; ++k[0])
          for (k[1] = -m[1]; k[1] <= m[1]; ++k[1])
            for (k[2] = -m[2]; k[2] <= m[2]; ++k[2])
              if (k[0] != 0 || k[1] != 0 || k[2] != 0)
                {
                  Vector3 s;
                  for (unsigned int d = 0; d < 3; ++d)
                    s[d] = k[d] * size[d];
                  shifts.push_back(s);
                }
        return shifts;
      }

      void
      check_positive(const double value, const std::string &name)
      {
        check_parameter_range(name, value, 0, 1e300, true, false);
      }
    } // namespace


    InclusionSet
    generate_inclusions(const InclusionParameters &p)
    {
      const auto           &names = p.names;
      std::array<double, 3> size;
      double                box_volume = 1;
      for (unsigned int d = 0; d < 3; ++d)
        {
          size[d] = p.upper[d] - p.lower[d];
          if (!(size[d] > 0))
            throw InputError("Inclusion generator: the box must have a "
                             "positive size in every direction (direction "
                             + std::to_string(d) + " has "
                             + format_number(size[d]) + ").");
          box_volume *= size[d];
        }
      check_parameter_range(names.cylinder_volume_fraction,
                            p.cylinder_volume_fraction,
                            0,
                            1,
                            false,
                            true);
      check_parameter_range(
        names.void_volume_fraction, p.void_volume_fraction, 0, 1, false, true);
      check_parameter_range(names.gap, p.gap, 0, 1e300, false, false);

      // The two kinds of shape, in placement order (large ones first).
      struct Kind
      {
        Inclusion::Shape   shape;
        double             radius, length, fraction;
        const std::string *fraction_name, *size_name;
        const char        *noun;
      };
      const Kind kinds[2] = {{Inclusion::Shape::cylinder,
                              p.cylinder_radius,
                              p.cylinder_length,
                              p.cylinder_volume_fraction,
                              &names.cylinder_volume_fraction,
                              &names.cylinder_length,
                              "cylinders"},
                             {Inclusion::Shape::sphere,
                              p.void_radius,
                              0.,
                              p.void_volume_fraction,
                              &names.void_volume_fraction,
                              &names.void_radius,
                              "voids"}};

      // Periodic images up to k_max periods away: enough for the largest
      // reach (two largest shapes plus the gap) in every direction.
      double reach = 0;
      for (const Kind &k : kinds)
        if (k.fraction > 0)
          reach = std::max(reach, 0.5 * k.length + k.radius);
      std::array<unsigned int, 3> k_max;
      for (unsigned int d = 0; d < 3; ++d)
        k_max[d] = 1 + static_cast<unsigned int>((2 * reach + p.gap) / size[d]);
      const auto shifts = periodic_shifts(size, p.periodic, k_max);

      InclusionSet    result;
      std::mt19937_64 engine(p.seed);
      for (const Kind &kind : kinds)
        {
          if (kind.fraction == 0)
            continue;
          const bool cylinder = kind.shape == Inclusion::Shape::cylinder;
          check_positive(kind.radius,
                         cylinder ? names.cylinder_radius : names.void_radius);
          if (cylinder)
            check_positive(kind.length, names.cylinder_length);
          Inclusion prototype;
          prototype.shape      = kind.shape;
          prototype.radius     = kind.radius;
          prototype.b[2]       = kind.length;
          const double volume  = prototype.volume();
          const double n_real  = kind.fraction * box_volume / volume;
          const auto n_targets = static_cast<unsigned int>(std::lround(n_real));
          if (n_targets == 0)
            throw InputError(
              *kind.fraction_name + " = " + format_number(kind.fraction)
              + " asks for less than half of one of the " + kind.noun
              + " in the box (one of them is "
              + format_number(volume / box_volume)
              + " of the box volume): enlarge the box, lower the size ("
              + *kind.size_name + ") or set the fraction to 0.");

          for (unsigned int placed = 0; placed < n_targets; ++placed)
            {
              bool success = false;
              for (unsigned int attempt = 0;
                   attempt < p.max_attempts && !success;
                   ++attempt)
                {
                  Vector3 u;
                  switch (p.orientation)
                    {
                      case InclusionOrientation::isotropic:
                        u = random_direction(engine);
                        break;
                      case InclusionOrientation::x:
                        u[0] = 1;
                        break;
                      case InclusionOrientation::y:
                        u[1] = 1;
                        break;
                      case InclusionOrientation::z:
                        u[2] = 1;
                        break;
                    }
                  if (!cylinder)
                    u = Vector3();
                  Inclusion trial = prototype;
                  trial.a         = Point3();
                  trial.b         = Point3() + kind.length * u;
                  // Centre: anywhere in periodic directions, such that the
                  // shape fits in non-periodic ones.
                  Point3 c;
                  bool   fits = true;
                  for (unsigned int d = 0; d < 3; ++d)
                    {
                      const double xi = uniform(engine);
                      if (p.periodic[d])
                        c[d] = p.lower[d] + xi * size[d];
                      else
                        {
                          const double h    = half_extent(trial, d);
                          const double span = size[d] - 2 * h;
                          fits              = fits && span >= 0;
                          c[d]              = p.lower[d] + h + xi * span;
                        }
                    }
                  if (!fits)
                    {
                      if (p.orientation != InclusionOrientation::isotropic
                          || !cylinder)
                        throw InputError(
                          "The " + std::string(kind.noun)
                          + " do not fit in the box in a non-periodic "
                            "direction: lower "
                          + *kind.size_name + " or the radius.");
                      continue;
                    }
                  trial.a = c - 0.5 * kind.length * u;
                  trial.b = c + 0.5 * kind.length * u;

                  success = true;
                  // Against its own images (long shapes, short periods).
                  for (std::size_t s = 1; s < shifts.size() && success; ++s)
                    if (overlap(trial, shifted(trial, shifts[s]), p.gap))
                      success = false;
                  for (std::size_t j = 0; j < result.shapes.size() && success;
                       ++j)
                    for (const Vector3 &shift : shifts)
                      if (overlap(trial,
                                  shifted(result.shapes[j], shift),
                                  p.gap))
                        {
                          success = false;
                          break;
                        }
                  if (success)
                    result.shapes.push_back(trial);
                }
              if (!success)
                throw InputError(
                  *kind.fraction_name + " = " + format_number(kind.fraction)
                  + " cannot be reached: placed " + std::to_string(placed)
                  + " of " + std::to_string(n_targets) + " " + kind.noun
                  + ", the next found no free position in "
                  + std::to_string(p.max_attempts)
                  + " random trials (random sequential addition of "
                    "non-overlapping shapes jams well below dense packing). "
                    "Lower the fraction or the gap ("
                  + names.gap + "), or enlarge the box.");
            }
          if (cylinder)
            {
              result.n_cylinders              = n_targets;
              result.cylinder_volume_fraction = n_targets * volume / box_volume;
            }
          else
            {
              result.n_voids              = n_targets;
              result.void_volume_fraction = n_targets * volume / box_volume;
            }
        }

      // Periodic images that reach into the box.
      const std::size_t n_primaries = result.shapes.size();
      for (std::size_t j = 0; j < n_primaries; ++j)
        result.primary.push_back(j);
      for (std::size_t j = 0; j < n_primaries; ++j)
        for (std::size_t s = 1; s < shifts.size(); ++s)
          {
            const Inclusion image = shifted(result.shapes[j], shifts[s]);
            if (meets(image.bounding_box(), p.lower, p.upper))
              {
                result.shapes.push_back(image);
                result.primary.push_back(j);
              }
          }
      return result;
    }


    InclusionIndex::InclusionIndex(const std::vector<Inclusion> &shapes,
                                   const Point3                 &lower,
                                   const Point3                 &upper,
                                   const std::array<bool, 3>    &periodic,
                                   const double                  cell_size)
        : shapes(shapes)
        , lower(lower)
        , upper(upper)
        , periodic(periodic)
    {
      double h = cell_size;
      if (h <= 0)
        {
          for (const Inclusion &s : shapes)
            h = std::max(h, 2 * s.radius);
          if (h <= 0)
            h = (upper - lower).norm();
        }
      // Cap the number of cells (memory), growing the cell if needed.
      while (true)
        {
          double total = 1;
          for (unsigned int d = 0; d < 3; ++d)
            total *= std::max(1., std::floor((upper[d] - lower[d]) / h));
          if (total <= 2097152.)
            break;
          h *= 1.26;
        }
      std::size_t total = 1;
      for (unsigned int d = 0; d < 3; ++d)
        {
          n_cells[d] = static_cast<unsigned int>(
            std::max(1., std::floor((upper[d] - lower[d]) / h)));
          cell_width[d] = (upper[d] - lower[d]) / n_cells[d];
          total *= n_cells[d];
        }
      cells.resize(total);
      for (unsigned int j = 0; j < shapes.size(); ++j)
        {
          const auto bb = shapes[j].bounding_box();
          if (!meets(bb, lower, upper))
            continue;
          int lo[3], hi[3];
          for (unsigned int d = 0; d < 3; ++d)
            {
              const auto index = [&](const double x) {
                const int i = static_cast<int>(
                  std::floor((x - lower[d]) / cell_width[d]));
                return std::min(static_cast<int>(n_cells[d]) - 1,
                                std::max(0, i));
              };
              lo[d] = index(bb.first[d]);
              hi[d] = index(bb.second[d]);
            }
          for (int i = lo[0]; i <= hi[0]; ++i)
            for (int k = lo[1]; k <= hi[1]; ++k)
              for (int l = lo[2]; l <= hi[2]; ++l)
                cells[(static_cast<std::size_t>(l) * n_cells[1] + k)
                        * n_cells[0]
                      + i]
                  .push_back(j);
        }
    }


    Point3
    InclusionIndex::wrap(const Point3 &p) const
    {
      Point3 q = p;
      for (unsigned int d = 0; d < 3; ++d)
        if (periodic[d])
          {
            const double L = upper[d] - lower[d];
            q[d]           = lower[d] + std::fmod(p[d] - lower[d], L);
            if (q[d] < lower[d])
              q[d] += L;
            if (q[d] >= upper[d]) // round-off of the addition above
              q[d] = lower[d];
          }
      return q;
    }


    std::size_t
    InclusionIndex::cell_of(const Point3 &q) const
    {
      std::size_t index[3];
      for (unsigned int d = 0; d < 3; ++d)
        {
          const double x = std::floor((q[d] - lower[d]) / cell_width[d]);
          index[d]       = static_cast<std::size_t>(
            std::min<double>(n_cells[d] - 1, std::max(0., x)));
        }
      return (index[2] * n_cells[1] + index[1]) * n_cells[0] + index[0];
    }


    const std::vector<unsigned int> &
    InclusionIndex::candidates(const Point3 &p) const
    {
      return cells[cell_of(wrap(p))];
    }


    int
    InclusionIndex::find(const Point3 &p) const
    {
      const Point3 q = wrap(p);
      for (const unsigned int j : cells[cell_of(q)])
        if (shapes[j].contains(q))
          return static_cast<int>(j);
      return -1;
    }


    double
    InclusionIndex::monte_carlo_volume_fraction(const unsigned int  n_samples,
                                                const std::uint64_t seed) const
    {
      std::mt19937_64 engine(seed);
      unsigned int    inside = 0;
      for (unsigned int i = 0; i < n_samples; ++i)
        {
          Point3 x;
          for (unsigned int d = 0; d < 3; ++d)
            x[d] = lower[d] + uniform(engine) * (upper[d] - lower[d]);
          if (find(x) >= 0)
            ++inside;
        }
      return static_cast<double>(inside) / n_samples;
    }
  } // namespace mca
} // namespace tribodyn
