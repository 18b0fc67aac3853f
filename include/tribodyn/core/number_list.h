// Lists of numbers in parameter entries ("1e9, 2e9" or "0 0 10 10").
#ifndef tribodyn_core_number_list_h
#define tribodyn_core_number_list_h

#include <algorithm>
#include <exception>
#include <sstream>
#include <string>
#include <tribodyn/core/errors.h>
#include <vector>

namespace tribodyn
{
  /**
   * The numbers of the list @p text (separated by commas and/or spaces; an
   * empty text is an empty list), or an InputError naming the parameter
   * @p name and the word that is not a number.
   */
  inline std::vector<double>
  parse_number_list(const std::string &text, const std::string &name)
  {
    std::string cleaned = text;
    std::replace(cleaned.begin(), cleaned.end(), ',', ' ');
    std::istringstream  in(cleaned);
    std::vector<double> values;
    for (std::string word; in >> word;)
      {
        std::size_t end = 0;
        double      v   = 0;
        try
          {
            v = std::stod(word, &end);
          }
        catch (const std::exception &)
          {
            end = 0;
          }
        if (end != word.size())
          throw InputError("'" + name + "': '" + word
                           + "' is not a number. Give numbers separated by "
                             "commas.");
        values.push_back(v);
      }
    return values;
  }
} // namespace tribodyn

#endif
