// Reading a parameter file for its problem, and entries addressed by path.

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>
#include <fstream>
#include <sstream>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/global_parameters.h>
#include <tribodyn/core/parameter_file.h>
#include <tribodyn/core/parameter_messages.h>
#include <tribodyn/core/parameter_renames.h>

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

    /// The text of @p file with each 'include NAME' whose NAME is a
    /// relative path made relative to the directory of @p file (deal.II
    /// looks for it in the working directory), so that a parameter file
    /// can build on a neighbour wherever it is run from. Lines keep their
    /// numbers: messages point at the file's own lines.
    std::string
    with_includes_beside(const std::string &file)
    {
      std::ifstream      in(file);
      std::ostringstream text;
      const auto         slash = file.find_last_of('/');
      const std::string  dir   = slash == std::string::npos
                                   ? std::string()
                                   : file.substr(0, slash + 1);
      for (std::string line; std::getline(in, line);)
        {
          const std::string trimmed = dealii::Utilities::trim(line);
          if (trimmed.rfind("include ", 0) == 0
              || trimmed.rfind("INCLUDE ", 0) == 0)
            {
              const std::string name
                = dealii::Utilities::trim(trimmed.substr(8));
              if (!name.empty() && name[0] != '/' && name[0] != '#')
                line = trimmed.substr(0, 8) + dir + name;
            }
          text << line << '\n';
        }
      return text.str();
    }


    /// ParameterHandler::parse_input() on @p file with its includes
    /// resolved beside it; messages name @p file.
    void
    parse_file(dealii::ParameterHandler &prm,
               const std::string        &file,
               const bool                skip_undefined)
    {
      std::istringstream text(with_includes_beside(file));
      prm.parse_input(text, file, "", skip_undefined);
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
      try
        {
          parse_file(first, file, true);
        }
      catch (const dealii::ExceptionBase &e)
        {
          throw InputError(describe_parameter_error(e, file));
        }
      problem_name = first.get("Problem");
    }
    const ProblemDescription &description = find_problem(problem_name);

    GlobalParameters::declare_parameters(prm);
    description.declare_parameters(prm);
    try
      {
        // parameters that depend on the file's values (e.g. a list of
        // names): a lenient first reading, then their declaration
        if (description.declare_dependent_parameters)
          {
            parse_file(prm, file, true);
            description.declare_dependent_parameters(prm);
          }
        parse_file(prm, file, false);
      }
    catch (const dealii::ExceptionBase &e)
      {
        throw InputError(describe_parameter_error(e, file));
      }
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
