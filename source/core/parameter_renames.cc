// The renamed parameters, subsections and choices (one name for one
// concept in every engine), written once; parameter_renames.h.

#include <algorithm>
#include <tribodyn/core/parameter_renames.h>

namespace tribodyn
{
  namespace
  {
    /// A subsection or entry @p old_name inside @p parent ("*": inside any
    /// subsection) is now @p new_name.
    struct RenamedName
    {
      const char *parent;
      const char *old_name;
      const char *new_name;
    };

    constexpr RenamedName renamed_names[] = {
      {"", "Time integration", "Time"},
      {"", "Material", "Materials"},
      {"Loading", "Plane velocity", "Sliding velocity"},
      {"Loading", "Plane start time", "Sliding start time"},
      {"Loading", "Plane velocity ramp time", "Sliding velocity ramp time"},
      {"Loading", "Plane velocity step time", "Sliding velocity step time"},
      {"Loading", "Plane velocity after step", "Sliding velocity after step"},
      {"*", "Random seed", "Seed"},
      {"*", "First random seed", "First seed"},
      {"Interaction", "Dieterich", "Rate and state friction"},
    };

    /// A subsection or entry @p old_name inside @p parent that a new layout
    /// replaced: @p layout says how to write it now.
    struct ReplacedName
    {
      const char *parent;
      const char *old_name;
      const char *layout;
    };

    constexpr ReplacedName replaced_names[] = {
      {"Materials",
       "Phases",
       "the phases are named materials now, as the automata's are: list "
       "them in 'Materials/Names' (e.g. 'set Names = pores, matrix, "
       "fibres'; material id k is the k-th name) and give each its "
       "subsection 'Materials/<Name>' (e.g. 'subsection Fibres') with "
       "'Young modulus', 'Poisson ratio' and 'Density'; a transversely "
       "isotropic one also 'Symmetry = transversely isotropic', 'Axis', "
       "'Axial Young modulus', 'Axial Poisson ratio' and 'Axial shear "
       "modulus'; 'Pore stiffness ratio' is in 'Materials'"},
      {"Materials",
       "Isotropic",
       "the isotropic pin is of a named material now: give its Young "
       "modulus, Poisson ratio and Density in its subsection (e.g. "
       "'subsection Matrix', a name of 'Materials/Names', whose first name "
       "the pin takes) or name it in 'Materials/Pin material'"},
    };

    /// The choice @p old_value of the entry at @p path is now @p new_value.
    struct RenamedChoice
    {
      const char *path;
      const char *old_value;
      const char *new_value;
    };

    constexpr RenamedChoice renamed_choices[] = {
      {"Interaction/Friction law", "Amontons-Coulomb", "Coulomb"},
      {"Interaction/Friction law", "Dieterich", "rate and state"},
    };


    const RenamedName *
    find_name(const std::string &parent, const std::string &name)
    {
      for (const RenamedName &r : renamed_names)
        if (name == r.old_name
            && (std::string(r.parent) == "*" || parent == r.parent))
          return &r;
      return nullptr;
    }


    const RenamedChoice *
    find_choice(const std::string &path, const std::string &value)
    {
      for (const RenamedChoice &r : renamed_choices)
        if (path == r.path && value == r.old_value)
          return &r;
      return nullptr;
    }
  } // namespace


  std::string
  renamed_hint(const std::string &parent, const std::string &name)
  {
    for (const ReplacedName &r : replaced_names)
      if (parent == r.parent && name == r.old_name)
        return std::string(" ('") + r.old_name + "' was replaced: " + r.layout
               + ")";
    const RenamedName *r = find_name(parent, name);
    if (r == nullptr)
      return "";
    return std::string(" ('") + r->old_name + "' is now called '" + r->new_name
           + "', the name the other engines use for the same thing: write '"
           + r->new_name + "' instead)";
  }


  std::string
  renamed_choice_hint(const std::string &path, const std::string &value)
  {
    const RenamedChoice *r = find_choice(path, value);
    if (r == nullptr)
      return "";
    return std::string(" ('") + r->old_value + "' is now called '"
           + r->new_value
           + "', the name the contact engine uses for the same law: write '"
           + r->new_value + "' instead)";
  }


  std::vector<std::string>
  with_current_names(const std::vector<std::string> &lines)
  {
    std::vector<std::string> current;
    current.reserve(lines.size());
    for (const std::string &line : lines)
      {
        const auto  eq    = line.find(" = ");
        std::string path  = line.substr(0, eq);
        std::string value = eq == std::string::npos ? "" : line.substr(eq + 3);

        std::string renamed, parent;
        std::size_t start = 0;
        while (true)
          {
            const auto        slash = path.find('/', start);
            const std::string part
              = path.substr(start,
                            slash == std::string::npos ? std::string::npos
                                                       : slash - start);
            const RenamedName *r    = find_name(parent, part);
            const std::string  name = r != nullptr ? r->new_name : part;
            renamed += (renamed.empty() ? "" : "/") + name;
            // the old parent path decides the match, as the table is keyed
            parent += (parent.empty() ? "" : "/") + part;
            if (slash == std::string::npos)
              break;
            start = slash + 1;
          }
        if (const RenamedChoice *c = find_choice(renamed, value))
          value = c->new_value;
        current.push_back(eq == std::string::npos ? renamed
                                                  : renamed + " = " + value);
      }
    std::sort(current.begin(), current.end());
    return current;
  }
} // namespace tribodyn
