// Reading and checking a tabulated friction coefficient mu(p, v)
// (include/tribodyn/contact/friction_table.h).
#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <tribodyn/contact/friction_table.h>
#include <tribodyn/core/errors.h>

namespace tribodyn
{
  namespace contact
  {
    FrictionTable::FrictionTable(std::vector<double> p,
                                 std::vector<double> v,
                                 std::vector<double> m)
        : pressures(std::move(p))
        , speeds(std::move(v))
        , mu(std::move(m))
    {
    }


    FrictionTable::FrictionTable(const std::string &file,
                                 const std::string &parameter)
    {
      const std::string where
        = "Parameter '" + parameter + "': the file '" + file + "' ";
      std::ifstream in(file);
      if (!in)
        throw InputError(where
                         + "cannot be read (missing, or no permission). Give "
                           "the path of a CSV table of mu with columns "
                           "pressure, speed, mu (e.g. written by "
                           "scripts/mca_friction_table).");
      std::string              line;
      std::vector<std::string> header;
      unsigned int             line_number = 0;
      while (header.empty() && std::getline(in, line))
        {
          ++line_number;
          if (line.empty() || line[0] == '#')
            continue;
          std::istringstream s(line);
          for (std::string c; std::getline(s, c, ',');)
            {
              c.erase(0, c.find_first_not_of(" \t\r"));
              c.erase(c.find_last_not_of(" \t\r") + 1);
              header.push_back(c);
            }
        }
      auto column = [&](const char *name) {
        const auto it = std::find(header.begin(), header.end(), name);
        if (it == header.end())
          throw InputError(where + "has no column '" + name
                           + "' in its header line: it needs the columns "
                             "pressure (Pa), speed (m/s) and mu.");
        return std::size_t(it - header.begin());
      };
      const std::size_t cp = column("pressure"), cv = column("speed"),
                        cm = column("mu");
      std::map<std::pair<double, double>, double> points;
      while (std::getline(in, line))
        {
          ++line_number;
          if (line.find_first_not_of(" \t\r") == std::string::npos
              || line[0] == '#')
            continue;
          std::vector<double> row;
          std::istringstream  s(line);
          for (std::string c; std::getline(s, c, ',');)
            {
              char        *end   = nullptr;
              const double value = std::strtod(c.c_str(), &end);
              row.push_back(end != c.c_str() ? value : std::nan(""));
            }
          const std::size_t need = std::max({cp, cv, cm}) + 1;
          if (row.size() < need || !std::isfinite(row[cp])
              || !std::isfinite(row[cv]) || !std::isfinite(row[cm]))
            throw InputError(where + "has a malformed row at line "
                             + std::to_string(line_number)
                             + ": every row needs finite numbers in the "
                               "columns pressure, speed and mu.");
          if (row[cm] < 0)
            throw InputError(where + "has mu = " + format_number(row[cm])
                             + " < 0 at line " + std::to_string(line_number)
                             + ": a friction coefficient is >= 0.");
          if (!points.emplace(std::make_pair(row[cp], row[cv]), row[cm]).second)
            throw InputError(where + "has two rows for pressure "
                             + format_number(row[cp]) + " and speed "
                             + format_number(row[cv]) + " (line "
                             + std::to_string(line_number) + ").");
        }
      for (const auto &pt : points)
        {
          pressures.push_back(pt.first.first);
          speeds.push_back(pt.first.second);
        }
      for (auto *axis : {&pressures, &speeds})
        {
          std::sort(axis->begin(), axis->end());
          axis->erase(std::unique(axis->begin(), axis->end()), axis->end());
        }
      if (pressures.size() < 2 || speeds.size() < 2)
        throw InputError(where + "holds " + std::to_string(pressures.size())
                         + " pressure(s) and " + std::to_string(speeds.size())
                         + " speed(s): a table needs at least two of each "
                           "(for a constant mu use 'Friction law = "
                           "Coulomb').");
      if (points.size() != pressures.size() * speeds.size())
        throw InputError(
          where + "is not a full grid: " + std::to_string(points.size())
          + " rows for " + std::to_string(pressures.size()) + " pressures x "
          + std::to_string(speeds.size())
          + " speeds. Give mu at every combination of pressure and speed.");
      mu.resize(points.size());
      std::size_t k = 0;
      for (const auto &pt : points) // sorted by (pressure, speed)
        mu[k++] = pt.second;
    }
  } // namespace contact
} // namespace tribodyn
