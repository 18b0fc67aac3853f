// Geometry/Inclusions: the inclusion and void generator (inclusions.cc)
// wired into the packing (seed 000 Sec. 2.2, Fig. 2b).

#include "parameter_tools.h"

#include <deal.II/base/patterns.h>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/parameter_binding.h>
#include <tribodyn/mca/inclusions.h>
#include <tribodyn/mca/parameters.h>

namespace tribodyn
{
  namespace mca
  {
    using namespace parameter_tools;
    using dealii::Patterns::Double;
    using dealii::Patterns::Integer;
    using dealii::Patterns::Selection;
    namespace Patterns = dealii::Patterns;

    ParameterBinding
    InclusionPackingParameters::binding(const std::vector<std::string> &names)
    {
      ParameterBinding b("Geometry/Inclusions");
      b.add("Enabled",
            enabled,
            "Place non-overlapping cylinders of the inclusion material (and "
            "optionally spherical voids) at random in the contacting part of "
            "each body of the rough interface, respecting the periodic "
            "images. Needs Geometry/Rough interface/Enabled. The achieved "
            "fraction is printed and written to summary.json "
            "(inclusion_volume_fraction: automata of the inclusion material / "
            "automata of the contacting parts).");
      b.add("Material",
            "carbon",
            "Material of the cylinders.",
            Patterns::Anything(),
            [this, names, where = b.path("Material")](const std::string &m) {
              material = material_index(names, m, where);
            });
      b.add("Contacting part thickness",
            part_thickness,
            "Thickness of each contacting part (m): z in [Height - t, Height] "
            "below and [Height, Height + t] above the mean interface height, "
            "> 0 when enabled.");
      b.add("Cylinder radius",
            cylinder_radius,
            "Cylinder radius (m; seed: 10 nm).");
      b.add("Cylinder length",
            cylinder_length,
            "Cylinder length (m; seed: 70 nm).");
      b.add("Orientation",
            orientation,
            "Cylinder axes: uniformly random on the sphere, or aligned with "
            "an axis.",
            Selection("isotropic|x|y|z"));
      b.add("Volume fraction",
            volume_fraction,
            "Target volume fraction of cylinders in each contacting part "
            "(seed: about 2 %); the number of cylinders is the nearest whole "
            "number.");
      b.add("Void radius", void_radius, "Void radius (m).");
      b.add("Void volume fraction",
            void_fraction,
            "Target volume fraction of spherical voids in each contacting part "
            "(seed Fig. 2b: voids for better stirring); 0 = none.");
      b.add("Gap",
            gap,
            "Minimum clearance between the surfaces of any two shapes (m), >= "
            "0; e.g. one automaton size so that inclusions are separated by "
            "matrix.");
      b.add("Seed",
            seed,
            "Seed of the generator (same seed: same shapes on every platform "
            "and rank count).",
            Integer(0));
      return b;
    }


    void
    InclusionPackingParameters::parse_parameters(
      dealii::ParameterHandler       &prm,
      const std::vector<std::string> &names)
    {
      ParameterBinding b = binding(names);
      b.parse(prm);
      if (enabled)
        check_parameter_range(b.path("Contacting part thickness"),
                              part_thickness,
                              0,
                              inf,
                              true,
                              true);
    }


    bool
    InclusionLayout::in_part(const dealii::Point<3> &p,
                             const unsigned int      body) const
    {
      // The part reaches from the generator box's far face to the rough
      // surface, asperities included.
      for (const Part &part : parts)
        if (part.body == body
            && (body == 0 ? p[2] >= part.z_lower : p[2] <= part.z_upper))
          return true;
      return false;
    }


    int
    InclusionLayout::shape_at(const dealii::Point<3> &p,
                              const unsigned int      body) const
    {
      for (const Part &part : parts)
        if (part.body == body)
          {
            const int k = part.index->find(p);
            if (k >= 0)
              return part.set.shapes[k].shape == Inclusion::Shape::cylinder ? 0
                                                                            : 1;
          }
      return -1;
    }


    void
    GeometryParameters::generate_inclusion_layout()
    {
      inclusion_layout.reset();
      if (!inclusions.enabled)
        return;
      const std::string s = "Geometry/Inclusions/";
      check_parameter(rough_interface,
                      s + "Enabled",
                      "inclusions are placed in the contacting parts of a "
                      "rough interface: enable Geometry/Rough interface.");
      auto layout      = std::make_shared<InclusionLayout>();
      layout->material = inclusions.material;
      const double t   = inclusions.part_thickness;
      for (unsigned int body = 0; body < 2; ++body)
        {
          InclusionLayout::Part part;
          part.body    = body;
          part.z_lower = body == 0 ? interface_height - t : interface_height;
          part.z_upper = body == 0 ? interface_height : interface_height + t;
          InclusionParameters ip;
          ip.lower    = Point3(domain_lower[0], domain_lower[1], part.z_lower);
          ip.upper    = Point3(domain_upper[0], domain_upper[1], part.z_upper);
          ip.periodic = {{periodic[0], periodic[1], false}};
          ip.cylinder_radius = inclusions.cylinder_radius;
          ip.cylinder_length = inclusions.cylinder_length;
          ip.orientation = parse_inclusion_orientation(inclusions.orientation,
                                                       s + "Orientation");
          ip.cylinder_volume_fraction = inclusions.volume_fraction;
          ip.void_radius              = inclusions.void_radius;
          ip.void_volume_fraction     = inclusions.void_fraction;
          ip.gap                      = inclusions.gap;
          // different shapes in the two parts, reproducibly
          ip.seed                           = inclusions.seed * 2 + body;
          ip.names.cylinder_radius          = s + "Cylinder radius";
          ip.names.cylinder_length          = s + "Cylinder length";
          ip.names.cylinder_volume_fraction = s + "Volume fraction";
          ip.names.void_radius              = s + "Void radius";
          ip.names.void_volume_fraction     = s + "Void volume fraction";
          ip.names.gap                      = s + "Gap";
          part.set                          = generate_inclusions(ip);
          part.index = std::make_unique<InclusionIndex>(part.set.shapes,
                                                        ip.lower,
                                                        ip.upper,
                                                        ip.periodic);
          layout->parts.push_back(std::move(part));
        }
      inclusion_layout = layout;
    }
  } // namespace mca
} // namespace tribodyn
