// What identifies a run for a resume or a reuse: the comparable lines of
// its parameters and the entries that may differ (resumable_parameters.h).
#include <algorithm>
#include <deal.II/base/utilities.h>
#include <functional>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/parameter_binding.h>
#include <tribodyn/core/parameter_renames.h>
#include <tribodyn/core/resumable_parameters.h>

namespace tribodyn
{
  namespace
  {
    /// Parameter lines as a run of any version compares them: renamed
    /// entries in their current names (with_current_names()), a value that
    /// is one number in one spelling ("0.5e6" and "5e5", as defaults were
    /// written before and after they came from the parameter structs),
    /// sorted.
    std::vector<std::string>
    comparable_parameter_lines(const std::vector<std::string> &lines)
    {
      std::vector<std::string> out;
      for (std::string line : with_current_names(lines))
        {
          const auto eq = line.find(" = ");
          if (eq != std::string::npos)
            {
              const std::string value = line.substr(eq + 3);
              try
                {
                  std::size_t  used = 0;
                  const double x    = std::stod(value, &used);
                  if (used == value.size())
                    {
                      line = line.substr(0, eq + 3) + exact_number(x);
                    }
                }
              catch (const std::exception &)
                {
                  // not a number: compared as written
                }
            }
          out.push_back(line);
        }
      std::sort(out.begin(), out.end());
      return out;
    }
  } // namespace


  std::vector<std::string>
  resumable_parameter_lines(std::istream      &short_prm,
                            const std::string &end_time_entry,
                            double            *end_time)
  {
    using dealii::Utilities::trim;
    std::vector<std::string> sections, lines;
    std::string              line;
    while (std::getline(short_prm, line))
      {
        line = trim(line);
        if (line.rfind("subsection ", 0) == 0)
          sections.push_back(trim(line.substr(11)));
        else if (line == "end" && !sections.empty())
          sections.pop_back();
        else if (line.rfind("set ", 0) == 0)
          {
            const auto  eq = line.find('=');
            std::string path;
            for (const auto &s : sections)
              path += s + "/";
            path += trim(line.substr(4, eq - 4));
            lines.push_back(path + " = "
                            + (eq == std::string::npos
                                 ? std::string()
                                 : trim(line.substr(eq + 1))));
          }
      }
    // a run written before a rename reads as one of the current names
    std::vector<std::string> kept;
    for (const std::string &l : comparable_parameter_lines(lines))
      {
        const std::string path = l.substr(0, l.find(" = "));
        if (path == end_time_entry && end_time != nullptr)
          *end_time = std::stod(l.substr(l.find(" = ") + 3));
        if (path == end_time_entry || path == "Progress interval"
            || path == "Output directory" || path.rfind("Checkpoint/", 0) == 0)
          continue;
        kept.push_back(l);
      }
    return kept;
  }


  ResumableParameters
  resumable_parameters(dealii::ParameterHandler &prm,
                       const std::string        &end_time_entry)
  {
    ResumableParameters r;
    std::ostringstream  text;
    prm.print_parameters(text, dealii::ParameterHandler::ShortPRM);
    std::istringstream short_prm(text.str());
    r.lines = resumable_parameter_lines(short_prm, end_time_entry);
    // Every entry's default, from deal.II's JSON description of the
    // declared tree (an entry is an object with a "default_value").
    std::ostringstream json;
    prm.print_parameters(json, dealii::ParameterHandler::JSON);
    std::vector<std::string>                                       lines;
    const std::function<void(const nlohmann::json &, std::string)> walk
      = [&](const nlohmann::json &node, const std::string &path) {
          for (auto it = node.begin(); it != node.end(); ++it)
            if (it.value().is_object())
              {
                if (it.value().contains("default_value"))
                  {
                    lines.push_back(
                      path + it.key() + " = "
                      + it.value()["default_value"].get<std::string>());
                    const auto doc    = it.value().find("documentation");
                    const auto tagged = [&doc, &it](const char *tag) {
                      return doc != it.value().end() && doc->is_string()
                             && doc->get<std::string>().find(tag)
                                  != std::string::npos;
                    };
                    if (tagged(ParameterBinding::analysis_only_tag))
                      r.analysis_only.push_back(path + it.key());
                    if (tagged(ParameterBinding::layout_only_tag))
                      r.layout_only.push_back(path + it.key());
                  }
                else
                  walk(it.value(), path + it.key() + "/");
              }
        };
    walk(nlohmann::json::parse(json.str()), "");
    r.defaults = comparable_parameter_lines(lines);
    std::sort(r.analysis_only.begin(), r.analysis_only.end());
    std::sort(r.layout_only.begin(), r.layout_only.end());
    return r;
  }


  std::string
  quoted_names(const std::vector<std::string> &names)
  {
    std::string list;
    for (const std::string &name : names)
      list += (list.empty() ? "'" : ", '") + name + "'";
    return list;
  }


  std::vector<std::string>
  ResumableParameters::differing_in_run(
    const std::vector<std::string> &stored) const
  {
    std::vector<std::string> names;
    for (const std::string &name : differing(stored))
      if (!std::binary_search(analysis_only.begin(), analysis_only.end(), name))
        names.push_back(name);
    return names;
  }


  std::vector<std::string>
  ResumableParameters::differing(const std::vector<std::string> &stored) const
  {
    // Both sides without the lines that say "this entry is at its
    // default": what remains is each run's choices (the stored lines in
    // today's names and spellings first; this run's are already).
    const auto choices = [this](const std::vector<std::string> &comparable) {
      std::set<std::string> kept;
      for (const std::string &l : comparable)
        if (!std::binary_search(defaults.begin(), defaults.end(), l))
          kept.insert(l);
      return kept;
    };
    const std::set<std::string> a = choices(comparable_parameter_lines(stored)),
                                b = choices(lines);
    std::set<std::string> names;
    for (const auto &s : a)
      if (!b.count(s))
        names.insert(s.substr(0, s.find(" = ")));
    for (const auto &s : b)
      if (!a.count(s))
        names.insert(s.substr(0, s.find(" = ")));
    // (the work's layout: never a difference)
    for (const std::string &name : layout_only)
      names.erase(name);
    return {names.begin(), names.end()};
  }
} // namespace tribodyn
