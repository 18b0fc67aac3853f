// Morphologies in plain-text grid files: reading (Generator = grid file)
// and writing (morphology.txt of a homogenization run).
#include <fstream>
#include <sstream>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/morphology.h>
#include <tribodyn/core/output.h>

namespace tribodyn
{
  Morphology
  Morphology::read_grid_file(const std::string &file_name,
                             const double       width,
                             const double       height)
  {
    std::ifstream in(file_name);
    if (!in)
      throw InputError("Cannot read the morphology grid file '" + file_name
                       + "' (parameter 'Morphology/Grid file'): it does not "
                         "exist or is not readable.");
    std::vector<std::vector<unsigned int>> rows;
    std::string                            line;
    unsigned int                           line_number = 0;
    while (std::getline(in, line))
      {
        ++line_number;
        const auto first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos || line[first] == '#')
          continue;
        std::istringstream        tokens(line);
        std::string               token;
        std::vector<unsigned int> row;
        while (tokens >> token)
          {
            // Ids 0 (matrix) and 1 (heterogeneity), or 0 .. N-1 naming
            // the materials of 'Materials/Names' (up to 255).
            const bool digits
              = token.size() <= 3
                && token.find_first_not_of("0123456789") == std::string::npos;
            if (!digits || std::stoi(token) > 255)
              throw InputError("Morphology grid file '" + file_name + "', line "
                               + std::to_string(line_number) + ": '" + token
                               + "' is not a material id. Allowed ids are 0 "
                                 "(matrix) and 1 (heterogeneity), or 0 to N-1 "
                                 "for the N materials of 'Materials/Names' "
                                 "(at most 255).");
            row.push_back(static_cast<unsigned int>(std::stoi(token)));
          }
        if (!rows.empty() && row.size() != rows.front().size())
          throw InputError("Morphology grid file '" + file_name + "', line "
                           + std::to_string(line_number) + " has "
                           + std::to_string(row.size())
                           + " ids where the first row has "
                           + std::to_string(rows.front().size())
                           + ": every row must have the same length.");
        rows.push_back(row);
      }
    if (rows.empty())
      throw InputError("Morphology grid file '" + file_name
                       + "' holds no rows of material ids.");
    const unsigned int        nx = rows.front().size(), ny = rows.size();
    std::vector<unsigned int> ids(static_cast<std::size_t>(nx) * ny);
    for (unsigned int r = 0; r < ny; ++r)
      for (unsigned int i = 0; i < nx; ++i)
        ids[(ny - 1 - r) * nx + i] = rows[r][i]; // top row first in the file
    Morphology m(width, height, nx, ny, ids);
    m.origin   = "grid file " + file_name;
    m.n_placed = m.count_connected_heterogeneities();
    return m;
  }


  void
  Morphology::write_grid_file(const std::string &file_name) const
  {
    std::ostringstream out;
    out << "# tribodyn morphology: " << description() << "\n"
        << (n_phases() > 2 ? "# one row of pixels per line, top row first; "
                             "material ids 0 to "
                               + std::to_string(n_phases() - 1) + "\n"
                           : "# one row of pixels per line, top row first; 0 "
                             "matrix, 1 heterogeneity\n");
    for (unsigned int r = 0; r < n_y; ++r)
      {
        for (unsigned int i = 0; i < n_x; ++i)
          out << (i > 0 ? " " : "") << pixel(i, n_y - 1 - r);
        out << "\n";
      }
    write_file_atomically(file_name, out.str());
  }


} // namespace tribodyn
