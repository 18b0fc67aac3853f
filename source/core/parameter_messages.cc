// The one-paragraph message of a parameter file that deal.II's
// ParameterHandler refuses: the subsection of the offending line, and the
// expected form of a value in words rather than deal.II's pattern notation.

#include <algorithm>
#include <deal.II/base/exceptions.h>
#include <fstream>
#include <regex>
#include <sstream>
#include <tribodyn/core/parameter_messages.h>
#include <tribodyn/core/parameter_renames.h>
#include <vector>

namespace tribodyn
{
  namespace
  {
    /// deal.II's multi-line message as one paragraph.
    std::string
    one_paragraph(const std::string &text)
    {
      std::string paragraph;
      bool        space = false;
      for (const char c : text)
        {
          if (c == '\n' || c == ' ' || c == '\t')
            space = !paragraph.empty();
          else
            {
              if (space)
                paragraph += ' ';
              paragraph += c;
              space = false;
            }
        }
      return paragraph;
    }


    std::string
    trim(const std::string &s)
    {
      const auto b = s.find_first_not_of(" \t\r");
      if (b == std::string::npos)
        return "";
      return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
    }


    /// "A/B" for the subsections open at line @p line of @p file (empty at
    /// the top level; unknown if the file cannot be read).
    std::string
    subsection_at(const std::string &file, const int line)
    {
      std::ifstream            in(file);
      std::vector<std::string> open;
      std::string              text;
      for (int n = 1; n < line && std::getline(in, text); ++n)
        {
          const std::string t = trim(text.substr(0, text.find('#')));
          if (t.rfind("subsection ", 0) == 0)
            open.push_back(trim(t.substr(11)));
          else if (t == "end" && !open.empty())
            open.pop_back();
        }
      std::string path;
      for (const auto &s : open)
        path += (path.empty() ? "" : "/") + s;
      return path;
    }


    /// A number of deal.II's pattern text in words ("MAX_DOUBLE" is none).
    bool
    finite_bound(const std::string &b)
    {
      return b.find("MAX_DOUBLE") == std::string::npos && b != "-2147483648"
             && b != "2147483647" && b != "4294967295";
    }


    std::string
    range_in_words(const std::string &lo, const std::string &hi)
    {
      const bool l = finite_bound(lo), h = finite_bound(hi);
      if (l && h)
        return " between " + lo + " and " + hi;
      if (l)
        return " of at least " + lo;
      if (h)
        return " of at most " + hi;
      return "";
    }
  } // namespace


  std::string
  pattern_in_words(const std::string &pattern)
  {
    std::smatch       m;
    const std::string p = trim(pattern);
    if (std::regex_match(
          p, m, std::regex(R"(\[Double (\S+)\.\.\.(\S+) \(inclusive\)\])")))
      return "a number" + range_in_words(m[1], m[2]);
    if (std::regex_match(
          p,
          m,
          std::regex(R"(\[Integer range (\S+)\.\.\.(\S+) \(inclusive\)\])")))
      return "a whole number" + range_in_words(m[1], m[2]);
    if (p == "[Integer]")
      return "a whole number";
    if (p == "[Bool]")
      return "true or false";
    if (std::regex_match(p, m, std::regex(R"(\[Selection (.*) \])")))
      {
        std::string choices = m[1];
        std::string words;
        std::size_t start = 0;
        while (start <= choices.size())
          {
            const std::size_t bar = choices.find('|', start);
            const std::string item
              = trim(choices.substr(start,
                                    bar == std::string::npos ? std::string::npos
                                                             : bar - start));
            words += (words.empty() ? "" : ", ") + ("'" + item + "'");
            if (bar == std::string::npos)
              break;
            start = bar + 1;
          }
        return "one of " + words;
      }
    if (std::regex_match(p,
                         m,
                         std::regex(R"(\[List of <(.*)> of length .*\])")))
      return "a comma-separated list, each entry "
             + pattern_in_words(m[1].str());
    if (p == "[Anything]")
      return "any text";
    if (p.rfind("[FileName", 0) == 0)
      return "a file name";
    return "of the form " + p;
  }


  std::string
  describe_parameter_error(
    const dealii::ExceptionBase                           &exception,
    const std::string                                     &file,
    const std::function<std::pair<std::string, int>(int)> &origin)
  {
    // The file and line an entry came from (deal.II names the parsed text).
    const auto from = [&](const std::string &line, const std::string &name) {
      return origin ? origin(std::stoi(line))
                    : std::make_pair(name, std::stoi(line));
    };
    std::ostringstream info;
    exception.print_info(info);
    const std::string text = one_paragraph(info.str());
    const std::string hint
      = " Run 'tribodyn --print-parameters PROBLEM' to see every valid "
        "parameter with its documentation and default.";

    std::smatch m;
    // A value that does not match its pattern.
    if (std::regex_search(
          text,
          m,
          std::regex(R"(Line <(\d+)> of file <([^>]*)>: The entry value (.*) )"
                     R"(for the entry named (.*) does not match the given )"
                     R"(pattern: (\[.*\]))")))
      {
        const auto [at_file, at_line] = from(m[1], m[2]);
        const std::string where       = subsection_at(at_file, at_line);
        const std::string name
          = (where.empty() ? "" : where + "/") + trim(m[4].str());
        return "Error in the parameter file '" + at_file + "', line "
               + std::to_string(at_line) + ": the value '" + trim(m[3].str())
               + "' of "
               + (where.empty() ? "the top-level parameter '" : "parameter '")
               + name + "' is not valid: it must be "
               + pattern_in_words(m[5].str())
               + renamed_choice_hint(name, trim(m[3].str())) + "." + hint;
      }
    // An entry or subsection that is not declared.
    if (std::regex_search(
          text, m, std::regex(R"(Line <(\d+)> of file <([^>:]*)>?: (.*))")))
      {
        const auto [at_file, at_line] = from(m[1], m[2]);
        const std::string where       = subsection_at(at_file, at_line);
        std::string       cause       = m[3];
        std::smatch       e;
        if (std::regex_search(
              cause,
              e,
              std::regex(R"(No entry with name <([^>]*)> was declared)")))
          {
            // Named by its full path, as every other refusal names it.
            const std::string renamed = renamed_hint(where, e[1].str());
            cause                     = "there is no parameter '"
                    + (where.empty() ? e[1].str() + "' in the top level"
                                     : where + "/" + e[1].str() + "'")
                    + (renamed.empty() ? " (check its spelling and the "
                                         "subsection it is in)."
                                       : renamed + ".");
          }
        else if (std::regex_search(
                   cause,
                   e,
                   std::regex(
                     R"(There is no such subsection to be entered: (.*))")))
          {
            // (deal.II names it by its path from the top, joined by '.')
            std::string dotted = where;
            std::replace(dotted.begin(), dotted.end(), '/', '.');
            std::string name = trim(e[1].str());
            if (!dotted.empty() && name.rfind(dotted + ".", 0) == 0)
              name = name.substr(dotted.size() + 1);
            const std::string renamed = renamed_hint(where, name);
            cause                     = "there is no subsection '"
                    + (where.empty() ? name + "' in the top level"
                                     : where + "/" + name + "'")
                    + (!renamed.empty() ? renamed + "."
                       : where == "Materials"
                         ? " (a material's subsection exists for the names "
                           "of 'Materials/Names' only: add the material's "
                           "name there, or check its spelling)."
                         : " (check its spelling).");
          }
        else if (!where.empty())
          cause += " (in subsection '" + where + "')";
        return "Error in the parameter file '" + at_file + "', line "
               + std::to_string(at_line) + ": " + cause + hint;
      }
    return "Error in the parameter file '" + file + "': " + text + hint;
  }
} // namespace tribodyn
