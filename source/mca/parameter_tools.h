#ifndef tribodyn_mca_parameter_tools_h
#define tribodyn_mca_parameter_tools_h

// Parsing helpers shared by the parameter files of the automata engine
// (parameters.cc, geometry_parameters.cc, boundary_parameters.cc).

#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/material_names.h>
#include <tribodyn/mca/parameters.h>
#include <vector>

namespace tribodyn
{
  namespace mca
  {
    namespace parameter_tools
    {
      constexpr double inf = std::numeric_limits<double>::max();

      inline std::vector<std::string>
      split(const std::string &text, const char separator)
      {
        std::vector<std::string> parts;
        std::string              current;
        for (const char c : text)
          if (c == separator)
            {
              parts.push_back(current);
              current.clear();
            }
          else
            current += c;
        parts.push_back(current);
        std::vector<std::string> nonempty;
        for (const auto &p : parts)
          if (p.find_first_not_of(" \t") != std::string::npos)
            nonempty.push_back(p);
        return nonempty;
      }

      /// Whitespace- or comma-separated tokens.
      inline std::vector<std::string>
      tokens(const std::string &text)
      {
        std::vector<std::string> out;
        std::string              current;
        for (const char c : text + " ")
          if (c == ' ' || c == '\t' || c == ',')
            {
              if (!current.empty())
                out.push_back(current);
              current.clear();
            }
          else
            current += c;
        return out;
      }

      inline double
      to_double(const std::string &token,
                const std::string &parameter,
                const std::string &entry)
      {
        if (token == "*")
          return std::numeric_limits<double>::quiet_NaN();
        try
          {
            std::size_t  used  = 0;
            const double value = std::stod(token, &used);
            if (used == token.size() && std::isfinite(value))
              return value;
          }
        catch (...)
          {
          }
        throw InputError("Parameter '" + parameter + "': '" + token
                         + "' in the entry '" + entry + "' is not a number.");
      }

      inline Point3
      read_point(const std::vector<std::string> &t,
                 const std::size_t               first,
                 const std::string              &parameter,
                 const std::string              &entry)
      {
        return Point3(to_double(t[first], parameter, entry),
                      to_double(t[first + 1], parameter, entry),
                      to_double(t[first + 2], parameter, entry));
      }

      inline Point3
      parse_point(const std::string &text, const std::string &parameter)
      {
        const auto t = tokens(text);
        if (t.size() != 3)
          throw InputError("Parameter '" + parameter + "' = '" + text
                           + "' must be three numbers 'x, y, z'.");
        return read_point(t, 0, parameter, text);
      }

    } // namespace parameter_tools
  }   // namespace mca
} // namespace tribodyn

#endif
