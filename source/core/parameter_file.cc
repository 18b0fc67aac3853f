// Reading a parameter file for its problem, and entries addressed by path.

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/global_parameters.h>
#include <tribodyn/core/parameter_file.h>
#include <tribodyn/core/parameter_messages.h>
#include <tribodyn/core/parameter_renames.h>
#include <utility>
#include <vector>

namespace tribodyn
{
  namespace
  {
    void
    check_readable(const std::string &file)
    {
      std::ifstream in(file);
      if (!in)
        throw InputError("Cannot read the parameter file '" + file
                         + "': it does not exist or is not readable. Give the "
                           "path of a .prm file (examples are in prm/).");
    }


    /// The subsections and the entry name of @p path.
    std::vector<std::string>
    path_components(const std::string &path, const std::string &source)
    {
      std::vector<std::string> parts;
      std::string              part;
      for (const char c : path + "/")
        if (c == '/')
          {
            const std::string trimmed = dealii::Utilities::trim(part);
            if (trimmed.empty())
              throw InputError("'" + source + "': '" + path
                               + "' is not a parameter path. Write it as "
                                 "'Subsection/Name' (e.g. 'Time/End time'), "
                                 "as the parameter reference names it.");
            parts.push_back(trimmed);
            part.clear();
          }
        else
          part += c;
      return parts;
    }


    /// Call @p action inside the subsections of @p path with the entry's
    /// name; the handler is back at the top level afterwards, also when
    /// @p action throws.
    template <typename Action>
    auto
    at_path(dealii::ParameterHandler &prm,
            const std::string        &path,
            const std::string        &source,
            const Action             &action)
    {
      const std::vector<std::string> parts = path_components(path, source);
      unsigned int                   depth = 0;
      try
        {
          for (; depth + 1 < parts.size(); ++depth)
            prm.enter_subsection(parts[depth]);
          auto result = action(parts.back());
          for (; depth > 0; --depth)
            prm.leave_subsection();
          return result;
        }
      catch (const dealii::ExceptionBase &e)
        {
          for (; depth > 0; --depth)
            prm.leave_subsection();
          const std::string what = e.what();
          const auto        at   = what.find("the pattern <");
          if (what.find("ExcValueDoesNotMatchPattern") != std::string::npos
              && at != std::string::npos)
            {
              const auto        begin = at + 13;
              const std::string pattern
                = what.substr(begin,
                              what.find(">", what.rfind(']') + 1) - begin);
              throw InputError("'" + source + "': the value given for '" + path
                               + "' does not fit that parameter, "
                               + "which takes " + pattern_in_words(pattern)
                               + ".");
            }
          // a renamed subsection or entry on the way: say its new name
          std::string renamed, parent;
          for (const std::string &part : parts)
            if (renamed.empty())
              {
                renamed = renamed_hint(parent, part);
                parent += (parent.empty() ? "" : "/") + part;
              }
          throw InputError("'" + source + "': '" + path
                           + "' names no parameter of the scene's problem"
                           + renamed
                           + ". Write the path as the parameter reference "
                             "names it ('tribodyn --print-parameters "
                             "PROBLEM'), e.g. 'Geometry/Rough "
                             "interface/Seed'.");
        }
    }

    /// A parameter file with its includes expanded in place: its text,
    /// and for each line of it the file and line it came from (messages
    /// name those). deal.II's ParameterHandler reads 'include NAME' from
    /// the working directory; here NAME is relative to the directory of
    /// the file that names it, at every depth, so that a parameter file can
    /// build on its neighbours wherever it is run from.
    struct ExpandedFile
    {
      std::string                              text;
      std::vector<std::pair<std::string, int>> origin;
    };

    /// @p chain: the files being expanded, outermost first (as named, and
    /// their canonical paths to recognize a loop).
    void
    expand_includes(const std::string                                &file,
                    ExpandedFile                                     &out,
                    std::vector<std::pair<std::string, std::string>> &chain)
    {
      // (the name as given when the path cannot be resolved: an empty
      // one would make every such file look like the same)
      std::error_code error;
      const auto      resolved = std::filesystem::weakly_canonical(file, error);
      const std::string canonical = error ? file : resolved.string();
      for (const auto &[named, seen] : chain)
        if (seen == canonical)
          {
            std::string loop;
            for (const auto &link : chain)
              loop += "'" + link.first + "' -> ";
            throw InputError("The parameter file '" + named
                             + "' includes itself (" + loop + "'" + file
                             + "'): remove the include that closes the loop.");
          }
      chain.emplace_back(file, canonical);
      std::ifstream     in(file);
      const auto        slash = file.find_last_of('/');
      const std::string dir   = slash == std::string::npos
                                  ? std::string()
                                  : file.substr(0, slash + 1);
      int               n     = 0;
      for (std::string line; std::getline(in, line);)
        {
          ++n;
          const std::string trimmed = dealii::Utilities::trim(line);
          if (trimmed.rfind("include ", 0) == 0
              || trimmed.rfind("INCLUDE ", 0) == 0)
            {
              const std::string rest = trimmed.substr(8);
              const std::string name
                = dealii::Utilities::trim(rest.substr(0, rest.find('#')));
              if (!name.empty())
                {
                  const std::string path = name[0] == '/' ? name : dir + name;
                  if (!std::ifstream(path))
                    throw InputError(
                      "Cannot read the file '" + path + "' included at line "
                      + std::to_string(n) + " of the parameter file '" + file
                      + "': it does not exist or is not readable (an include "
                        "names a file relative to the file that includes "
                        "it).");
                  expand_includes(path, out, chain);
                  continue;
                }
            }
          out.text += line + '\n';
          out.origin.emplace_back(file, n);
        }
      chain.pop_back();
    }


    /// ParameterHandler::parse_input() on @p file with its includes
    /// expanded; a refusal names the file and line the entry came from.
    void
    parse_file(dealii::ParameterHandler &prm,
               const std::string        &file,
               const bool                skip_undefined)
    {
      ExpandedFile                                     expanded;
      std::vector<std::pair<std::string, std::string>> chain;
      expand_includes(file, expanded, chain);
      std::istringstream text(expanded.text);
      try
        {
          prm.parse_input(text, file, "", skip_undefined);
        }
      catch (const dealii::ExceptionBase &e)
        {
          throw InputError(
            describe_parameter_error(e, file, [&](const int line) {
              return line >= 1
                         && line <= static_cast<int>(expanded.origin.size())
                       ? expanded.origin[line - 1]
                       : std::make_pair(file, line);
            }));
        }
    }
  } // namespace


  const ProblemDescription &
  read_parameter_file(const std::string &file, dealii::ParameterHandler &prm)
  {
    check_readable(file);

    // First pass: only the global parameters, to learn which problem's
    // parameters to declare. Undefined entries are skipped here and
    // checked strictly in the second pass.
    std::string problem_name;
    {
      dealii::ParameterHandler first;
      GlobalParameters::declare_parameters(first);
      parse_file(first, file, true);
      problem_name = first.get("Problem");
    }
    const ProblemDescription &description = find_problem(problem_name);

    GlobalParameters::declare_parameters(prm);
    description.declare_parameters(prm);
    // parameters that depend on the file's values (e.g. a list of names): a
    // lenient first reading, then their declaration
    if (description.declare_dependent_parameters)
      {
        parse_file(prm, file, true);
        description.declare_dependent_parameters(prm);
      }
    parse_file(prm, file, false);
    return description;
  }


  void
  set_parameter_by_path(dealii::ParameterHandler &prm,
                        const std::string        &path,
                        const std::string        &value,
                        const std::string        &source)
  {
    at_path(prm, path, source, [&](const std::string &name) {
      // set() creates no entry: an undeclared name throws
      prm.set(name, value);
      return 0;
    });
  }


  std::string
  get_parameter_by_path(dealii::ParameterHandler &prm,
                        const std::string        &path,
                        const std::string        &source)
  {
    return at_path(prm, path, source, [&](const std::string &name) {
      return prm.get(name);
    });
  }
} // namespace tribodyn
